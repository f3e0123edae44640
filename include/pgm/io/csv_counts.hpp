#pragma once
/// \file
/// Counting families straight from CSV, without holding the data in memory: `csv_reader`
/// opens a file (mapped), standard input ("-") or gzip-compressed data and reads its header;
/// `count_csv` streams the rest in windows and counts every family (node + parents) on
/// provisional per-column ids, in chunks split at line boundaries on several threads, then
/// maps the ids to the states `read_csv` would give the same columns. The counts equal
/// `count_family` on the data set `read_csv` returns, for any number of threads, chunk size or
/// window size, and memory stays bounded by the window, not the file.
///
/// The byte-range step is public for splitting a file over processes (the scale-out issue):
/// each counts its own whole records with `csv_counter::count`, the partial counts add up
/// with `+=`, and `csv_counter::finish` turns the sum into tables.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/process_group.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/family_counts.hpp"
#include "pgm/data/missing.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/io/csv.hpp"

namespace pgm {

namespace detail {
struct csv_access;  // the implementation's way in (src/lib/data)
}  // namespace detail

/// A CSV input opened and its header read: a file (mapped), standard input ("-", named
/// "<stdin>"), or gzip-compressed data (a .gz file, or gzip bytes on standard input), or text
/// in memory. Move-only.
class csv_reader {
 public:
  /// Opens `path` and reads the header. Throws io_error when it cannot be read (or is not
  /// gzip data though named .gz), parse_error for an empty file or a bad header.
  explicit csv_reader(const std::filesystem::path& path, char delimiter = ',');
  /// Reads CSV held in memory (valid while the reader is used); `source` names it.
  csv_reader(std::string_view text, std::string source, char delimiter = ',');
  ~csv_reader();
  csv_reader(csv_reader&&) noexcept;
  csv_reader& operator=(csv_reader&&) noexcept;

  /// The name used in messages: the path, or "<stdin>".
  [[nodiscard]] const std::string& source() const noexcept;
  /// The column names, in file order.
  [[nodiscard]] const std::vector<std::string>& header() const noexcept;

  struct impl;

 private:
  friend struct detail::csv_access;
  std::unique_ptr<impl> impl_;
};

/// Reads the rest of `input` and counts the requested families. Errors are those `read_csv`
/// reports for the same columns (file:line:column), plus "no data rows" for an empty body.
[[nodiscard]] family_counts count_csv(csv_reader& input, const family_count_request& request);

/// As above, with the records split over the processes of `group` (pgm::processes()
/// under mpirun), every one of which opened the same file: each counts its own byte range, cut
/// at line ends; process 0 merges their labels in file order and gives every process the ids
/// of all labels, and the count tables over those ids are summed by one reduction. Process 0
/// returns the same counts as one process would; the others return empty counts. Input that is not all in
/// memory (standard input, compressed data) or that holds quotes (a quoted field may span
/// lines) is counted whole by process 0. A failure is agreed on by all processes
/// (pgm::agree): the first in the file wins.
[[nodiscard]] family_counts count_csv(csv_reader& input, const family_count_request& request, process_group& group);

/// Counts of some of a file's records, over provisional ids: add up those of one counter with
/// `+=` (in any order) and turn them into tables with csv_counter::finish. They refer to their
/// counter, which must outlive them. A default-constructed one is empty.
class csv_partial_counts {
 public:
  csv_partial_counts();
  ~csv_partial_counts();
  csv_partial_counts(csv_partial_counts&&) noexcept;
  csv_partial_counts& operator=(csv_partial_counts&&) noexcept;

  /// Records counted.
  [[nodiscard]] std::size_t rows() const noexcept;
  /// Records left out for a missing value (policy drop).
  [[nodiscard]] std::size_t dropped() const noexcept;
  /// Line ends consumed (blank lines included): where the next range's lines start.
  [[nodiscard]] std::size_t lines() const noexcept;

  /// Adds the counts of other records of the same counter (std::invalid_argument otherwise).
  csv_partial_counts& operator+=(csv_partial_counts&& other);

  struct impl;

 private:
  friend struct detail::csv_access;
  std::unique_ptr<impl> impl_;
};

/// The plan of a count: which columns of a header are read, how, and which families counted.
class csv_counter {
 public:
  /// Throws data_error for a requested column the header lacks or a family column that is
  /// not requested.
  csv_counter(std::string source, std::vector<std::string> header, const family_count_request& request,
              char delimiter = ',');
  ~csv_counter();
  csv_counter(csv_counter&&) noexcept;
  csv_counter& operator=(csv_counter&&) noexcept;

  /// Counts the whole records in `bytes`, which starts at a record boundary and ends at one
  /// (or at the end of the input). `first_line` is the line it starts on, for messages and
  /// for the order in which labels first appear (by line and column). Throws parse_error.
  [[nodiscard]] csv_partial_counts count(std::string_view bytes, std::size_t first_line) const;

  /// The tables of all the counts added up. Throws data_error when there are no rows.
  [[nodiscard]] family_counts finish(const csv_partial_counts& counts) const;

  struct impl;

 private:
  friend struct detail::csv_access;
  std::unique_ptr<impl> impl_;
};

}  // namespace pgm
