#pragma once
// Influence diagrams for tests and benchmarks: the published oil wildcatter, a robot's
// 20-decision LIMID, and expected utilities by plain enumeration of every configuration.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/influence_diagram.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/decide/solve_decisions.hpp"

namespace pgm::testing {

/// Raiffa's oil wildcatter (Decision Analysis, 1968), as Shachter evaluates it ("Evaluating
/// influence diagrams", Operations Research 34(6), 1986): test the ground for 10, then drill for
/// 70 or not. MEU 22.5: test, and drill unless the sounding is diffuse.
inline influence_diagram oil_wildcatter() {
  influence_diagram d;
  const auto oil = d.add_chance(variable("Oil", {"dry", "wet", "soaking"}));
  const auto test = d.add_decision(variable("Test", {"yes", "no"}));
  const auto seismic = d.add_chance(variable("Seismic", {"closed", "open", "diffuse"}));
  const auto drill = d.add_decision(variable("Drill", {"yes", "no"}));
  d.set_table(oil, {}, {0.5, 0.3, 0.2});
  const double third = 1.0 / 3;
  d.set_table(seismic, {oil, test},
              {0.1, 0.3, 0.6, third, third, third,    // dry: tested, not
               0.3, 0.4, 0.3, third, third, third,    // wet
               0.5, 0.4, 0.1, third, third, third});  // soaking
  d.set_observed(test, {});
  d.set_observed(drill, {test, seismic});
  d.add_utility("TestCost", {test}, {-10, 0});
  d.add_utility("Payoff", {drill, oil}, {-70, 50, 200, 0, 0, 0});
  return d;
}

/// A robot acting over `steps` steps: the hidden state S_t (3 states) drifts, depends on the
/// last action, and shows through a noisy reading O_t; the action D_t (3 actions) sees O_t only
/// (limited memory) and is paid by U_t(S_t, D_t). Tables from a fixed seed.
inline influence_diagram robot_limid(std::size_t steps, unsigned seed = 7) {
  std::mt19937 rng(seed);
  const auto column = [&](std::size_t n) {
    std::vector<double> p(n);
    double total = 0;
    for (auto& x : p) total += x = std::uniform_real_distribution<double>(0.05, 1)(rng);
    for (auto& x : p) x /= total;
    return p;
  };
  const auto columns = [&](std::size_t count, std::size_t n) {
    std::vector<double> table;
    for (std::size_t c = 0; c < count; ++c) {
      const auto p = column(n);
      table.insert(table.end(), p.begin(), p.end());
    }
    return table;
  };
  const std::vector<std::string> three{"0", "1", "2"};
  influence_diagram d;
  variable_id state_before{};
  variable_id action_before{};
  for (std::size_t t = 0; t < steps; ++t) {
    const auto suffix = std::to_string(t);
    const auto s = d.add_chance(variable("S" + suffix, three));
    const auto o = d.add_chance(variable("O" + suffix, three));
    const auto a = d.add_decision(variable("D" + suffix, three));
    if (t == 0) {
      d.set_table(s, {}, column(3));
    } else {
      d.set_table(s, {state_before, action_before}, columns(9, 3));
    }
    d.set_table(o, {s}, columns(3, 3));
    d.set_observed(a, {o});
    std::vector<double> payoff(9);
    for (auto& u : payoff) u = std::uniform_real_distribution<double>(-5, 10)(rng);
    d.add_utility("U" + suffix, {s, a}, payoff);
    state_before = s;
    action_before = a;
  }
  return d;
}

/// A full configuration's probability (decisions as chosen) and utility.
struct joint_term {
  double probability;
  double utility;
};

inline joint_term term_at(const influence_diagram& d, const std::vector<std::size_t>& x) {
  joint_term t{1, 0};
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto id = index_at<variable_id>(i);
    if (d.is_decision(id)) continue;
    std::size_t column = 0;
    for (const auto p : d.parents(id)) column = column * d.at(p).cardinality() + x[p.value()];
    t.probability *= d.table(id)[column * d.at(id).cardinality() + x[i]];
  }
  for (const auto& u : d.utilities()) {
    std::size_t cell = 0;
    for (const auto p : u.parents) cell = cell * d.at(p).cardinality() + x[p.value()];
    t.utility += u.values[cell];
  }
  return t;
}

inline std::vector<std::pair<std::size_t, std::size_t>> evidence_states(const influence_diagram& d, const evidence& e) {
  std::vector<std::pair<std::size_t, std::size_t>> states;
  for (const auto& [name, label] : e) states.emplace_back(d.id(name).value(), d.at(d.id(name)).state(label).value());
  return states;
}

/// E[U | e] of deterministic policies, by enumerating every configuration.
inline double expected_utility_by_enumeration(const influence_diagram& d, const std::vector<decision_policy>& policies,
                                              const evidence& e) {
  const auto fixed = evidence_states(d, e);
  std::vector<std::size_t> cards;
  for (const auto& v : d.variables()) cards.push_back(v.cardinality());
  const mixed_radix all(cards);
  double mass = 0;
  double weighted = 0;
  for (std::size_t c = 0; c < all.size(); ++c) {
    const auto x = all.decode(c);
    if (std::any_of(fixed.begin(), fixed.end(), [&](const auto& f) { return x[f.first] != f.second; })) continue;
    bool follows = true;
    for (const auto& policy : policies) {
      std::size_t cell = 0;
      for (const auto o : policy.observed) cell = cell * d.at(o).cardinality() + x[o.value()];
      follows = follows && policy.actions[cell] == x[policy.decision.value()];
    }
    if (!follows) continue;
    const auto t = term_at(d, x);
    mass += t.probability;
    weighted += t.probability * t.utility;
  }
  // Each configuration of the chance variables is counted once: the policies fix the decisions.
  return weighted / mass;
}

/// The best expected utility over every deterministic policy of decisions that know their
/// parents only.
inline double best_over_every_policy(const influence_diagram& d, const evidence& e) {
  const auto fixed = evidence_states(d, e);
  std::vector<decision_policy> policies;
  for (const auto decision : d.decision_order()) {
    decision_policy p{decision, {}, {}};
    std::size_t cells = 1;
    for (const auto o : d.parents(decision)) {
      if (std::none_of(fixed.begin(), fixed.end(), [&](const auto& f) { return f.first == o.value(); })) {
        p.observed.push_back(o);
        cells *= d.at(o).cardinality();
      }
    }
    p.actions.assign(cells, 0);
    policies.push_back(p);
  }
  double best = -std::numeric_limits<double>::infinity();
  while (true) {
    best = std::max(best, expected_utility_by_enumeration(d, policies, e));
    // The next policy combination, as an odometer over every action of every cell.
    std::size_t k = 0;
    std::size_t cell = 0;
    for (; k < policies.size(); ++k, cell = 0) {
      auto& actions = policies[k].actions;
      const auto card = d.at(policies[k].decision).cardinality();
      for (cell = 0; cell < actions.size() && ++actions[cell] == card; ++cell) actions[cell] = 0;
      if (cell < actions.size()) break;
    }
    if (k == policies.size()) return best;
  }
}

}  // namespace pgm::testing
