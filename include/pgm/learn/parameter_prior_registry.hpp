#pragma once
/// \file
/// Parameter priors by name: `make_parameter_prior("dirichlet[alpha=2]")` gives a
/// `parameter_prior`, which `fit_options::prior`, the program's `--prior` and Python's
/// `prior=` all take. The built-in names are bdeu[ess=1] (the Bayesian estimator's default),
/// dirichlet[alpha=1], k2 and none (maximum likelihood).
///
/// A user's prior joins in one line in its own translation unit:
///
///     static const pgm::register_parameter_prior<my_prior> registered("mine", "what it believes");
///
/// where `my_prior` models ParameterPrior and either is default-constructible or declares
/// `static std::vector<pgm::option_declaration> options()` and is constructible from the
/// `const pgm::option_values&` they are read into; `--prior mine[key=value]` then reaches it.

#include <string>
#include <string_view>
#include <utility>

#include "pgm/core/compilation.hpp"
#include "pgm/core/component_registry.hpp"
#include "pgm/learn/parameter_prior.hpp"

namespace pgm {

using parameter_prior_registry = component_registry<parameter_prior>;

/// The prior of the Bayesian estimator when none is named, as bnlearn's "bayes" method has it.
inline constexpr std::string_view default_parameter_prior = "bdeu";

/// The program-wide registry of parameter priors, holding the built-in ones from the start.
[[nodiscard]] PGM_DECL parameter_prior_registry& parameter_priors();

/// The prior `text` chooses ("k2", "bdeu[ess=10]"). Throws unknown_name for an unknown prior
/// or option, model_error for a bad value.
[[nodiscard]] inline parameter_prior make_parameter_prior(std::string_view text) {
  return parameter_priors().make(text);
}

/// Registers a prior type when the program starts:
/// `static const register_parameter_prior<P> r("name", "…");`.
template <ParameterPrior P>
using register_parameter_prior = component_registration<&parameter_priors, P>;

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/parameter_prior_registry.ipp"
#endif
