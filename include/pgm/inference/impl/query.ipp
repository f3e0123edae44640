#pragma once
// The definitions of pgm/inference/query.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/query.hpp"

namespace pgm {

PGM_DECL std::size_t posterior::index_of(std::span<const std::string> states) const {
  if (states.size() != variables.size()) {
    throw model_error("the posterior is over " + std::to_string(variables.size()) + " variables, got " +
                      std::to_string(states.size()) + " states");
  }
  std::size_t index = 0;
  for (std::size_t i = 0; i < states.size(); ++i) {
    index = index * variables[i].cardinality() + variables[i].state(states[i]).value();
  }
  return index;
}

PGM_DECL evidence mpe_result::assignment() const {
  evidence result;
  for (std::size_t i = 0; i < variables.size(); ++i) {
    result.emplace(variables[i].name(), variables[i].states()[states[i].value()]);
  }
  return result;
}

}  // namespace pgm

namespace pgm::detail {

PGM_DECL std::string describe(const std::vector<variable>& variables, const evidence_set& observed) {
  std::string text;
  for (const auto& o : observed.intervened) {
    const auto& v = variables[o.variable.value()];
    text += (text.empty() ? "do(" : ", do(") + v.name() + "=" + v.states()[o.state.value()] + ")";
  }
  for (const auto& o : observed.hard) {
    const auto& v = variables[o.variable.value()];
    text += (text.empty() ? "" : ", ") + v.name() + "=" + v.states()[o.state.value()];
  }
  for (const auto& l : observed.soft) {
    std::vector<std::string> weights;
    for (double w : l.weights) weights.push_back(text::format_short(w));
    text += (text.empty() ? "" : ", ") + variables[l.variable.value()].name() + "~" + text::join(weights, ":");
  }
  return text;
}

PGM_DECL std::vector<double> checked_likelihood(const variable& v, const std::vector<double>& weights) {
  const auto& name = v.name();
  if (weights.size() != v.cardinality()) {
    throw model_error("the soft evidence on '" + name + "' has " + std::to_string(weights.size()) + " weights, but '" +
                      name + "' has " + std::to_string(v.cardinality()) + " states (" +
                      text::list_for_message(v.states()) + ")");
  }
  bool positive = false;
  for (double w : weights) {
    if (!std::isfinite(w) || w < 0.0) {
      throw model_error("the soft evidence on '" + name + "' has the weight " + text::format_double(w) +
                        "; likelihoods are finite and not negative");
    }
    positive = positive || w > 0.0;
  }
  if (!positive) throw model_error("the soft evidence on '" + name + "' gives every state weight 0");
  return weights;
}

}  // namespace pgm::detail
