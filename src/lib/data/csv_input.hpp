#pragma once
// Internal to the CSV reader (src/lib/data), not installed: an opened CSV input (csv_reader's
// state) and the way parallel chunk parsers report a failure before their line is known.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "data/byte_source.hpp"
#include "data/csv_engine.hpp"
#include "pgm/core/error.hpp"
#include "pgm/io/csv_counts.hpp"

namespace pgm {

struct csv_reader::impl {
  std::string source;
  char delimiter = ',';
  std::unique_ptr<detail::byte_source> bytes;
  std::vector<std::string> header;
  /// The line the data (after the header) starts on.
  std::size_t first_line = 1;
};

namespace detail {

/// Gives the implementation files the private state of the public classes.
struct csv_access {
  static csv_reader::impl& of(csv_reader& reader) { return *reader.impl_; }
  static csv_partial_counts::impl& of(csv_partial_counts& counts) { return *counts.impl_; }
  static const csv_partial_counts::impl& of(const csv_partial_counts& counts) { return *counts.impl_; }
  static const csv_counter::impl& of(const csv_counter& counter) { return *counter.impl_; }
};

/// A failure in chunk `chunk` of a piece of text parsed in parallel.
struct chunk_failure {
  std::size_t chunk;
  csv_failure failure;
};

/// The parse_error of `failure` in the chunk that starts on line `first_line`.
[[noreturn]] inline void throw_at(const std::string& source, std::size_t first_line, const csv_failure& failure) {
  if (failure.missing_value) {
    throw missing_value_error(source, first_line + failure.line, failure.column, failure.what);
  }
  throw parse_error(source, first_line + failure.line, failure.column, failure.what);
}

/// First line of each chunk, from the line ends each consumed.
[[nodiscard]] inline std::vector<std::size_t> chunk_first_lines(std::size_t first_line,
                                                                const std::vector<std::size_t>& lines) {
  std::vector<std::size_t> first(lines.size());
  for (std::size_t k = 0; k < lines.size(); ++k) {
    first[k] = first_line;
    first_line += lines[k];
  }
  return first;
}

/// Runs `parse(chunk)` for every chunk (via pgm's parallel_for, `make_state` and `body`) and
/// turns the first failing chunk's csv_failure into a parse_error with its absolute line,
/// from `lines` (each successful chunk writes its own slot).
template <class Run>
void rethrow_located(const std::string& source, std::size_t first_line, const std::vector<std::size_t>& lines,
                     Run&& run) {
  try {
    run();
  } catch (const chunk_failure& failed) {
    std::size_t line = first_line;
    for (std::size_t k = 0; k < failed.chunk; ++k) line += lines[k];
    throw_at(source, line, failed.failure);
  }
}

}  // namespace detail
}  // namespace pgm
