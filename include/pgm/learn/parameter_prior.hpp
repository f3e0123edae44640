#pragma once
/// \file
/// Parameter priors for Bayesian estimation (eq. 6): each is a Dirichlet prior given by its
/// pseudo-counts α[x, u]. The paper's weighted prior (eq. 7/8) sets α[x, u] = w·f(θ'_{x|u'})
/// from a prior table f that a transfer strategy produced in the target node's shape.

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"

namespace pgm {

/// No prior: maximum likelihood (eq. 3).
struct no_prior {
  friend bool operator==(const no_prior&, const no_prior&) = default;
};

/// The same pseudo-count α in every cell (α = 1 is the K2 prior, α = 0 is MLE).
struct dirichlet_prior {
  double alpha = 1.0;
  friend bool operator==(const dirichlet_prior&, const dirichlet_prior&) = default;
};

/// Cooper and Herskovits' K2 prior: α = 1 in every cell.
struct k2_prior {
  friend bool operator==(const k2_prior&, const k2_prior&) = default;
};

/// Bayesian Dirichlet equivalent uniform: α = N' / (J·|Val(Pa)|) for an equivalent sample
/// size N'.
struct bdeu_prior {
  double equivalent_sample_size = 1.0;
  friend bool operator==(const bdeu_prior&, const bdeu_prior&) = default;
};

/// Explicit pseudo-counts α[x, u], laid out like a cpt (configuration major).
struct pseudo_counts_prior {
  std::vector<double> alpha;
  friend bool operator==(const pseudo_counts_prior&, const pseudo_counts_prior&) = default;
};

/// The paper's weighted prior (eq. 7/8): θ = (w·f + M[x,u]) / (w + M[u]) for a prior table f
/// of the target node's shape and a weight w ≥ 0. With w = 0 it is MLE; where M[u] = 0 it is
/// f itself.
struct weighted_prior {
  cpt<double> prior;
  double weight = 0.0;
  friend bool operator==(const weighted_prior&, const weighted_prior&) = default;
};

using parameter_prior =
    std::variant<no_prior, dirichlet_prior, k2_prior, bdeu_prior, pseudo_counts_prior, weighted_prior>;

namespace detail {

inline void check_pseudo_count(double value, const char* what) {
  if (!std::isfinite(value) || value < 0.0) {
    throw model_error(std::string(what) + " must be a finite number ≥ 0, got " +
                      format_double(value));
  }
}

}  // namespace detail

}  // namespace pgm
