#pragma once
/// \file
/// CSV reading and writing. A header row names the columns; fields may be quoted ("a, b",
/// with "" for a quote). Numeric columns become continuous, other columns discrete, unless
/// `csv_options` says otherwise. Every error names the file, line, column and what was
/// expected.
///
/// Reading is compiled into the library (src/lib/data/csv.cpp): a file is mapped and parsed in
/// chunks split at line boundaries on several threads; standard input ("-") and
/// gzip-compressed data (a .csv.gz) are read as streams. The result is the same for any
/// number of threads and any chunk size. To count families without holding the data in
/// memory, see pgm/io/csv_counts.hpp.

#include <cstddef>
#include <deque>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/text.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/episodes.hpp"
#include "pgm/data/missing.hpp"

namespace pgm {

enum class column_kind {
  automatic,   ///< continuous if every value is a number, else discrete
  continuous,  ///< numbers only
  discrete,    ///< states; numeric labels sort numerically, others alphabetically
};

struct csv_options {
  char delimiter = ',';
  /// Read only these columns (in file order); empty reads all. Naming a column the file lacks
  /// is an error.
  std::vector<std::string> columns;
  /// The kind of each named column; others get `default_kind`.
  std::map<std::string, column_kind, std::less<>> kinds;
  column_kind default_kind = column_kind::automatic;
  /// Discrete columns whose variable is known already (from a model): their values must be
  /// its state labels, and the codes follow its state order.
  std::map<std::string, variable, std::less<>> variables;
  /// Which texts are missing values (`NA`, empty, `?` by default) and what happens to a row
  /// with one in a column read: an error (the default), the row dropped, or the value kept as
  /// missing (missing_code in a discrete column, NaN in a continuous one). See pgm/data/missing.hpp.
  missing_values missing;
  /// A header with no rows is an error unless this is set.
  bool allow_empty = false;
  /// Parsing threads; 0 uses every hardware thread. The result is the same for any number.
  unsigned threads = 0;
  /// Bytes per chunk parsed at a time (split at a line end); 0 chooses. Tests set it small to
  /// put chunk boundaries everywhere.
  std::size_t chunk_bytes = 0;
};

/// How episodes in long form (pgm/data/episodes.hpp) are read: every column as states, the
/// step as a number, the episode as numbers or labels, whichever it holds (numbers need no
/// dictionary of 10⁵ labels).
[[nodiscard]] inline csv_options long_form_options(const episode_columns& columns = {}) {
  csv_options options;
  options.default_kind = column_kind::discrete;
  options.kinds[columns.step] = column_kind::continuous;
  options.kinds[columns.episode] = column_kind::automatic;
  return options;
}

namespace detail {

/// One field of a CSV record. `text` stays valid until the next record is read.
struct csv_field {
  std::string_view text;
  std::size_t line;
  std::size_t column;  // 1-based byte column where the field starts
};

/// Where a scan of CSV text is: the byte position, its line and where that line starts.
struct csv_cursor {
  std::size_t pos = 0;
  std::size_t line = 1;
  std::size_t line_start = 0;
};

/// Splits CSV text into records of fields (RFC 4180 quoting; unquoted fields are trimmed;
/// blank lines are skipped; CRLF and LF line ends), one record at a time. Throws parse_error.
class csv_scanner {
 public:
  csv_scanner(std::string_view text, std::string source, char delimiter);

  [[nodiscard]] const std::string& source() const noexcept { return source_; }
  [[nodiscard]] std::size_t line() const noexcept { return cursor_.line; }

  /// Reads the next non-blank record; false at the end of the text.
  bool next(std::vector<csv_field>& fields);

  /// The line where the current record starts.
  [[nodiscard]] std::size_t record_line() const noexcept { return record_line_; }

 private:
  std::string_view text_;
  std::string source_;
  char delimiter_;
  csv_cursor cursor_;
  std::size_t record_line_ = 1;
  std::deque<std::string> unescaped_;  // deque: views into it survive push_back
};

}  // namespace detail

/// A data set read from CSV, and how many rows the missing-value policy `drop` left out.
struct csv_data {
  dataset data;
  std::size_t dropped = 0;
};

/// Parses CSV text; see parse_csv. Tells how many rows were dropped.
[[nodiscard]] csv_data parse_csv_data(std::string_view text, const std::string& source,
                                      const csv_options& options = {});

/// Reads a CSV file; see read_csv. Tells how many rows were dropped.
[[nodiscard]] csv_data read_csv_data(const std::filesystem::path& path, const csv_options& options = {});

/// Parses CSV text. `source` names it in error messages.
[[nodiscard]] dataset parse_csv(std::string_view text, const std::string& source, const csv_options& options = {});

/// Reads a CSV file; see parse_csv. "-" reads standard input (named "<stdin>" in messages);
/// gzip-compressed input (a .gz file, or gzip bytes on standard input) is inflated as it is
/// read, and a truncated or corrupt one is an error naming the file.
[[nodiscard]] dataset read_csv(const std::filesystem::path& path, const csv_options& options = {});

/// Writes a data set as CSV: discrete columns by state label, continuous ones as the
/// shortest decimal text that reads back to the same double, a missing value as `missing`.
void write_csv(const dataset& data, std::ostream& out, char delimiter = ',', std::string_view missing = "NA");

/// The records of write_csv without the header: a data set made in blocks of rows is written
/// as one file by writing the first block with write_csv and appending the others with this.
void write_csv_rows(const dataset& data, std::ostream& out, char delimiter = ',', std::string_view missing = "NA");

/// Writes a data set to a CSV file atomically (see write_csv).
void write_csv(const dataset& data, const std::filesystem::path& path, char delimiter = ',',
               std::string_view missing = "NA");

}  // namespace pgm
