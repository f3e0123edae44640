#pragma once
/// \file
/// Internal, do not depend on it: number parsing and formatting shared by the readers and
/// writers, so that every file pgm writes reads back to the same bits.

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace pgm::detail {

/// The whole of `text` as a double (a leading '+' allowed), or nothing. NaN and infinities
/// are returned as such; callers decide whether they are acceptable.
[[nodiscard]] inline std::optional<double> parse_double(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const auto* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec == std::errc::result_out_of_range) {
    // Subnormal underflow is still a number; overflow is reported by the caller as infinite.
    return std::strtod(std::string(text).c_str(), nullptr);
  }
  if (ec != std::errc{} || ptr != end) return std::nullopt;
  return value;
}

/// Why `text`, which is not a finite number as pgm reads numbers (docs/limits.md, "Numbers"),
/// might have been meant as one: "a comma is no decimal mark: write 1.5". Empty for a finite
/// number and for text that looks like no number at all.
[[nodiscard]] inline std::string number_hint(std::string_view text) {
  const auto value = parse_double(text);
  if (value && std::isfinite(*value)) return {};
  auto body = text;
  if (!body.empty() && (body.front() == '-' || body.front() == '+')) body.remove_prefix(1);
  if (value && std::isnan(*value)) return "NaN is not accepted";
  if (value) {
    const bool spelled =
        body.size() >= 3 && (body[0] | 0x20) == 'i' && (body[1] | 0x20) == 'n' && (body[2] | 0x20) == 'f';
    return spelled ? "infinities are not accepted" : "out of the range of a double, magnitudes up to about 1.8e308";
  }
  if (body.size() > 1 && body[0] == '0' && (body[1] | 0x20) == 'x') {
    return "hexadecimal is not accepted: write the value in decimal";
  }
  const auto comma = text.find(',');
  if (comma == std::string_view::npos) return {};
  std::string with_point(text);
  with_point[comma] = '.';
  const auto after = text.substr(comma + 1);
  const bool one_comma = after.find(',') == std::string_view::npos;
  if (one_comma && after.size() == 3 && parse_double(with_point)) {
    return "neither thousands separators nor a decimal comma are accepted: write " +
           std::string(text.substr(0, comma)) + std::string(after) + " or " + with_point;
  }
  if (one_comma && parse_double(with_point)) return "a comma is no decimal mark: write " + with_point;
  std::string without;
  for (char c : text) {
    if (c != ',') without += c;
  }
  if (parse_double(without)) return "thousands separators are not accepted: write " + without;
  return {};
}

/// `text` quoted, with number_hint's reason in parentheses when there is one: for messages
/// such as "expected a number, got '1,5' (a comma is no decimal mark: write 1.5)".
[[nodiscard]] inline std::string quoted_number(std::string_view text) {
  const auto hint = number_hint(text);
  return "'" + std::string(text) + "'" + (hint.empty() ? "" : " (" + hint + ")");
}

/// The shortest decimal text that reads back to exactly `value`.
[[nodiscard]] inline std::string format_double(double value) {
  char buffer[32];
  auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc{} ? std::string(buffer, ptr) : std::string("nan");
}

/// `value` with at most `digits` significant digits, for people rather than files.
[[nodiscard]] inline std::string format_short(double value, int digits = 6) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

[[nodiscard]] inline std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

/// Splits on `separator`, trimming each piece; an empty input gives no pieces.
[[nodiscard]] inline std::vector<std::string> split(std::string_view text, char separator) {
  std::vector<std::string> pieces;
  if (trim(text).empty()) return pieces;
  std::size_t start = 0;
  while (true) {
    const auto end = text.find(separator, start);
    pieces.emplace_back(trim(text.substr(start, end - start)));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return pieces;
}

template <class Range>
[[nodiscard]] std::string join(const Range& items, std::string_view separator = ", ") {
  std::string text;
  bool first = true;
  for (const auto& item : items) {
    if (!first) text += separator;
    text += item;
    first = false;
  }
  return text;
}

/// "a, b, c" or, past `limit` items, "a, b, c, … (12 in all)": for error messages.
template <class Range>
[[nodiscard]] std::string list_for_message(const Range& items, std::size_t limit = 12) {
  std::string text;
  std::size_t count = 0;
  for (const auto& item : items) {
    if (count < limit) text += (count ? ", " : "") + std::string(item);
    ++count;
  }
  if (count > limit) text += ", … (" + std::to_string(count) + " in all)";
  return text;
}

}  // namespace pgm::detail
