#pragma once
/// \file
/// A table's columns as running sums, for drawing a child's state by a short scan: dense, one
/// column per parent configuration; for a sparse table (core/cpt.hpp), the stored columns and
/// the rest, found by a binary search, so that sampling never densifies a table.

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "pgm/core/cpt.hpp"
#include "pgm/core/strong_index.hpp"

namespace pgm::detail {

class cumulative_columns {
 public:
  cumulative_columns() = default;

  /// Running sums of each column of `table`; `normalized` divides them by the column's sum
  /// (a column summing to 0 then holds zeros).
  cumulative_columns(const cpt<double>& table, bool normalized)
      : j_(table.child_cardinality()), sparse_(table.is_sparse()) {
    auto add = [&](std::span<const double> column) {
      double sum = 0.0;
      if (normalized) {
        for (const double p : column) sum += p;
      }
      double running = 0.0;
      for (const double p : column) {
        running += p;
        sums_.push_back(normalized ? (sum > 0.0 ? running / sum : 0.0) : running);
      }
    };
    if (sparse_) {
      const auto stored = table.stored_configurations();
      stored_.assign(stored.begin(), stored.end());
      sums_.reserve((stored_.size() + 1) * j_);
      for (const auto u : stored_) add(table.column(config_index(u)));
      add(table.rest());
    } else {
      sums_.reserve(table.size());
      for (std::size_t u = 0; u < table.configurations(); ++u) add(table.column(config_index(u)));
    }
  }

  /// The running sums of configuration u's column (child_cardinality() of them).
  [[nodiscard]] const double* column(std::size_t u) const noexcept {
    if (!sparse_) return sums_.data() + u * j_;
    const auto at = std::lower_bound(stored_.begin(), stored_.end(), u);
    const auto i = at != stored_.end() && *at == u ? static_cast<std::size_t>(at - stored_.begin()) : stored_.size();
    return sums_.data() + i * j_;
  }

 private:
  std::size_t j_ = 0;
  bool sparse_ = false;
  std::vector<std::size_t> stored_;
  std::vector<double> sums_;
};

}  // namespace pgm::detail
