#pragma once
/// \file
/// Data of a task that unfolds over several steps, in long form: one row per episode and step,
/// a column naming the episode and one numbering the step (t = 0, 1, … within an episode), then
/// the variables. `index_episodes` finds each episode's rows in step order, whatever the order
/// of the rows in the file; a dynamic network learns from it (pgm/learn/fit_dynamic.hpp).

#include <cstddef>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/data/dataset.hpp"

namespace pgm {

/// The names of the long form's two bookkeeping columns.
struct episode_columns {
  /// The episode each row belongs to (labels or numbers). Without this column the data are one
  /// episode.
  std::string episode = "episode";
  /// The step within the episode: a whole number, 0 for the first step.
  std::string step = "t";
};

/// The rows of each episode in step order.
struct episode_index {
  /// Data rows, episode after episode (in order of each episode's first row), each episode's
  /// rows by t; empty when the data are in that order already (then the i-th is row i).
  std::vector<std::size_t> rows;
  /// Episode k's rows are row(starts[k]) … row(starts[k + 1] − 1); one more entry than episodes.
  std::vector<std::size_t> starts{0};

  [[nodiscard]] bool in_order() const noexcept { return rows.empty(); }
  /// The i-th row in episode and step order.
  [[nodiscard]] std::size_t row(std::size_t i) const { return rows.empty() ? i : rows[i]; }
  [[nodiscard]] std::size_t episodes() const noexcept { return starts.size() - 1; }
  [[nodiscard]] std::size_t length(std::size_t episode) const { return starts[episode + 1] - starts[episode]; }
};

/// Indexes the episodes of `data`. Throws data_error, naming the data's source and the row or
/// episode, when the step column is absent, holds a missing value or a number that is not a
/// whole number ≥ 0, or when an episode does not have exactly one row for each t = 0 … L−1.
[[nodiscard]] PGM_DECL episode_index index_episodes(const dataset& data, const episode_columns& columns = {});

/// The name of episode k of `index` (its label or number as the data hold it), for messages.
[[nodiscard]] PGM_DECL std::string episode_name(const dataset& data, const episode_index& index, std::size_t k,
                                                const episode_columns& columns = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/data/impl/episodes.ipp"
#endif
