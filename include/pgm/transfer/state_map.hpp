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

#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/detail/text.hpp"

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
  return "{" + list_for_message(v.states()) + "}";
}

[[nodiscard]] inline std::vector<weighted_state> overlap_weights(const variable& prior, double lo, double hi) {
  const auto& edges = prior.edges();
  std::vector<weighted_state> shares;
  double total = 0;
  for (std::size_t s = 0; s + 1 < edges.size(); ++s) {
    // The outer prior intervals reach to ±infinity, as binning puts outside values there.
    const double a = s == 0 ? -INFINITY : edges[s];
    const double b = s + 2 == edges.size() ? INFINITY : edges[s + 1];
    const double length = std::min(hi, b) - std::max(lo, a);
    if (length > 0) {
      shares.push_back({s, length});
      total += length;
    }
  }
  for (auto& share : shares) share.weight /= total;
  return shares;
}

}  // namespace detail

/// How the states of `target` stand for states of `prior`. Same states (and edges) map one to
/// one; interval or numeric states map by value; categorical states by label.
[[nodiscard]] inline state_mapping map_states(const variable& target, const variable& prior,
                                              state_matching matching = state_matching::midpoint) {
  state_mapping mapping(target.cardinality());
  const auto cannot = [&](const std::string& why) {
    return model_error("cannot match the states of '" + target.name() + "' " + detail::states_for_message(target) +
                       " to those of the prior's '" + prior.name() + "' " + detail::states_for_message(prior) + ": " +
                       why);
  };
  if (target.states() == prior.states() && target.edges() == prior.edges()) {
    for (std::size_t s = 0; s < mapping.size(); ++s) mapping[s] = {{s, 1.0}};
    return mapping;
  }
  if (prior.has_intervals()) {
    for (std::size_t s = 0; s < mapping.size(); ++s) {
      const state_index state(static_cast<state_index::rep>(s));
      if (matching == state_matching::overlap && target.has_intervals()) {
        mapping[s] = detail::overlap_weights(prior, target.edges()[s], target.edges()[s + 1]);
        continue;
      }
      const auto middle = target.midpoint(state);
      if (!middle) throw cannot("state '" + target.states()[s] + "' has no value on the prior's scale");
      mapping[s] = {{prior.bin(*middle).value(), 1.0}};
    }
    return mapping;
  }
  for (std::size_t s = 0; s < mapping.size(); ++s) {
    const auto& label = target.states()[s];
    if (const auto same = prior.find_state(label)) {
      mapping[s] = {{same->value(), 1.0}};
      continue;
    }
    // Numeric labels written differently ("0.9" vs "0.90") still name the same value.
    const auto value = target.midpoint(state_index(static_cast<state_index::rep>(s)));
    bool found = false;
    for (std::size_t p = 0; value && p < prior.cardinality() && !found; ++p) {
      const auto other = prior.midpoint(state_index(static_cast<state_index::rep>(p)));
      if (other && *other == *value) {
        mapping[s] = {{p, 1.0}};
        found = true;
      }
    }
    if (!found) throw cannot("the prior has no state '" + label + "'");
  }
  return mapping;
}

/// The prior state a pinned value selects. For an interval variable the value is on its scale
/// (cm, say) and is binned, since its labels are only bin numbers; otherwise it is a state
/// label or a number equal to a numeric label.
[[nodiscard]] inline std::size_t pinned_state(const variable& prior, const std::string& value) {
  const auto number = detail::parse_double(value);
  if (prior.has_intervals() && number && std::isfinite(*number)) return prior.bin(*number).value();
  if (const auto same = prior.find_state(value)) return same->value();
  if (number && std::isfinite(*number)) {
    for (std::size_t p = 0; p < prior.cardinality(); ++p) {
      const auto other = prior.midpoint(state_index(static_cast<state_index::rep>(p)));
      if (other && *other == *number) return p;
    }
  }
  throw model_error("cannot pin the prior's '" + prior.name() + "' to '" + value +
                    "': it is neither one of its states " + detail::states_for_message(prior) +
                    (prior.has_intervals() ? " nor a number" : ""));
}

}  // namespace pgm
