#pragma once
// The definitions of pgm/core/structural_model.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cmath>
#include <string>

#include "pgm/core/cpt.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/structural_model.hpp"
#include "pgm/core/text.hpp"

namespace pgm {

PGM_DECL std::size_t parent_configurations(const structural_model& model, const std::vector<variable_id>& parents) {
  std::size_t count = 1;
  for (const auto parent : parents) count *= model.at(parent).cardinality();
  return count;
}

PGM_DECL structural_model::structural_model(std::vector<variable> variables, std::vector<structural_equation> equations)
    : variables_(std::move(variables)), equations_(std::move(equations)) {
  if (equations_.size() != variables_.size()) {
    throw model_error("a structural model needs one equation per variable: " + std::to_string(variables_.size()) +
                      " variables, " + std::to_string(equations_.size()) + " equations");
  }
  for (const auto& v : variables_) {
    if (graph_.contains(v.name())) throw model_error("the variable '" + v.name() + "' is declared twice");
    (void)graph_.add_node(v.name());
  }
  for (std::size_t i = 0; i < variables_.size(); ++i) {
    const auto& name = variables_[i].name();
    const auto& e = equations_[i];
    std::size_t configurations = 1;
    for (const auto parent : e.parents) {
      if (parent.value() >= variables_.size()) {
        throw model_error("the equation of '" + name + "' names variable " + std::to_string(parent.value()) +
                          ", but the model has " + std::to_string(variables_.size()));
      }
      configurations = checked_table_cells(name, variables_[parent.value()].cardinality(), configurations);
      graph_.add_edge(parent, index_at<variable_id>(i));  // names a cycle or a repeated parent
    }
    if (e.noise.empty()) throw model_error("the noise of '" + name + "' has no state");
    double total = 0;
    for (const double p : e.noise) {
      if (!(p >= 0 && p <= 1)) {
        throw model_error("the noise of '" + name + "' holds " + text::format_short(p) + ", which is no probability");
      }
      total += p;
    }
    if (std::abs(total - 1) > 1e-6) {
      throw model_error("the noise of '" + name + "' sums to " + text::format_short(total) + ", not 1");
    }
    const auto cells = checked_table_cells(name, e.noise.size(), configurations);
    if (e.values.size() != cells) {
      throw model_error("the function of '" + name + "' has " + std::to_string(e.values.size()) + " values; " +
                        std::to_string(configurations) + " configurations of its parents and " +
                        std::to_string(e.noise.size()) + " noise states need " + std::to_string(cells));
    }
    const auto states = variables_[i].cardinality();
    for (const auto s : e.values) {
      if (s >= states) {
        throw model_error("the function of '" + name + "' gives state " + std::to_string(s) + ", but '" + name +
                          "' has " + std::to_string(states));
      }
    }
  }
}

PGM_DECL std::size_t structural_model::value(variable_id v, std::size_t configuration, std::size_t noise_state) const {
  const auto& e = equation(v);
  return e.values[configuration * e.noise.size() + noise_state];
}

PGM_DECL bayesian_network structural_model::network() const {
  std::vector<cpt<double>> tables;
  tables.reserve(size());
  for (std::size_t i = 0; i < size(); ++i) {
    const auto& e = equations_[i];
    const auto states = variables_[i].cardinality();
    std::vector<variable> parents;
    for (const auto parent : e.parents) parents.push_back(at(parent));
    const auto configurations = parent_configurations(*this, e.parents);
    std::vector<double> values(configurations * states, 0.0);
    for (std::size_t c = 0; c < configurations; ++c) {
      for (std::size_t k = 0; k < e.noise.size(); ++k)
        values[c * states + e.values[c * e.noise.size() + k]] += e.noise[k];
    }
    for (auto& p : values) p = std::min(p, 1.0);  // a sum of a whole noise may round above 1
    tables.emplace_back(variables_[i], std::move(parents), std::move(values));
  }
  return bayesian_network::from_tables(std::move(tables));
}

}  // namespace pgm
