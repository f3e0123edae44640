#pragma once
// The definitions of pgm/causal/probability_of_causation.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <string>

#include "pgm/causal/intervention.hpp"
#include "pgm/causal/probability_of_causation.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

PGM_DECL causation_bounds bound_causation(const causation_terms& t) {
  if (!(t.cause_effect > 0)) {
    throw model_error(
        "P(cause, effect) is 0: the network has no case where both happened, so there is nothing to explain");
  }
  if (!(t.alternative_no_effect > 0)) {
    throw model_error("P(alternative, no effect) is 0: the network has no case where neither happened");
  }
  const double y_x = t.effect_if_cause;
  const double y_alt = t.effect_if_alternative;
  // P(X is neither x nor x'): each such case may count towards PNS in full.
  const double elsewhere =
      std::max(0.0, 1 - t.cause_effect - t.cause_no_effect - t.alternative_effect - t.alternative_no_effect);
  causation_bounds b;
  // P(x, y) + P(x', y) is Tian & Pearl's P(y) when X has two states; P(x, y') + P(x', y') − 1
  // their −P(y). Each term below is theirs with that substitution.
  b.pns_lower = std::max({0.0, y_x - y_alt, t.cause_effect + t.alternative_effect - y_alt,
                          y_x + t.cause_no_effect + t.alternative_no_effect - 1});
  b.pns_upper = std::min({y_x, 1 - y_alt, t.cause_effect + t.alternative_no_effect + elsewhere});
  if (t.binary_cause) {
    b.pns_upper = std::min(b.pns_upper, y_x - y_alt + t.cause_no_effect + t.alternative_effect);
  }
  b.pn_lower = std::max(0.0, (t.cause_effect + t.alternative_effect - y_alt) / t.cause_effect);
  b.pn_upper = std::min(1.0, (1 - y_alt - t.alternative_no_effect) / t.cause_effect);
  b.ps_lower = std::max(0.0, (y_x + t.cause_no_effect + t.alternative_no_effect - 1) / t.alternative_no_effect);
  b.ps_upper = std::min(1.0, (y_x - t.cause_effect) / t.alternative_no_effect);
  return b;
}

PGM_DECL causation_terms causation_terms_of(const bayesian_network& network, std::string_view cause,
                                            std::string_view cause_state, std::string_view alternative,
                                            std::string_view effect, std::string_view effect_state,
                                            const evidence& observed) {
  const auto& x = network.at(cause);
  const auto& y = network.at(effect);
  const auto x_state = x.state(cause_state);
  const auto alternative_state = x.state(alternative);
  const auto y_state = y.state(effect_state);
  if (x.name() == y.name()) throw model_error("the cause '" + x.name() + "' is also the effect");
  if (x_state == alternative_state) {
    throw model_error("the alternative '" + std::string(alternative) + "' is the state the cause took");
  }
  for (const auto& [name, state] : observed) {
    const auto id = network.id(name);
    if (name == x.name() || name == y.name() || !network.graph().path_between(network.id(cause), id).empty()) {
      throw model_error("evidence on '" + name + "', which the cause '" + x.name() +
                        "' influences: the bounds take evidence on what comes before the cause only");
    }
  }
  const std::string names[] = {x.name(), y.name()};
  const auto joint = query(network, names, observed);
  causation_terms t;
  for (std::size_t s = 0; s < y.cardinality(); ++s) {
    const auto& label = y.states()[s];
    const double at_cause = joint.probability({x.states()[x_state.value()], label});
    const double at_alternative = joint.probability({x.states()[alternative_state.value()], label});
    (s == y_state.value() ? t.cause_effect : t.cause_no_effect) += at_cause;
    (s == y_state.value() ? t.alternative_effect : t.alternative_no_effect) += at_alternative;
  }
  const auto effect_given_do = [&](std::string_view state) {
    const auto intervened = intervene(network, {{x.name(), std::string(state)}});
    return query(intervened, {y.name()}, observed).probability({y.states()[y_state.value()]});
  };
  t.effect_if_cause = effect_given_do(cause_state);
  t.effect_if_alternative = effect_given_do(alternative);
  t.binary_cause = x.cardinality() == 2;
  return t;
}

}  // namespace pgm
