#pragma once
/// \file
/// Conditional independence tests for discrete data: Pearson's chi-square and the likelihood
/// ratio G² for X ⟂ Y | Z, with p-values from Boost.Math's chi-square distribution.
///
/// Degrees of freedom are adjusted for empty cells as pgmpy and bnlearn do: in each stratum z
/// of Z, only the states of X and of Y that occur there count, so the stratum contributes
/// (rows with a nonzero margin − 1) · (columns with a nonzero margin − 1), and empty strata
/// contribute nothing. Without the adjustment a sparse table has far too many degrees of
/// freedom and every test looks like independence. A test with 0 degrees of freedom has
/// p = 1: the data cannot show a dependence.
///
/// Two options reproduce the peers (docs/structure-learning.md says how each differs): Yates'
/// continuity correction of every stratum with one degree of freedom (pgmpy, through scipy's
/// chi2_contingency), and a minimum number of rows per cell below which a test declares
/// independence without looking at the statistic (bnlearn's rule for sparse tables). Neither
/// is on by default.

#include <algorithm>
#include <array>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/learn/sufficient_statistics.hpp"

namespace pgm {

/// Which statistic a test computes.
enum class ci_test {
  chi_square,  ///< Pearson: sum over cells of (O − E)² / E
  g_squared,   ///< likelihood ratio: 2 · sum over cells of O · ln(O / E)
};

/// "chi2" or "g2", as the command line spells them.
[[nodiscard]] inline std::string_view to_string(ci_test test) noexcept {
  return test == ci_test::chi_square ? "chi2" : "g2";
}

inline constexpr std::array ci_tests{ci_test::chi_square, ci_test::g_squared};

/// The tests' names, for parsing, messages and the command line's allowed values.
[[nodiscard]] inline std::vector<std::string> known_ci_tests() { return names_of(ci_tests); }

/// Parses "chi2" or "g2"; throws unknown_name otherwise.
[[nodiscard]] inline ci_test parse_ci_test(std::string_view text) {
  return parse_choice("independence test", text, ci_tests);
}

/// A continuity correction of the 2 x 2 strata (one degree of freedom).
enum class continuity_correction {
  none,
  /// Yates: each count moves half a unit toward its expected value (never past it), as scipy's
  /// chi2_contingency does by default, for chi-square and G² alike.
  yates,
};

/// "none" or "yates", as the command line spells them.
[[nodiscard]] inline std::string_view to_string(continuity_correction correction) noexcept {
  return correction == continuity_correction::yates ? "yates" : "none";
}

inline constexpr std::array continuity_corrections{continuity_correction::none, continuity_correction::yates};

/// The corrections' names, for parsing, messages and the command line's allowed values.
[[nodiscard]] inline std::vector<std::string> known_continuity_corrections() {
  return names_of(continuity_corrections);
}

/// Parses "none" or "yates"; throws unknown_name otherwise.
[[nodiscard]] inline continuity_correction parse_continuity_correction(std::string_view text) {
  return parse_choice("continuity correction", text, continuity_corrections);
}

/// How a test is computed and when it gives up on a sparse table.
struct ci_test_options {
  ci_test test = ci_test::chi_square;
  continuity_correction correction = continuity_correction::none;
  /// A test counting fewer rows than this many per cell of its whole table (|X|·|Y|·|Z|
  /// cells) declares independence (p = 1, `too_few_rows` set); 0 never does.
  double min_rows_per_cell = 0.0;
  friend bool operator==(const ci_test_options&, const ci_test_options&) = default;
};

/// The outcome of one test.
struct ci_result {
  double statistic = 0.0;
  /// Adjusted for empty cells (see the file comment).
  double df = 0.0;
  double p_value = 1.0;
  /// Rows the table counted.
  std::uint64_t rows = 0;
  /// Fewer rows than ci_test_options::min_rows_per_cell asks for: p was set to 1.
  bool too_few_rows = false;

