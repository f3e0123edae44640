#pragma once
/// \file
/// Base64 (RFC 4648, with '=' padding), by Boost's archive iterators: how pgm keeps a block of
/// its own (a fit's counts) in a property of a BIF, XMLBIF or NET file, where any other text
/// could collide with the format's own syntax or with a peer's parser.

#include <boost/archive/iterators/base64_from_binary.hpp>
#include <boost/archive/iterators/binary_from_base64.hpp>
#include <boost/archive/iterators/transform_width.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace pgm::detail {

[[nodiscard]] inline std::string base64_encode(std::string_view bytes) {
  using namespace boost::archive::iterators;
  using encoder = base64_from_binary<transform_width<std::string_view::const_iterator, 6, 8>>;
  std::string text(encoder(bytes.begin()), encoder(bytes.end()));
  text.append((3 - bytes.size() % 3) % 3, '=');
  return text;
}

/// The bytes `text` encodes, or nothing when it is not base64 (a character outside the
/// alphabet, a length that is not a multiple of 4, padding other than at the end).
[[nodiscard]] inline std::optional<std::string> base64_decode(std::string_view text) {
  if (text.size() % 4 != 0) return std::nullopt;
  std::size_t padding = 0;
  while (padding < 2 && padding < text.size() && text[text.size() - 1 - padding] == '=') ++padding;
  const auto body = text.substr(0, text.size() - padding);
  for (const char c : body) {
    const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    if (!letter && c != '+' && c != '/') return std::nullopt;
  }
  using namespace boost::archive::iterators;
  using decoder = transform_width<binary_from_base64<std::string_view::const_iterator>, 8, 6>;
  std::string bytes(decoder(body.begin()), decoder(body.end()));
  // The last group's spare bits, which padding stands for, decode as extra bytes.
  bytes.resize(text.size() / 4 * 3 - padding);
  return bytes;
}

}  // namespace pgm::detail
