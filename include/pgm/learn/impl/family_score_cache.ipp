#pragma once
// The definitions of pgm/learn/family_score_cache.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/family_score_cache.hpp"

namespace pgm {

PGM_DECL std::size_t family_key_hash::operator()(const family_key& key) const noexcept {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ key.node;
  for (auto p : key.parents) {
    h ^= p + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  }
  return static_cast<std::size_t>(h);
}

PGM_DECL family_score_cache::family_score_cache(std::span<const discrete_column* const> columns, family_score score,
                                                unsigned threads)
    : columns_(columns.begin(), columns.end()), score_(std::move(score)), threads_(threads) {
  for (const auto* c : columns_) {
    if (c->size() != columns_.front()->size()) {
      throw data_error("column '" + c->name() + "' has " + std::to_string(c->size()) + " rows, '" +
                       columns_.front()->name() + "' " + std::to_string(columns_.front()->size()));
    }
  }
}

PGM_DECL double family_score_cache::score(const family_key& key) {
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

PGM_DECL std::vector<double> family_score_cache::score_all(std::span<const family_key> keys) {
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

PGM_DECL double family_score_cache::compute(const family_key& key, unsigned threads) const {
  std::vector<const discrete_column*> parents;
  parents.reserve(key.parents.size());
  for (auto p : key.parents) parents.push_back(columns_.at(p));
  const auto counts = count_family(*columns_.at(key.node), parents, {.threads = threads});
  return score_(counts);
}

}  // namespace pgm
