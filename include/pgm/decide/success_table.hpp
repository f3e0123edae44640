#pragma once
/// \file
/// The table a decision works on: P(success variable | some variables), with those variables
/// as the table's parents. When they are exactly the success node's parents this is the
/// node's own table (no inference); otherwise the inference engine computes it, conditioning
/// on further observations if given.

#include <algorithm>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/inference/evidence_scope.hpp"
#include "pgm/inference/inference_engine.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

/// P(`success` | `given`, `observed`) as a table whose parents are `given` in order, computed by
/// `engine` (whose evidence is restored afterwards). A configuration of `given` that has
/// probability zero together with `observed` gets the uniform distribution (1/J), the same rule
/// as a parent configuration without data. Throws model_error for unknown or repeated
/// variables, or a variable both given and observed.
template <InferenceEngine Engine>
[[nodiscard]] cpt<double> success_table(Engine& engine, std::string_view success, std::span<const std::string> given,
                                        std::span<const observation> observed = {}) {
  const auto& network = engine.network();
  const auto target = node_of(network, success);
  std::vector<variable_id> ids;
  std::vector<variable> parents;
  for (const auto& name : given) {
    const auto id = node_of(network, name);
    if (id == target) throw model_error("'" + name + "' cannot condition its own success table");
    if (std::find(ids.begin(), ids.end(), id) != ids.end()) throw model_error("'" + name + "' is given twice");
    for (const auto& o : observed) {
      if (o.variable == id) throw model_error("'" + name + "' is both given and observed");
    }
    ids.push_back(id);
    parents.push_back(network.at(name));
  }
  for (const auto& o : observed) {
    if (o.variable == target) throw model_error("the success variable '" + std::string(success) + "' is observed");
  }
  const auto& own = network.table(target);
  if (observed.empty() && ids == network.graph().parents(target)) return own;

  auto query_ids = ids;
  query_ids.push_back(target);
  posterior joint;
  {
    const evidence_scope scope(engine, {{observed.begin(), observed.end()}, {}});
    joint = engine.joint(query_ids);
  }
  // The success variable is last in the joint, so each run of J values is one configuration.
  const auto j = own.child_cardinality();
  std::vector<double> values(joint.table.values().begin(), joint.table.values().end());
  for (std::size_t u = 0; u * j < values.size(); ++u) {
    double sum = 0.0;
    for (std::size_t x = 0; x < j; ++x) sum += values[u * j + x];
    for (std::size_t x = 0; x < j; ++x) {
      values[u * j + x] = sum > 0.0 ? values[u * j + x] / sum : 1.0 / static_cast<double>(j);
    }
  }
  return cpt<double>(own.child(), std::move(parents), std::move(values));
}

/// P(`success` | do(`controllable` = c), the rest of `given` = g, `observed`) as a table whose
/// parents are `given` in order (the controllable variables among them): what setting the
/// controllable variables does, which prevention needs (docs/decide.md). When no controllable
/// variable has a parent, setting it is observing it and this is success_table; otherwise the
/// engine answers one intervention per configuration of the controllable variables, under the
/// other observations. A configuration of the rest whose probability is zero under an
/// intervention gets the uniform distribution, as in success_table.
template <InferenceEngine Engine>
[[nodiscard]] cpt<double> intervened_success_table(Engine& engine, std::string_view success,
                                                   std::span<const std::string> given,
                                                   std::span<const std::string> controllable,
                                                   std::span<const observation> observed = {}) {
  const auto& network = engine.network();
  const auto is_controllable = [&](const std::string& name) {
    return std::find(controllable.begin(), controllable.end(), name) != controllable.end();
  };
  const bool all_roots = std::all_of(controllable.begin(), controllable.end(), [&](const std::string& name) {
    return network.graph().parents(node_of(network, name)).empty();
  });
  const auto target = node_of(network, success);
  std::vector<variable_id> given_ids;
  for (const auto& name : given) given_ids.push_back(node_of(network, name));
  // With every parent given and nothing below observed, the success node's own table is the
  // answer whether its parents are set or seen: given its parents it depends on nothing else.
  const bool own_table = observed.empty() && given_ids == network.graph().parents(target);
  if (all_roots || own_table) return success_table(engine, success, given, observed);
  const auto& own = network.table(target);
  std::vector<variable> parents;
  std::vector<std::size_t> set_positions;  // positions in `given` of the controllable variables
  std::vector<std::string> rest;           // the others, then the success variable, for the joint
  for (std::size_t k = 0; k < given.size(); ++k) {
    parents.push_back(network.at(given[k]));
    if (is_controllable(given[k])) {
      set_positions.push_back(k);
    } else {
      rest.push_back(given[k]);
    }
  }
  // The checks of success_table (unknown, repeated, observed variables) on the plain table.
  static_cast<void>(success_table(engine, success, given, observed));
  rest.emplace_back(success);
  const cpt<double> shape(own.child(), parents);
  const auto j = own.child_cardinality();
  std::vector<double> values(shape.size(), 1.0 / static_cast<double>(j));
  evidence_scope scope(engine);
  std::vector<std::size_t> codes(given.size(), 0);
  std::vector<std::size_t> set_cards;
  std::size_t settings = 1;
  for (auto k : set_positions) {
    set_cards.push_back(parents[k].cardinality());
    settings *= set_cards.back();
  }
  for (std::size_t c = 0; c < settings; ++c) {
    evidence_set scenario{{observed.begin(), observed.end()}, {}, {}};
    std::size_t rem = c;
    for (std::size_t i = set_positions.size(); i-- > 0;) {
      const auto k = set_positions[i];
      codes[k] = rem % set_cards[i];
      rem /= set_cards[i];
      scenario.intervened.push_back({network.id(given[k]), index_at<state_index>(codes[k])});
    }
    scope.replace(std::move(scenario));
    posterior joint;
    try {
      joint = query(engine, rest);
    } catch (const impossible_evidence&) {
      continue;  // the observations cannot happen under this setting: every column uniform
    }
    // The joint runs over the non-controllable parents (in `given` order), the success last.
    const auto cells = joint.table.size() / j;
    for (std::size_t g = 0; g < cells; ++g) {
      std::size_t grem = g;
      for (std::size_t k = given.size(); k-- > 0;) {
        if (is_controllable(given[k])) continue;
        codes[k] = grem % parents[k].cardinality();
        grem /= parents[k].cardinality();
      }
      const auto u = shape.configuration(codes).value();
      double sum = 0.0;
      for (std::size_t x = 0; x < j; ++x) sum += joint.table.values()[g * j + x];
      for (std::size_t x = 0; x < j; ++x) {
        values[u * j + x] = sum > 0.0 ? joint.table.values()[g * j + x] / sum : 1.0 / static_cast<double>(j);
      }
    }
  }
  return cpt<double>(own.child(), std::move(parents), std::move(values));
}

/// The same by variable elimination on `network`.
[[nodiscard]] PGM_DECL cpt<double> success_table(const bayesian_network& network, std::string_view success,
                                                 std::span<const std::string> given,
                                                 std::span<const observation> observed = {},
                                                 elimination_heuristic heuristic = elimination_heuristic::min_fill);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/decide/impl/success_table.ipp"
#endif
