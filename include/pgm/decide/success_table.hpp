#pragma once
/// \file
/// The table a decision works on: P(success variable | some variables), with those variables
/// as the table's parents. When they are exactly the success node's parents this is the
/// node's own table (no inference); otherwise variable elimination computes it, conditioning
/// on further observations if given.

#include <algorithm>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

/// P(`success` | `given`, `observed`) as a table whose parents are `given` in order. A
/// configuration of `given` that has probability zero together with `observed` gets the
/// uniform distribution (1/J), the same rule as a parent configuration without data.
/// Throws model_error for unknown or repeated variables, or a variable both given and observed.
[[nodiscard]] inline cpt<double> success_table(const bayesian_network& network, std::string_view success,
                                               std::span<const std::string> given,
                                               std::span<const observation> observed = {},
                                               elimination_heuristic heuristic = elimination_heuristic::min_fill) {
  const auto target = detail::node_of(network, success);
  std::vector<variable_id> ids;
  std::vector<variable> parents;
  for (const auto& name : given) {
    const auto id = detail::node_of(network, name);
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
  const auto joint = joint_with_evidence(network, query_ids, observed, heuristic);
  // The success variable is last in the joint, so each run of J values is one configuration.
  if (!(joint.sum() > 0.0)) throw impossible_evidence("the observations have probability 0 under the network");
  const auto j = own.child_cardinality();
  std::vector<double> values(joint.values().begin(), joint.values().end());
  for (std::size_t u = 0; u * j < values.size(); ++u) {
    double sum = 0.0;
    for (std::size_t x = 0; x < j; ++x) sum += values[u * j + x];
    for (std::size_t x = 0; x < j; ++x) {
      values[u * j + x] = sum > 0.0 ? values[u * j + x] / sum : 1.0 / static_cast<double>(j);
    }
  }
  return cpt<double>(own.child(), std::move(parents), std::move(values));
}

}  // namespace pgm
