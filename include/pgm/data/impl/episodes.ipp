#pragma once
// The definitions of pgm/data/episodes.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <unordered_map>
#include <utility>

#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/data/episodes.hpp"

namespace pgm {

namespace detail {

/// "runs.csv: data row 4: the step 't' ", which a message about that step goes on from.
inline std::string step_at(const dataset& data, const std::string& name, std::size_t row) {
  return data.source() + ": data row " + std::to_string(row + 1) + ": the step '" + name + "' ";
}

/// The episode of a row as the data hold it, for messages: its label or number.
inline std::string episode_at(const dataset& data, const std::string& name, std::size_t row) {
  if (!data.contains(name)) return "(the only one)";
  if (data.is_discrete(name)) return data.discrete(name).label(row);
  return text::format_double(data.continuous(name).values()[row] + 0.0);
}

/// The step of each row: the column's own numbers, or `parsed` filled from its labels (a
/// data_error naming the row for a label that is no number).
inline std::span<const double> steps_of(const dataset& data, const std::string& name, std::vector<double>& parsed) {
  const auto where = [&](std::size_t row) { return step_at(data, name, row); };
  std::span<const double> steps;
  if (data.is_discrete(name)) {
    const auto& column = data.discrete(name);
    parsed.resize(data.rows());
    for (std::size_t r = 0; r < data.rows(); ++r) {
      if (column.is_missing(r)) throw data_error(where(r) + "is missing");
      const auto value = text::parse_double(column.label(r));
      if (!value) throw data_error(where(r) + "is '" + column.label(r) + "', not a number");
      parsed[r] = *value;
    }
    steps = parsed;
  } else {
    steps = data.continuous(name).values();
  }
  return steps;
}

/// Throws data_error, naming the row, for a step that is not a whole number ≥ 0.
inline void check_steps(const dataset& data, const std::string& name, std::span<const double> steps) {
  for (std::size_t r = 0; r < steps.size(); ++r) {
    if (!(steps[r] >= 0.0) || steps[r] != std::floor(steps[r])) {
      const auto where = step_at(data, name, r);
      if (std::isnan(steps[r])) throw data_error(where + "is missing");
      throw data_error(where + "is " + text::format_double(steps[r]) + ", not a whole number ≥ 0");
    }
  }
}

/// Calls `visit(values, missing)` with the episode column's values (a code vector, or the
/// numbers) and a test of whether one is missing; without the column, with one value per row.
template <class Visit>
auto visit_episodes(const dataset& data, const std::string& name, Visit&& visit) {
  if (!data.contains(name)) {
    const std::vector<std::uint8_t> one(data.rows(), 0);
    return visit(one, [](std::uint8_t) { return false; });
  }
  if (data.is_discrete(name)) {
    const auto& column = data.discrete(name);
    return std::visit(
        [&](const auto& codes) {
          using code = typename std::decay_t<decltype(codes)>::value_type;
          const bool any_missing = column.missing() != 0;
          return visit(codes, [any_missing](code c) { return any_missing && c == missing_code<code>; });
        },
        column.codes());
  }
  return visit(data.continuous(name).values(), [](double v) { return std::isnan(v); });
}

/// The index of rows already in episode and step order (each episode's rows together, t = 0, 1,
/// … in turn, no episode twice), found in one pass; nothing for any other order or a problem,
/// which the general path then finds and names.
template <class Values, class Missing>
std::optional<episode_index> in_order_index(const Values& episode, const Missing& missing,
                                            std::span<const double> steps) {
  using value = typename Values::value_type;
  episode_index index;
  index.starts.clear();
  std::vector<value> firsts;
  for (std::size_t r = 0; r < steps.size(); ++r) {
    if (missing(episode[r])) return std::nullopt;
    const bool same = r > 0 && episode[r] == episode[r - 1];
    if (steps[r] == 0.0 && !same) {
      index.starts.push_back(r);
      firsts.push_back(episode[r]);
    } else if (!same || steps[r] != steps[r - 1] + 1.0) {
      return std::nullopt;
    }
  }
  index.starts.push_back(steps.size());
  // No episode twice: episodes numbered upwards need no sort.
  if (std::adjacent_find(firsts.begin(), firsts.end(), std::greater_equal<>()) != firsts.end()) {
    std::sort(firsts.begin(), firsts.end());
    if (std::adjacent_find(firsts.begin(), firsts.end()) != firsts.end()) return std::nullopt;
  }
  return index;  // rows empty: in order (every step a whole number ≥ 0, counted up from 0)
}

/// Each row's episode, numbered in order of first appearance. Throws data_error for a missing one.
template <class Values, class Missing>
std::vector<std::uint32_t> episode_numbers(const dataset& data, const std::string& name, const Values& episode,
                                           const Missing& missing, std::size_t& episodes) {
  using value = std::decay_t<typename Values::value_type>;
  std::vector<std::uint32_t> number(episode.size(), 0);
  std::unordered_map<value, std::uint32_t> numbers;
  for (std::size_t r = 0; r < episode.size(); ++r) {
    if (missing(episode[r])) {
      throw data_error(data.source() + ": data row " + std::to_string(r + 1) + ": the episode '" + name +
                       "' is missing");
    }
    value key = episode[r];
    if constexpr (std::is_floating_point_v<value>) key += 0.0;  // -0 and 0 are one episode
    number[r] = numbers.try_emplace(key, static_cast<std::uint32_t>(numbers.size())).first->second;
  }
  episodes = numbers.size();
  return number;
}

/// Why the rows `rows` of one episode, with steps `steps`, are not t = 0 … L−1 once each.
[[noreturn]] inline void fail_episode_steps(const dataset& data, const std::string& episode,
                                            std::vector<std::size_t> rows, std::span<const double> steps) {
  std::sort(rows.begin(), rows.end(),
            [&](std::size_t a, std::size_t b) { return std::pair(steps[a], a) < std::pair(steps[b], b); });
  const auto prefix = data.source() + ": episode '" + episode + "' ";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double t = steps[rows[i]];
    if (t == static_cast<double>(i)) continue;
    if (i > 0 && t == steps[rows[i - 1]]) {
      throw data_error(prefix + "has two rows with t = " + text::format_double(t) + " (data rows " +
                       std::to_string(rows[i - 1] + 1) + " and " + std::to_string(rows[i] + 1) +
                       "): an episode has one row per step");
    }
    throw data_error(prefix + "has no row with t = " + std::to_string(i) +
                     ", but one with t = " + text::format_double(t) + " (data row " + std::to_string(rows[i] + 1) +
                     "): the steps of an episode run t = 0, 1, 2, … without a gap");
  }
  throw data_error(prefix + "has steps that are not t = 0, 1, 2, …");  // not reached: a row differs above
}

}  // namespace detail

