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

#include "pgm/core/error.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/learn/score.hpp"
#include "pgm/learn/sufficient_statistics.hpp"

namespace pgm {

/// A node and a set of parents, by column position; `parents` sorted, without duplicates.
struct family_key {
  std::size_t node = 0;
  std::vector<std::size_t> parents;

  friend bool operator==(const family_key&, const family_key&) = default;
};

struct family_key_hash {
  [[nodiscard]] std::size_t operator()(const family_key& key) const noexcept {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ key.node;
    for (auto p : key.parents) {
      h ^= p + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return static_cast<std::size_t>(h);
  }
};

class family_score_cache {
 public:
  /// Scores families of `columns` (node i is columns[i]), which must outlive the cache.
  /// Throws model_error for bad score options, data_error for columns of different lengths.
  family_score_cache(std::span<const discrete_column* const> columns, score_choice choice, unsigned threads = 0)
      : columns_(columns.begin(), columns.end()), choice_(choice), threads_(threads) {
    check_score_choice(choice_);
    for (const auto* c : columns_) {
      if (c->size() != columns_.front()->size()) {
        throw data_error("column '" + c->name() + "' has " + std::to_string(c->size()) + " rows, '" +
                         columns_.front()->name() + "' " + std::to_string(columns_.front()->size()));
      }
    }
  }

  [[nodiscard]] std::size_t size() const noexcept { return columns_.size(); }
  [[nodiscard]] const discrete_column& column(std::size_t node) const { return *columns_.at(node); }
  [[nodiscard]] const score_choice& choice() const noexcept { return choice_; }

  /// The score of one family (computed now if not known).
  [[nodiscard]] double score(const family_key& key) {
    const auto it = known_.find(key);
    if (it != known_.end()) {
      ++hits_;
      return it->second;
    }
    const double value = compute(key, threads_);
    known_.emplace(key, value);
    ++computed_;
    return value;
  }

  /// The scores of a batch of families, in order.
  [[nodiscard]] std::vector<double> score_all(std::span<const family_key> keys) {
    std::vector<double> values(keys.size());
    std::vector<std::size_t> missing;
    for (std::size_t k = 0; k < keys.size(); ++k) {
      const auto it = known_.find(keys[k]);
      if (it == known_.end()) {
        missing.push_back(k);
      } else {
        values[k] = it->second;
        ++hits_;
      }
    }
    const unsigned threads = detail::resolve_threads(threads_);
    // Families over threads when there are several; a lone family's rows over threads.
    const unsigned count_threads = missing.size() >= threads ? 1U : threads;
    static_cast<void>(detail::parallel_for(
        missing.size(), {.threads = threads}, [] { return 0; },
        [&](int&, detail::item_range chunk) {
          for (std::size_t m = chunk.begin; m < chunk.end; ++m) {
            values[missing[m]] = compute(keys[missing[m]], count_threads);
          }
        }));
    for (auto k : missing) {
      if (known_.emplace(keys[k], values[k]).second) ++computed_;
    }
    return values;
  }

  /// Families counted and scored so far, and lookups answered from the cache.
  [[nodiscard]] std::size_t computed() const noexcept { return computed_; }
  [[nodiscard]] std::size_t hits() const noexcept { return hits_; }

 private:
  [[nodiscard]] double compute(const family_key& key, unsigned threads) const {
    std::vector<const discrete_column*> parents;
    parents.reserve(key.parents.size());
    for (auto p : key.parents) parents.push_back(columns_.at(p));
    const auto counts = count_family(*columns_.at(key.node), parents, {.threads = threads});
    return family_score(counts, choice_);
  }

  std::vector<const discrete_column*> columns_;
  score_choice choice_;
  unsigned threads_;
  std::unordered_map<family_key, double, family_key_hash> known_;
  std::size_t computed_ = 0;
  std::size_t hits_ = 0;
};

}  // namespace pgm
