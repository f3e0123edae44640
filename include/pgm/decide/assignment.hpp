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
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

/// A state label, or a value in an interval variable's units.
using planned_value = std::variant<std::string, double>;

/// Planned values by variable name.
using assignment = std::map<std::string, planned_value, std::less<>>;

/// The state `value` selects of `v`. Throws model_error for an unknown label, a value that is
/// not finite, or a number given for a variable without interval edges.
[[nodiscard]] PGM_DECL state_index state_of(const variable& v, const planned_value& value);

/// The observations an assignment makes, checked against the network.
[[nodiscard]] PGM_DECL std::vector<observation> resolve(const bayesian_network& network, const assignment& planned);

/// The planned value `text` gives `v`: a number when `v` has interval edges and the text reads
/// as one (a state label then needs a leading '@', as in "@2"); otherwise a state label — or,
/// when it is no label of `v` but reads as a number, that number (which state_of rejects with a
/// message saying why).
[[nodiscard]] PGM_DECL planned_value planned_value_of(const variable& v, std::string_view text);

/// Parses "name=value,…", each value by planned_value_of ("xOff1=0.3", "xOff1=@2"). Throws
/// model_error for a malformed piece, an unknown or repeated variable.
[[nodiscard]] PGM_DECL assignment parse_assignment(std::string_view text, const bayesian_network& network);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/decide/impl/assignment.ipp"
#endif
