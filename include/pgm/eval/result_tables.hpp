#pragma once
/// \file
/// The experiment's tables as CSV: `points.csv` (every measured value, one row per
/// pgm::experiment_point) and `summary.csv` (mean and standard deviation per point, one row
/// per pgm::aggregated_point), written with the data module's quoting and shortest
/// round-trip numbers, and the summary read back (for `pgm report`) to the same bits.

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/eval/experiment.hpp"
#include "pgm/io/csv.hpp"

namespace pgm {

namespace detail {

inline constexpr std::array<std::string_view, 9> summary_columns{"scenario", "target", "strategy", "w",          "rows",
                                                                 "metric",   "mean",   "sd",       "repetitions"};

[[nodiscard]] inline std::string csv_text(std::string_view text) { return text::csv_escape(text, ','); }

}  // namespace detail

/// Writes the points as CSV: scenario, target, strategy, w, rows, repetition, metric, value.
PGM_DECL void write_points_csv(const std::vector<experiment_point>& points, std::ostream& out);

/// Writes the points to a file atomically (see the stream overload).
inline void write_points_csv(const std::vector<experiment_point>& points, const std::filesystem::path& path) {
  pgm::write_file_atomically(path, [&](std::ostream& out) { write_points_csv(points, out); });
}

/// Writes the summary as CSV: scenario, target, strategy, w, rows, metric, mean, sd, repetitions.
PGM_DECL void write_summary_csv(const std::vector<aggregated_point>& summary, std::ostream& out);

/// Writes the summary to a file atomically (see the stream overload).
inline void write_summary_csv(const std::vector<aggregated_point>& summary, const std::filesystem::path& path) {
  pgm::write_file_atomically(path, [&](std::ostream& out) { write_summary_csv(summary, out); });
}

/// Reads a summary as write_summary_csv writes it (columns in any order, others ignored).
/// Errors name `source`, the line and column, the column's name and what was expected.
[[nodiscard]] PGM_DECL std::vector<aggregated_point> parse_summary_csv(std::string_view text,
                                                                       const std::string& source);

/// Reads a summary file; see parse_summary_csv.
[[nodiscard]] inline std::vector<aggregated_point> read_summary_csv(const std::filesystem::path& path) {
  return parse_summary_csv(pgm::read_file(path), path.string());
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/result_tables.ipp"
#endif
