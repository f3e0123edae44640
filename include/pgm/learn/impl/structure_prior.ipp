#pragma once
// The definitions of pgm/learn/structure_prior.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/structure_prior.hpp"

namespace pgm {

PGM_DECL std::vector<named_edge> mapped_prior_edges(const std::vector<named_edge>& prior_edges,
                                                    const correspondence& map, const std::vector<std::string>& target) {
  auto stands_for = [&](const std::string& t, const std::string& prior) {
    const auto transferred = map.transferred.find(t);
    if (transferred != map.transferred.end() && transferred->second == prior) return true;
    if (map.identical_to(t) == prior) return true;
    const auto related = map.related_to(t);
    return related && *related == prior;
  };
  // A name the data lacks maps nothing: refused as pgm fit refuses it (issue #49).
  const auto in_target = [&](const std::string& name, const char* kind) {
    if (std::find(target.begin(), target.end(), name) == target.end()) {
      throw model_error("the map's " + std::string(kind) + " '" + name + "' is not a variable of the data");
    }
  };
  for (const auto& [t, p] : map.transferred) in_target(t, "transferred node");
  for (const auto& [t, p] : map.identical) in_target(t, "identical variable");
  for (const auto& [t, p] : map.related) in_target(t, "related variable");
  std::vector<named_edge> result;
  for (const auto& from : target) {
    for (const auto& to : target) {
      if (from == to) continue;
      const bool mapped = std::any_of(prior_edges.begin(), prior_edges.end(), [&](const named_edge& e) {
        return stands_for(from, e.from) && stands_for(to, e.to);
      });
      if (mapped) result.push_back({from, to});
    }
  }
  return result;
}

}  // namespace pgm
