#pragma once
// The definitions of pgm/detail/cumulative_columns.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/detail/cumulative_columns.hpp"

namespace pgm::detail {

PGM_DECL cumulative_columns::cumulative_columns(const cpt<double>& table, bool normalized)
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

PGM_DECL const double* cumulative_columns::column(std::size_t u) const noexcept {
  if (!sparse_) return sums_.data() + u * j_;
  const auto at = std::lower_bound(stored_.begin(), stored_.end(), u);
  const auto i = at != stored_.end() && *at == u ? static_cast<std::size_t>(at - stored_.begin()) : stored_.size();
  return sums_.data() + i * j_;
}

}  // namespace pgm::detail
