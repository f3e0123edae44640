#pragma once
// The definitions of pgm/transfer/state_map.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/transfer/state_map.hpp"

namespace pgm::detail {

PGM_DECL std::vector<weighted_state> overlap_weights(const variable& prior, double lo, double hi) {
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

}  // namespace pgm::detail

namespace pgm {

PGM_DECL state_mapping map_states(const variable& target, const variable& prior, state_matching matching) {
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
      const state_index state = index_at<state_index>(s);
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
    const auto value = target.midpoint(index_at<state_index>(s));
    bool found = false;
    for (std::size_t p = 0; value && p < prior.cardinality() && !found; ++p) {
      const auto other = prior.midpoint(index_at<state_index>(p));
      if (other && *other == *value) {
        mapping[s] = {{p, 1.0}};
        found = true;
      }
    }
    if (!found) throw cannot("the prior has no state '" + label + "'");
  }
  return mapping;
}

PGM_DECL std::size_t pinned_state(const variable& prior, const std::string& value) {
  const auto number = text::parse_double(value);
  if (prior.has_intervals() && number && std::isfinite(*number)) return prior.bin(*number).value();
  if (const auto same = prior.find_state(value)) return same->value();
  if (number && std::isfinite(*number)) {
    for (std::size_t p = 0; p < prior.cardinality(); ++p) {
      const auto other = prior.midpoint(index_at<state_index>(p));
      if (other && *other == *number) return p;
    }
  }
  throw model_error("cannot pin the prior's '" + prior.name() + "' to '" + value +
                    "': it is neither one of its states " + detail::states_for_message(prior) +
                    (prior.has_intervals() ? " nor a number" : ""));
}

}  // namespace pgm
