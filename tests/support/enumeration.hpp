#pragma once
// Reference answers by brute force, for tests and benchmarks only: P(query | evidence) by
// enumerating every joint state of a network, and failure-prevention targets by a plain
// breadth-first search from each configuration with no sharing between them.

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <span>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/decide/prevent.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm::testing {

/// Unnormalized P(query, evidence) over `query` in order, by summing the full joint.
inline std::vector<double> enumerate_joint(const bayesian_network& network, std::span<const variable_id> query,
                                           std::span<const observation> observed) {
  const auto n = network.size();
  std::vector<std::size_t> cards(n);
  for (std::size_t i = 0; i < n; ++i) cards[i] = network.variables()[i].cardinality();
  std::size_t out_size = 1;
  for (auto q : query) out_size *= cards[q.value()];
  std::vector<double> out(out_size, 0.0);
  std::vector<std::size_t> state(n, 0);
  std::vector<std::vector<variable_id>> parents(n);
  for (std::size_t i = 0; i < n; ++i) parents[i] = network.graph().parents(index_at<variable_id>(i));
  while (true) {
    bool consistent = true;
    for (const auto& o : observed) consistent = consistent && state[o.variable.value()] == o.state.value();
    if (consistent) {
      double p = 1.0;
      for (std::size_t i = 0; i < n; ++i) {
        const auto& table = network.tables()[i];
        std::size_t u = 0;
        for (auto parent : parents[i]) u = u * cards[parent.value()] + state[parent.value()];
        p *= table.values()[u * cards[i] + state[i]];
      }
      std::size_t index = 0;
      for (auto q : query) index = index * cards[q.value()] + state[q.value()];
      out[index] += p;
    }
    std::size_t k = n;
    while (k-- > 0) {
      if (++state[k] < cards[k]) break;
      state[k] = 0;
    }
    if (k == static_cast<std::size_t>(-1)) break;
  }
  return out;
}

/// Calls visit(state, p) for every joint state of the network, p = Π tables × Π likelihoods of
/// `observed`'s soft evidence, 0 for states against its hard evidence or interventions, an
/// intervened variable's own table left out (the truncated factorisation); tables read as their
/// columns' distributions, as the engines read them.
template <class Visit>
void enumerate_states(const bayesian_network& network, const evidence_set& observed, Visit&& visit) {
  const auto n = network.size();
  std::vector<std::size_t> cards(n);
  for (std::size_t i = 0; i < n; ++i) cards[i] = network.variables()[i].cardinality();
  std::vector<std::vector<variable_id>> parents(n);
  for (std::size_t i = 0; i < n; ++i) parents[i] = network.graph().parents(index_at<variable_id>(i));
  std::vector<std::size_t> state(n, 0);
  while (true) {
    bool consistent = true;
    for (const auto& o : observed.hard) consistent = consistent && state[o.variable.value()] == o.state.value();
    for (const auto& o : observed.intervened) consistent = consistent && state[o.variable.value()] == o.state.value();
    double p = 0.0;
    if (consistent) {
      p = 1.0;
      for (std::size_t i = 0; i < n; ++i) {
        if (observed.intervenes(index_at<variable_id>(i))) continue;
        const auto& table = network.tables()[i];
        std::size_t u = 0;
        for (auto parent : parents[i]) u = u * cards[parent.value()] + state[parent.value()];
        double column = 0.0;
        for (std::size_t x = 0; x < cards[i]; ++x) column += table.values()[u * cards[i] + x];
        p *= table.values()[u * cards[i] + state[i]] / column;
      }
      for (const auto& l : observed.soft) p *= l.weights[state[l.variable.value()]];
    }
    visit(state, p);
    std::size_t k = n;
    while (k-- > 0) {
      if (++state[k] < cards[k]) break;
      state[k] = 0;
    }
    if (k == static_cast<std::size_t>(-1)) break;
  }
}

/// The unnormalized joint of `query` (in order) with hard and soft evidence, by enumeration.
inline std::vector<double> enumerate_joint(const bayesian_network& network, std::span<const variable_id> query,
                                           const evidence_set& observed) {
  std::size_t size = 1;
  for (auto q : query) size *= network.variables()[q.value()].cardinality();
  std::vector<double> out(size, 0.0);
  enumerate_states(network, observed, [&](const std::vector<std::size_t>& state, double p) {
    std::size_t index = 0;
    for (auto q : query) index = index * network.variables()[q.value()].cardinality() + state[q.value()];
    out[index] += p;
  });
  return out;
}

/// max over the states of `variables` of Σ over the others of the joint with the evidence.
inline double enumerate_maximum(const bayesian_network& network, std::span<const variable_id> variables,
                                const evidence_set& observed) {
  const auto joint = enumerate_joint(network, variables, observed);
  return *std::max_element(joint.begin(), joint.end());
}

/// Prevention targets the slow, obvious way: for each u below ε, a breadth-first search over
/// configurations (one controllable parent ± one bin per step), layer by layer, until a layer
/// holds a configuration above ε; if none does, the best configuration reached.
inline std::vector<std::size_t> naive_prevention_targets(const cpt<double>& table, std::size_t success,
                                                         std::span<const bool> controllable, double epsilon) {
  const auto& radix = table.parent_radix();
  const auto j = table.child_cardinality();
  auto estimate = [&](std::size_t u) { return table.values()[u * j + success]; };
  auto better = [&](std::size_t a, std::size_t b) {
    return estimate(a) > estimate(b) || (estimate(a) == estimate(b) && a < b);
  };
  std::vector<std::size_t> targets(table.configurations());
  for (std::size_t u = 0; u < targets.size(); ++u) {
    targets[u] = u;
    if (!(estimate(u) < epsilon)) continue;
    std::vector<bool> seen(table.configurations(), false);
    std::vector<std::size_t> layer{u};
    seen[u] = true;
    bool found = false;
    while (!layer.empty() && !found) {
      std::size_t pick = std::numeric_limits<std::size_t>::max();
      for (auto v : layer) {
        if (estimate(v) > epsilon && (pick == std::numeric_limits<std::size_t>::max() || better(v, pick))) pick = v;
      }
      if (pick != std::numeric_limits<std::size_t>::max()) {
        targets[u] = pick;
        found = true;
        break;
      }
      std::vector<std::size_t> next;
      for (auto v : layer) {
        const auto digits = radix.decode(v);
        for (std::size_t d = 0; d < digits.size(); ++d) {
          if (!controllable[d]) continue;
          for (int step : {-1, 1}) {
            if ((step < 0 && digits[d] == 0) || (step > 0 && digits[d] + 1 == radix.radix(d))) continue;
            auto moved = digits;
            moved[d] = static_cast<std::size_t>(static_cast<long>(moved[d]) + step);
            const auto w = radix.encode(moved);
            if (!seen[w]) {
              seen[w] = true;
              next.push_back(w);
            }
          }
        }
      }
      layer = std::move(next);
    }
    if (!found) {
      // Highest estimate; ties: nearest (steps), then lower index.
      std::size_t best = u;
      std::size_t best_distance = 0;
      for (std::size_t v = 0; v < table.configurations(); ++v) {
        if (!seen[v]) continue;
        const auto a = radix.decode(u);
        const auto b = radix.decode(v);
        std::size_t distance = 0;
        for (std::size_t d = 0; d < a.size(); ++d) distance += a[d] > b[d] ? a[d] - b[d] : b[d] - a[d];
        if (estimate(v) > estimate(best) ||
            (estimate(v) == estimate(best) && (distance < best_distance || (distance == best_distance && v < best)))) {
          best = v;
          best_distance = distance;
        }
      }
      targets[u] = best;
    }
  }
  return targets;
}

}  // namespace pgm::testing
