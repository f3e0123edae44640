#pragma once
// The definitions of pgm/data/state_order.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/data/state_order.hpp"

namespace pgm::detail {

PGM_DECL std::optional<exact_decimal> exact_decimal_of(std::string_view text) {
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

PGM_DECL int compare_exact(const exact_decimal& a, const exact_decimal& b) {
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

}  // namespace pgm::detail
