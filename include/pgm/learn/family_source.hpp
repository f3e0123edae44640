#pragma once
/// \file
/// Where a fit's counts come from. A family source reads the columns a request names, as the
/// CSV reader reads them (a known variable's column takes its states, a raw numeric column is
/// binned into intervals, a missing value follows the policy), and counts the requested
/// families; the fit pipeline (pgm/pipeline/fit_pipeline.hpp) asks every source the same way.
/// Three ship: a data set in memory (`dataset_source`, here), a CSV file streamed without being
/// held (`csv_source`, pgm/io/csv_source.hpp) and NumPy columns (the Python module).

#include <algorithm>
#include <concepts>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/discretizer.hpp"
#include "pgm/data/family_counts.hpp"
#include "pgm/data/sufficient_statistics.hpp"

namespace pgm {

/// A source of family counts: its column names in its own order (which orders a structure
/// read off the data), a name for messages, and the counts of a request. `count` may return
/// empty counts where another party holds the result (`holds_counts() == false`: the
/// processes of a group other than the first).
template <class Source>
concept family_source = requires(Source& source, const family_count_request& request) {
  { source.columns() } -> std::convertible_to<std::vector<std::string>>;
  { source.name() } -> std::convertible_to<std::string>;
  { source.count(request) } -> std::same_as<family_counts>;
  { source.holds_counts() } -> std::convertible_to<bool>;
};

/// A source that also gives the rows it reads, as a data set with the missing values kept:
/// what EM needs, which reads the data once per iteration.
template <class Source>
concept row_source = family_source<Source> &&
    requires(Source& source, const family_count_request& request, family_counts& result) {
  { source.read(request, result) } -> std::same_as<dataset>;
};

namespace detail {

/// `column` under `known`: each row's label becomes the index of the same label among the
/// known variable's states. Throws data_error for a label the variable lacks.
[[nodiscard]] PGM_DECL discrete_column recode_to(const discrete_column& column, const variable& known,
                                                 const std::string& source);

}  // namespace detail

/// A data set in memory as a family source. Columns are taken as they are, except that a known
/// variable's column is recoded to its states and a continuous column named among the
/// request's intervals is binned (values outside the edges go to the outer bins, and are
/// counted in `outside`). Missing values follow the request's policy: `error` refuses them,
/// `drop` leaves out every row with one among the requested columns, `available` counts each
/// family over the rows where it is present.
class dataset_source {
 public:
  explicit dataset_source(const dataset& data) : data_(&data) {}

  [[nodiscard]] std::vector<std::string> columns() const { return data_->names(); }
  [[nodiscard]] std::string name() const { return data_->source().empty() ? "data" : data_->source(); }
  [[nodiscard]] static bool holds_counts() noexcept { return true; }

  [[nodiscard]] PGM_DECL family_counts count(const family_count_request& request) const;

  /// The requested columns as counting reads them (recoded, binned, in the data's order), with
  /// their missing values kept; `result` gets the rows and the values outside the bins. For
  /// what needs the rows themselves (EM).
  [[nodiscard]] PGM_DECL dataset read(const family_count_request& request, family_counts& result) const;

 private:
  [[nodiscard]] PGM_DECL data_column read_column(const std::string& name, const family_count_request& request,
                                                 family_counts& result) const;

  /// The policy error or drop applied to the columns read.
  [[nodiscard]] PGM_DECL dataset without_missing(dataset read, const family_count_request& request,
                                                 family_counts& result) const;

  const dataset* data_;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/family_source.ipp"
#endif