PGM_DECL std::string episode_name(const dataset& data, const episode_index& index, std::size_t k,
                                  const episode_columns& columns) {
  return detail::episode_at(data, columns.episode, index.row(index.starts.at(k)));
}

PGM_DECL episode_index index_episodes(const dataset& data, const episode_columns& columns) {
  if (!data.contains(columns.step)) {
    throw data_error(data.source() + ": the data have no column '" + columns.step +
                     "' numbering the steps (long form: " + columns.episode + "," + columns.step +
                     ",<variables>, one row per episode and step)");
  }
  std::vector<double> parsed;
  const auto steps = detail::steps_of(data, columns.step, parsed);
  return detail::visit_episodes(data, columns.episode, [&](const auto& episode, const auto& missing) {
    if (auto in_order = detail::in_order_index(episode, missing, steps)) return std::move(*in_order);
    detail::check_steps(data, columns.step, steps);
    std::size_t episodes = 0;
    const auto number = detail::episode_numbers(data, columns.episode, episode, missing, episodes);
    // Each episode's rows go to their place by t, in one pass: an episode of L rows has each
    // t = 0 … L−1 once, so row r of episode k goes to starts[k] + t.
    episode_index index;
    std::vector<std::size_t> lengths(episodes, 0);
    for (const auto k : number) ++lengths[k];
    index.starts.resize(episodes + 1);
    for (std::size_t k = 0; k < episodes; ++k) index.starts[k + 1] = index.starts[k] + lengths[k];
    constexpr auto empty = std::numeric_limits<std::size_t>::max();
    index.rows.assign(data.rows(), empty);
    for (std::size_t r = 0; r < data.rows(); ++r) {
      const auto k = number[r];
      const double t = steps[r];
      auto* slot =
          t < static_cast<double>(lengths[k]) ? &index.rows[index.starts[k] + static_cast<std::size_t>(t)] : nullptr;
      if (slot == nullptr || *slot != empty) {
        std::vector<std::size_t> rows;
        for (std::size_t s = 0; s < data.rows(); ++s) {
          if (number[s] == k) rows.push_back(s);
        }
        detail::fail_episode_steps(data, detail::episode_at(data, columns.episode, r), std::move(rows), steps);
      }
      *slot = r;
    }
    return index;
  });
}

}  // namespace pgm
