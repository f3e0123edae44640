#pragma once
// The definitions of pgm/decide/prevent_by_utility.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pgm/core/mixed_radix.hpp"
#include "pgm/decide/prevent_by_utility.hpp"
#include "pgm/decide/solve_decisions.hpp"

namespace pgm {
namespace detail {

/// What moving `v` from state `from` to `to` costs at `rate` per step or unit.
PGM_DECL double move_cost(const variable& v, std::size_t from, std::size_t to, double rate, move_costs::per unit) {
  if (rate == 0 || from == to) return 0;
  if (unit == move_costs::per::steps) return rate * static_cast<double>(from > to ? from - to : to - from);
  const auto a = v.midpoint(index_at<state_index>(from));
  const auto b = v.midpoint(index_at<state_index>(to));
  return rate * std::abs(*b - *a);  // both exist: prevention_diagram checked
}

/// Each parent's cost rate (0 for a free or uncontrollable one), the costs checked.
PGM_DECL std::vector<double> cost_rates(const cpt<double>& table, std::span<const bool> controllable,
                                        const move_costs& costs) {
  if (!std::isfinite(costs.reward)) throw model_error("the reward of success must be a finite number");
  std::vector<double> rates(table.parents().size(), 0.0);
  for (const auto& [name, rate] : costs.cost) {
    std::size_t p = 0;
    while (p < rates.size() && table.parents()[p].name() != name) ++p;
    if (p == rates.size() || !controllable[p]) {
      throw model_error("a cost of moving '" + name + "', which is not a controllable parent of '" +
                        table.child().name() + "'");
    }
    if (!(rate >= 0) || !std::isfinite(rate)) {
      throw model_error("the cost of moving '" + name + "' must be a finite number ≥ 0");
    }
    const auto& v = table.parents()[p];
    if (costs.unit == move_costs::per::units && rate > 0) {
      for (std::size_t s = 0; s < v.cardinality(); ++s) {
        if (!v.midpoint(index_at<state_index>(s))) {
          throw model_error("'" + name + "' has no units (state '" + v.states()[s] +
                            "' is no interval nor number), so it has no cost per unit: cost it per step");
        }
      }
    }
    rates[p] = rate;
  }
  return rates;
}

PGM_DECL double utility_of(const cpt<double>& table, std::size_t success_state, const std::vector<std::size_t>& from,
                           const std::vector<std::size_t>& to, const std::vector<double>& rates,
                           const move_costs& costs, double* cost = nullptr) {
  double total = 0;
  for (std::size_t p = 0; p < from.size(); ++p) {
    total += move_cost(table.parents()[p], from[p], to[p], rates[p], costs.unit);
  }
  if (cost != nullptr) *cost = total;
  const double success = table(index_at<state_index>(success_state), table.configuration(to));
  return costs.reward * success - total;
}

}  // namespace detail

PGM_DECL influence_diagram prevention_diagram(const cpt<double>& table, std::size_t success_state,
                                              std::size_t configuration, std::span<const bool> controllable,
                                              const move_costs& costs) {
  const auto rates = detail::cost_rates(table, controllable, costs);
  const auto from = table.parent_codes(config_index(configuration));
  influence_diagram diagram;
  std::vector<variable_id> decisions;
  std::vector<std::size_t> moved;  // the parents that are decisions
  for (std::size_t p = 0; p < from.size(); ++p) {
    if (!controllable[p]) continue;
    const auto& v = table.parents()[p];
    decisions.push_back(diagram.add_decision(variable(v.name(), v.states())));
    moved.push_back(p);
  }
  const auto success = diagram.add_chance(variable(table.child().name(), table.child().states()));
  // Each decision is taken after seeing the earlier ones: one order, perfect recall.
  for (std::size_t k = 0; k < decisions.size(); ++k) {
    diagram.set_observed(
        decisions[k], std::vector<variable_id>(decisions.begin(), decisions.begin() + static_cast<std::ptrdiff_t>(k)));
  }
  std::vector<std::size_t> cards;
  for (const auto p : moved) cards.push_back(table.parents()[p].cardinality());
  const mixed_radix choices(cards);
  std::vector<double> values;
  auto codes = from;
  std::vector<std::size_t> chosen(moved.size());
  for (std::size_t c = 0; c < choices.size(); ++c) {
    choices.decode(c, chosen);
    for (std::size_t k = 0; k < moved.size(); ++k) codes[moved[k]] = chosen[k];
    const auto column = table.column(table.configuration(codes));
    values.insert(values.end(), column.begin(), column.end());
  }
  diagram.set_table(success, decisions, std::move(values));
  std::vector<double> reward(table.child_cardinality(), 0.0);
  reward.at(success_state) = costs.reward;
  diagram.add_utility("reward of " + table.child().name(), {success}, std::move(reward));
  for (std::size_t k = 0; k < moved.size(); ++k) {
    const auto p = moved[k];
    if (rates[p] == 0) continue;
    const auto& v = table.parents()[p];
    std::vector<double> cost(v.cardinality());
    for (std::size_t s = 0; s < cost.size(); ++s) cost[s] = -detail::move_cost(v, from[p], s, rates[p], costs.unit);
    diagram.add_utility("cost of moving " + v.name(), {decisions[k]}, std::move(cost));
  }
  return diagram;
}

PGM_DECL utility_move best_move(const cpt<double>& table, std::size_t success_state, std::size_t configuration,
                                std::span<const bool> controllable, const move_costs& costs) {
  const auto rates = detail::cost_rates(table, controllable, costs);
  const auto from = table.parent_codes(config_index(configuration));
  utility_move move;
  if (std::none_of(controllable.begin(), controllable.end(), [](bool c) { return c; })) {  // nothing moves
    move.target = configuration;
    move.expected_utility = detail::utility_of(table, success_state, from, from, rates, costs, &move.cost);
    move.success_probability = table(index_at<state_index>(success_state), config_index(configuration));
    return move;
  }
  const auto diagram = prevention_diagram(table, success_state, configuration, controllable, costs);
  const auto solution = solve_decisions(diagram);
  // Follow the policies from the first decision: each action given the ones before.
  std::vector<std::size_t> action(diagram.size(), 0);
  for (const auto& policy : solution.policies) {
    std::vector<std::size_t> seen;
    std::vector<std::size_t> cards;
    for (const auto id : policy.observed) {
      seen.push_back(action[id.value()]);
      cards.push_back(diagram.at(id).cardinality());
    }
    action[policy.decision.value()] = policy.actions[mixed_radix(cards).encode(seen)];
  }
  auto to = from;
  for (std::size_t p = 0, k = 0; p < from.size(); ++p) {
    if (controllable[p]) to[p] = action[k++];
  }
  // Of equally good moves, stay, or else keep a variable where moving it gains nothing.
  double best = detail::utility_of(table, success_state, from, to, rates, costs);
  const auto equal = [&](double utility) { return utility >= best - 1e-12 * std::max(1.0, std::abs(best)); };
  if (equal(detail::utility_of(table, success_state, from, from, rates, costs))) to = from;
  for (std::size_t p = 0; p < from.size(); ++p) {
    if (to[p] == from[p]) continue;
    auto kept = to;
    kept[p] = from[p];
    const double utility = detail::utility_of(table, success_state, from, kept, rates, costs);
    if (equal(utility)) {
      to = kept;
      best = std::max(best, utility);
    }
  }
  move.target = table.configuration(to).value();
  move.expected_utility = detail::utility_of(table, success_state, from, to, rates, costs, &move.cost);
  move.success_probability = table(index_at<state_index>(success_state), config_index(move.target));
  return move;
}

PGM_DECL utility_prevention prevent_by_utility(const prevention_plan& plan, std::span<const std::string> controllable,
                                               const move_costs& costs) {
  const auto& table = plan.table;
  // std::vector<bool> has no contiguous storage; the span needs real bools.
  const std::unique_ptr<bool[]> mask(new bool[table.parents().size()]);
  for (std::size_t p = 0; p < table.parents().size(); ++p) {
    mask[p] = std::find(controllable.begin(), controllable.end(), table.parents()[p].name()) != controllable.end();
  }
  const std::span<const bool> flags(mask.get(), table.parents().size());
  const auto success = table.child().state(plan.why.success_state).value();
  const auto move = best_move(table, success, plan.why.configuration, flags, costs);
  return {move, explain_move(table, success, plan.why.configuration, move.target, flags, plan.why.epsilon)};
}

}  // namespace pgm
