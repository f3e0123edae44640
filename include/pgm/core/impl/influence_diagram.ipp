#pragma once
// The definitions of pgm/core/influence_diagram.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cmath>
#include <string>

#include "pgm/core/influence_diagram.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/unknown_name.hpp"

namespace pgm {

PGM_DECL variable_id influence_diagram::add_chance(variable v) { return add(std::move(v), node_kind::chance); }

PGM_DECL variable_id influence_diagram::add_decision(variable v) { return add(std::move(v), node_kind::decision); }

PGM_DECL variable_id influence_diagram::add(variable v, node_kind kind) {
  check_name_free(v.name());
  const auto id = graph_.add_node(v.name());
  index_.emplace(v.name(), id);
  variables_.push_back(std::move(v));
  kinds_.push_back(kind);
  parents_.emplace_back();
  tables_.emplace_back();
  connected_.push_back(false);
  return id;
}

PGM_DECL void influence_diagram::check_name_free(const std::string& name) const {
  const bool utility = std::any_of(utilities_.begin(), utilities_.end(), [&](const auto& u) { return u.name == name; });
  if (index_.contains(name) || utility) throw model_error("the node '" + name + "' is declared twice");
}

PGM_DECL void influence_diagram::connect(variable_id child, const std::vector<variable_id>& parents) {
  if (connected_.at(child.value())) {
    throw model_error("the parents of '" + variables_[child.value()].name() + "' are given twice");
  }
  for (std::size_t i = 0; i < parents.size(); ++i) {
    try {
      graph_.add_edge(parents[i], child);  // throws for a cycle or a repeat
    } catch (...) {
      for (std::size_t j = 0; j < i; ++j) graph_.remove_edge(parents[j], child);
      throw;
    }
  }
  parents_[child.value()] = parents;
  connected_[child.value()] = true;
}

PGM_DECL std::size_t influence_diagram::configurations(const std::vector<variable_id>& parents,
                                                       const std::string& owner) const {
  std::size_t count = 1;
  for (const auto parent : parents) count = checked_table_cells(owner, at(parent).cardinality(), count);
  return count;
}

PGM_DECL void influence_diagram::set_table(variable_id chance, const std::vector<variable_id>& parents,
                                           std::vector<double> table) {
  const auto& name = at(chance).name();
  if (is_decision(chance)) {
    throw model_error("'" + name + "' is a decision: it is chosen, so it has no probability table");
  }
  const auto states = at(chance).cardinality();
  const auto cells = checked_table_cells(name, states, configurations(parents, name));
  if (table.size() != cells) {
    throw model_error("the table of '" + name + "' has " + std::to_string(table.size()) + " values; its " +
                      std::to_string(parents.size()) + " parents and " + std::to_string(states) + " states need " +
                      std::to_string(cells));
  }
  for (std::size_t column = 0; column < cells / states; ++column) {
    double total = 0;
    for (std::size_t s = 0; s < states; ++s) {
      const double p = table[column * states + s];
      if (!(p >= 0 && p <= 1)) {
        throw model_error("the table of '" + name + "' holds " + std::to_string(p) + ", which is no probability");
      }
      total += p;
    }
    if (std::abs(total - 1) > 1e-6) {
      throw model_error("column " + std::to_string(column) + " of the table of '" + name + "' sums to " +
                        std::to_string(total) + ", not 1");
    }
  }
  connect(chance, parents);
  tables_[chance.value()] = std::move(table);
}

PGM_DECL void influence_diagram::set_observed(variable_id decision, const std::vector<variable_id>& observed) {
  if (!is_decision(decision)) {
    throw model_error("'" + at(decision).name() + "' is a chance variable; set_table gives its parents");
  }
  connect(decision, observed);
}

PGM_DECL void influence_diagram::add_utility(std::string name, std::vector<variable_id> parents,
                                             std::vector<double> values) {
  check_name_free(name);
  const auto cells = configurations(parents, name);
  if (values.size() != cells) {
    throw model_error("the utility '" + name + "' has " + std::to_string(values.size()) + " values; its " +
                      std::to_string(parents.size()) + " parents need " + std::to_string(cells));
  }
  for (std::size_t i = 0; i < parents.size(); ++i) {
    static_cast<void>(at(parents[i]));  // throws for an unknown id
    if (std::find(parents.begin(), parents.begin() + static_cast<std::ptrdiff_t>(i), parents[i]) !=
        parents.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw model_error("the utility '" + name + "' lists '" + at(parents[i]).name() + "' twice");
    }
  }
  for (const double u : values) {
    if (!std::isfinite(u)) throw model_error("the utility '" + name + "' holds a value that is not finite");
  }
  utilities_.push_back({std::move(name), std::move(parents), std::move(values)});
}

PGM_DECL void influence_diagram::validate() const {
  for (std::size_t i = 0; i < variables_.size(); ++i) {
    if (kinds_[i] == node_kind::chance && tables_[i].empty()) {
      throw model_error("the chance variable '" + variables_[i].name() + "' has no table");
    }
  }
  if (std::none_of(kinds_.begin(), kinds_.end(), [](node_kind k) { return k == node_kind::decision; })) {
    throw model_error("the influence diagram has no decision");
  }
  if (utilities_.empty()) throw model_error("the influence diagram has no utility");
}

PGM_DECL variable_id influence_diagram::id(std::string_view name) const {
  const auto it = index_.find(name);
  if (it == index_.end()) {
    std::vector<std::string> known;
    for (const auto& v : variables_) known.push_back(v.name());
    throw unknown_name("variable", std::string(name), std::move(known));
  }
  return it->second;
}

PGM_DECL std::vector<variable_id> influence_diagram::decision_order() const {
  // The earliest declared decision with no decision left among its ancestors, repeatedly: the
  // graph's order where it has one, the declarations' order where it has none.
  std::vector<variable_id> left;
  for (std::size_t i = 0; i < size(); ++i) {
    if (kinds_[i] == node_kind::decision) left.push_back(index_at<variable_id>(i));
  }
  std::vector<variable_id> order;
  while (!left.empty()) {
    const auto next = std::find_if(left.begin(), left.end(), [&](variable_id d) {
      return std::none_of(left.begin(), left.end(),
                          [&](variable_id e) { return e != d && !graph_.path_between(e, d).empty(); });
    });
    order.push_back(*next);
    left.erase(next);
  }
  return order;
}

}  // namespace pgm
