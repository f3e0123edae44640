#pragma once
// The definitions of pgm/learn/score.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/score.hpp"

namespace pgm {

PGM_DECL std::string to_string(score_type type) {
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

PGM_DECL std::vector<std::string> known_score_types() {
  auto known = names_of(score_types);
  known.emplace_back("bde");
  return known;
}

PGM_DECL score_type parse_score_type(std::string_view text) {
  for (auto type : score_types) {
    if (text == to_string(type)) return type;
  }
  if (text == "bde") return score_type::bdeu;
  throw unknown_name("score", std::string(text), known_score_types());
}

PGM_DECL void check_score_choice(const score_choice& choice) {
  if (!(choice.iss > 0.0) || !std::isfinite(choice.iss)) {
    throw model_error("the imaginary sample size (iss) must be a finite number > 0, got " +
                      detail::format_short(choice.iss));
  }
  if (!(choice.aic_k >= 0.0) || !std::isfinite(choice.aic_k)) {
    throw model_error("the AIC penalty k must be a finite number >= 0, got " + detail::format_short(choice.aic_k));
  }
}

PGM_DECL double family_loglik(const count_table& counts) {
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

PGM_DECL double family_dirichlet(const count_table& counts, double alpha) {
  const detail::log_gamma_ratio of_alpha(alpha);
  const detail::log_gamma_ratio of_alpha_u(alpha * static_cast<double>(counts.child_cardinality()));
  double total = 0.0;
  for (std::size_t u = 0; u < counts.configurations(); ++u) {
    const auto column = counts.column(config_index(static_cast<config_index::rep>(u)));
    count_table::count_type n_u = 0;
    for (auto m : column) n_u += m;
    if (n_u == 0) continue;  // an unseen configuration contributes lgamma(a_u) - lgamma(a_u) = 0
    total += -of_alpha_u(static_cast<double>(n_u));
    for (auto m : column) {
      if (m > 0) total += of_alpha(static_cast<double>(m));
    }
  }
  return total;
}

PGM_DECL double family_score(const count_table& counts, const score_choice& choice) {
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
