#pragma once
/// \file
/// d-separation on a network's DAG: whether every path between two sets of variables is blocked
/// given a third. Reachability as Koller & Friedman's algorithm 3.1 finds it ("Bayes-ball"): a
/// walk over (node, direction) pairs from X that passes a chain or fork through an unobserved
/// node and a collider whose descendants include an observed one; Y is d-separated from X given
/// Z when the walk reaches no node of Y.

#include <algorithm>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"

namespace pgm {

/// The nodes d-connected to `from` given `given` (the nodes of `from` included, `given`
/// excluded): what a trail from `from` can reach without being blocked.
[[nodiscard]] PGM_DECL std::vector<bool> d_connected(const dag& graph, std::span<const variable_id> from,
                                                     std::span<const variable_id> given);

/// Whether `x` and `y` are d-separated given `z` (disjoint sets of nodes). Throws model_error
/// when the sets overlap.
[[nodiscard]] PGM_DECL bool d_separated(const dag& graph, std::span<const variable_id> x,
                                        std::span<const variable_id> y, std::span<const variable_id> z = {});

/// The same by names. Throws model_error for an unknown name (naming the known ones), an empty
/// set X or Y, or overlapping sets.
[[nodiscard]] PGM_DECL bool d_separated(const network_structure& structure, std::span<const std::string> x,
                                        std::span<const std::string> y, std::span<const std::string> z = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/causal/impl/d_separation.ipp"
#endif