  /// X ⟂ Y | Z is accepted when p > alpha (bnlearn's rule).
  [[nodiscard]] bool independent(double alpha) const noexcept { return p_value > alpha; }

  friend bool operator==(const ci_result&, const ci_result&) = default;
};

/// The upper tail P(χ²_df ≥ statistic); 1 for df = 0.
[[nodiscard]] inline double chi_square_p_value(double statistic, double df) {
  if (!(df > 0.0) || !(statistic > 0.0)) return 1.0;
  if (!std::isfinite(statistic)) return 0.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(df), statistic));
}

/// The test on a three-way table laid out X fastest, then Y, then the stratum of Z:
/// `counts[(z · y_states + y) · x_states + x]`. counts.size() must be a multiple of
/// x_states · y_states (one stratum when Z is empty).
[[nodiscard]] inline ci_result test_independence(std::span<const std::uint64_t> counts, std::size_t x_states,
                                                 std::size_t y_states, const ci_test_options& options) {
  if (!(options.min_rows_per_cell >= 0.0) || !std::isfinite(options.min_rows_per_cell)) {
    throw model_error("the minimum rows per cell must be a finite number >= 0, got " +
                      detail::format_short(options.min_rows_per_cell));
  }
  const std::size_t cells = x_states * y_states;
  if (cells == 0 || counts.size() % cells != 0) {
    throw model_error("a contingency table of " + std::to_string(counts.size()) + " cells is not a stack of " +
                      std::to_string(x_states) + " x " + std::to_string(y_states) + " tables");
  }
  ci_result result;
  std::vector<std::uint64_t> x_margin(x_states);
  std::vector<std::uint64_t> y_margin(y_states);
  for (std::size_t first = 0; first < counts.size(); first += cells) {
    const auto* table = counts.data() + first;
    std::fill(x_margin.begin(), x_margin.end(), 0);
    std::fill(y_margin.begin(), y_margin.end(), 0);
    std::uint64_t n = 0;
    for (std::size_t y = 0; y < y_states; ++y) {
      for (std::size_t x = 0; x < x_states; ++x) {
        const auto c = table[y * x_states + x];
        x_margin[x] += c;
        y_margin[y] += c;
        n += c;
      }
    }
    if (n == 0) continue;
    result.rows += n;
    std::size_t x_seen = 0;
    std::size_t y_seen = 0;
    for (auto m : x_margin) x_seen += m > 0;
    for (auto m : y_margin) y_seen += m > 0;
    const auto stratum_df = (x_seen - 1) * (y_seen - 1);
    result.df += static_cast<double>(stratum_df);
    const bool yates = options.correction == continuity_correction::yates && stratum_df == 1;
    const double total = static_cast<double>(n);
    for (std::size_t y = 0; y < y_states; ++y) {
      if (y_margin[y] == 0) continue;
      const double y_share = static_cast<double>(y_margin[y]) / total;
      for (std::size_t x = 0; x < x_states; ++x) {
        if (x_margin[x] == 0) continue;
        const double expected = static_cast<double>(x_margin[x]) * y_share;
        double observed = static_cast<double>(table[y * x_states + x]);
        if (yates) {
          const double gap = expected - observed;
          observed += std::copysign(std::min(0.5, std::abs(gap)), gap);
        }
        if (options.test == ci_test::chi_square) {
          const double d = observed - expected;
          result.statistic += d * d / expected;
        } else if (observed > 0) {
          result.statistic += 2.0 * observed * std::log(observed / expected);
        }
      }
    }
  }
  // Rounding can leave a tiny negative G² for a perfectly independent table.
  if (result.statistic < 0.0) result.statistic = 0.0;
  result.p_value = chi_square_p_value(result.statistic, result.df);
  if (static_cast<double>(result.rows) < options.min_rows_per_cell * static_cast<double>(counts.size())) {
    result.too_few_rows = true;
    result.p_value = 1.0;
  }
  return result;
}

