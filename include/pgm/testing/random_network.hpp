#pragma once
/// \file
/// Random networks for property tests: a random DAG over `nodes` variables with up to
/// `max_parents` parents each and random tables drawn from a flat Dirichlet.

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/inference/sampling.hpp"

namespace pgm::testing {

struct random_network_options {
  std::size_t nodes = 8;
  std::size_t max_parents = 3;
  std::size_t min_states = 2;
  std::size_t max_states = 4;
};

inline bayesian_network random_network(std::uint64_t seed, const random_network_options& options = {}) {
  std::mt19937_64 engine(seed);
  auto below = [&](std::size_t n) { return static_cast<std::size_t>(engine() % n); };
  std::vector<variable> variables;
  for (std::size_t i = 0; i < options.nodes; ++i) {
    const auto states = options.min_states + below(options.max_states - options.min_states + 1);
    std::vector<std::string> labels;
    for (std::size_t s = 0; s < states; ++s) labels.push_back("s" + std::to_string(s));
    variables.emplace_back("v" + std::to_string(i), labels);
  }
  network_structure structure(variables);
  std::vector<std::vector<variable>> parents(options.nodes);
  for (std::size_t i = 1; i < options.nodes; ++i) {
    std::vector<std::size_t> candidates(i);
    for (std::size_t k = 0; k < i; ++k) candidates[k] = k;
    std::shuffle(candidates.begin(), candidates.end(), engine);
    const auto count = below(std::min(options.max_parents, i) + 1);
    for (std::size_t k = 0; k < count; ++k) {
      structure.add_edge(variables[candidates[k]].name(), variables[i].name());
    }
  }
  std::vector<cpt<double>> tables;
  for (std::size_t i = 0; i < options.nodes; ++i) {
    const variable_id node = index_at<variable_id>(i);
    const auto parent_variables = structure.parent_variables(node);
    cpt<double> shape(variables[i], parent_variables);
    std::vector<double> values(shape.size());
    const auto j = variables[i].cardinality();
    std::exponential_distribution<double> gamma1(1.0);  // flat Dirichlet via normalized Exp(1)
    for (std::size_t u = 0; u < shape.configurations(); ++u) {
      double sum = 0;
      for (std::size_t x = 0; x < j; ++x) sum += values[u * j + x] = gamma1(engine);
      for (std::size_t x = 0; x < j; ++x) values[u * j + x] /= sum;
    }
    tables.emplace_back(variables[i], parent_variables, values);
  }
  return bayesian_network(structure, tables);
}

}  // namespace pgm::testing
