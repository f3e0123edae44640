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
