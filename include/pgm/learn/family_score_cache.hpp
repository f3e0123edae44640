#pragma once
/// \file
/// Family scores over a set of columns, remembered by (node, parent set), so that a structure
/// search scores each family once however often its moves come back to it. Parent sets are
/// kept sorted by node, so a family's counts (and the last bits of its score) do not depend on
/// the order its parents were named in.
///
/// `score_all` scores a batch of families: the ones not yet known are counted and scored on
/// up to `threads` threads through the one parallel-for (each into its own slot), then stored
/// in batch order, so the cache and every value are the same for any number of threads.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/learn/score_registry.hpp"

namespace pgm {

/// A node and a set of parents, by column position; `parents` sorted, without duplicates.
struct family_key {
  std::size_t node = 0;
  std::vector<std::size_t> parents;

  friend bool operator==(const family_key&, const family_key&) = default;
};

struct family_key_hash {
  [[nodiscard]] PGM_DECL std::size_t operator()(const family_key& key) const noexcept;
};

class family_score_cache {
 public:
  /// Scores families of `columns` (node i is columns[i]), which must outlive the cache.
  /// Throws data_error for columns of different lengths.
  PGM_DECL family_score_cache(std::span<const discrete_column* const> columns, family_score score,
                              unsigned threads = 0);

  [[nodiscard]] std::size_t size() const noexcept { return columns_.size(); }
  [[nodiscard]] const discrete_column& column(std::size_t node) const { return *columns_.at(node); }
  [[nodiscard]] const family_score& scored_by() const noexcept { return score_; }

  /// The score of one family (computed now if not known).
  [[nodiscard]] PGM_DECL double score(const family_key& key);

  /// The scores of a batch of families, in order.
  [[nodiscard]] PGM_DECL std::vector<double> score_all(std::span<const family_key> keys);

  /// Families counted and scored so far, and lookups answered from the cache.
  [[nodiscard]] std::size_t computed() const noexcept { return computed_; }
  [[nodiscard]] std::size_t hits() const noexcept { return hits_; }

 private:
  [[nodiscard]] PGM_DECL double compute(const family_key& key, unsigned threads) const;

  std::vector<const discrete_column*> columns_;
  family_score score_;
  unsigned threads_;
  std::unordered_map<family_key, double, family_key_hash> known_;
  std::size_t computed_ = 0;
  std::size_t hits_ = 0;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/family_score_cache.ipp"
#endif
