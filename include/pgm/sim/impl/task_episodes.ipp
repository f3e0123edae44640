#pragma once
// The definitions of pgm/sim/task_episodes.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <charconv>
#include <map>
#include <optional>
#include <utility>

#include "pgm/core/error.hpp"
#include "pgm/sim/task_episodes.hpp"

namespace pgm::sim {

namespace detail {

/// "xOff12" -> ("xOff", 12); nullopt for a name without a trailing number ≥ 1 or nothing before it.
[[nodiscard]] inline std::optional<std::pair<std::string, std::size_t>> numbered(const std::string& name) {
  const auto digits = name.find_last_not_of("0123456789") + 1;
  if (digits == 0 || digits == name.size() || name[digits] == '0') return std::nullopt;
  std::size_t number = 0;
  const auto [end, failure] = std::from_chars(name.data() + digits, name.data() + name.size(), number);
  if (failure != std::errc() || end != name.data() + name.size()) return std::nullopt;
  return std::pair{name.substr(0, digits), number};
}

}  // namespace detail

PGM_DECL episode_layout episode_layout_of(const task_definition& task) {
  const auto where = "task '" + task.name + "'";
  std::map<std::string, std::map<std::size_t, std::size_t>, std::less<>> steps_of;  // stem -> number -> column
  std::vector<std::string> stems;                                                   // in order of appearance
  episode_layout layout;
  for (std::size_t k = 0; k < task.variables.size(); ++k) {
    const auto parsed = detail::numbered(task.variables[k].name);
    if (!parsed) {
      layout.constants.push_back(k);
      continue;
    }
    auto [it, added] = steps_of.try_emplace(parsed->first);
    if (added) stems.push_back(parsed->first);
    it->second[parsed->second] = k;
    layout.steps = std::max(layout.steps, parsed->second);
  }
  if (stems.empty()) {
    throw data_error(where + " has no numbered variables (xOff1, onTop1, …), so no steps to write as episodes");
  }
  for (const auto k : layout.constants) {
    if (steps_of.contains(task.variables[k].name)) {
      throw data_error(where + ": '" + task.variables[k].name +
                       "' is a variable of its own and the template of numbered ones");
    }
  }
  layout.columns.assign(layout.steps, {});
  for (const auto& stem : stems) {
    const auto& numbers = steps_of.find(stem)->second;
    for (std::size_t n = 1; n <= layout.steps; ++n) {
      const auto found = numbers.find(n);
      if (found == numbers.end()) {
        const auto present = numbers.begin()->first;
        throw data_error(where + ": '" + stem + std::to_string(present) + "' has no '" + stem + std::to_string(n) +
                         "', so it is not the same variable at every one of the " + std::to_string(layout.steps) +
                         " steps");
      }
      layout.columns[n - 1].push_back(found->second);
    }
    layout.template_names.push_back(stem);
  }
  return layout;
}

PGM_DECL dataset episodes_of(const dataset& wide, const task_definition& task, const episode_layout& layout,
                             std::size_t first_episode) {
  const std::size_t episodes = wide.rows(), steps = layout.steps, rows = episodes * steps;
  dataset result(wide.source() + " (episodes)");
  std::vector<double> episode(rows), step(rows);
  for (std::size_t row = 0; row < rows; ++row) {
    episode[row] = static_cast<double>(first_episode + row / steps);
    step[row] = static_cast<double>(row % steps);
  }
  result.add(continuous_column("episode", std::move(episode)));
  result.add(continuous_column("t", std::move(step)));
  // The long column of task variables `at(t)` (one per step, or the same one at every step).
  const auto add_long = [&](const std::string& name, auto&& at) {
    const auto& first = wide.at(task.variables[at(0)].name);
    if (const auto* c = std::get_if<continuous_column>(&first)) {
      std::vector<double> values(rows);
      for (std::size_t t = 0; t < steps; ++t) {
        const auto source = wide.continuous(task.variables[at(t)].name).values();
        for (std::size_t e = 0; e < episodes; ++e) values[e * steps + t] = source[e];
      }
      auto tags = c->tags();
      if (name != c->name()) tags.role.clear();
      result.add(continuous_column(name, std::move(values), std::move(tags)));
      return;
    }
    const auto& var = std::get<discrete_column>(first).var();
    std::vector<std::uint32_t> codes(rows);
    for (std::size_t t = 0; t < steps; ++t) {
      const auto& source = wide.discrete(task.variables[at(t)].name);
      if (source.var().states() != var.states()) {
        throw data_error("task '" + task.name + "': '" + source.name() + "' has other states than '" + var.name() +
                         "', so they are not one variable at two steps");
      }
      for (std::size_t e = 0; e < episodes; ++e) codes[e * steps + t] = source.code(e);
    }
    auto tags = var.tags();
    if (name != var.name()) tags.role.clear();
    result.add(discrete_column(variable(name, var.states(), std::move(tags)), codes));
  };
  for (std::size_t j = 0; j < layout.template_names.size(); ++j) {
    add_long(layout.template_names[j], [&](std::size_t t) { return layout.columns[t][j]; });
  }
  for (const auto k : layout.constants) add_long(task.variables[k].name, [k](std::size_t) { return k; });
  return result;
}

}  // namespace pgm::sim
