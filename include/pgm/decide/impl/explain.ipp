#pragma once
// The definitions of pgm/decide/explain.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/decide/explain.hpp"

namespace pgm {

PGM_DECL std::vector<variable_change> explanation::responsible() const {
  std::vector<variable_change> result;
  for (const auto& c : changes) {
    if (c.moves()) result.push_back(c);
  }
  return result;
}

PGM_DECL explanation explain(const cpt<double>& table, std::size_t success_state, std::size_t configuration,
                             std::span<const bool> controllable, const prevention_options& options) {
  const auto target = prevention_target(table, success_state, configuration, controllable, options);
  return explain_move(table, success_state, configuration, target, controllable, options.epsilon);
}

PGM_DECL explanation explain_move(const cpt<double>& table, std::size_t success_state, std::size_t configuration,
                                  std::size_t target, std::span<const bool> controllable, double epsilon) {
  explanation result;
  result.success_variable = table.child().name();
  result.success_state = table.child().states()[success_state];
  result.epsilon = epsilon;
  result.configuration = configuration;
  result.target = target;
  result.predicted = table(index_at<state_index>(success_state), config_index(configuration));
  result.target_predicted = table(index_at<state_index>(success_state), config_index(target));
  const auto from = table.parent_codes(config_index(configuration));
  const auto to = table.parent_codes(config_index(target));
  double squared = 0.0;
  bool measurable = true;
  for (std::size_t p = 0; p < from.size(); ++p) {
    if (!controllable[p]) continue;
    const auto& v = table.parents()[p];
    variable_change change{v.name(),
                           v.tags().unit,
                           from[p],
                           to[p],
                           v.states()[from[p]],
                           v.states()[to[p]],
                           detail::interval_of(v, from[p]),
                           detail::interval_of(v, to[p]),
                           std::nullopt};
    const auto a = v.midpoint(index_at<state_index>(from[p]));
    const auto b = v.midpoint(index_at<state_index>(to[p]));
    if (a && b) {
      change.move = *b - *a;
      squared += (*b - *a) * (*b - *a);
    } else if (change.moves()) {
      measurable = false;
    }
    result.steps += from[p] > to[p] ? from[p] - to[p] : to[p] - from[p];
    result.changes.push_back(std::move(change));
  }
  if (measurable) result.distance_units = std::sqrt(squared);
  return result;
}

PGM_DECL prevention_plan plan_prevention(const bayesian_network& network, const success_event& success,
                                         const assignment& planned, std::span<const std::string> controllable,
                                         const prevention_options& options, const prediction_options& prediction) {
  variable_elimination engine(borrowed(network), {prediction.heuristic});
  return plan_prevention(engine, success, planned, controllable, options, prediction);
}

PGM_DECL std::vector<std::string> default_controllable(const bayesian_network& network, const success_event& success) {
  std::vector<std::string> names;
  for (const auto& p : network.table(node_of(network, success.variable)).parents()) names.push_back(p.name());
  return names;
}

PGM_DECL assignment suggested_values(const explanation& why, const assignment& planned) {
  assignment result;
  for (const auto& c : why.changes) {
    const auto given = planned.find(c.variable);
    if (!c.moves() && given != planned.end() && std::holds_alternative<double>(given->second)) {
      result.emplace(c.variable, given->second);
    } else if (c.to_interval) {
      result.emplace(c.variable, c.to_interval->midpoint());
    } else {
      result.emplace(c.variable, c.to_label);
    }
  }
  return result;
}

}  // namespace pgm
