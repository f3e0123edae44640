#pragma once
/// \file
/// How pgm reads and writes numbers and names as text, for the library's readers and writers
/// and for programs built on it: numbers parsed by one rule (docs/limits.md, "Numbers") and
/// written so that they read back to the same bits, lists and names in messages as pgm writes
/// them, text made safe for a terminal, and the "did you mean" of an unknown name.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace pgm::text {

/// A field written into CSV: quoted (RFC 4180) where it holds the delimiter, a quote or a line
/// end, or starts or ends with a space (which readers trim).
[[nodiscard]] inline std::string csv_escape(std::string_view text, char delimiter) {
  const bool needs_quotes = text.find_first_of(std::string{delimiter, '"', '\n', '\r'}) != std::string_view::npos ||
                            (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!needs_quotes) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return quoted + '"';
}

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

/// The length of a valid UTF-8 sequence at the start of `text` (1 to 4), or 0 if it is none.
[[nodiscard]] inline std::size_t utf8_sequence(std::string_view text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const auto lead = byte(0);
  if (lead < 0x80) return 1;
  const std::size_t length = lead >= 0xC2 && lead <= 0xDF   ? 2
                             : lead >= 0xE0 && lead <= 0xEF ? 3
                             : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                            : 0;
  if (length == 0 || text.size() < length) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    if ((byte(i) & 0xC0) != 0x80) return 0;
  }
  // Overlong forms, UTF-16 surrogates and code points past U+10FFFF are not UTF-8.
  if ((lead == 0xE0 && byte(1) < 0xA0) || (lead == 0xED && byte(1) >= 0xA0) || (lead == 0xF0 && byte(1) < 0x90) ||
      (lead == 0xF4 && byte(1) >= 0x90)) {
    return 0;
  }
  return length;
}

/// `text` as a terminal should show it in a message: control characters (a file's escape
/// sequences included, which a terminal would obey), the C1 controls, the bidirectional
/// overrides and bytes that are not UTF-8 written as `\n`, `\t`, `\r` or `\xNN`; printable
/// text, UTF-8 included, unchanged. The program prints every error and note through it.
[[nodiscard]] inline std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  const auto escape = [&](unsigned char c) {
    static constexpr char digits[] = "0123456789abcdef";
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else {
      out += "\\x";
      out += digits[c >> 4];
      out += digits[c & 0xF];
    }
  };
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    const auto length = utf8_sequence(text.substr(i));
    const auto second = length > 1 ? static_cast<unsigned char>(text[i + 1]) : 0;
    const auto third = length > 2 ? static_cast<unsigned char>(text[i + 2]) : 0;
    const bool control = c < 0x20 || c == 0x7F || (c == 0xC2 && second < 0xA0);  // C0, DEL, C1
    // U+202A–U+202E and U+2066–U+2069 reorder the text around them.
    const bool bidi = c == 0xE2 && ((second == 0x80 && third >= 0xAA && third <= 0xAE) ||
                                    (second == 0x81 && third >= 0xA6 && third <= 0xA9));
    if (length == 0 || control || bidi) {
      for (std::size_t k = 0; k < std::max<std::size_t>(length, 1); ++k)
        escape(static_cast<unsigned char>(text[i + k]));
      i += std::max<std::size_t>(length, 1);
      continue;
    }
    out.append(text.substr(i, length));
    i += length;
  }
  return out;
}

/// How many single-character insertions, deletions, substitutions and swaps of neighbours turn
/// `a` into `b` (optimal string alignment).
[[nodiscard]] inline std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

/// The one of `names` `word` was most likely meant to be — within two edits, and fewer than half
/// its length — for "did you mean" in messages; nothing when none is that close.
template <class Range>
[[nodiscard]] std::optional<std::string> closest_name(std::string_view word, const Range& names) {
  std::optional<std::string> best;
  std::size_t best_distance = 3;
  for (const auto& name : names) {
    const auto distance = edit_distance(word, name);
    if (distance < best_distance && 2 * distance < std::max<std::size_t>(std::string_view(name).size(), 2)) {
      best = std::string(name);
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace pgm::text
