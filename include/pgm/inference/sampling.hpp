#pragma once
/// \file
/// Forward (ancestral) sampling of complete observations from a network. The stream of
/// draws is fixed by the seed on every platform: std::mt19937_64's sequence is specified by
/// the standard, and doubles are made from its bits here rather than by a library
/// distribution whose algorithm is left to the implementation.

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/cumulative_columns.hpp"

namespace pgm {

/// A uniform double in [0, 1) from the top 53 bits of one draw.
[[nodiscard]] inline double uniform01(std::mt19937_64& engine) {
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

/// `rows` independent observations of every variable of `network`, as discrete columns in
/// the network's variable order.
[[nodiscard]] PGM_DECL dataset sample(const bayesian_network& network, std::size_t rows, std::uint64_t seed);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/sampling.ipp"
#endif
