#pragma once
/// \file
/// Parameter estimation of one node from its counts: maximum likelihood (eq. 3) and Bayesian
/// estimation with a Dirichlet prior (eq. 6), including the paper's weighted prior (eq. 7/8).

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/dirichlet.hpp"
#include "pgm/learn/parameter_prior.hpp"

namespace pgm {

/// What to do for a parent configuration with no data and no prior counts.
enum class empty_configuration {
  uniform,  ///< 1/J for each state (the paper's 0.5 for a binary child)
  fail,     ///< throw data_error naming the configuration
};

/// "uniform" or "fail", as the command line, Python and a model's statistics spell the rule.
[[nodiscard]] constexpr std::string_view to_string(empty_configuration rule) noexcept {
  return rule == empty_configuration::fail ? "fail" : "uniform";
}

inline constexpr std::array empty_configurations{empty_configuration::uniform, empty_configuration::fail};

/// The rules' names, for parsing, messages and the command line's allowed values.
[[nodiscard]] inline std::vector<std::string> known_empty_configurations() { return names_of(empty_configurations); }

/// Parses "uniform" or "fail"; throws unknown_name otherwise.
[[nodiscard]] inline empty_configuration parse_empty_configuration(std::string_view text) {
  return parse_choice("empty-configuration rule", text, empty_configurations);
}

struct estimate_options {
  empty_configuration empty = empty_configuration::uniform;
  /// Store a large table fitted from fewer rows than it has configurations sparse (see
  /// estimate_is_sparse); off, such a table is dense whenever pgm's limit allows.
  bool sparse = true;
};

namespace detail {

/// θ[x,u] = (α[x,u] + M[x,u]) / (α_u + M[u]) for one column u, written to `out` by the
/// Dirichlet kernel, with the empty-configuration rule where there is neither data nor prior.
template <class Count, PseudoCounts A>
void posterior_column(const basic_count_table<Count>& counts, std::size_t u, std::span<const Count> column,
                      const A& alpha, const estimate_options& options, double* out) {
  const std::size_t j = counts.child_cardinality();
  const double denominator = dirichlet_posterior_column(column, u, alpha, out);
  auto where = [&] {
    std::string text;
    const auto codes = counts.parent_radix().decode(u);
    for (std::size_t i = 0; i < codes.size(); ++i) {
      text += (i ? ", " : " given ") + counts.parents()[i].name() + "=" + counts.parents()[i].states()[codes[i]];
    }
    return text;
  };
  // Each pseudo-count alone may be finite while the column's sum is not; the quotient would
  // then be 0 everywhere, a table that does not sum to 1.
  if (!std::isfinite(denominator)) {
    throw model_error("the pseudo-counts and counts of '" + counts.child().name() + "'" + where() +
                      " add up to more than the largest finite number (" +
                      text::format_double(std::numeric_limits<double>::max()) +
                      "): the pseudo-counts (alpha, the equivalent sample size) must keep that sum finite");
  }
  if (denominator == 0.0) {
    if (options.empty == empty_configuration::fail) {
      throw data_error("no data for '" + counts.child().name() + "'" + where() + ", and no prior to fall back on");
    }
    for (std::size_t x = 0; x < j; ++x) out[x] = 1.0 / static_cast<double>(j);
  }
}

template <class Count, PseudoCounts A>
std::vector<double> dirichlet_posterior_mean(const basic_count_table<Count>& counts, const A& alpha,
                                             const estimate_options& options) {
  const std::size_t j = counts.child_cardinality();
  std::vector<double> values(counts.counts().size());
  for (std::size_t u = 0; u < counts.configurations(); ++u) {
    posterior_column(counts, u, counts.column(config_index(u)), alpha, options, values.data() + u * j);
  }
  return values;
}

/// Tables with more cells than this, fitted from fewer rows than they have parent
/// configurations, are stored sparse (cpt.hpp); smaller ones stay dense.
inline constexpr std::size_t sparse_table_min_cells = std::size_t{1} << 16;

/// Whether the estimate of `counts` is stored sparse: always for sparse counts, and for dense
/// ones over sparse_table_min_cells with more configurations than rows.
template <class Count>
[[nodiscard]] bool estimate_is_sparse(const basic_count_table<Count>& counts) {
  if (counts.is_sparse()) return true;
  const auto cells = counts.child_cardinality() * counts.configurations();
  return cells > sparse_table_min_cells &&
         static_cast<double>(counts.total()) < static_cast<double>(counts.configurations());
}

/// Eq. 6 with the same pseudo-count α in every cell (0 for MLE), stored sparse: the columns of
/// the configurations with rows, and for the others the column of an empty configuration,
/// computed by the same formula as a dense table's, so that dense() equals it to the bit.
template <class Count>
cpt<double> sparse_dirichlet_estimate(const basic_count_table<Count>& counts, double alpha,
                                      const estimate_options& options) {
  const std::size_t j = counts.child_cardinality();
  const uniform_pseudo_counts same{alpha, j};
  sparse_columns<double> columns;
  auto store = [&](std::size_t u, std::span<const Count> column) {
    columns.configurations.push_back(u);
    columns.values.resize(columns.values.size() + j);
    posterior_column(counts, u, column, same, options, columns.values.data() + columns.values.size() - j);
  };
  if (counts.is_sparse()) {
    const auto stored = counts.stored_configurations();
    for (std::size_t i = 0; i < stored.size(); ++i) store(stored[i], counts.stored_column(i));
  } else {
    for (std::size_t u = 0; u < counts.configurations(); ++u) {
      const auto column = counts.column(config_index(u));
      if (std::any_of(column.begin(), column.end(), [](Count c) { return c != 0; })) store(u, column);
    }
  }
  // The first configuration without rows names the rest in an error.
  std::size_t empty = 0;
  while (empty < columns.configurations.size() && columns.configurations[empty] == empty) ++empty;
  columns.rest.resize(j);
  if (empty < counts.configurations()) {
    const std::vector<Count> zeros(j, 0);
    posterior_column(counts, empty, std::span<const Count>(zeros), same, options, columns.rest.data());
  } else {
    std::fill(columns.rest.begin(), columns.rest.end(), 1.0 / static_cast<double>(j));
  }
  return cpt<double>(counts.child(), counts.parents(), std::move(columns));
}

template <class Count>
cpt<double> table_of(const basic_count_table<Count>& counts, std::vector<double> values) {
  return cpt<double>(counts.child(), counts.parents(), std::move(values));
}

/// Eq. 6 with explicit pseudo-counts α[x, u]; `who` prefixes error messages (names a user's prior).
template <class Count>
cpt<double> estimate_from_pseudo_counts(const basic_count_table<Count>& counts, const std::vector<double>& alpha,
                                        const std::string& who, const estimate_options& options) {
  if (alpha.size() != counts.counts().size()) {
    throw model_error(who + "the pseudo-counts of '" + counts.child().name() + "' need " +
                      std::to_string(counts.counts().size()) + " values, got " + std::to_string(alpha.size()));
  }
  std::vector<double> column_sums(counts.configurations(), 0.0);
  const auto cells = counts.child_cardinality();
  const auto what = who + "a pseudo-count";
  for (std::size_t i = 0; i < alpha.size(); ++i) {
    check_pseudo_count(alpha[i], what.c_str());
    column_sums[i / cells] += alpha[i];
  }
  return table_of(counts, dirichlet_posterior_mean(counts, table_pseudo_counts{alpha, column_sums, cells}, options));
}

template <class Count>
[[nodiscard]] bool stores_sparse(const basic_count_table<Count>& counts, const estimate_options& options) {
  return counts.is_sparse() || (options.sparse && estimate_is_sparse(counts));
}

/// Throws table_too_large when `counts` are sparse: `what` needs a pseudo-count per cell.
template <class Count>
void check_dense(const basic_count_table<Count>& counts, const std::string& what) {
  if (counts.is_sparse()) {
    throw table_too_large(what + " gives a pseudo-count for every cell of '" + counts.child().name() +
                          "', whose table is too large to be dense (" + std::to_string(counts.configurations()) +
                          " parent configurations; docs/limits.md): use a Dirichlet, K2 or BDeu prior");
  }
}

template <class Count>
void check_shape(const basic_count_table<Count>& counts, const cpt<double>& prior) {
  if (prior.child_cardinality() != counts.child_cardinality() || prior.parent_radix() != counts.parent_radix()) {
    throw model_error("the prior table of '" + prior.child().name() + "' (" +
                      std::to_string(prior.child_cardinality()) + " states × " +
                      std::to_string(prior.configurations()) + " configurations) does not match the shape of '" +
                      counts.child().name() + "' (" + std::to_string(counts.child_cardinality()) + " × " +
                      std::to_string(counts.configurations()) + ")");
  }
}

/// Eq. 8 where the counts or the prior table f are sparse: θ = (w·f + M)/(w + M) for every
/// configuration with rows or a column of f of its own, f's rest for all the others.
template <class Count>
cpt<double> sparse_weighted_estimate(const basic_count_table<Count>& counts,
                                     const family_pseudo_counts::weighted_table& p, const estimate_options& options) {
  const auto& f = p.table;
  const double w = p.weight;
  const std::size_t j = counts.child_cardinality();
  const weighted_pseudo_counts weighted{&f, w};
  // The configurations with rows or a column of f: both sorted lists, merged.
  std::vector<std::size_t> seen;
  if (counts.is_sparse()) {
    const auto stored = counts.stored_configurations();
    seen.assign(stored.begin(), stored.end());
  } else {
    for (std::size_t u = 0; u < counts.configurations(); ++u) {
      if (counts.total(config_index(u)) != 0) seen.push_back(u);
    }
  }
  std::vector<std::size_t> configurations;
  std::set_union(seen.begin(), seen.end(), f.stored_configurations().begin(), f.stored_configurations().end(),
                 std::back_inserter(configurations));
  sparse_columns<double> columns;
  columns.configurations = configurations;
  columns.values.resize(configurations.size() * j);
  for (std::size_t i = 0; i < configurations.size(); ++i) {
    const auto u = configurations[i];
    const auto prior = f.column(config_index(u));
    const auto column = counts.column(config_index(u));
    double* out = columns.values.data() + i * j;
    if (w > 0.0 && counts.total(config_index(u)) == 0) {
      std::copy(prior.begin(), prior.end(), out);  // as the dense estimate: f itself
    } else {
      posterior_column(counts, u, column, weighted, options, out);
    }
  }
  if (w > 0.0) {
    PGM_ASSERT(f.is_sparse(), "sparse counts with a dense prior table of their shape");
    columns.rest.assign(f.rest().begin(), f.rest().end());
  } else {
    // w = 0 is MLE: a configuration without rows follows the empty-configuration rule.
    std::size_t empty = 0;
    while (empty < configurations.size() && configurations[empty] == empty) ++empty;
    const std::vector<Count> zeros(j, 0);
    columns.rest.resize(j);
    posterior_column(counts, empty, std::span<const Count>(zeros), uniform_pseudo_counts{0.0, j}, options,
                     columns.rest.data());
  }
  return cpt<double>(counts.child(), counts.parents(), std::move(columns));
}

}  // namespace detail

/// Maximum likelihood, eq. 3: θ[x,u] = M[x,u] / M[u]. The counts may be rows counted or the
/// expected counts of EM.
template <class Count>
[[nodiscard]] cpt<double> estimate_mle(const basic_count_table<Count>& counts, const estimate_options& options = {}) {
  if (detail::stores_sparse(counts, options)) return detail::sparse_dirichlet_estimate(counts, 0.0, options);
  return detail::table_of(counts, detail::dirichlet_posterior_mean(
                                      counts, uniform_pseudo_counts{0.0, counts.child_cardinality()}, options));
}

/// The estimate under any parameter prior (eq. 6; eq. 7/8 for `weighted_prior`).
template <class Count>
[[nodiscard]] cpt<double> estimate(const basic_count_table<Count>& counts, const parameter_prior& prior,
                                   const estimate_options& options = {}) {
  const auto alpha = prior.pseudo_counts(counts.child(), counts.parents());
  if (const auto* uniform = alpha.uniform_alpha()) {
    detail::check_pseudo_count(*uniform, "the Dirichlet pseudo-count alpha");
    if (detail::stores_sparse(counts, options)) return detail::sparse_dirichlet_estimate(counts, *uniform, options);
    return detail::table_of(counts, detail::dirichlet_posterior_mean(
                                        counts, uniform_pseudo_counts{*uniform, counts.child_cardinality()}, options));
  }
  if (const auto* weighted = alpha.weighted()) {
    const auto& f = weighted->table;
    const double w = weighted->weight;
    detail::check_shape(counts, f);
    detail::check_pseudo_count(w, "the prior weight w");
    if (counts.is_sparse() || f.is_sparse()) return detail::sparse_weighted_estimate(counts, *weighted, options);
    auto values = detail::dirichlet_posterior_mean(counts, weighted_pseudo_counts{&f, w}, options);
    // Where M[u] = 0 the formula is f itself; (w·f)/w can differ from f in the last bit.
    const auto prior_values = f.values();
    const auto cells = counts.child_cardinality();
    for (std::size_t u = 0; u < counts.configurations(); ++u) {
      if (w > 0.0 && counts.total(config_index(u)) == 0) {
        std::copy(prior_values.begin() + static_cast<std::ptrdiff_t>(u * cells),
                  prior_values.begin() + static_cast<std::ptrdiff_t>((u + 1) * cells),
                  values.begin() + static_cast<std::ptrdiff_t>(u * cells));
      }
    }
    return detail::table_of(counts, std::move(values));
  }
  const auto who = "the prior '" + std::string(prior.name()) + "'";
  detail::check_dense(counts, who);
  return detail::estimate_from_pseudo_counts(counts, *alpha.cells(), who + ": ", options);
}

}  // namespace pgm
