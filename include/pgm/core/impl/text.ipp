#pragma once
// The definitions of pgm/core/text.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/text.hpp"

namespace pgm::text {

PGM_DECL std::string csv_escape(std::string_view text, char delimiter) {
  const bool needs_quotes = text.find_first_of(std::string{delimiter, '"', '\n', '\r'}) != std::string_view::npos ||
                            (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!needs_quotes) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return quoted + '"';
}

PGM_DECL std::optional<double> parse_double(std::string_view text) {
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

PGM_DECL std::string number_hint(std::string_view text) {
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

PGM_DECL std::string format_double(double value) {
  char buffer[32];
  auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc{} ? std::string(buffer, ptr) : std::string("nan");
}

PGM_DECL std::string format_short(double value, int digits) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

PGM_DECL std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

PGM_DECL std::vector<std::string> split(std::string_view text, char separator) {
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

PGM_DECL std::size_t utf8_sequence(std::string_view text) {
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

PGM_DECL std::size_t edit_distance(std::string_view a, std::string_view b) {
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

}  // namespace pgm::text
