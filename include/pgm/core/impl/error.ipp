#pragma once
// The definitions of pgm/core/error.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/error.hpp"

namespace pgm {

PGM_DECL parse_error::parse_error(std::string file, std::size_t line, std::size_t column, const std::string& what)
    : data_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what),
      file_(std::move(file)),
      line_(line),
      column_(column) {}

PGM_DECL std::string not_a_dag::join(const std::vector<std::string>& nodes) {
  std::string text;
  for (const auto& node : nodes) text += (text.empty() ? "" : " -> ") + node;
  return text;
}

}  // namespace pgm
