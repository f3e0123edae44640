#pragma once
/// \file
/// A table's columns as running sums, for drawing a child's state by a short scan: dense, one
/// column per parent configuration; for a sparse table (core/cpt.hpp), the stored columns and
/// the rest, found by a binary search, so that sampling never densifies a table.

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/strong_index.hpp"

namespace pgm::detail {

class cumulative_columns {
 public:
  cumulative_columns() = default;

  /// Running sums of each column of `table`; `normalized` divides them by the column's sum
  /// (a column summing to 0 then holds zeros).
  PGM_DECL cumulative_columns(const cpt<double>& table, bool normalized);

  /// The running sums of configuration u's column (child_cardinality() of them).
  [[nodiscard]] PGM_DECL const double* column(std::size_t u) const noexcept;

 private:
  std::size_t j_ = 0;
  bool sparse_ = false;
  std::vector<std::size_t> stored_;
  std::vector<double> sums_;
};

}  // namespace pgm::detail

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/detail/impl/cumulative_columns.ipp"
#endif
