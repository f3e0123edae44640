#pragma once
/// \file
/// Network scores for structure learning, as R bnlearn's `score()` defines them (larger is
/// better): a node's term depends only on its family's counts M[x, u], so a network's score is
/// the sum of its families' terms. With r states of the child, q parent configurations (every
/// combination of the parents' states, seen or not), N_u = sum_x M[x, u] and n the rows counted:
///
///   loglik = sum_{x,u} M[x,u] log(M[x,u] / N_u)
///   aic    = loglik - k (r - 1) q            (k = 1, bnlearn's default)
///   bic    = loglik - (log n / 2) (r - 1) q
///   bdeu   = sum_u [lgamma(a_u) - lgamma(a_u + N_u) + sum_x lgamma(a + M[x,u]) - lgamma(a)],
///            a = iss / (r q), a_u = r a = iss / q        (bnlearn's "bde", iss 1 by default)
///   k2     = the same with a = 1 per cell: a_u = r
///
/// Each is a FamilyScore; pgm/learn/score_registry.hpp gives them their names and options.
/// docs/structure-learning.md says how pgmpy's scores differ.

#include <cmath>
#include <concepts>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/component_options.hpp"
#include "pgm/data/sufficient_statistics.hpp"

namespace pgm {

/// A decomposable score: the term of one family, from its counts alone (larger is better). A
/// search calls it from several threads at once, so it must not change when called.
template <class S>
concept FamilyScore = std::copy_constructible<S> && requires(const S& score, const count_table& counts) {
  { score(counts) } -> std::convertible_to<double>;
};

/// The log-likelihood term sum_{x,u} M[x,u] log(M[x,u] / N_u) of a family at its MLE.
[[nodiscard]] PGM_DECL double family_loglik(const count_table& counts);

/// The free parameters (r - 1) q of a family.
[[nodiscard]] inline double family_parameters(const count_table& counts) {
  return static_cast<double>(counts.child_cardinality() - 1) * static_cast<double>(counts.configurations());
}

/// The log marginal likelihood of a family under a Dirichlet prior of `alpha` per cell.
[[nodiscard]] PGM_DECL double family_dirichlet(const count_table& counts, double alpha);

struct loglik_score {
  [[nodiscard]] double operator()(const count_table& counts) const { return family_loglik(counts); }
};

struct aic_score {
  [[nodiscard]] static std::vector<option_declaration> options() {
    return {number_option("k", 1.0, "the penalty per free parameter").at_least(0.0)};
  }
  explicit aic_score(const option_values& options) : k(options.number("k")) {}
  explicit aic_score(double penalty) : k(penalty) {}
  [[nodiscard]] double operator()(const count_table& counts) const {
    return family_loglik(counts) - k * family_parameters(counts);
  }
  double k;
};

/// n is the rows the family was counted over (all of them for complete data).
struct bic_score {
  [[nodiscard]] double operator()(const count_table& counts) const {
    const auto rows = static_cast<double>(counts.total());
    const double penalty = rows > 0 ? std::log(rows) / 2.0 : 0.0;
    return family_loglik(counts) - penalty * family_parameters(counts);
  }
};

struct bdeu_score {
  [[nodiscard]] static std::vector<option_declaration> options() {
    return {number_option("iss", 1.0, "the imaginary (equivalent) sample size").greater_than(0.0)};
  }
  explicit bdeu_score(const option_values& options) : iss(options.number("iss")) {}
  explicit bdeu_score(double imaginary_sample_size) : iss(imaginary_sample_size) {}
  [[nodiscard]] double operator()(const count_table& counts) const {
    return family_dirichlet(
        counts, iss / (static_cast<double>(counts.child_cardinality()) * static_cast<double>(counts.configurations())));
  }
  double iss;
};

struct k2_score {
  [[nodiscard]] double operator()(const count_table& counts) const { return family_dirichlet(counts, 1.0); }
};

static_assert(FamilyScore<loglik_score> && FamilyScore<aic_score> && FamilyScore<bic_score> &&
              FamilyScore<bdeu_score> && FamilyScore<k2_score>);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/score.ipp"
#endif
