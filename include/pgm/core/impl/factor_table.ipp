#pragma once
// The definitions of pgm/core/factor_table.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cmath>
#include <string>

#include "pgm/core/factor_table.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/text.hpp"

namespace pgm {

PGM_DECL factor_table::factor_table(std::vector<variable_id> scope, std::vector<std::size_t> cardinalities,
                                    std::vector<double> values)
    : scope_(std::move(scope)), cardinalities_(std::move(cardinalities)), values_(std::move(values)) {
  if (scope_.size() != cardinalities_.size()) throw model_error("a factor needs one cardinality per variable");
  std::size_t size = 1;
  for (std::size_t i = 0; i < scope_.size(); ++i) {
    if (cardinalities_[i] == 0) throw model_error("a factor's variable has no states");
    if (std::find(scope_.begin(), scope_.begin() + static_cast<std::ptrdiff_t>(i), scope_[i]) !=
        scope_.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw model_error("a factor lists the variable " + std::to_string(scope_[i].value()) + " twice");
    }
    size = detail::saturating_multiply(size, cardinalities_[i]);
  }
  if (size > max_table_cells) {
    throw table_too_large("a factor of " + std::to_string(size) + " cells is more than pgm's limit of " +
                          std::to_string(max_table_cells) + " (docs/limits.md)");
  }
  if (values_.size() != size) {
    throw model_error("a factor over " + std::to_string(scope_.size()) + " variables needs " + std::to_string(size) +
                      " values, got " + std::to_string(values_.size()));
  }
  for (std::size_t i = 0; i < values_.size(); ++i) {
    if (!(values_[i] >= 0.0) || !std::isfinite(values_[i])) {
      throw model_error("a factor's value " + std::to_string(i) + " is " + text::format_double(values_[i]) +
                        ": factor values must be finite and not negative");
    }
  }
}

}  // namespace pgm
