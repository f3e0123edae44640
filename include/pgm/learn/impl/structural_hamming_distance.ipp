#pragma once
// The definitions of pgm/learn/structural_hamming_distance.hpp: inline in a header-only build, compiled once into
// libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/structural_hamming_distance.hpp"

namespace pgm {

PGM_DECL hamming_parts hamming_differences(const cpdag& learned, const cpdag& truth) {
  if (learned.names() != truth.names()) {
    throw model_error("the graphs to compare have different nodes");
  }
  hamming_parts parts;
  for (std::size_t i = 0; i < learned.size(); ++i) {
    for (std::size_t j = i + 1; j < learned.size(); ++j) {
      const variable_id a = index_at<variable_id>(i);
      const variable_id b = index_at<variable_id>(j);
      const bool in_learned = learned.adjacent(a, b);
      const bool in_truth = truth.adjacent(a, b);
      if (in_learned && !in_truth) {
        ++parts.extra;
      } else if (!in_learned && in_truth) {
        ++parts.missing;
      } else if (in_learned &&
                 (learned.directed(a, b) != truth.directed(a, b) || learned.directed(b, a) != truth.directed(b, a))) {
        ++parts.misoriented;
      }
    }
  }
  return parts;
}

}  // namespace pgm
