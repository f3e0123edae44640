#pragma once
/// \file
/// A field written into CSV: quoted (RFC 4180) where it holds the delimiter, a quote or a line
/// end, or starts or ends with a space (which readers trim). Header-only, for what writes CSV
/// text without reading any (posterior tables, result tables).

#include <string>
#include <string_view>

namespace pgm::detail {

[[nodiscard]] inline std::string csv_escape(std::string_view text, char delimiter) {
  const bool needs_quotes = text.find_first_of(std::string{delimiter, '"', '\n', '\r'}) != std::string_view::npos ||
                            (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!needs_quotes) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return quoted + '"';
}

}  // namespace pgm::detail
