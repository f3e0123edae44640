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

#include "pgm/core/compilation.hpp"
#include "pgm/core/component_options.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/sufficient_statistics.hpp"

namespace pgm {

/// Which statistic a test computes.
enum class ci_test {
  chi_square,  ///< Pearson: sum over cells of (O − E)² / E
  g_squared,   ///< likelihood ratio: 2 · sum over cells of O · ln(O / E)
};

/// "chi2" or "g2", the names of their tests in the registry.
[[nodiscard]] inline std::string_view to_string(ci_test test) noexcept {
  return test == ci_test::chi_square ? "chi2" : "g2";
}

/// A continuity correction of the 2 x 2 strata (one degree of freedom).
enum class continuity_correction {
  none,
  /// Yates: each count moves half a unit toward its expected value (never past it), as scipy's
  /// chi2_contingency does by default, for chi-square and G² alike.
  yates,
};

/// "none" or "yates", as the tests' option spells them.
[[nodiscard]] inline std::string_view to_string(continuity_correction correction) noexcept {
  return correction == continuity_correction::yates ? "yates" : "none";
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
[[nodiscard]] PGM_DECL double chi_square_p_value(double statistic, double df);

/// The test on a three-way table laid out X fastest, then Y, then the stratum of Z:
/// `counts[(z · y_states + y) · x_states + x]`. counts.size() must be a multiple of
/// x_states · y_states (one stratum when Z is empty).
[[nodiscard]] PGM_DECL ci_result test_independence(std::span<const std::uint64_t> counts, std::size_t x_states,
                                                   std::size_t y_states, const ci_test_options& options);

/// The test without correction or minimum rows.
[[nodiscard]] inline ci_result test_independence(std::span<const std::uint64_t> counts, std::size_t x_states,
                                                 std::size_t y_states, ci_test test) {
  return test_independence(counts, x_states, y_states, ci_test_options{.test = test});
}

/// A test of X ⟂ Y | Z on their three-way table, laid out as test_independence reads it (X
/// fastest, then Y, then the strata of Z). PC and the DAG check call it from several threads at
/// once, so it must not change when called.
template <class T>
concept IndependenceTest = std::copy_constructible<T> &&
    requires(const T& test, std::span<const std::uint64_t> counts, std::size_t x_states, std::size_t y_states) {
  { test(counts, x_states, y_states) } -> std::convertible_to<ci_result>;
};

/// Pearson's chi-square ("chi2") or G² ("g2") with its options declared for the registry
/// (pgm/learn/independence_test_registry.hpp).
template <ci_test Statistic>
struct contingency_test {
  [[nodiscard]] static std::vector<option_declaration> options() {
    return {word_option("correction", "none", {"none", "yates"},
                        "Yates' continuity correction of the 2 x 2 strata, as pgmpy applies it"),
            number_option("min_rows_per_cell", 0.0,
                          "independence without a test below this many rows per cell, as bnlearn decides sparse "
                          "tables (0: always test)")
                .at_least(0.0)};
  }
  explicit contingency_test(const option_values& options)
      : settings{Statistic,
                 options.word("correction") == "yates" ? continuity_correction::yates : continuity_correction::none,
                 options.number("min_rows_per_cell")} {}

  [[nodiscard]] ci_result operator()(std::span<const std::uint64_t> counts, std::size_t x_states,
                                     std::size_t y_states) const {
    return test_independence(counts, x_states, y_states, settings);
  }

  ci_test_options settings;
};

using chi_square_test = contingency_test<ci_test::chi_square>;
using g_squared_test = contingency_test<ci_test::g_squared>;

static_assert(IndependenceTest<chi_square_test> && IndependenceTest<g_squared_test>);

namespace detail {

/// Counts the table (x | given..., y) into `counts` (resized and zeroed) over all rows where
/// none of them is missing (test-wise deletion, as pgmpy's tests count).
/// The layout is the one test_independence reads: x fastest, then y, then the strata of
/// `given` (its last column fastest). With `threads` > 1 (0: every hardware thread) the rows
/// are counted on up to that many threads, each into a private table, summed: the counts are
/// the same.
/// Throws model_error if the table has 2^32 cells or more.
PGM_DECL void count_ci_table(const discrete_column& x, const discrete_column& y,
                             std::span<const discrete_column* const> given, std::vector<std::uint64_t>& counts,
                             unsigned threads = 1);

}  // namespace detail

/// X ⟂ Y | given, counted over all rows of the columns.
[[nodiscard]] PGM_DECL ci_result test_independence(const discrete_column& x, const discrete_column& y,
                                                   std::span<const discrete_column* const> given,
                                                   const ci_test_options& options);

/// X ⟂ Y | given by column names. Throws data_error for a missing or continuous column.
[[nodiscard]] PGM_DECL ci_result test_independence(const dataset& data, std::string_view x, std::string_view y,
                                                   std::span<const std::string> given, const ci_test_options& options);

/// X ⟂ Y | given by any IndependenceTest, counted over all rows of the columns.
template <IndependenceTest T>
[[nodiscard]] ci_result test_independence(const discrete_column& x, const discrete_column& y,
                                          std::span<const discrete_column* const> given, const T& test) {
  std::vector<std::uint64_t> counts;
  detail::count_ci_table(x, y, given, counts);
  return test(std::span<const std::uint64_t>(counts), x.var().cardinality(), y.var().cardinality());
}

/// The same by column names. Throws data_error for a missing or continuous column.
template <IndependenceTest T>
[[nodiscard]] ci_result test_independence(const dataset& data, std::string_view x, std::string_view y,
                                          std::span<const std::string> given, const T& test) {
  std::vector<const discrete_column*> given_columns;
  for (const auto& name : given) given_columns.push_back(&data.discrete(name));
  return test_independence(data.discrete(x), data.discrete(y), given_columns, test);
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

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/independence_test.ipp"
#endif
