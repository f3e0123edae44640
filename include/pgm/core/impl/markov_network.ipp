#pragma once
// The definitions of pgm/core/markov_network.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <string>

#include "pgm/core/markov_network.hpp"
#include "pgm/core/text.hpp"

namespace pgm {

PGM_DECL markov_network::markov_network(std::vector<variable> variables, std::vector<factor_table> factors)
    : variables_(std::move(variables)), factors_(std::move(factors)) {
  for (std::size_t i = 0; i < variables_.size(); ++i) {
    const auto [at, added] = index_.emplace(variables_[i].name(), index_at<variable_id>(i));
    if (!added) throw model_error("the variable '" + variables_[i].name() + "' is declared twice");
  }
  for (std::size_t f = 0; f < factors_.size(); ++f) {
    const auto& scope = factors_[f].scope();
    for (std::size_t k = 0; k < scope.size(); ++k) {
      if (scope[k].value() >= variables_.size()) {
        throw model_error("factor " + std::to_string(f) + " names variable " + std::to_string(scope[k].value()) +
                          ", but the model has " + std::to_string(variables_.size()) + " variables");
      }
      const auto& v = variables_[scope[k].value()];
      if (factors_[f].cardinalities()[k] != v.cardinality()) {
        throw model_error("factor " + std::to_string(f) + " gives '" + v.name() + "' " +
                          std::to_string(factors_[f].cardinalities()[k]) + " states, but it has " +
                          std::to_string(v.cardinality()));
      }
    }
  }
}

PGM_DECL variable_id markov_network::id(std::string_view name) const {
  const auto it = index_.find(name);
  if (it == index_.end()) {
    std::vector<std::string> known;
    for (const auto& v : variables_) known.push_back(v.name());
    throw model_error("unknown variable '" + std::string(name) + "' (known: " + text::list_for_message(known) + ")");
  }
  return it->second;
}

}  // namespace pgm
