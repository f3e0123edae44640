#pragma once
/// \file
/// Matching the states of a target variable to those of its prior counterpart when the two
/// tasks discretize it differently (5 simulated bins vs the 3 offsets of the real robot): each
/// target state maps to the prior state whose interval holds its midpoint, or, as an option,
/// to every prior interval it overlaps, weighted by the overlap. A mapping that cannot be made
/// is an error naming both variables, never a guess.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/core/variable.hpp"

namespace pgm {

enum class state_matching {
  midpoint,  ///< the prior interval holding the target state's midpoint (or numeric label)
  overlap,   ///< every prior interval the target interval overlaps, weighted by overlap length
};

/// "midpoint" or "overlap", as the command line and Python spell a matching.
[[nodiscard]] constexpr std::string_view to_string(state_matching matching) noexcept {
  return matching == state_matching::overlap ? "overlap" : "midpoint";
}

inline constexpr std::array state_matchings{state_matching::midpoint, state_matching::overlap};

/// The matchings' names, for parsing, messages and the command line's allowed values.
[[nodiscard]] inline std::vector<std::string> known_state_matchings() { return names_of(state_matchings); }

/// Parses "midpoint" or "overlap"; throws unknown_name otherwise.
[[nodiscard]] inline state_matching parse_state_matching(std::string_view text) {
  return parse_choice("state matching", text, state_matchings);
}

/// One prior state with its share of a target state.
struct weighted_state {
  std::size_t state;
  double weight;
  friend bool operator==(const weighted_state&, const weighted_state&) = default;
};

/// For each target state, the prior states it stands for (weights sum to 1).
using state_mapping = std::vector<std::vector<weighted_state>>;

namespace detail {

[[nodiscard]] inline std::string states_for_message(const variable& v) {
  return "{" + text::list_for_message(v.states()) + "}";
}

[[nodiscard]] PGM_DECL std::vector<weighted_state> overlap_weights(const variable& prior, double lo, double hi);

}  // namespace detail

/// How the states of `target` stand for states of `prior`. Same states (and edges) map one to
/// one; interval or numeric states map by value; categorical states by label.
[[nodiscard]] PGM_DECL state_mapping map_states(const variable& target, const variable& prior,
                                                state_matching matching = state_matching::midpoint);

/// The prior state a pinned value selects. For an interval variable the value is on its scale
/// (cm, say) and is binned, since its labels are only bin numbers; otherwise it is a state
/// label or a number equal to a numeric label.
[[nodiscard]] PGM_DECL std::size_t pinned_state(const variable& prior, const std::string& value);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/transfer/impl/state_map.ipp"
#endif
