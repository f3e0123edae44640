#pragma once
// Internal to the compiled readers (xmlbif.cpp, net.cpp): what they share once a file's syntax
// is read — positions from offsets, pgm's properties, and tables checked and normalized.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/core/text.hpp"
#include "pgm/io/read_options.hpp"

namespace pgm::detail {

struct text_position {
  std::size_t line = 1;
  std::size_t column = 1;
};

/// Line and column (from 1) of byte `offset` of `text`.
[[nodiscard]] inline text_position position_of(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  text_position at;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++at.line;
      line_start = i + 1;
    }
  }
  at.column = offset - line_start + 1;
  return at;
}

/// A variable as a file declares it, with where it does so.
struct declared_variable {
  std::string name;
  std::vector<std::string> states;
  semantic_tags tags;
  std::optional<std::vector<double>> edges;
  text_position at;
};

/// A table as a file gives it: parents by name, values parent configuration major.
struct declared_table {
  std::string child;
  std::vector<std::pair<std::string, text_position>> parents;
  std::vector<double> values;
  /// The values the file gives: more than `values` holds when they overflow the table.
  std::size_t values_given = 0;
  text_position at;         // the child's name
  text_position values_at;  // the values

  /// Takes a value of the file. Past the table's `cells` (known when its variables are declared
  /// already, check_table_cells) values are counted for build_network's message, not kept, so a
  /// list far longer than its table takes no memory; with `cells` unknown, false past
  /// max_table_cells, where the reader refuses the table.
  [[nodiscard]] bool add_value(double value, std::optional<std::size_t> cells) {
    ++values_given;
    if (values_given <= cells.value_or(max_table_cells)) {
      values.push_back(value);
      return true;
    }
    return cells.has_value();
  }
};

/// The variable `name` among `declared`, or null.
[[nodiscard]] inline const declared_variable* find_declared(const std::vector<declared_variable>& declared,
                                                            const std::string& name) {
  for (const auto& v : declared) {
    if (v.name == name) return &v;
  }
  return nullptr;
}

/// The cells of a table whose child and parents are declared already, refusing through
/// `fail(at, message)` a table beyond max_table_cells whose child and parents
/// are declared already, before its values are read; a table with an undeclared member is
/// left to build_network (and its values to the readers' own bound of max_table_cells).
template <class Fail>
std::optional<std::size_t> check_table_cells(const std::vector<declared_variable>& declared, const std::string& child,
                                             const std::vector<std::pair<std::string, text_position>>& parents,
                                             text_position at, Fail&& fail) {
  const auto* v = find_declared(declared, child);
  if (v == nullptr || v->states.empty()) return std::nullopt;
  std::vector<std::size_t> cards;
  for (const auto& [parent, where] : parents) {
    const auto* p = find_declared(declared, parent);
    if (p == nullptr || p->states.empty()) return std::nullopt;
    cards.push_back(p->states.size());
  }
  try {
    return checked_table_cells(child, v->states.size(), mixed_radix(cards).size());
  } catch (const model_error& e) {
    fail(at, e.what());
  }
  return std::nullopt;  // not reached: `fail` throws
}

/// Sets a pgm property (edges, quantity, unit, role) of `v`; other keys are left to the caller.
/// Returns false for a key pgm does not know; throws the message for bad edges.
inline bool apply_pgm_property(declared_variable& v, std::string_view key, std::string_view value,
                               const std::string& edge_separators) {
  if (key == "quantity") {
    v.tags.quantity = std::string(value);
  } else if (key == "unit") {
    v.tags.unit = std::string(value);
  } else if (key == "role") {
    v.tags.role = std::string(value);
  } else if (key == "edges") {
    std::vector<double> edges;
    std::string piece;
    auto flush = [&] {
      if (piece.empty()) return;
      const auto number = text::parse_double(piece);
      if (!number) throw model_error("the edges of '" + v.name + "' must be numbers, found '" + piece + "'");
      edges.push_back(*number);
      piece.clear();
    };
    for (const char c : value) {
      if (edge_separators.find(c) != std::string::npos) {
        flush();
      } else {
        piece += c;
      }
    }
    flush();
    v.edges = std::move(edges);
  } else {
    return false;
  }
  return true;
}

