#pragma once
/// \file
/// `factor_table`: a non-negative function over the joint states of a few discrete variables, as
/// a model stores it (a Markov network's potentials; a Bayesian network's tables read as factors).
/// Values are numbered mixed-radix over the scope in order, last variable fastest, as `cpt` and
/// the inference factors number theirs. Zeros are allowed (hard constraints); negative, NaN and
/// infinite values are not.

#include <cstddef>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/strong_index.hpp"

namespace pgm {

class factor_table {
 public:
  /// The constant 1 over no variables.
  factor_table() : values_{1.0} {}

  /// A table over `scope` (distinct ids) with these cardinalities and values (their product of
  /// them). Throws model_error for a repeated variable, a cardinality of 0, a size mismatch or a
  /// negative or non-finite value, and table_too_large past max_table_cells.
  PGM_DECL factor_table(std::vector<variable_id> scope, std::vector<std::size_t> cardinalities,
                        std::vector<double> values);

  [[nodiscard]] const std::vector<variable_id>& scope() const noexcept { return scope_; }
  [[nodiscard]] const std::vector<std::size_t>& cardinalities() const noexcept { return cardinalities_; }
  [[nodiscard]] const std::vector<double>& values() const noexcept { return values_; }
  [[nodiscard]] std::size_t size() const noexcept { return values_.size(); }

  friend bool operator==(const factor_table&, const factor_table&) = default;

 private:
  std::vector<variable_id> scope_;
  std::vector<std::size_t> cardinalities_;
  std::vector<double> values_;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/factor_table.ipp"
#endif
