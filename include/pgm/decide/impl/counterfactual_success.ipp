#pragma once
// The definitions of pgm/decide/counterfactual_success.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/causal/counterfactual.hpp"
#include "pgm/causal/intervention.hpp"
#include "pgm/decide/counterfactual_success.hpp"

namespace pgm {

PGM_DECL std::optional<double> counterfactual_success(const bayesian_network& network, const explanation& why,
                                                      const assignment& planned) {
  intervention carried_out;  // the controllable variables as the plan set them
  intervention changed;      // and as the change would have
  for (const auto& c : why.changes) {
    carried_out[c.variable] = c.from_label;
    if (c.moves()) changed[c.variable] = c.to_label;
  }
  if (changed.empty()) return std::nullopt;
  const auto executed = intervene(network, carried_out);
  evidence seen;
  for (const auto& o : resolve(network, planned)) {
    const auto& v = network.variables()[o.variable.value()];
    seen[v.name()] = v.label(o.state);
  }
  // P(success* | plan, failed) = Σ over the failing states y' of P(success*, y' | plan) / P(failed | plan).
  const auto& success = network.at(why.success_variable);
  const std::string asked[] = {why.success_variable};
  double joint = 0;
  double failed = 0;
  for (const auto& state : success.states()) {
    if (state == why.success_state) continue;
    seen[why.success_variable] = state;
    try {
      const auto answer = monotone_counterfactual_query(executed, asked, seen, changed);
      joint += answer.probability({why.success_state}) * answer.evidence_probability;
      failed += answer.evidence_probability;
    } catch (const impossible_evidence&) {
      // The plan cannot fail this way.
    }
  }
  if (!(failed > 0)) return std::nullopt;
  return joint / failed;
}

}  // namespace pgm
