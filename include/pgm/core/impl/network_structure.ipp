#pragma once
// The definitions of pgm/core/network_structure.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/network_structure.hpp"

namespace pgm {

PGM_DECL std::vector<variable> network_structure::parent_variables(variable_id node) const {
  std::vector<variable> result;
  for (auto parent : graph_.parents(node)) result.push_back(at(parent));
  return result;
}

PGM_DECL std::vector<named_edge> network_structure::edges() const {
  std::vector<named_edge> result;
  for (auto [from, to] : graph_.edges()) result.push_back({at(from).name(), at(to).name()});
  return result;
}

PGM_DECL void network_structure::update_variable(variable replacement) {
  const auto node = id(replacement.name());
  if (replacement.cardinality() != at(node).cardinality()) {
    throw model_error("variable '" + replacement.name() + "' has " + std::to_string(at(node).cardinality()) +
                      " states, the replacement " + std::to_string(replacement.cardinality()));
  }
  variables_[node.value()] = std::move(replacement);
}

PGM_DECL std::vector<named_edge> parse_edge_list(std::string_view text) {
  std::vector<named_edge> edges;
  std::size_t number = 0;
  for (const auto& piece : text::split(text, ',')) {
    ++number;
    const auto arrow = piece.find("->");
    const auto from =
        arrow == std::string::npos ? std::string_view{} : text::trim(std::string_view(piece).substr(0, arrow));
    const auto to =
        arrow == std::string::npos ? std::string_view{} : text::trim(std::string_view(piece).substr(arrow + 2));
    if (from.empty() || to.empty() || to.find("->") != std::string_view::npos) {
      throw model_error("edge " + std::to_string(number) + " ('" + piece + "') is not of the form 'from->to'");
    }
    edges.push_back({std::string(from), std::string(to)});
  }
  if (edges.empty()) throw model_error("the edge list is empty");
  return edges;
}

}  // namespace pgm
