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

#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/detail/text.hpp"
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

[[nodiscard]] inline std::string to_string(score_type type) {
  switch (type) {
    case score_type::loglik:
      return "loglik";
    case score_type::aic:
      return "aic";
    case score_type::bic:
      return "bic";
    case score_type::bdeu:
      return "bdeu";
    case score_type::k2:
      return "k2";
  }
  return "?";
}

inline constexpr std::array score_types{score_type::bic, score_type::aic, score_type::bdeu, score_type::k2,
                                        score_type::loglik};

/// The scores' names, and bnlearn's "bde" for bdeu: what parse_score_type and the command
/// line accept.
[[nodiscard]] inline std::vector<std::string> known_score_types() {
  auto known = names_of(score_types);
  known.emplace_back("bde");
  return known;
}

/// "bic", "aic", "bdeu" (or bnlearn's "bde"), "k2", "loglik"; throws unknown_name otherwise.
[[nodiscard]] inline score_type parse_score_type(std::string_view text) {
  for (auto type : score_types) {
    if (text == to_string(type)) return type;
  }
  if (text == "bde") return score_type::bdeu;
  throw unknown_name("score", std::string(text), known_score_types());
}

/// Throws model_error for an iss or k that is not a finite positive number.
inline void check_score_choice(const score_choice& choice) {
  if (!(choice.iss > 0.0) || !std::isfinite(choice.iss)) {
    throw model_error("the imaginary sample size (iss) must be a finite number > 0, got " +
                      detail::format_short(choice.iss));
  }
  if (!(choice.aic_k >= 0.0) || !std::isfinite(choice.aic_k)) {
    throw model_error("the AIC penalty k must be a finite number >= 0, got " + detail::format_short(choice.aic_k));
  }
}

/// The log-likelihood term sum_{x,u} M[x,u] log(M[x,u] / N_u) of a family at its MLE.
[[nodiscard]] inline double family_loglik(const count_table& counts) {
  double total = 0.0;
  for (std::size_t u = 0; u < counts.configurations(); ++u) {
    const auto column = counts.column(config_index(static_cast<config_index::rep>(u)));
    count_table::count_type n_u = 0;
    for (auto m : column) n_u += m;
    if (n_u == 0) continue;
    const double log_n_u = std::log(static_cast<double>(n_u));
    for (auto m : column) {
      if (m > 0) total += static_cast<double>(m) * (std::log(static_cast<double>(m)) - log_n_u);
    }
  }
  return total;
}

/// The free parameters (r - 1) q of a family.
[[nodiscard]] inline double family_parameters(const count_table& counts) {
  return static_cast<double>(counts.child_cardinality() - 1) * static_cast<double>(counts.configurations());
}

/// The log marginal likelihood of a family under a Dirichlet prior of `alpha` per cell.
[[nodiscard]] inline double family_dirichlet(const count_table& counts, double alpha) {
  const double alpha_u = alpha * static_cast<double>(counts.child_cardinality());
  const double lgamma_alpha = boost::math::lgamma(alpha);
  const double lgamma_alpha_u = boost::math::lgamma(alpha_u);
  double total = 0.0;
  for (std::size_t u = 0; u < counts.configurations(); ++u) {
    const auto column = counts.column(config_index(static_cast<config_index::rep>(u)));
    count_table::count_type n_u = 0;
    for (auto m : column) n_u += m;
    if (n_u == 0) continue;  // an unseen configuration contributes lgamma(a_u) - lgamma(a_u) = 0
    total += lgamma_alpha_u - boost::math::lgamma(alpha_u + static_cast<double>(n_u));
    for (auto m : column) {
      if (m > 0) total += boost::math::lgamma(alpha + static_cast<double>(m)) - lgamma_alpha;
    }
  }
  return total;
}

/// A family's term of the score; bic's n is the rows the family was counted over (all of them
/// for complete data).
[[nodiscard]] inline double family_score(const count_table& counts, const score_choice& choice) {
  switch (choice.type) {
    case score_type::loglik:
      return family_loglik(counts);
    case score_type::aic:
      return family_loglik(counts) - choice.aic_k * family_parameters(counts);
    case score_type::bic: {
      const auto rows = static_cast<double>(counts.total());
      const double penalty = rows > 0 ? std::log(rows) / 2.0 : 0.0;
      return family_loglik(counts) - penalty * family_parameters(counts);
    }
    case score_type::bdeu:
      return family_dirichlet(counts, choice.iss / (static_cast<double>(counts.child_cardinality()) *
                                                    static_cast<double>(counts.configurations())));
    case score_type::k2:
      return family_dirichlet(counts, 1.0);
  }
  return 0.0;
}

}  // namespace pgm
