#pragma once
// The definitions of pgm/core/success_event.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/success_event.hpp"
#include "pgm/core/text.hpp"

namespace pgm {

PGM_DECL success_event default_success_event(const bayesian_network& network) {
  std::vector<std::string> sinks;
  for (std::size_t i = 0; i < network.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    const auto& v = network.variables()[i];
    if (network.graph().children(node).empty() && !network.graph().parents(node).empty() && v.find_state("1")) {
      sinks.push_back(v.name());
    }
  }
  if (sinks.size() == 1) return {sinks.front(), "1"};
  if (sinks.empty()) {
    throw model_error("no variable without children has a state '1'; name the success event, e.g. onTop2=1");
  }
  throw model_error("several variables could be the success variable (" + text::list_for_message(sinks) +
                    "); name one, e.g. " + sinks.front() + "=1");
}

PGM_DECL success_event parse_success_event(std::string_view text, const bayesian_network& network) {
  const auto equals = text.find('=');
  const auto name = text::trim(text.substr(0, equals));
  const auto state = equals == std::string_view::npos ? std::string_view{} : text::trim(text.substr(equals + 1));
  if (name.empty() || state.empty()) {
    throw model_error("the success event '" + std::string(text) + "' is not of the form variable=state");
  }
  const auto& v = network.structure().at(node_of(network, name));
  static_cast<void>(v.state(state));
  return {std::string(name), std::string(state)};
}

}  // namespace pgm
