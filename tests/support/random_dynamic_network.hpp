#pragma once
// Random dynamic networks (2-TBNs) for property tests.

#include <cstdint>
#include <random>
#include <vector>

#include "pgm/core/dynamic_network.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::testing {

// A random 2-TBN: a random first slice over v0 … v(n−1); in the transition, each variable has up
// to two parents among the earlier ones of its slice and up to two in the previous slice (any
// variable, itself included), its tables from a flat Dirichlet (a zero among them with `zeros`).
inline dynamic_network random_dynamic(std::uint64_t seed, std::size_t n, bool zeros = false) {
  random_network_options shape;
  shape.nodes = n;
  shape.max_parents = 2;
  shape.max_states = 3;
  const auto first = random_network(seed, shape);
  std::mt19937_64 engine(seed * 977);
  std::exponential_distribution<double> gamma1(1.0);
  std::vector<cpt<double>> tables;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<variable> parents;
    for (std::size_t k = 0; k < i; ++k) {
      if (engine() % 3 == 0 && parents.size() < 2) parents.push_back(first.variables()[k]);
    }
    std::size_t before = 0;
    for (std::size_t k = 0; k < n && before < 2; ++k) {
      if (engine() % 3 != 0) continue;
      parents.push_back(detail::renamed(first.variables()[k], slice_name(first.variables()[k].name(), -1)));
      ++before;
    }
    cpt<double> shape_of(first.variables()[i], parents);
    const auto j = first.variables()[i].cardinality();
    std::vector<double> values(shape_of.size());
    for (std::size_t u = 0; u < shape_of.configurations(); ++u) {
      double sum = 0.0;
      for (std::size_t x = 0; x < j; ++x) {
        values[u * j + x] = zeros && engine() % 4 == 0 ? 0.0 : gamma1(engine);
        sum += values[u * j + x];
      }
      if (sum == 0.0) values[u * j] = sum = 1.0;
      for (std::size_t x = 0; x < j; ++x) values[u * j + x] /= sum;
    }
    tables.emplace_back(first.variables()[i], parents, values);
  }
  return dynamic_network(first, tables);
}

}  // namespace pgm::testing
