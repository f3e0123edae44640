#pragma once
/// \file
/// Binning the continuous columns of a data set as `pgm discretize` and the Python
/// `pgm.discretize` do: the named columns, or by default every numeric column with more
/// distinct values than bins (outcomes such as 0/1 stay as they are), by quantile or equal
/// width — or by edges saved from an earlier run, so that new data is binned the same way.

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/discretizer.hpp"

namespace pgm {

struct column_binning {
  /// The columns to bin; empty: every continuous column with more distinct values than `bins`.
  std::vector<std::string> columns;
  binning method = binning::quantile;
  std::size_t bins = 5;
  /// Saved edges to apply instead of fitting new ones (`method` and `bins` then play no part),
  /// and where they came from, for messages.
  std::optional<discretization> saved;
  std::string saved_source;
};

struct binned_columns {
  /// The data with the binned columns replaced by their codes.
  dataset data;
  /// The edges used, by column.
  discretization edges;
  /// Continuous columns the default choice left as they are, with their (few) distinct values.
  std::vector<std::pair<std::string, std::size_t>> left;
};

/// A numeric column as `pgm fit` reads it back from the file `pgm discretize` wrote with the
/// column left as it is: one state per distinct value, named as pgm writes the value (the
/// shortest text that reads back to it), in numeric order (pgm/data/state_order.hpp). A
/// missing value (NaN) stays missing.
[[nodiscard]] PGM_DECL discrete_column values_as_states(const continuous_column& values);

/// Bins the columns `request` names (see column_binning). Throws data_error for a column that
/// is missing, not numeric or has no saved edges, or when the default choice finds nothing to bin.
[[nodiscard]] PGM_DECL binned_columns bin_columns(const dataset& data, const column_binning& request);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/data/impl/bin_columns.ipp"
#endif
