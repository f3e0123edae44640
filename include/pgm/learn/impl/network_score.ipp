#pragma once
// The definitions of pgm/learn/network_score.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/network_score.hpp"

namespace pgm {

PGM_DECL network_score score_network(const network_structure& structure, const dataset& data, const family_score& score,
                                     unsigned threads) {
  std::vector<const discrete_column*> columns;
  for (const auto& v : structure.variables()) {
    const auto& column = data.discrete(v.name());
    if (column.var().cardinality() != v.cardinality()) {
      throw data_error("column '" + v.name() + "' has " + std::to_string(column.var().cardinality()) +
                       " states, the model's variable " + std::to_string(v.cardinality()));
    }
    columns.push_back(&column);
  }
  family_score_cache cache(columns, score, threads);
  std::vector<family_key> keys;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    family_key key{i, {}};
    for (auto p : structure.parents(index_at<variable_id>(i))) key.parents.push_back(p.value());
    std::sort(key.parents.begin(), key.parents.end());
    keys.push_back(std::move(key));
  }
  network_score result;
  result.nodes = cache.score_all(keys);
  for (auto v : result.nodes) result.total += v;
  return result;
}

}  // namespace pgm
