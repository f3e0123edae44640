#pragma once
// The definitions of pgm/decide/assignment.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/decide/assignment.hpp"

namespace pgm {

PGM_DECL state_index state_of(const variable& v, const planned_value& value) {
  if (const auto* label = std::get_if<std::string>(&value)) return v.state(*label);
  const double number = std::get<double>(value);
  if (!std::isfinite(number)) {
    throw model_error("'" + v.name() + "': " + text::format_double(number) + " is not a finite number");
  }
  if (!v.has_intervals()) {
    throw model_error("'" + v.name() + "' has no interval edges, so the number " + text::format_short(number) +
                      " cannot be binned; give one of its states (" + text::list_for_message(v.states()) + ")");
  }
  return v.bin(number);
}

PGM_DECL std::vector<observation> resolve(const bayesian_network& network, const assignment& planned) {
  std::vector<observation> result;
  result.reserve(planned.size());
  for (const auto& [name, value] : planned) {
    const auto id = node_of(network, name);
    result.push_back({id, state_of(network.at(name), value)});
  }
  return result;
}

PGM_DECL planned_value planned_value_of(const variable& v, std::string_view text) {
  if (!text.empty() && text.front() == '@') return std::string(text.substr(1));
  if (const auto number = text::parse_double(text); number && (v.has_intervals() || !v.find_state(text))) {
    return *number;
  }
  return std::string(text);
}

PGM_DECL assignment parse_assignment(std::string_view text, const bayesian_network& network) {
  assignment result;
  for (const auto& piece : text::split(text, ',')) {
    const auto equals = piece.find('=');
    const auto name =
        equals == std::string::npos ? std::string_view{} : text::trim(std::string_view(piece).substr(0, equals));
    const auto value =
        equals == std::string::npos ? std::string_view{} : text::trim(std::string_view(piece).substr(equals + 1));
    if (name.empty() || value.empty()) throw model_error("'" + piece + "' is not of the form name=value");
    const auto& v = network.structure().at(node_of(network, name));
    if (!result.emplace(std::string(name), planned_value_of(v, value)).second) {
      throw model_error("'" + std::string(name) + "' is assigned twice");
    }
  }
  if (result.empty()) throw model_error("the assignment is empty");
  return result;
}

}  // namespace pgm
