#pragma once
/// \file
/// The Dirichlet–multinomial family, the one kernel of every Bayesian computation over a child's
/// counts M[x, u] with pseudo-counts α[x, u] (α_u = Σ_x α[x, u]):
///
/// - the posterior mean, eq. 6: θ[x, u] = (α[x, u] + M[x, u]) / (α_u + M[u]), which estimation
///   and EM's M-step use (pgm/learn/estimate.hpp);
/// - the log marginal likelihood, Σ_u [ln Γ(α_u) − ln Γ(α_u + M[u]) + Σ_x (ln Γ(α[x, u] + M[x, u])
///   − ln Γ(α[x, u]))], which is the BDeu and K2 scores (pgm/learn/score.hpp) and the evidence
///   that chooses the prior weight (pgm/transfer/prior_weight.hpp).
///
/// A prior reaches the kernel as a PseudoCounts source: the same α everywhere, a table of them,
/// or the paper's weighted prior w·f.

#include <concepts>
#include <cstddef>
#include <span>

#include "pgm/core/cpt.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/log_gamma_ratio.hpp"

namespace pgm {

/// Pseudo-counts by column: α_u and the column's cells α[x, u], indexed by x.
template <class A>
concept PseudoCounts = requires(const A& alpha, std::size_t u, std::size_t x) {
  { alpha.column(u) } -> std::convertible_to<double>;
  { alpha.cells(u)[x] } -> std::convertible_to<double>;
};

/// The same α in every cell of a child of `states` states: α = 0 is MLE, 1 the K2 prior.
struct uniform_pseudo_counts {
  struct same {
    double alpha;
    double operator[](std::size_t) const noexcept { return alpha; }
  };
  double alpha = 0.0;
  std::size_t states = 0;

  [[nodiscard]] double column(std::size_t) const noexcept { return alpha * static_cast<double>(states); }
  [[nodiscard]] same cells(std::size_t) const noexcept { return {alpha}; }
};

/// α[x, u] given cell by cell (configuration major), with the sums of their columns.
struct table_pseudo_counts {
  std::span<const double> alpha;
  std::span<const double> column_sums;
  std::size_t states = 0;

  [[nodiscard]] double column(std::size_t u) const noexcept { return column_sums[u]; }
  [[nodiscard]] std::span<const double> cells(std::size_t u) const noexcept {
    return alpha.subspan(u * states, states);
  }
};

/// The paper's weighted prior (eq. 7/8), α[x, u] = w·((1 − floor)·f[x|u] + floor/J), with α_u
/// = w exactly as eq. 8 writes the denominator (not the cells' sum, which may differ in the
/// last bit). `floor` mixes in the uniform table, so that a zero in f is no certainty.
struct weighted_pseudo_counts {
  struct scaled {
    std::span<const double> prior;
    double weight;
    double floor;
    double uniform;
    double operator[](std::size_t x) const noexcept { return weight * ((1 - floor) * prior[x] + uniform); }
  };
  const cpt<double>* prior = nullptr;
  double weight = 0.0;
  double floor = 0.0;

  [[nodiscard]] double column(std::size_t) const noexcept { return weight; }
  [[nodiscard]] scaled cells(std::size_t u) const {
    return {prior->column(index_at<config_index>(u)), weight, floor,
            floor / static_cast<double>(prior->child_cardinality())};
  }
};

static_assert(PseudoCounts<uniform_pseudo_counts> && PseudoCounts<table_pseudo_counts> &&
              PseudoCounts<weighted_pseudo_counts>);

/// θ[·, u] of one column of counts, written to `out`; its denominator α_u + M[u] is returned
/// so the caller can refuse an infinite one or a zero (no data and no prior) before using it.
template <class Count, PseudoCounts A>
double dirichlet_posterior_column(std::span<const Count> column, std::size_t u, const A& alpha, double* out) {
  Count total = 0;
  for (auto c : column) total += c;
  const double denominator = alpha.column(u) + static_cast<double>(total);
  const auto cells = alpha.cells(u);
  for (std::size_t x = 0; x < column.size(); ++x) out[x] = (cells[x] + static_cast<double>(column[x])) / denominator;
  return denominator;
}

/// ln P(M | α), the Dirichlet–multinomial log marginal likelihood of the family. Columns
/// without counts add nothing, and neither do cells without counts.
template <class Count, PseudoCounts A>
[[nodiscard]] double dirichlet_log_marginal(const basic_count_table<Count>& counts, const A& alpha) {
  double total = 0.0;
  if constexpr (std::same_as<A, uniform_pseudo_counts>) {
    // One α everywhere: ln Γ(α) and ln Γ(α_u) once for the family.
    const detail::log_gamma_ratio of_alpha(alpha.alpha);
    const detail::log_gamma_ratio of_alpha_u(alpha.column(0));
    counts.for_each_column([&](std::size_t, std::span<const Count> column) {
      Count n_u = 0;
      for (auto m : column) n_u += m;
      if (n_u == 0) return;
      total += -of_alpha_u(static_cast<double>(n_u));
      for (auto m : column) {
        if (m > 0) total += of_alpha(static_cast<double>(m));
      }
    });
  } else {
    counts.for_each_column([&](std::size_t u, std::span<const Count> column) {
      const auto cells = alpha.cells(u);
      double n = 0;
      for (std::size_t x = 0; x < column.size(); ++x) {
        if (column[x] == 0) continue;
        total += detail::log_gamma_ratio(cells[x])(static_cast<double>(column[x]));
        n += static_cast<double>(column[x]);
      }
      if (n > 0) total += -detail::log_gamma_ratio(alpha.column(u))(n);
    });
  }
  return total;
}

}  // namespace pgm
