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

#include "pgm/core/compilation.hpp"

namespace pgm::text {

/// A field written into CSV: quoted (RFC 4180) where it holds the delimiter, a quote or a line
/// end, or starts or ends with a space (which readers trim).
[[nodiscard]] PGM_DECL std::string csv_escape(std::string_view text, char delimiter);

/// The whole of `text` as a double (a leading '+' allowed), or nothing. NaN and infinities
/// are returned as such; callers decide whether they are acceptable.
[[nodiscard]] PGM_DECL std::optional<double> parse_double(std::string_view text);

/// Why `text`, which is not a finite number as pgm reads numbers (docs/limits.md, "Numbers"),
/// might have been meant as one: "a comma is no decimal mark: write 1.5". Empty for a finite
/// number and for text that looks like no number at all.
[[nodiscard]] PGM_DECL std::string number_hint(std::string_view text);

/// `text` quoted, with number_hint's reason in parentheses when there is one: for messages
/// such as "expected a number, got '1,5' (a comma is no decimal mark: write 1.5)".
[[nodiscard]] inline std::string quoted_number(std::string_view text) {
  const auto hint = number_hint(text);
  return "'" + std::string(text) + "'" + (hint.empty() ? "" : " (" + hint + ")");
}

/// The shortest decimal text that reads back to exactly `value`.
[[nodiscard]] PGM_DECL std::string format_double(double value);

/// `value` with at most `digits` significant digits, for people rather than files.
[[nodiscard]] PGM_DECL std::string format_short(double value, int digits = 6);

[[nodiscard]] PGM_DECL std::string_view trim(std::string_view text);

/// Splits on `separator`, trimming each piece; an empty input gives no pieces.
[[nodiscard]] PGM_DECL std::vector<std::string> split(std::string_view text, char separator);

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
[[nodiscard]] PGM_DECL std::size_t utf8_sequence(std::string_view text);

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
[[nodiscard]] PGM_DECL std::size_t edit_distance(std::string_view a, std::string_view b);

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

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/text.ipp"
#endif
