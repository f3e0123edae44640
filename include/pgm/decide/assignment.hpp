#pragma once
/// \file
/// A planned assignment of network variables: per variable a state label or, for a variable
/// discretized into intervals, a number in its units — binned with the variable's saved edges
/// by the discretizer's rule (left-closed intervals, values outside the range in the outer
/// bins). Parsed from text such as "xOff1=0.3,yOff1=-1.2,colour=Red".

#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

/// A state label, or a value in an interval variable's units.
using planned_value = std::variant<std::string, double>;

/// Planned values by variable name.
using assignment = std::map<std::string, planned_value, std::less<>>;

/// The state `value` selects of `v`. Throws model_error for an unknown label, a value that is
/// not finite, or a number given for a variable without interval edges.
[[nodiscard]] inline state_index state_of(const variable& v, const planned_value& value) {
  if (const auto* label = std::get_if<std::string>(&value)) return v.state(*label);
  const double number = std::get<double>(value);
  if (!std::isfinite(number)) {
    throw model_error("'" + v.name() + "': " + detail::format_double(number) + " is not a finite number");
  }
  if (!v.has_intervals()) {
    throw model_error("'" + v.name() + "' has no interval edges, so the number " + detail::format_short(number) +
                      " cannot be binned; give one of its states (" + detail::list_for_message(v.states()) + ")");
  }
  return v.bin(number);
}

/// The observations an assignment makes, checked against the network.
[[nodiscard]] inline std::vector<observation> resolve(const bayesian_network& network, const assignment& planned) {
  std::vector<observation> result;
  result.reserve(planned.size());
  for (const auto& [name, value] : planned) {
    const auto id = node_of(network, name);
    result.push_back({id, state_of(network.at(name), value)});
  }
  return result;
}

/// The planned value `text` gives `v`: a number when `v` has interval edges and the text reads
/// as one (a state label then needs a leading '@', as in "@2"); otherwise a state label — or,
/// when it is no label of `v` but reads as a number, that number (which state_of rejects with a
/// message saying why).
[[nodiscard]] inline planned_value planned_value_of(const variable& v, std::string_view text) {
  if (!text.empty() && text.front() == '@') return std::string(text.substr(1));
  if (const auto number = detail::parse_double(text); number && (v.has_intervals() || !v.find_state(text))) {
    return *number;
  }
  return std::string(text);
}

/// Parses "name=value,…", each value by planned_value_of ("xOff1=0.3", "xOff1=@2"). Throws
/// model_error for a malformed piece, an unknown or repeated variable.
[[nodiscard]] inline assignment parse_assignment(std::string_view text, const bayesian_network& network) {
  assignment result;
  for (const auto& piece : detail::split(text, ',')) {
    const auto equals = piece.find('=');
    const auto name =
        equals == std::string::npos ? std::string_view{} : detail::trim(std::string_view(piece).substr(0, equals));
    const auto value =
        equals == std::string::npos ? std::string_view{} : detail::trim(std::string_view(piece).substr(equals + 1));
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
