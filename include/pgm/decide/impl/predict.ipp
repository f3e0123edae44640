#pragma once
// The definitions of pgm/decide/predict.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/decide/predict.hpp"

namespace pgm {

PGM_DECL success_event default_success_event(const bayesian_network& network) {
  std::vector<std::string> sinks;
  for (std::size_t i = 0; i < network.size(); ++i) {
    const variable_id node(static_cast<variable_id::rep>(i));
    const auto& v = network.variables()[i];
    if (network.graph().children(node).empty() && !network.graph().parents(node).empty() && v.find_state("1")) {
      sinks.push_back(v.name());
    }
  }
  if (sinks.size() == 1) return {sinks.front(), "1"};
  if (sinks.empty()) {
    throw model_error("no variable without children has a state '1'; name the success event, e.g. onTop2=1");
  }
  throw model_error("several variables could be the success variable (" + detail::list_for_message(sinks) +
                    "); name one, e.g. " + sinks.front() + "=1");
}

PGM_DECL success_event parse_success_event(std::string_view text, const bayesian_network& network) {
  const auto equals = text.find('=');
  const auto name = detail::trim(text.substr(0, equals));
  const auto state = equals == std::string_view::npos ? std::string_view{} : detail::trim(text.substr(equals + 1));
  if (name.empty() || state.empty()) {
    throw model_error("the success event '" + std::string(text) + "' is not of the form variable=state");
  }
  const auto& v = network.structure().at(node_of(network, name));
  static_cast<void>(v.state(state));
  return {std::string(name), std::string(state)};
}

PGM_DECL std::vector<std::string> unassigned_parents(const bayesian_network& network, const success_event& success,
                                                     const assignment& planned) {
  std::vector<std::string> missing;
  for (const auto& parent : network.table(node_of(network, success.variable)).parents()) {
    if (!planned.contains(parent.name())) missing.push_back(parent.name());
  }
  return missing;
}

}  // namespace pgm

namespace pgm::detail {

PGM_DECL void throw_missing(const success_event& success, const std::vector<std::string>& missing) {
  throw model_error("no value is given for " + std::string(missing.size() == 1 ? "" : "the parents ") +
                    list_for_message(missing) + (missing.size() == 1 ? ", a parent" : "") + " of '" + success.variable +
                    "'; assign " + (missing.size() == 1 ? "it" : "them") + " or ask to marginalize");
}

PGM_DECL bool observes_descendant(const bayesian_network& network, variable_id node,
                                  std::span<const observation> observed) {
  std::vector<bool> below(network.size(), false);
  std::vector<variable_id> stack = network.graph().children(node);
  while (!stack.empty()) {
    const auto n = stack.back();
    stack.pop_back();
    if (below[n.value()]) continue;
    below[n.value()] = true;
    for (auto c : network.graph().children(n)) stack.push_back(c);
  }
  return std::any_of(observed.begin(), observed.end(), [&](const observation& o) { return below[o.variable.value()]; });
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL double predict_success(const bayesian_network& network, const success_event& success,
                                const assignment& planned, const prediction_options& options) {
  variable_elimination engine(borrowed(network), {options.heuristic});
  return predict_success(engine, success, planned, options);
}

}  // namespace pgm
