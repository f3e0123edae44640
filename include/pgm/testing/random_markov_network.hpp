#pragma once
/// \file
/// Random Markov networks for property tests, and their answers by brute force: every joint state
/// enumerated, in long double, with the log of Z kept apart so that huge factors do not overflow.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/markov_network.hpp"
#include "pgm/inference/query.hpp"

namespace pgm::testing {

struct random_markov_options {
  std::size_t variables = 7;
  std::size_t factors = 9;
  std::size_t min_states = 2;
  std::size_t max_states = 4;
  std::size_t max_arity = 4;
  /// The chance that a factor value is 0 (hard constraints).
  double zero_chance = 0.1;
  /// Values are drawn as exp(U[-scale, scale]): a large scale makes Z overflow a double.
  double scale = 2.0;
};

inline markov_network random_markov_network(std::uint64_t seed, const random_markov_options& options = {}) {
  std::mt19937_64 engine(seed);
  auto below = [&](std::size_t n) { return static_cast<std::size_t>(engine() % n); };
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<variable> variables;
  std::vector<std::size_t> cards;
  for (std::size_t i = 0; i < options.variables; ++i) {
    const auto states = options.min_states + below(options.max_states - options.min_states + 1);
    std::vector<std::string> labels;
    for (std::size_t s = 0; s < states; ++s) labels.push_back(std::to_string(s));
    variables.emplace_back("x" + std::to_string(i), labels);
    cards.push_back(states);
  }
  std::vector<factor_table> factors;
  for (std::size_t f = 0; f < options.factors; ++f) {
    std::vector<std::size_t> order(options.variables);
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), engine);
    const auto arity = 1 + below(std::min(options.max_arity, options.variables));
    std::vector<variable_id> scope;
    std::vector<std::size_t> scope_cards;
    std::size_t cells = 1;
    for (std::size_t k = 0; k < arity; ++k) {
      scope.push_back(index_at<variable_id>(order[k]));
      scope_cards.push_back(cards[order[k]]);
      cells *= cards[order[k]];
    }
    std::vector<double> values(cells);
    for (auto& v : values)
      v = unit(engine) < options.zero_chance ? 0.0 : std::exp((2 * unit(engine) - 1) * options.scale);
    factors.emplace_back(std::move(scope), std::move(scope_cards), std::move(values));
  }
  return markov_network(std::move(variables), std::move(factors));
}

/// ln of the product of the factors at a joint state (−∞ where one is 0).
inline double log_value(const markov_network& model, const std::vector<std::size_t>& state) {
  double total = 0.0;
  for (const auto& f : model.factors()) {
    std::size_t index = 0;
    for (std::size_t k = 0; k < f.scope().size(); ++k)
      index = index * f.cardinalities()[k] + state[f.scope()[k].value()];
    total += std::log(f.values()[index]);
  }
  return total;
}

/// Calls visit(state, ln value) for every joint state that agrees with `fixed` (−1: free).
template <class Visit>
void for_each_state(const markov_network& model, const std::vector<long>& fixed, Visit&& visit) {
  const auto n = model.size();
  std::vector<std::size_t> state(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (fixed[i] >= 0) state[i] = static_cast<std::size_t>(fixed[i]);
  }
  while (true) {
    visit(state, log_value(model, state));
    std::size_t k = n;
    while (k-- > 0) {
      if (fixed[k] >= 0) continue;
      if (++state[k] < model.variables()[k].cardinality()) break;
      state[k] = 0;
    }
    if (k == static_cast<std::size_t>(-1)) return;
  }
}

/// What brute force says: ln Z with the evidence, every variable's marginal, and the largest ln
/// value of a joint state.
struct brute_force_answers {
  double log_z = 0.0;
  std::vector<std::vector<double>> marginals;
  double log_max = 0.0;
};

inline brute_force_answers brute_force(const markov_network& model, const std::vector<long>& fixed) {
  // Shifted by the largest ln value so that exp never overflows.
  double shift = -INFINITY;
  for_each_state(model, fixed, [&](const std::vector<std::size_t>&, double v) { shift = std::max(shift, v); });
  brute_force_answers answers;
  answers.log_max = shift;
  answers.marginals.resize(model.size());
  for (std::size_t i = 0; i < model.size(); ++i) answers.marginals[i].assign(model.variables()[i].cardinality(), 0.0);
  long double z = 0;
  std::vector<std::vector<long double>> sums(model.size());
  for (std::size_t i = 0; i < model.size(); ++i) sums[i].assign(model.variables()[i].cardinality(), 0.0L);
  if (shift == -INFINITY) {
    answers.log_z = -INFINITY;
    return answers;
  }
  for_each_state(model, fixed, [&](const std::vector<std::size_t>& state, double v) {
    const long double w = std::exp(static_cast<long double>(v - shift));
    z += w;
    for (std::size_t i = 0; i < state.size(); ++i) sums[i][state[i]] += w;
  });
  answers.log_z = static_cast<double>(std::log(z)) + shift;
  for (std::size_t i = 0; i < model.size(); ++i) {
    for (std::size_t s = 0; s < sums[i].size(); ++s) answers.marginals[i][s] = static_cast<double>(sums[i][s] / z);
  }
  return answers;
}

/// The largest ln Σ over the others of a joint state of `query`, by brute force.
inline double brute_force_marginal_map(const markov_network& model, const std::vector<variable_id>& query,
                                       const std::vector<long>& fixed) {
  std::vector<std::pair<std::vector<std::size_t>, long double>> sums;
  double shift = -INFINITY;
  for_each_state(model, fixed, [&](const std::vector<std::size_t>&, double v) { shift = std::max(shift, v); });
  if (shift == -INFINITY) return -INFINITY;
  std::vector<std::vector<std::size_t>> keys;
  std::vector<long double> totals;
  for_each_state(model, fixed, [&](const std::vector<std::size_t>& state, double v) {
    std::vector<std::size_t> key;
    for (auto q : query) key.push_back(state[q.value()]);
    const auto at = std::find(keys.begin(), keys.end(), key);
    const long double w = std::exp(static_cast<long double>(v - shift));
    if (at == keys.end()) {
      keys.push_back(key);
      totals.push_back(w);
    } else {
      totals[static_cast<std::size_t>(at - keys.begin())] += w;
    }
  });
  return static_cast<double>(std::log(*std::max_element(totals.begin(), totals.end()))) + shift;
}

/// ln Σ over the others of the joint state `states` of `query`, by brute force.
inline double brute_force_query_value(const markov_network& model, const std::vector<variable_id>& query,
                                      const std::vector<std::size_t>& states, std::vector<long> fixed) {
  for (std::size_t k = 0; k < query.size(); ++k) fixed[query[k].value()] = static_cast<long>(states[k]);
  return brute_force(model, fixed).log_z;
}

/// Hard evidence on about one variable in four, drawn from `seed`; `fixed` receives each
/// variable's observed state (−1 for none), as brute_force takes it.
inline evidence_set random_hard_evidence(const markov_network& model, std::uint64_t seed, std::vector<long>& fixed) {
  fixed.assign(model.size(), -1);
  evidence_set observed;
  std::mt19937_64 engine(seed);
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (engine() % 4 != 0) continue;
    const auto state = engine() % model.variables()[i].cardinality();
    fixed[i] = static_cast<long>(state);
    observed.hard.push_back({index_at<variable_id>(i), index_at<state_index>(state)});
  }
  return observed;
}

}  // namespace pgm::testing
