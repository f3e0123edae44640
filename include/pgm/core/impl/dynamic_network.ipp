#pragma once
// The definitions of pgm/core/dynamic_network.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <charconv>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/dynamic_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"

namespace pgm {

namespace detail {

PGM_DECL variable renamed(const variable& v, std::string name) {
  variable result(std::move(name), v.states(), v.tags());
  if (v.has_intervals()) result.set_edges(v.edges());
  return result;
}

PGM_DECL cpt<double> renamed(const cpt<double>& table, variable child, std::vector<variable> parents) {
  if (!table.is_sparse()) {
    const auto values = table.values();
    return cpt<double>(std::move(child), std::move(parents), std::vector<double>(values.begin(), values.end()));
  }
  sparse_columns<double> columns;
  const auto stored = table.stored_configurations();
  columns.configurations.assign(stored.begin(), stored.end());
  for (const auto u : stored) {
    const auto column = table.column(index_at<config_index>(u));
    columns.values.insert(columns.values.end(), column.begin(), column.end());
  }
  columns.rest.assign(table.rest().begin(), table.rest().end());
  return cpt<double>(std::move(child), std::move(parents), std::move(columns));
}

PGM_DECL std::pair<std::string, long> slice_of_parent(const std::string& parent, const std::string& child) {
  const auto at = parent.rfind('@');
  if (at == std::string::npos) return {parent, 0};
  const auto name = parent.substr(0, at);
  const auto suffix = std::string_view(parent).substr(at + 1);
  long slice = 0;
  const auto* end = suffix.data() + suffix.size();
  const auto [last, error] = std::from_chars(suffix.data() + (suffix.starts_with('+') ? 1 : 0), end, slice);
  if (suffix.empty() || error != std::errc() || last != end) {
    throw model_error("the parent '" + parent + "' of '" + child +
                      "' names no slice: write 'Y' for this slice or 'Y@-1' for the one before");
  }
  if (slice > 0 || (slice == 0 && suffix.starts_with('+'))) {
    throw model_error("the parent '" + parent + "' of '" + child +
                      "' lies in a later slice: a parent lies in the same slice or the one before");
  }
  if (slice < -1) {
    throw model_error("the parent '" + parent + "' of '" + child + "' lies " + std::to_string(-slice) +
                      " slices back: pgm's dynamic networks are of order 1 (a parent in the same slice or the "
                      "one before)");
  }
  return {name, slice};
}

}  // namespace detail

PGM_DECL dynamic_network::dynamic_network(bayesian_network initial, std::vector<cpt<double>> transition)
    : initial_(std::move(initial)) {
  const auto& templates = initial_.variables();
  for (const auto& v : templates) {
    if (v.name().find('@') != std::string::npos) {
      throw model_error("the template variable '" + v.name() + "' has '@' in its name, which marks a slice");
    }
  }
  transition_ = two_slices(templates);

  std::vector<std::optional<cpt<double>>> by_variable(templates.size());
  for (auto& table : transition) {
    const auto& child = table.child().name();
    if (!initial_.structure().contains(child)) {
      throw model_error("the transition has a table for '" + child + "', which is not a variable of the first slice");
    }
    const auto node = initial_.id(child);
    if (by_variable[node.value()]) throw model_error("the transition has two tables for '" + child + "'");
    if (table.child().states() != templates[node.value()].states()) {
      throw model_error("the transition table of '" + child + "' has other states than the first slice's '" + child +
                        "'");
    }
    std::vector<variable> parents;
    for (const auto& parent : table.parents()) {
      const auto [name, slice] = detail::slice_of_parent(parent.name(), child);
      if (!initial_.structure().contains(name)) {
        throw model_error("the parent '" + parent.name() + "' of '" + child + "' names no template variable");
      }
      const auto& held = transition_.at(slice == 0 ? name : slice_name(name, -1));
      if (parent.states() != held.states()) {
        throw model_error("the parent '" + parent.name() + "' of '" + child + "' has other states than '" + name +
                          "' in the first slice");
      }
      transition_.add_edge(held.name(), child);
      parents.push_back(held);
    }
    by_variable[node.value()] = detail::renamed(table, templates[node.value()], std::move(parents));
  }
  for (std::size_t i = 0; i < templates.size(); ++i) {
    if (!by_variable[i]) {
      throw model_error("the transition has no table for '" + templates[i].name() +
                        "': every variable of the first slice needs one");
    }
    tables_.push_back(std::move(*by_variable[i]));
  }
}

PGM_DECL network_structure dynamic_network::two_slices(const std::vector<variable>& templates) {
  std::vector<variable> both;
  for (const auto& v : templates) both.push_back(detail::renamed(v, slice_name(v.name(), -1)));
  both.insert(both.end(), templates.begin(), templates.end());
  return network_structure(std::move(both));
}

PGM_DECL bayesian_network dynamic_network::unroll(std::size_t slices, char separator) const {
  if (slices == 0) throw model_error("a dynamic network unrolls over at least one slice");
  if (slices > max_unrolled_variables / std::max<std::size_t>(size(), 1)) {
    throw model_error("unrolling " + std::to_string(slices) + " slices of " + std::to_string(size()) +
                      " variables makes more variables than pgm's limit of " + std::to_string(max_unrolled_variables) +
                      " (docs/limits.md)");
  }
  const auto& templates = variables();
  // The variables of each slice, built once: X@t for every template variable X.
  std::vector<std::vector<variable>> at(slices);
  for (std::size_t t = 0; t < slices; ++t) {
    for (const auto& v : templates) {
      at[t].push_back(detail::renamed(v, slice_name(v.name(), static_cast<long>(t), separator)));
    }
  }
  std::vector<cpt<double>> tables;
  tables.reserve(slices * templates.size());
  for (std::size_t i = 0; i < templates.size(); ++i) {
    const auto& first = initial_.tables()[i];
    std::vector<variable> parents;
    for (const auto& p : first.parents()) parents.push_back(at[0][initial_.id(p.name()).value()]);
    tables.push_back(detail::renamed(first, at[0][i], std::move(parents)));
  }
  for (std::size_t t = 1; t < slices; ++t) {
    for (std::size_t i = 0; i < templates.size(); ++i) {
      const auto& table = tables_[i];
      std::vector<variable> parents;
      for (const auto& p : table.parents()) {
        const auto node = transition_.id(p.name()).value();
        // The first size() variables of the two-slice network are the previous slice's.
        parents.push_back(node < size() ? at[t - 1][node] : at[t][node - size()]);
      }
      tables.push_back(detail::renamed(table, at[t][i], std::move(parents)));
    }
  }
  return bayesian_network::from_tables(std::move(tables));
}

}  // namespace pgm
