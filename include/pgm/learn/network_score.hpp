#pragma once
/// \file
/// The score of a network's structure on data (pgm/learn/score.hpp): each node's term and their
/// sum, as bnlearn's `score(x, data, type, by.node = TRUE)`.

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/learn/family_score_cache.hpp"
#include "pgm/learn/score.hpp"

namespace pgm {

struct network_score {
  double total = 0.0;
  /// One term per node, in the structure's order.
  std::vector<double> nodes;
};

/// Scores `structure` on `data`, which must hold a discrete column for each of its variables
/// with the same number of states. Throws data_error for a missing or continuous column or one
/// whose states differ, model_error for bad score options.
[[nodiscard]] inline network_score score_network(const network_structure& structure, const dataset& data,
                                                 const score_choice& choice = {}, unsigned threads = 0) {
  std::vector<const discrete_column*> columns;
  for (const auto& v : structure.variables()) {
    const auto& column = data.discrete(v.name());
    if (column.var().cardinality() != v.cardinality()) {
      throw data_error("column '" + v.name() + "' has " + std::to_string(column.var().cardinality()) +
                       " states, the model's variable " + std::to_string(v.cardinality()));
    }
    columns.push_back(&column);
  }
  family_score_cache cache(columns, choice, threads);
  std::vector<family_key> keys;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    family_key key{i, {}};
    for (auto p : structure.parents(variable_id(static_cast<variable_id::rep>(i)))) key.parents.push_back(p.value());
    std::sort(key.parents.begin(), key.parents.end());
    keys.push_back(std::move(key));
  }
  network_score result;
  result.nodes = cache.score_all(keys);
  for (auto v : result.nodes) result.total += v;
  return result;
}

}  // namespace pgm
