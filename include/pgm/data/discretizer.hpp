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

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/dataset.hpp"

namespace pgm {

namespace detail {

/// Fails on an infinity; NaN is a missing value, which binning leaves missing.
PGM_DECL void check_finite(std::span<const double> values, const std::string& name);

/// Strictly increasing edges from candidates (ties merge bins), or a data_error when the
/// column holds a single value.
PGM_DECL std::vector<double> distinct_edges(std::vector<double> edges, const std::string& name);

/// The values that are present (not NaN), as pandas' quantiles skip missing values.
[[nodiscard]] PGM_DECL std::vector<double> present_values(std::span<const double> values);

}  // namespace detail

/// Edges of `bins` equal-frequency bins: the minimum, the k/bins quantiles (linear
/// interpolation between order statistics, NumPy's default) and the maximum. Bins that would
/// be empty because of ties are merged, so fewer than `bins` may come back. Missing values
/// (NaN) are left out.
[[nodiscard]] PGM_DECL std::vector<double> quantile_edges(std::span<const double> values, std::size_t bins,
                                                          const std::string& name = "values");

/// Edges of `bins` bins of equal width between the minimum and the maximum (of the values
/// present: NaN is missing).
[[nodiscard]] PGM_DECL std::vector<double> equal_width_edges(std::span<const double> values, std::size_t bins,
                                                             const std::string& name = "values");

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
[[nodiscard]] PGM_DECL discretization fit_discretization(const dataset& data, std::span<const std::string> columns,
                                                         binning method, std::size_t bins);

/// The codes of `values` in the intervals of `intervals`; a missing value (NaN) stays missing.
[[nodiscard]] PGM_DECL discrete_column discretize(const continuous_column& values, const variable& intervals);

/// `data` with every continuous column named in `d` replaced by its discretized form.
/// A column that is discrete already must carry the same variable; a named column that is
/// absent is an error.
[[nodiscard]] PGM_DECL dataset apply_discretization(const dataset& data, const discretization& d);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/data/impl/discretizer.ipp"
#endif
