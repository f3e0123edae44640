#pragma once
/// \file
/// Parameter priors for Bayesian estimation (eq. 6): each is a Dirichlet prior given by its
/// pseudo-counts α[x, u]. The paper's weighted prior (eq. 7/8) sets α[x, u] = w·f(θ'_{x|u'})
/// from a prior table f that a transfer strategy produced in the target node's shape.
///
/// A prior of the user's own is any type that models `ParameterPrior` — a `name()` and the
/// pseudo-counts of a family from its variables — and goes wherever a `parameter_prior` does
/// (`fit_options::prior`, `fit_options::node_priors`, `estimate`), with nothing to derive from.

#include <cmath>
#include <concepts>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/variable.hpp"

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

namespace detail {

/// A prior names itself, for error messages.
template <class P>
concept NamedPrior = requires(const P& p) {
  { p.name() } -> std::convertible_to<std::string_view>;
};

/// A prior gives the pseudo-counts α[x, u] of a family from its variables alone (a prior does
/// not look at the data), laid out like the family's cpt: configuration major, parents
/// numbered by `mixed_radix` with the last parent fastest.
template <class P>
concept GivesPseudoCounts = requires(const P& p, const variable& child, const std::vector<variable>& parents) {
  { p.pseudo_counts(child, parents) } -> std::same_as<std::vector<double>>;
};

}  // namespace detail

template <class P>
concept ParameterPrior = std::copy_constructible<P> && detail::NamedPrior<P> && detail::GivesPseudoCounts<P>;

/// A user's prior, type-erased; it models ParameterPrior itself.
class any_parameter_prior {
 public:
  // Whether P is this type is asked first: checking ParameterPrior<any_parameter_prior> asks
  // whether it is copy constructible, which would otherwise ask this constraint again (clang
  // recurses without end).
  template <class P>
  requires(!std::same_as<P, any_parameter_prior> && ParameterPrior<P>)
      any_parameter_prior(P prior)  // NOLINT(google-explicit-constructor): `options.prior = mine{}`
      : name_(prior.name()),
        pseudo_counts_([p = std::move(prior)](const variable& child, const std::vector<variable>& parents) {
          return p.pseudo_counts(child, parents);
        }) {}

  [[nodiscard]] std::string_view name() const noexcept { return name_; }
  [[nodiscard]] std::vector<double> pseudo_counts(const variable& child, const std::vector<variable>& parents) const {
    return pseudo_counts_(child, parents);
  }

 private:
  std::string name_;
  std::function<std::vector<double>(const variable&, const std::vector<variable>&)> pseudo_counts_;
};

static_assert(ParameterPrior<any_parameter_prior>);

using parameter_prior = std::variant<no_prior, dirichlet_prior, k2_prior, bdeu_prior, pseudo_counts_prior,
                                     weighted_prior, any_parameter_prior>;

namespace detail {

PGM_DECL void check_pseudo_count(double value, const char* what);

}  // namespace detail

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/parameter_prior.ipp"
#endif
