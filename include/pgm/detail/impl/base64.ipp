#pragma once
// The definitions of pgm/detail/base64.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/detail/base64.hpp"

namespace pgm::detail {

PGM_DECL std::string base64_encode(std::string_view bytes) {
  using namespace boost::archive::iterators;
  using encoder = base64_from_binary<transform_width<std::string_view::const_iterator, 6, 8>>;
  std::string text(encoder(bytes.begin()), encoder(bytes.end()));
  text.append((3 - bytes.size() % 3) % 3, '=');
  return text;
}

PGM_DECL std::optional<std::string> base64_decode(std::string_view text) {
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
