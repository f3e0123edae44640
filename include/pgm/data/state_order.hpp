#pragma once
/// \file
/// The states of a discrete column read off its values, in pgm's one order: when every label
/// is a number they sort by value, otherwise alphabetically (by bytes). Labels are one state
/// only when they are the same text or exactly the same number ("1", "1.0" and "1e0"; "0" and
/// "-0"), named by the label met first; numbers that differ are two states however close they
/// are ("9007199254740992" and "9007199254740993", one double). The CSV reader and the Python
/// bindings both take states this way, so a column gets the same states whichever way it comes
/// in (docs/limits.md).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/text.hpp"

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

namespace detail {

/// The exact value of a decimal number as written: its sign, its significant digits (no zeros
/// at either end) and the power of ten of the first of them, 0.d₁d₂… × 10^exponent. Zero, signed
/// or not, has no digits. Two labels are the same number exactly when these are equal.
struct exact_decimal {
  bool negative = false;
  std::string digits;
  std::int64_t exponent = 0;

  friend bool operator==(const exact_decimal&, const exact_decimal&) = default;
};

/// The exact value of `text`, a decimal number as parse_double reads it ("-1.50e+3", ".5",
/// "5."); nothing for anything else (NaN, infinities).
[[nodiscard]] PGM_DECL std::optional<exact_decimal> exact_decimal_of(std::string_view text);

/// -1, 0 or 1 as `a` is below, equal to or above `b`, exactly.
[[nodiscard]] PGM_DECL int compare_exact(const exact_decimal& a, const exact_decimal& b);

}  // namespace detail

/// Orders distinct labels, given in the order they were met, into states. `Labels` is a
/// random-access range of strings (std::vector, std::deque).
template <class Labels>
[[nodiscard]] state_order order_states(const Labels& labels) {
  state_order result;
  std::vector<std::optional<detail::exact_decimal>> values;
  values.reserve(labels.size());
  result.numeric = true;
  for (std::size_t i = 0; i < labels.size() && result.numeric; ++i) {
    const auto number = text::parse_double(labels[i]);
    result.numeric = number.has_value();
    if (number && !std::isfinite(*number)) {
      result.non_finite = result.non_finite.value_or(i);
    } else if (number) {
      values.push_back(detail::exact_decimal_of(labels[i]));
    }
  }
  if (result.numeric && result.non_finite) return result;
  result.non_finite.reset();
  // A label parse_double reads but the exact reader does not (none are known) is text.
  if (result.numeric && std::any_of(values.begin(), values.end(), [](const auto& v) { return !v; })) {
    result.numeric = false;
  }
  std::vector<std::uint32_t> order(labels.size());
  std::iota(order.begin(), order.end(), 0U);
  if (result.numeric) {
    std::stable_sort(order.begin(), order.end(),
                     [&](auto a, auto b) { return detail::compare_exact(*values[a], *values[b]) < 0; });
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

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/data/impl/state_order.ipp"
#endif
