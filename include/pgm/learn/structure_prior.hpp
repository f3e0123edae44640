#pragma once
/// \file
/// A structure prior from a related task (the paper's transfer applied to the structure): the
/// edges of the prior task's network, carried over to the target's variables by the
/// correspondence map the transfer uses (pgm/core/correspondence.hpp). A target variable t
/// stands for the prior variables it is transferred from (`onTop2=onTop1`), identical to (the
/// same name, or `xOffset==xOff1`) or related to (`xOff2~xOff1`); a prior edge a -> b becomes
/// every target edge t -> u with t standing for a and u for b. Hill climbing then adds a weight
/// to the score for each of those edges in the network (search_options::favoured), so that with
/// few rows the search keeps the structure experience suggests unless the data speak against it.

#include <algorithm>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/correspondence.hpp"
#include "pgm/core/network_structure.hpp"

namespace pgm {

/// The target edges the prior network's edges map to, ordered by (from, to) in `target` order.
[[nodiscard]] PGM_DECL std::vector<named_edge> mapped_prior_edges(const std::vector<named_edge>& prior_edges,
                                                                  const correspondence& map,
                                                                  const std::vector<std::string>& target);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/structure_prior.ipp"
#endif
