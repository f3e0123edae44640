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
#include "pgm/data/dataset.hpp"
#include "pgm/detail/cumulative_columns.hpp"

namespace pgm {

/// A uniform double in [0, 1) from the top 53 bits of one draw.
[[nodiscard]] inline double uniform01(std::mt19937_64& engine) {
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

/// `rows` independent observations of every variable of `network`, as discrete columns in
/// the network's variable order.
[[nodiscard]] inline dataset sample(const bayesian_network& network, std::size_t rows, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::vector<std::vector<std::uint32_t>> codes(network.size(), std::vector<std::uint32_t>(rows));
  std::vector<std::size_t> parent_codes;
  for (const auto node : network.graph().topological_order()) {
    const auto& table = network.table(node);
    const auto parents = network.graph().parents(node);
    const auto j = table.child_cardinality();
    // Cumulative distributions per configuration, so that a draw is a short scan.
    const detail::cumulative_columns cumulative(table, false);
    const auto& strides = table.parent_radix().strides();
    auto& out = codes[node.value()];
    for (std::size_t row = 0; row < rows; ++row) {
      std::size_t u = 0;
      for (std::size_t p = 0; p < parents.size(); ++p) u += codes[parents[p].value()][row] * strides[p];
      const double* column = cumulative.column(u);
      const double draw = uniform01(engine) * column[j - 1];
      std::size_t x = 0;
      while (x + 1 < j && draw >= column[x]) ++x;
      out[row] = static_cast<std::uint32_t>(x);
    }
  }
  dataset data;
  for (std::size_t i = 0; i < network.size(); ++i) {
    data.add(discrete_column(network.variables()[i], codes[i]));
  }
  return data;
}

}  // namespace pgm
