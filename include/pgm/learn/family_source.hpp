#pragma once
/// \file
/// Where a fit's counts come from. A family source reads the columns a request names, as the
/// CSV reader reads them (a known variable's column takes its states, a raw numeric column is
/// binned into intervals, a missing value follows the policy), and counts the requested
/// families; the fit pipeline (pgm/learn/fit_pipeline.hpp) asks every source the same way.
/// Three ship: a data set in memory (`dataset_source`, here), a CSV file streamed without being
/// held (`csv_source`, pgm/io/csv_source.hpp) and NumPy columns (the Python module).

#include <algorithm>
#include <concepts>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/discretizer.hpp"
#include "pgm/data/family_counts.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/learn/sufficient_statistics.hpp"

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
[[nodiscard]] inline discrete_column recode_to(const discrete_column& column, const variable& known,
                                               const std::string& source) {
  if (column.var().states() == known.states()) return column.with_variable(known);
  std::vector<std::uint32_t> index_of;
  for (const auto& label : column.var().states()) {
    const auto found = known.find_state(label);
    if (!found) {
      throw data_error((source.empty() ? std::string() : source + ": ") + "column '" + column.name() +
                       "' holds the value '" + detail::printable(label) + "', which is not a state of '" +
                       known.name() + "' {" + detail::list_for_message(known.states()) + "}");
    }
    index_of.push_back(static_cast<std::uint32_t>(found->value()));
  }
  auto codes = make_code_vector(known.cardinality(), column.size());
  std::visit(
      [&](const auto& from, auto& to) {
        using from_code = typename std::decay_t<decltype(from)>::value_type;
        using to_code = typename std::decay_t<decltype(to)>::value_type;
        for (std::size_t row = 0; row < from.size(); ++row) {
          to[row] = from[row] == missing_code<from_code> && column.missing() != 0
                        ? missing_code<to_code>
                        : static_cast<to_code>(index_of[from[row]]);
        }
      },
      column.codes(), codes);
  return discrete_column(known, std::move(codes), std::in_place, column.missing());
}

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

  [[nodiscard]] family_counts count(const family_count_request& request) const {
    family_counts result;
    auto read = this->read(request, result);
    if (request.missing.policy != missing_policy::available) read = without_missing(std::move(read), request, result);
    for (const auto& name : read.names()) result.variables.push_back(read.discrete(name).var());
    const count_options counting{.threads = request.threads};
    for (const auto& family : request.families) {
      result.families.push_back(count_family(read, family.child, family.parents, counting));
    }
    return result;
  }

  /// The requested columns as counting reads them (recoded, binned, in the data's order), with
  /// their missing values kept; `result` gets the rows and the values outside the bins. For
  /// what needs the rows themselves (EM).
  [[nodiscard]] dataset read(const family_count_request& request, family_counts& result) const {
    dataset read(data_->source());
    for (const auto& column : data_->names()) {
      if (std::find(request.columns.begin(), request.columns.end(), column) == request.columns.end()) continue;
      read.add(read_column(column, request, result));
    }
    for (const auto& column : request.columns) static_cast<void>(data_->at(column));  // each exists
    result.rows = read.rows();
    return read;
  }

 private:
  [[nodiscard]] data_column read_column(const std::string& name, const family_count_request& request,
                                        family_counts& result) const {
    const auto& column = data_->at(name);
    if (const auto binned = request.intervals.find(name); binned != request.intervals.end()) {
      if (const auto* values = std::get_if<continuous_column>(&column)) {
        const auto& edges = binned->second.edges();
        std::size_t outside = 0;
        for (double v : values->values()) outside += v < edges.front() || v > edges.back();  // NaN never is
        result.outside[name] = outside;
        return discretize(*values, binned->second);
      }
      return detail::recode_to(std::get<discrete_column>(column), binned->second, data_->source());
    }
    if (const auto known = request.variables.find(name); known != request.variables.end()) {
      return detail::recode_to(data_->discrete(name), known->second, data_->source());
    }
    return data_->discrete(name);
  }

  /// The policy error or drop applied to the columns read.
  [[nodiscard]] dataset without_missing(dataset read, const family_count_request& request,
                                        family_counts& result) const {
    std::vector<std::size_t> kept;
    kept.reserve(read.rows());
    for (std::size_t row = 0; row < read.rows(); ++row) {
      bool present = true;
      for (const auto& name : read.names()) {
        if (!read.discrete(name).is_missing(row)) continue;
        if (request.missing.policy == missing_policy::error) {
          throw data_error((data_->source().empty() ? std::string() : data_->source() + ": ") + "row " +
                           std::to_string(row + 1) + ": the value of '" + name + "' is missing");
        }
        present = false;
        break;
      }
      if (present) kept.push_back(row);
    }
    if (kept.size() == read.rows()) return read;
    result.dropped = read.rows() - kept.size();
    result.rows = kept.size();
    return read.select_rows(kept);
  }

  const dataset* data_;
};

}  // namespace pgm
