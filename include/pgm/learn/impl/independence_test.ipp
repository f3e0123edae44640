#pragma once
// The definitions of pgm/learn/independence_test.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/independence_test.hpp"

namespace pgm {

PGM_DECL double chi_square_p_value(double statistic, double df) {
  if (!(df > 0.0) || !(statistic > 0.0)) return 1.0;
  if (!std::isfinite(statistic)) return 0.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(df), statistic));
}

PGM_DECL ci_result test_independence(std::span<const std::uint64_t> counts, std::size_t x_states, std::size_t y_states,
                                     const ci_test_options& options) {
  if (!(options.min_rows_per_cell >= 0.0) || !std::isfinite(options.min_rows_per_cell)) {
    throw model_error("the minimum rows per cell must be a finite number >= 0, got " +
                      text::format_short(options.min_rows_per_cell));
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

}  // namespace pgm

namespace pgm::detail {

PGM_DECL void count_ci_table(const discrete_column& x, const discrete_column& y,
                             std::span<const discrete_column* const> given, std::vector<std::uint64_t>& counts,
                             unsigned threads) {
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

}  // namespace pgm::detail

namespace pgm {

PGM_DECL ci_result test_independence(const discrete_column& x, const discrete_column& y,
                                     std::span<const discrete_column* const> given, const ci_test_options& options) {
  std::vector<std::uint64_t> counts;
  detail::count_ci_table(x, y, given, counts);
  return test_independence(counts, x.var().cardinality(), y.var().cardinality(), options);
}

PGM_DECL ci_result test_independence(const dataset& data, std::string_view x, std::string_view y,
                                     std::span<const std::string> given, const ci_test_options& options) {
  std::vector<const discrete_column*> given_columns;
  for (const auto& name : given) given_columns.push_back(&data.discrete(name));
  return test_independence(data.discrete(x), data.discrete(y), given_columns, options);
}

}  // namespace pgm
