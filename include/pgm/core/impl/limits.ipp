#pragma once
// The definitions of pgm/core/limits.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/limits.hpp"

namespace pgm {

PGM_DECL std::size_t checked_table_cells(const std::string& child, std::size_t child_states,
                                         std::size_t configurations) {
  if (configurations != 0 && child_states > max_table_cells / configurations) {
    const bool overflows = child_states > std::numeric_limits<std::size_t>::max() / configurations;
    throw table_too_large("the table of '" + child + "' would have " +
                          (overflows ? std::string("more than 2^64") : std::to_string(child_states * configurations)) +
                          " cells (" + std::to_string(child_states) + " states × " + std::to_string(configurations) +
                          " parent configurations), more than pgm's limit of " + std::to_string(max_table_cells) +
                          " cells per table (docs/limits.md)");
  }
  return child_states * configurations;
}

}  // namespace pgm