/// Builds the network, failing through `fail(position, message)` ([[noreturn]]) at the place a
/// problem comes from. Tables are matched to variables by name, in any order.
template <class Fail>
bayesian_network build_network(const std::vector<declared_variable>& declared, std::vector<declared_table> tables,
                               const std::string& source, const network_read_options& options, Fail&& fail) {
  std::vector<variable> variables;
  for (const auto& d : declared) {
    try {
      variable v(d.name, d.states, d.tags);
      if (d.edges) v.set_edges(*d.edges);
      variables.push_back(std::move(v));
    } catch (const model_error& e) {
      fail(d.at, e.what());
    }
  }
  auto index_of = [&](const std::string& name) -> std::optional<std::size_t> {
    for (std::size_t i = 0; i < declared.size(); ++i) {
      if (declared[i].name == name) return i;
    }
    return std::nullopt;
  };
  std::vector<std::optional<declared_table>> by_variable(declared.size());
  for (auto& table : tables) {
    const auto i = index_of(table.child);
    if (!i) fail(table.at, "a table for '" + table.child + "', which is not declared");
    if (by_variable[*i]) fail(table.at, "'" + table.child + "' has two tables");
    for (const auto& [parent, at] : table.parents) {
      if (!index_of(parent)) fail(at, "parent '" + parent + "' of '" + table.child + "' is not declared");
    }
    by_variable[*i] = std::move(table);
  }
  network_structure structure;
  try {
    structure = network_structure(variables);
  } catch (const model_error& e) {
    fail(declared.empty() ? text_position{} : declared.front().at, e.what());
  }
  for (std::size_t i = 0; i < declared.size(); ++i) {
    if (!by_variable[i]) fail(declared[i].at, "variable '" + declared[i].name + "' has no table");
    for (const auto& [parent, at] : by_variable[i]->parents) {
      try {
        structure.add_edge(parent, declared[i].name);
      } catch (const error& e) {
        fail(at, "the table of '" + declared[i].name + "' cannot take '" + parent + "' as a parent: " + e.what());
      }
    }
  }
  column_normalizer normalizer(options.tolerance);
  std::vector<cpt<double>> cpts;
  for (std::size_t i = 0; i < declared.size(); ++i) {
    auto& table = *by_variable[i];
    std::vector<variable> parents;
    std::vector<std::size_t> cards;
    for (const auto& [parent, at] : table.parents) {
      parents.push_back(variables[*index_of(parent)]);
      cards.push_back(parents.back().cardinality());
    }
    const auto j = variables[i].cardinality();
    std::size_t expected = j;
    try {
      expected = checked_table_cells(variables[i].name(), j, mixed_radix(cards).size());
    } catch (const model_error& e) {
      fail(table.at, e.what());
    }
    if (table.values_given != expected) {
      fail(table.values_at, "expected " + std::to_string(expected) + " probabilities for '" + table.child + "' (" +
                                std::to_string(j) + " states × " + std::to_string(expected / j) +
                                " parent configurations), found " + std::to_string(table.values_given));
    }
    if (const auto bad = normalizer.normalize(table.values, j)) {
      const auto codes = mixed_radix(cards).decode(bad->first);
      std::string where;
      for (std::size_t p = 0; p < codes.size(); ++p) {
        where += (p ? ", " : " given ") + parents[p].name() + " = " + parents[p].states()[codes[p]];
      }
      fail(table.values_at,
           normalizer.refusal(table.child, bad->second) + (where.empty() ? "" : " (" + where.substr(1) + ")"));
    }
    try {
      cpts.emplace_back(variables[i], std::move(parents), std::move(table.values));
    } catch (const model_error& e) {
      fail(table.values_at, e.what());
    }
  }
  normalizer.report(source, options.notes);
  return bayesian_network(std::move(structure), std::move(cpts));
}

}  // namespace pgm::detail