/// The test without correction or minimum rows.
[[nodiscard]] inline ci_result test_independence(std::span<const std::uint64_t> counts, std::size_t x_states,
                                                 std::size_t y_states, ci_test test) {
  return test_independence(counts, x_states, y_states, ci_test_options{.test = test});
}

namespace detail {

/// Counts the table (x | given..., y) into `counts` (resized and zeroed) over all rows where
/// none of them is missing (test-wise deletion, as pgmpy's tests count).
/// The layout is the one test_independence reads: x fastest, then y, then the strata of
/// `given` (its last column fastest). With `threads` > 1 (0: every hardware thread) the rows
/// are counted on up to that many threads, each into a private table, summed: the counts are
/// the same.
/// Throws model_error if the table has 2^32 cells or more.
inline void count_ci_table(const discrete_column& x, const discrete_column& y,
                           std::span<const discrete_column* const> given, std::vector<std::uint64_t>& counts,
                           unsigned threads = 1) {
  std::vector<const code_vector*> columns{&x.codes()};
  std::vector<std::uint32_t> strides{1};
  std::size_t stride = x.var().cardinality();
  const auto limit = static_cast<std::size_t>(std::numeric_limits<std::uint32_t>::max());
  auto add = [&](const discrete_column& c) {
    if (c.size() != x.size()) {
      throw data_error("column '" + c.name() + "' has " + std::to_string(c.size()) + " rows, '" + x.name() + "' " +
                       std::to_string(x.size()));
    }
    columns.push_back(&c.codes());
    strides.push_back(static_cast<std::uint32_t>(stride));
    if (stride > limit / c.var().cardinality()) {
      throw model_error("the test of '" + x.name() + "' and '" + y.name() + "' given " + std::to_string(given.size()) +
                        " variables needs a table of 2^32 cells or more; lower the largest "
                        "conditioning set");
    }
    stride *= c.var().cardinality();
  };
  add(y);
  for (std::size_t k = given.size(); k-- > 0;) add(*given[k]);
  counts.assign(stride, 0);
  bool skip_missing = x.missing() != 0 || y.missing() != 0;
  for (const auto* c : given) skip_missing = skip_missing || c->missing() != 0;
  // Below ~64k rows per thread, starting a thread costs more than it saves.
  count_rows_parallel(columns, strides, 0, x.size(), counts, threads, std::size_t{1} << 16, skip_missing);
}

}  // namespace detail

/// X ⟂ Y | given, counted over all rows of the columns.
[[nodiscard]] inline ci_result test_independence(const discrete_column& x, const discrete_column& y,
                                                 std::span<const discrete_column* const> given,
                                                 const ci_test_options& options) {
  std::vector<std::uint64_t> counts;
  detail::count_ci_table(x, y, given, counts);
  return test_independence(counts, x.var().cardinality(), y.var().cardinality(), options);
}

/// X ⟂ Y | given by column names. Throws data_error for a missing or continuous column.
[[nodiscard]] inline ci_result test_independence(const dataset& data, std::string_view x, std::string_view y,
                                                 std::span<const std::string> given, const ci_test_options& options) {
  std::vector<const discrete_column*> given_columns;
  for (const auto& name : given) given_columns.push_back(&data.discrete(name));
  return test_independence(data.discrete(x), data.discrete(y), given_columns, options);
}

/// The same without correction or minimum rows.
[[nodiscard]] inline ci_result test_independence(const discrete_column& x, const discrete_column& y,
                                                 std::span<const discrete_column* const> given, ci_test test) {
  return test_independence(x, y, given, ci_test_options{.test = test});
}

[[nodiscard]] inline ci_result test_independence(const dataset& data, std::string_view x, std::string_view y,
                                                 std::span<const std::string> given, ci_test test) {
  return test_independence(data, x, y, given, ci_test_options{.test = test});
}

}  // namespace pgm
