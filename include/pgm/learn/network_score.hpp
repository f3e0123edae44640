#pragma once
/// \file
/// The score of a network's structure on data (pgm/learn/score.hpp): each node's term and their
/// sum, as bnlearn's `score(x, data, type, by.node = TRUE)`.

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/learn/family_score_cache.hpp"
#include "pgm/learn/score_registry.hpp"

namespace pgm {

struct network_score {
  double total = 0.0;
  /// One term per node, in the structure's order.
  std::vector<double> nodes;
};

/// Scores `structure` on `data`, which must hold a discrete column for each of its variables
/// with the same number of states. Throws data_error for a missing or continuous column or one
/// whose states differ.
[[nodiscard]] PGM_DECL network_score score_network(const network_structure& structure, const dataset& data,
                                                   const family_score& score = {}, unsigned threads = 0);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/network_score.ipp"
#endif
