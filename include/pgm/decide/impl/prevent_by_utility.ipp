#pragma once
// The definitions of pgm/decide/prevent_by_utility.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pgm/core/mixed_radix.hpp"
#include "pgm/decide/prevent.hpp"
#include "pgm/decide/prevent_by_utility.hpp"

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

slice_mover::slice_mover(const cpt<double>& table, std::size_t success_state, std::span<const bool> controllable,
                         const move_costs& costs)
    : table_(table), success_state_(success_state), reward_(costs.reward) {
  check_prevention_inputs(table, success_state, controllable, {});
  const auto rates = cost_rates(table, controllable, costs);
  for (std::size_t p = 0; p < controllable.size(); ++p) {
    if (!controllable[p]) continue;
    const auto& v = table.parents()[p];
    const auto k = v.cardinality();
    moved_.push_back(p);
    cards_.push_back(k);
    auto& matrix = cost_between_.emplace_back(k * k);
    for (std::size_t a = 0; a < k; ++a) {
      for (std::size_t b = 0; b < k; ++b) matrix[a * k + b] = move_cost(v, a, b, rates[p], costs.unit);
    }
  }
  const mixed_radix local(cards_);
  const auto& radix = table.parent_radix();
  const auto m = moved_.size();
  digits_.assign(local.size() * m, 0);
  offset_.assign(local.size(), 0);
  std::vector<std::size_t> digits(m);
  for (std::size_t l = 0; l < local.size(); ++l) {
    local.decode(l, digits);
    for (std::size_t k = 0; k < m; ++k) {
      digits_[l * m + k] = static_cast<std::uint32_t>(digits[k]);
      offset_[l] += digits[k] * radix.stride(moved_[k]);
    }
  }
}

PGM_DECL void slice_mover::members_of(std::size_t u, std::vector<std::size_t>& members) const {
  const auto& radix = table_.parent_radix();
  std::size_t base = u;
  for (const auto p : moved_) base -= (u / radix.stride(p)) % radix.radix(p) * radix.stride(p);
  members.resize(offset_.size());
  for (std::size_t l = 0; l < offset_.size(); ++l) members[l] = base + offset_[l];
}

PGM_DECL std::size_t slice_mover::local_of(std::size_t u) const {
  const auto& radix = table_.parent_radix();
  std::size_t local = 0;
  for (std::size_t k = 0; k < moved_.size(); ++k) {
    local = local * cards_[k] + (u / radix.stride(moved_[k])) % radix.radix(moved_[k]);
  }
  return local;
}

PGM_DECL utility_move slice_mover::best_from(std::size_t from, const std::vector<std::size_t>& members) const {
  const auto j = table_.child_cardinality();
  const auto values = table_.values();
  utility_move best{.target = members[from], .expected_utility = -std::numeric_limits<double>::infinity()};
  std::size_t fewest = moved_.size() + 1;
  for (std::size_t to = 0; to < members.size(); ++to) {
    double cost = 0;
    std::size_t changed = 0;
    for (std::size_t k = 0; k < moved_.size(); ++k) {
      const auto a = digits_[from * moved_.size() + k], b = digits_[to * moved_.size() + k];
      cost += cost_between_[k][a * cards_[k] + b];
      changed += a != b;
    }
    const double success = values[members[to] * j + success_state_];
    const double utility = reward_ * success - cost;
    const double tolerance = 1e-12 * std::max(1.0, std::abs(best.expected_utility));
    const bool better = fewest > moved_.size() ||  // the first candidate
                        utility > best.expected_utility + tolerance ||
                        (utility >= best.expected_utility - tolerance &&
                         (changed < fewest || (changed == fewest && members[to] < best.target)));
    if (better) {
      best = {.target = members[to], .expected_utility = utility, .success_probability = success, .cost = cost};
      fewest = changed;
    }
  }
  return best;
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
  if (configuration >= table.configurations()) {
    throw model_error("configuration " + std::to_string(configuration) + " is out of range for '" +
                      table.child().name() + "'");
  }
  if (table.is_sparse()) return best_move(table.dense(), success_state, configuration, controllable, costs);
  const detail::slice_mover mover(table, success_state, controllable, costs);
  std::vector<std::size_t> members;
  mover.members_of(configuration, members);
  return mover.best_from(mover.local_of(configuration), members);
}

PGM_DECL std::vector<utility_move> best_moves(const cpt<double>& table, std::size_t success_state,
                                              std::span<const bool> controllable, const move_costs& costs) {
  if (table.is_sparse()) return best_moves(table.dense(), success_state, controllable, costs);
  const detail::slice_mover mover(table, success_state, controllable, costs);
  std::vector<utility_move> moves(table.configurations());
  std::vector<char> solved(moves.size(), 0);
  std::vector<std::size_t> members;
  for (std::size_t u = 0; u < moves.size(); ++u) {
    if (solved[u]) continue;
    mover.members_of(u, members);
    for (std::size_t from = 0; from < members.size(); ++from) {
      moves[members[from]] = mover.best_from(from, members);
      solved[members[from]] = 1;
    }
  }
  return moves;
}

PGM_DECL prevention_outcome prevention_outcome_of(std::span<const std::size_t> targets, const cpt<double>& truth,
                                                  std::size_t success_state, std::span<const bool> controllable,
                                                  std::span<const double> configuration_weights,
                                                  const move_costs& costs) {
  detail::check_prevention_inputs(truth, success_state, controllable, {});
  const auto rates = detail::cost_rates(truth, controllable, costs);
  const double total = detail::checked_weight_total(configuration_weights, truth.configurations());
  if (targets.size() != truth.configurations()) {
    throw model_error("expected " + std::to_string(truth.configurations()) + " prevention targets, got " +
                      std::to_string(targets.size()));
  }
  prevention_outcome outcome;
  for (std::size_t u = 0; u < targets.size(); ++u) {
    if (configuration_weights[u] == 0.0) continue;
    if (targets[u] >= truth.configurations()) {
      throw model_error("prevention target " + std::to_string(targets[u]) + " is out of range for '" +
                        truth.child().name() + "'");
    }
    const auto from = truth.parent_codes(config_index(u));
    const auto to = truth.parent_codes(config_index(targets[u]));
    double cost = 0;
    for (std::size_t p = 0; p < from.size(); ++p) {
      if (from[p] != to[p] && !controllable[p]) {
        throw model_error("a prevention target moves '" + truth.parents()[p].name() + "', which is not controllable");
      }
      cost += detail::move_cost(truth.parents()[p], from[p], to[p], rates[p], costs.unit);
    }
    const double success = truth(index_at<state_index>(success_state), config_index(targets[u]));
    const double w = configuration_weights[u] / total;
    outcome.success += w * success;
    outcome.cost += w * cost;
  }
  outcome.utility = costs.reward * outcome.success - outcome.cost;
  return outcome;
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
