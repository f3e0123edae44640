#pragma once
// The definitions of pgm/learn/learn_structure.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/learn_structure.hpp"

namespace pgm {

PGM_DECL structure_problem structure_problem_of(const dataset& data, std::span<const std::string> names,
                                                structure_context context) {
  structure_problem problem{std::move(context)};
  for (const auto& name : names) problem.columns.push_back(&data.discrete(name));
  problem.names.assign(names.begin(), names.end());
  return problem;
}

}  // namespace pgm
