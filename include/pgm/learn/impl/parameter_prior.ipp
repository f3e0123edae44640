#pragma once
// The definitions of pgm/learn/parameter_prior.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/parameter_prior.hpp"

namespace pgm::detail {

PGM_DECL void check_pseudo_count(double value, const char* what) {
  if (!std::isfinite(value) || value < 0.0) {
    throw model_error(std::string(what) + " must be a finite number ≥ 0, got " + format_double(value));
  }
}

}  // namespace pgm::detail
