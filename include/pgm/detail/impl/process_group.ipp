#pragma once
// The definitions of pgm/detail/process_group.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/detail/process_group.hpp"

namespace pgm::detail {

PGM_DECL std::string_view byte_reader::take(std::size_t n) {
  if (n > bytes_.size()) throw std::logic_error("bytes from another process end early");
  const auto part = bytes_.substr(0, n);
  bytes_.remove_prefix(n);
  return part;
}

}  // namespace pgm::detail
