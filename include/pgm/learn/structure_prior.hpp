#pragma once
/// \file
/// A structure prior from a related task (the paper's transfer applied to the structure): the
/// edges of the prior task's network, carried over to the target's variables by the
/// correspondence map the transfer uses (pgm/transfer/correspondence.hpp). A target variable t
/// stands for the prior variables it is transferred from (`onTop2=onTop1`), identical to (the
/// same name, or `xOffset==xOff1`) or related to (`xOff2~xOff1`); a prior edge a -> b becomes
/// every target edge t -> u with t standing for a and u for b. Hill climbing then adds a weight
/// to the score for each of those edges in the network (search_options::favoured), so that with
/// few rows the search keeps the structure experience suggests unless the data speak against it.

#include <algorithm>
#include <string>
#include <vector>

#include "pgm/core/network_structure.hpp"
#include "pgm/transfer/correspondence.hpp"

namespace pgm {

/// The target edges the prior network's edges map to, ordered by (from, to) in `target` order.
[[nodiscard]] inline std::vector<named_edge> mapped_prior_edges(const std::vector<named_edge>& prior_edges,
                                                                const correspondence& map,
                                                                const std::vector<std::string>& target) {
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
