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
[[nodiscard]] inline std::optional<exact_decimal> exact_decimal_of(std::string_view text) {
  exact_decimal value;
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) value.negative = text[i++] == '-';
  std::string digits;
  std::int64_t point = -1;  // digits before the decimal point
  bool any = false;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c >= '0' && c <= '9') {
      digits += c;
      any = true;
    } else if (c == '.' && point < 0) {
      point = static_cast<std::int64_t>(digits.size());
    } else {
      break;
    }
  }
  if (!any) return std::nullopt;
  if (point < 0) point = static_cast<std::int64_t>(digits.size());
  std::int64_t exponent = 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool negative_exponent = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative_exponent = text[i++] == '-';
    if (i == text.size()) return std::nullopt;
    for (; i < text.size(); ++i) {
      if (text[i] < '0' || text[i] > '9') return std::nullopt;
      // Beyond ±10^15 the number is no finite double anyway; the exponent stays exact below.
      if (exponent < 1'000'000'000'000'000) exponent = exponent * 10 + (text[i] - '0');
    }
    if (negative_exponent) exponent = -exponent;
  }
  if (i != text.size()) return std::nullopt;
  const auto first = digits.find_first_not_of('0');
  if (first == std::string::npos) return exact_decimal{};  // zero, whatever its sign
  const auto last = digits.find_last_not_of('0');
  value.digits = digits.substr(first, last - first + 1);
  value.exponent = point - static_cast<std::int64_t>(first) + exponent;
  return value;
}

/// -1, 0 or 1 as `a` is below, equal to or above `b`, exactly.
[[nodiscard]] inline int compare_exact(const exact_decimal& a, const exact_decimal& b) {
  const auto sign = [](const exact_decimal& v) { return v.digits.empty() ? 0 : v.negative ? -1 : 1; };
  if (sign(a) != sign(b)) return sign(a) < sign(b) ? -1 : 1;
  if (sign(a) == 0) return 0;
  int magnitude = 0;  // of |a| against |b|
  if (a.exponent != b.exponent) {
    magnitude = a.exponent < b.exponent ? -1 : 1;
  } else if (const auto c = a.digits.compare(b.digits); c != 0) {
    magnitude = c < 0 ? -1 : 1;
  }
  return sign(a) * magnitude;
}

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
    const auto number = detail::parse_double(labels[i]);
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
