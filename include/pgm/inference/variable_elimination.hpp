#pragma once
/// \file
/// Exact inference by variable elimination: P(query | evidence) for any set of query variables.
/// Only the ancestors of the query and evidence variables take part (the others sum to one),
/// the evidence is applied to each table before any product, and the remaining variables are
/// eliminated greedily in min-fill (default) or min-degree order over the interaction graph.

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/inference/factor.hpp"

namespace pgm {

/// Evidence whose probability is zero under the network: nothing can be conditioned on it.
class impossible_evidence : public model_error {
 public:
  using model_error::model_error;
};

/// Observed states by variable name.
using evidence = std::map<std::string, std::string, std::less<>>;

/// One observed state by id, the form the library passes around internally.
struct observation {
  variable_id variable;
  state_index state;
  friend bool operator==(const observation&, const observation&) = default;
};

enum class elimination_heuristic {
  min_fill,   ///< fewest new edges among the neighbours; ties by degree, then id
  min_degree  ///< fewest neighbours; ties by id
};

/// A normalized distribution over `variables` (in the order asked), with P(evidence).
struct posterior {
  std::vector<variable> variables;
  /// Over the variables' network ids in the same order, values summing to one.
  factor table;
  double evidence_probability = 1.0;

  /// The probability of these states (labels, one per variable in order).
  [[nodiscard]] double probability(std::span<const std::string> states) const {
    if (states.size() != variables.size()) {
      throw model_error("the posterior is over " + std::to_string(variables.size()) + " variables, got " +
                        std::to_string(states.size()) + " states");
    }
    std::vector<std::size_t> codes(states.size());
    for (std::size_t i = 0; i < codes.size(); ++i) codes[i] = variables[i].state(states[i]).value();
    return table.at(codes);
  }
  [[nodiscard]] double probability(std::initializer_list<std::string> states) const {
    return probability(std::span<const std::string>(states.begin(), states.size()));
  }
};

namespace detail {

/// The node ids of `names`, throwing model_error naming an unknown one.
[[nodiscard]] inline variable_id node_of(const bayesian_network& network, std::string_view name) {
  if (!network.structure().contains(name)) {
    std::vector<std::string> names;
    for (const auto& v : network.variables()) names.push_back(v.name());
    throw model_error("the network has no variable '" + std::string(name) +
                      "' (variables: " + detail::list_for_message(names) + ")");
  }
  return network.id(name);
}

/// Whether each node is an ancestor of (or one of) `targets`.
[[nodiscard]] inline std::vector<bool> ancestral_set(const bayesian_network& network,
                                                     std::span<const variable_id> targets) {
  std::vector<bool> in(network.size(), false);
  std::vector<variable_id> stack(targets.begin(), targets.end());
  while (!stack.empty()) {
    const auto node = stack.back();
    stack.pop_back();
    if (in[node.value()]) continue;
    in[node.value()] = true;
    for (auto parent : network.graph().parents(node)) stack.push_back(parent);
  }
  return in;
}

}  // namespace detail

/// A greedy elimination order of `eliminate` for the interaction graph of `factors`.
[[nodiscard]] inline std::vector<variable_id> elimination_order(
    const std::vector<factor>& factors, std::vector<variable_id> eliminate,
    elimination_heuristic heuristic = elimination_heuristic::min_fill) {
  // Dense adjacency over the variables that occur: networks here have a few dozen nodes.
  std::vector<variable_id> nodes;
  for (const auto& f : factors) nodes.insert(nodes.end(), f.scope().begin(), f.scope().end());
  nodes.insert(nodes.end(), eliminate.begin(), eliminate.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const auto n = nodes.size();
  auto index = [&](variable_id id) {
    return static_cast<std::size_t>(std::lower_bound(nodes.begin(), nodes.end(), id) - nodes.begin());
  };
  std::vector<std::vector<char>> adjacent(n, std::vector<char>(n, 0));
  for (const auto& f : factors) {
    for (auto a : f.scope()) {
      for (auto b : f.scope()) {
        if (a != b) adjacent[index(a)][index(b)] = 1;
      }
    }
  }
  std::vector<char> gone(n, 0);
  std::vector<variable_id> order;
  order.reserve(eliminate.size());
  std::sort(eliminate.begin(), eliminate.end());
  while (!eliminate.empty()) {
    std::size_t best = 0;
    auto best_cost = std::make_pair(std::numeric_limits<std::size_t>::max(), std::numeric_limits<std::size_t>::max());
    for (std::size_t c = 0; c < eliminate.size(); ++c) {
      const auto v = index(eliminate[c]);
      std::vector<std::size_t> neighbours;
      for (std::size_t w = 0; w < n; ++w) {
        if (!gone[w] && adjacent[v][w]) neighbours.push_back(w);
      }
      std::size_t fill = 0;
      if (heuristic == elimination_heuristic::min_fill) {
        for (std::size_t i = 0; i < neighbours.size(); ++i) {
          for (std::size_t j = i + 1; j < neighbours.size(); ++j)
            fill += adjacent[neighbours[i]][neighbours[j]] ? 0 : 1;
        }
      }
      const auto cost = std::make_pair(fill, neighbours.size());
      if (cost < best_cost) {
        best_cost = cost;
        best = c;
      }
    }
    const auto v = index(eliminate[best]);
    for (std::size_t a = 0; a < n; ++a) {
      if (gone[a] || !adjacent[v][a]) continue;
      for (std::size_t b = 0; b < n; ++b) {
        if (b != a && !gone[b] && adjacent[v][b]) adjacent[a][b] = 1;
      }
    }
    gone[v] = 1;
    order.push_back(eliminate[best]);
    eliminate.erase(eliminate.begin() + static_cast<std::ptrdiff_t>(best));
  }
  return order;
}

/// The unnormalized P(query, evidence) over `query` in the order given; its sum is P(evidence).
/// Query and evidence variables must be distinct network ids (checked by the named overload).
[[nodiscard]] inline factor joint_with_evidence(const bayesian_network& network, std::span<const variable_id> query,
                                                std::span<const observation> observed,
                                                elimination_heuristic heuristic = elimination_heuristic::min_fill) {
  std::vector<variable_id> targets(query.begin(), query.end());
  for (const auto& o : observed) targets.push_back(o.variable);
  const auto relevant = detail::ancestral_set(network, targets);

  std::vector<std::ptrdiff_t> observed_state(network.size(), -1);
  for (const auto& o : observed) observed_state[o.variable.value()] = static_cast<std::ptrdiff_t>(o.state.value());

  std::vector<factor> factors;
  std::vector<variable_id> eliminate;
  for (std::size_t i = 0; i < network.size(); ++i) {
    if (!relevant[i]) continue;
    const variable_id node(static_cast<variable_id::rep>(i));
    const auto parents = network.graph().parents(node);
    factor f = factor::from_cpt(network.table(node), node, parents);
    const auto scope = f.scope();  // a copy: reducing replaces f
    for (auto id : scope) {
      if (observed_state[id.value()] >= 0) f = f.reduce(id, static_cast<std::size_t>(observed_state[id.value()]));
    }
    factors.push_back(std::move(f));
    const bool queried = std::find(query.begin(), query.end(), node) != query.end();
    if (!queried && observed_state[i] < 0) eliminate.push_back(node);
  }

  for (auto variable : elimination_order(factors, std::move(eliminate), heuristic)) {
    factor product;
    std::vector<factor> rest;
    rest.reserve(factors.size());
    for (auto& f : factors) {
      if (f.contains(variable)) {
        product = product * f;
      } else {
        rest.push_back(std::move(f));
      }
    }
    rest.push_back(product.sum_out(variable));
    factors = std::move(rest);
  }
  factor result;
  for (const auto& f : factors) result = result * f;
  return result.permuted(query);
}

/// P(query | evidence) by name. Throws model_error for an unknown variable or state, a
/// variable asked twice or both asked and observed; impossible_evidence when P(evidence) = 0.
[[nodiscard]] inline posterior query(const bayesian_network& network, std::span<const std::string> variables,
                                     const evidence& observed = {},
                                     elimination_heuristic heuristic = elimination_heuristic::min_fill) {
  std::vector<variable_id> ids;
  posterior result;
  for (const auto& name : variables) {
    const auto id = detail::node_of(network, name);
    if (std::find(ids.begin(), ids.end(), id) != ids.end()) {
      throw model_error("the query names '" + name + "' twice");
    }
    if (observed.contains(name)) {
      throw model_error("'" + name + "' is both queried and observed");
    }
    ids.push_back(id);
    result.variables.push_back(network.at(name));
  }
  std::vector<observation> codes;
  for (const auto& [name, state] : observed) {
    const auto id = detail::node_of(network, name);
    codes.push_back({id, network.at(name).state(state)});
  }
  result.table = joint_with_evidence(network, ids, codes, heuristic);
  result.evidence_probability = result.table.normalize();
  if (!(result.evidence_probability > 0.0)) {
    std::string text;
    for (const auto& [name, state] : observed) text += (text.empty() ? "" : ", ") + name + "=" + state;
    throw impossible_evidence("the evidence " + text + " has probability 0 under the network");
  }
  return result;
}

[[nodiscard]] inline posterior query(const bayesian_network& network, std::initializer_list<std::string> variables,
                                     const evidence& observed = {},
                                     elimination_heuristic heuristic = elimination_heuristic::min_fill) {
  return query(network, std::span<const std::string>(variables.begin(), variables.size()), observed, heuristic);
}

}  // namespace pgm
