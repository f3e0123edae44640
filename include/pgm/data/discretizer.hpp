#pragma once
/// \file
/// Discretization of continuous columns into interval variables: quantile (equal frequency,
/// the paper's choice), equal width, or explicit edges. A `discretization` is fitted on one
/// data set and applied to others; it is saved with the model so that new data is binned the
/// same way. Intervals are closed on the left, [e_i, e_{i+1}); values outside the fitted range
/// fall into the outer bins.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/dataset.hpp"

namespace pgm {

namespace detail {

/// Fails on an infinity; NaN is a missing value, which binning leaves missing.
inline void check_finite(std::span<const double> values, const std::string& name) {
  for (std::size_t row = 0; row < values.size(); ++row) {
    if (std::isinf(values[row])) {
      throw data_error("column '" + name + "' row " + std::to_string(row + 1) +
                       ": cannot discretize a value that is not finite");
    }
  }
}

/// Strictly increasing edges from candidates (ties merge bins), or a data_error when the
/// column holds a single value.
inline std::vector<double> distinct_edges(std::vector<double> edges, const std::string& name) {
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  if (edges.size() < 2) {
    throw data_error("column '" + name + "' holds a single value; it cannot be split into bins");
  }
  return edges;
}

/// The values that are present (not NaN), as pandas' quantiles skip missing values.
[[nodiscard]] inline std::vector<double> present_values(std::span<const double> values) {
  std::vector<double> present;
  present.reserve(values.size());
  for (double v : values) {
    if (!std::isnan(v)) present.push_back(v);
  }
  return present;
}

}  // namespace detail

/// Edges of `bins` equal-frequency bins: the minimum, the k/bins quantiles (linear
/// interpolation between order statistics, NumPy's default) and the maximum. Bins that would
/// be empty because of ties are merged, so fewer than `bins` may come back. Missing values
/// (NaN) are left out.
[[nodiscard]] inline std::vector<double> quantile_edges(std::span<const double> values, std::size_t bins,
                                                        const std::string& name = "values") {
  if (bins == 0) throw data_error("the number of bins must be positive");
  detail::check_finite(values, name);
  auto sorted = detail::present_values(values);
  if (sorted.empty()) throw data_error("column '" + name + "' has no values to discretize");
  std::sort(sorted.begin(), sorted.end());
  const auto n = sorted.size();
  std::vector<double> edges;
  edges.reserve(bins + 1);
  for (std::size_t k = 0; k <= bins; ++k) {
    const double h = static_cast<double>(n - 1) * static_cast<double>(k) / static_cast<double>(bins);
    const auto lower = static_cast<std::size_t>(std::floor(h));
    const auto upper = std::min(lower + 1, n - 1);
    edges.push_back(sorted[lower] + (h - static_cast<double>(lower)) * (sorted[upper] - sorted[lower]));
  }
  return detail::distinct_edges(std::move(edges), name);
}

/// Edges of `bins` bins of equal width between the minimum and the maximum (of the values
/// present: NaN is missing).
[[nodiscard]] inline std::vector<double> equal_width_edges(std::span<const double> values, std::size_t bins,
                                                           const std::string& name = "values") {
  if (bins == 0) throw data_error("the number of bins must be positive");
  detail::check_finite(values, name);
  const auto present = detail::present_values(values);
  if (present.empty()) throw data_error("column '" + name + "' has no values to discretize");
  const auto [lo, hi] = std::minmax_element(present.begin(), present.end());
  std::vector<double> edges;
  for (std::size_t k = 0; k <= bins; ++k) {
    edges.push_back(k == bins ? *hi : *lo + (*hi - *lo) * static_cast<double>(k) / static_cast<double>(bins));
  }
  return detail::distinct_edges(std::move(edges), name);
}

/// Interval variables by column name: what a discretizer learned, to apply to new data.
using discretization = std::map<std::string, variable, std::less<>>;

enum class binning { quantile, equal_width };

/// "quantile" or "width", as the command line and Python spell a binning method.
[[nodiscard]] constexpr std::string_view to_string(binning method) noexcept {
  return method == binning::equal_width ? "width" : "quantile";
}

inline constexpr std::array binnings{binning::quantile, binning::equal_width};

/// The methods' names, for parsing, messages and the command line's allowed values.
[[nodiscard]] inline std::vector<std::string> known_binnings() { return names_of(binnings); }

/// Parses "quantile" or "width"; throws unknown_name otherwise.
[[nodiscard]] inline binning parse_binning(std::string_view text) {
  return parse_choice("binning method", text, binnings);
}

/// Fits interval variables for the named continuous columns of `data`.
[[nodiscard]] inline discretization fit_discretization(const dataset& data, std::span<const std::string> columns,
                                                       binning method, std::size_t bins) {
  discretization result;
  for (const auto& name : columns) {
    const auto& c = data.continuous(name);
    auto edges = method == binning::quantile ? quantile_edges(c.values(), bins, name)
                                             : equal_width_edges(c.values(), bins, name);
    result.insert_or_assign(name, variable::intervals(name, std::move(edges), c.tags()));
  }
  return result;
}

/// The codes of `values` in the intervals of `intervals`; a missing value (NaN) stays missing.
[[nodiscard]] inline discrete_column discretize(const continuous_column& values, const variable& intervals) {
  if (!intervals.has_intervals()) {
    throw model_error("variable '" + intervals.name() + "' has no interval edges to bin values by");
  }
  detail::check_finite(values.values(), values.name());
  const auto missing = values.missing();
  auto codes = make_code_vector(intervals.cardinality() + (missing ? 1 : 0), values.size());
  std::visit(
      [&](auto& stored) {
        using code = typename std::decay_t<decltype(stored)>::value_type;
        const auto v = values.values();
        for (std::size_t row = 0; row < v.size(); ++row) {
          stored[row] = std::isnan(v[row]) ? missing_code<code> : static_cast<code>(intervals.bin(v[row]).value());
        }
      },
      codes);
  return discrete_column(intervals, std::move(codes), std::in_place, missing);
}

/// `data` with every continuous column named in `d` replaced by its discretized form.
/// A column that is discrete already must carry the same variable; a named column that is
/// absent is an error.
[[nodiscard]] inline dataset apply_discretization(const dataset& data, const discretization& d) {
  dataset result = data;
  for (const auto& [name, intervals] : d) {
    const auto& c = data.at(name);
    if (const auto* values = std::get_if<continuous_column>(&c)) {
      result.replace(discretize(*values, intervals));
    } else if (std::get<discrete_column>(c).var().states() != intervals.states()) {
      throw data_error("column '" + name + "' is discrete already, with other states than the " + "discretization");
    }
  }
  return result;
}

}  // namespace pgm
