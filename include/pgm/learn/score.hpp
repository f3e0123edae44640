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
/// docs/structure-learning.md says how pgmpy's scores differ.

#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/learn/log_gamma_ratio.hpp"
#include "pgm/learn/sufficient_statistics.hpp"

namespace pgm {

enum class score_type { loglik, aic, bic, bdeu, k2 };

struct score_choice {
  score_type type = score_type::bic;
  /// The imaginary (equivalent) sample size of bdeu.
  double iss = 1.0;
  /// The penalty per free parameter of aic.
  double aic_k = 1.0;
};

[[nodiscard]] PGM_DECL std::string to_string(score_type type);

inline constexpr std::array score_types{score_type::bic, score_type::aic, score_type::bdeu, score_type::k2,
                                        score_type::loglik};

/// The scores' names, and bnlearn's "bde" for bdeu: what parse_score_type and the command
/// line accept.
[[nodiscard]] PGM_DECL std::vector<std::string> known_score_types();

/// "bic", "aic", "bdeu" (or bnlearn's "bde"), "k2", "loglik"; throws unknown_name otherwise.
[[nodiscard]] PGM_DECL score_type parse_score_type(std::string_view text);

/// Throws model_error for an iss or k that is not a finite positive number.
PGM_DECL void check_score_choice(const score_choice& choice);

/// The log-likelihood term sum_{x,u} M[x,u] log(M[x,u] / N_u) of a family at its MLE.
[[nodiscard]] PGM_DECL double family_loglik(const count_table& counts);

/// The free parameters (r - 1) q of a family.
[[nodiscard]] inline double family_parameters(const count_table& counts) {
  return static_cast<double>(counts.child_cardinality() - 1) * static_cast<double>(counts.configurations());
}

/// The log marginal likelihood of a family under a Dirichlet prior of `alpha` per cell.
[[nodiscard]] PGM_DECL double family_dirichlet(const count_table& counts, double alpha);

/// A family's term of the score; bic's n is the rows the family was counted over (all of them
/// for complete data).
[[nodiscard]] PGM_DECL double family_score(const count_table& counts, const score_choice& choice);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/score.ipp"
#endif
