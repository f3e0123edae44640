#pragma once
/// \file
/// The states of a discrete column read off its values, in pgm's one order: when every label
/// is a number they sort by value ("1" and "1.0" are one state, named by the label met first),
/// otherwise alphabetically (by bytes). The CSV reader and the Python bindings both take
/// states this way, so a column gets the same states whichever way it comes in.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "pgm/detail/text.hpp"

namespace pgm {

/// States of a column and the state of each distinct label.
struct state_order {
  std::vector<std::string> states;
  /// `state_of[i]` is the state of the i-th label given.
  std::vector<std::uint32_t> state_of;
  /// Every label reads as a number.
  bool numeric = false;
  /// When every label reads as a number, the first (in the order given) that is not finite:
  /// NaN cannot be ordered, so nothing is ordered and the caller reports it.
  std::optional<std::size_t> non_finite;
};

/// Orders distinct labels, given in the order they were met, into states. `Labels` is a
/// random-access range of strings (std::vector, std::deque).
template <class Labels>
[[nodiscard]] state_order order_states(const Labels& labels) {
  state_order result;
  std::vector<std::optional<double>> values;
  values.reserve(labels.size());
  result.numeric = true;
  for (const auto& label : labels) {
    values.push_back(detail::parse_double(label));
    result.numeric = result.numeric && values.back().has_value();
  }
  if (result.numeric) {
    const auto bad = std::find_if(values.begin(), values.end(), [](const auto& v) { return !std::isfinite(*v); });
    if (bad != values.end()) {
      result.non_finite = static_cast<std::size_t>(bad - values.begin());
      return result;
    }
  }
  std::vector<std::uint32_t> order(labels.size());
  std::iota(order.begin(), order.end(), 0U);
  if (result.numeric) {
    std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return *values[a] < *values[b]; });
  } else {
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return labels[a] < labels[b]; });
  }
  result.state_of.resize(labels.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const bool same_number = result.numeric && i > 0 && *values[order[i]] == *values[order[i - 1]];
    if (!same_number) result.states.emplace_back(labels[order[i]]);
    result.state_of[order[i]] = static_cast<std::uint32_t>(result.states.size() - 1);
  }
  return result;
}

}  // namespace pgm
