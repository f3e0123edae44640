#pragma once
/// \file
/// "Was it the cause?" on a causal network, where counterfactuals are not identified: bounds on
/// the probabilities of necessity and sufficiency (Tian & Pearl, "Probabilities of causation:
/// bounds and identification", Annals of Mathematics and Artificial Intelligence 28, 2000),
/// from the network's observational distribution P(X, Y) and its interventional one P(Y | do(X)).
///
/// | quantity | reads | e.g. |
/// |---|---|---|
/// | PN = P(y'_{x'} \| x, y) | necessity: had X been x', would Y not have been y? | the tower fell with xOff1 = 4:
/// would it have stood at 2? | | PS = P(y_x \| x', y') | sufficiency: had X been x, would Y have been y? | | | PNS =
/// P(y_x, y'_{x'}) | both | |
///
/// Y = y is one state of the effect against all others (y'). A cause with more than two states
/// is compared at x and x' only: the bounds then use the consistency of the other states too
/// (they reduce to Tian & Pearl's for two), and hold for every structural model that agrees with
/// the network (tests/causal/probability_of_causation_test.cpp samples such models).

#include <string>
#include <string_view>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/inference/query.hpp"

namespace pgm {

/// The probabilities the bounds need, all given the same evidence.
struct causation_terms {
  double cause_effect = 0;           ///< P(x, y)
  double cause_no_effect = 0;        ///< P(x, y')
  double alternative_effect = 0;     ///< P(x', y)
  double alternative_no_effect = 0;  ///< P(x', y')
  double effect_if_cause = 0;        ///< P(y_x) = P(y | do(x))
  double effect_if_alternative = 0;  ///< P(y_{x'}) = P(y | do(x'))
  bool binary_cause = true;          ///< X has no state but x and x'
};

struct causation_bounds {
  double pn_lower = 0;
  double pn_upper = 1;
  double ps_lower = 0;
  double ps_upper = 1;
  double pns_lower = 0;
  double pns_upper = 1;
};

/// Tian & Pearl's bounds from the terms. Throws model_error when P(x, y) = 0 (PN is about a case
/// where both happened) or P(x', y') = 0 (PS, where neither did).
[[nodiscard]] PGM_DECL causation_bounds bound_causation(const causation_terms& terms);

/// What X = `cause`… asks of a network: its terms from exact inference, given `observed`
/// (variables that X does not influence). Throws model_error for unknown names or states, x = x',
/// a cause that is the effect, or evidence on X, Y or a descendant of X.
[[nodiscard]] PGM_DECL causation_terms causation_terms_of(const bayesian_network& network, std::string_view cause,
                                                          std::string_view cause_state, std::string_view alternative,
                                                          std::string_view effect, std::string_view effect_state,
                                                          const evidence& observed = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/causal/impl/probability_of_causation.ipp"
#endif
