#pragma once
/// \file
/// What a fit asks of its data and what it gets back: the families (child and parents, by
/// column name) to count, how their columns are read (known variables, raw columns binned,
/// missing values), and the count tables with what reading them found. Every family source
/// speaks these (pgm/learn/family_source.hpp): a CSV file streamed by count_csv, a data set in
/// memory, NumPy columns.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "pgm/core/variable.hpp"
#include "pgm/data/missing.hpp"
#include "pgm/data/sufficient_statistics.hpp"

namespace pgm {

/// One family to count: a child column and its parent columns, by name.
struct family_names {
  std::string child;
  std::vector<std::string> parents;
};

struct family_count_request {
  /// The columns to read, by name; each value is checked as `read_csv` would. Every family's
  /// columns must be among them. Naming a column the file lacks is an error.
  std::vector<std::string> columns;
  /// Columns whose variable is known (from a model): their values must be its state labels,
  /// and the counts follow its state order.
  std::map<std::string, variable, std::less<>> variables;
  /// Raw numeric columns binned into these interval variables while they are read (values
  /// outside the edges go to the outer bins).
  std::map<std::string, variable, std::less<>> intervals;
  /// The families to count.
  std::vector<family_names> families;
  /// Missing values, as csv_options::missing: an error, rows dropped, or each family counted
  /// over the rows where its child and parents are present (policy available).
  missing_values missing;
  /// Counting threads; 0 uses every hardware thread. The counts are the same for any number.
  unsigned threads = 0;
  /// Bytes per chunk (split at a line end) and per window (what is in memory at once); 0
  /// chooses. Tests set them small to put boundaries everywhere.
  std::size_t chunk_bytes = 0;
  std::size_t window_bytes = 0;
};

struct family_counts {
  /// Data rows read (those dropped for a missing value not included).
  std::size_t rows = 0;
  /// Rows left out for a missing value (policy drop).
  std::size_t dropped = 0;
  /// The columns read, in file order, with their states: the values seen, sorted as
  /// `read_csv` sorts them, or the given variable, or the interval variable.
  std::vector<variable> variables;
  /// One table per requested family, in request order, over `variables`. With the policy
  /// available a table counts only the rows where its family is present, so it may sum to
  /// less than `rows`.
  std::vector<count_table> families;
  /// For each binned column, how many values lie outside its edges' range.
  std::map<std::string, std::size_t, std::less<>> outside;
};

}  // namespace pgm
