#pragma once
/// \file
/// Structural Hamming distance between two partially directed graphs over the same nodes
/// (Tsamardinos, Brown & Aliferis 2006): the number of node pairs whose edge differs —
/// missing, extra, or with another orientation (a -> b vs b -> a vs a - b). Compare a learned
/// CPDAG with `cpdag_of(true DAG)`, not with the DAG itself, since PC cannot tell apart the
/// DAGs of one equivalence class.

#include <cstddef>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/learn/cpdag.hpp"

namespace pgm {

/// Counts of the differences; `total()` is the SHD.
struct hamming_parts {
  std::size_t missing = 0;      ///< adjacent in `truth` only
  std::size_t extra = 0;        ///< adjacent in `learned` only
  std::size_t misoriented = 0;  ///< adjacent in both, marks differ
  [[nodiscard]] std::size_t total() const noexcept { return missing + extra + misoriented; }
};

/// Throws model_error if the graphs have different nodes.
[[nodiscard]] PGM_DECL hamming_parts hamming_differences(const cpdag& learned, const cpdag& truth);

/// The structural Hamming distance.
[[nodiscard]] inline std::size_t structural_hamming_distance(const cpdag& learned, const cpdag& truth) {
  return hamming_differences(learned, truth).total();
}

/// Pairs adjacent in one graph but not the other (orientation ignored).
[[nodiscard]] inline std::size_t skeleton_distance(const cpdag& learned, const cpdag& truth) {
  const auto parts = hamming_differences(learned, truth);
  return parts.missing + parts.extra;
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/structural_hamming_distance.ipp"
#endif
