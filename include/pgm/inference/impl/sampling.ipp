#pragma once
// The definitions of pgm/inference/sampling.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/sampling.hpp"

namespace pgm {

PGM_DECL dataset sample(const bayesian_network& network, std::size_t rows, std::uint64_t seed) {
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
