#pragma once
// The definitions of pgm/decide/success_table.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/decide/success_table.hpp"

namespace pgm {

PGM_DECL cpt<double> success_table(const bayesian_network& network, std::string_view success,
                                   std::span<const std::string> given, std::span<const observation> observed,
                                   elimination_heuristic heuristic) {
  variable_elimination engine(borrowed(network), {heuristic});
  return success_table(engine, success, given, observed);
}

}  // namespace pgm
