#pragma once
// The definitions of pgm/io/dot.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/io/dot.hpp"

namespace pgm::detail {

PGM_DECL std::string dot_quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    // Graphviz reads HTML entities in every string: "R&amp;D" would be drawn as R&D.
    if (c == '&') {
      out += "&amp;";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL std::string to_dot(const network_structure& structure, const dot_options& options) {
  const auto require = [&](const std::string& name, const char* what) {
    if (!structure.contains(name)) {
      throw model_error(std::string(what) + " '" + name + "' is not a variable of the network");
    }
  };
  for (const auto& name : options.success) require(name, "the success variable");
  for (const auto& name : options.controllable) require(name, "the controllable variable");
  const std::set<std::string> success(options.success.begin(), options.success.end());
  const std::set<std::string> controllable(options.controllable.begin(), options.controllable.end());
  std::set<std::pair<std::string, std::string>> undirected;
  for (const auto& [a, b] : options.undirected) {
    undirected.emplace(a, b);
    undirected.emplace(b, a);
  }

  std::ostringstream out;
  out << "digraph network {\n"
         "  graph [rankdir=TB, nodesep=0.35, ranksep=0.55, fontname=\"Helvetica\"];\n"
         "  node [shape=ellipse, style=filled, fillcolor=\"#f2f2f2\", color=\"#595959\", "
         "fontname=\"Helvetica\", fontsize=12];\n"
         "  edge [color=\"#404040\", arrowsize=0.7, fontname=\"Helvetica\", fontsize=10];\n";
  for (const auto& v : structure.variables()) {
    out << "  " << detail::dot_quoted(v.name())
        << " [label=" << detail::dot_quoted(v.name() + "\n" + std::to_string(v.cardinality()) + " states");
    if (success.contains(v.name())) {
      out << ", shape=doubleoctagon, fillcolor=\"#d5f0d5\", color=\"#2e7d32\", penwidth=2";
    } else if (controllable.contains(v.name())) {
      out << ", shape=box, style=\"rounded,filled\", fillcolor=\"#dbe8f7\", color=\"#1f5fa6\"";
    }
    out << "];\n";
  }
  for (const auto& edge : structure.edges()) {
    out << "  " << detail::dot_quoted(edge.from) << " -> " << detail::dot_quoted(edge.to);
    std::vector<std::string> attributes;
    if (undirected.contains({edge.from, edge.to})) attributes.emplace_back("dir=none");
    if (const auto found = options.strength.find({edge.from, edge.to}); found != options.strength.end()) {
      char label[16];
      std::snprintf(label, sizeof label, "%.2f", found->second);
      char width[16];
      std::snprintf(width, sizeof width, "%.2f", 0.5 + 3.5 * std::clamp(found->second, 0.0, 1.0));
      attributes.push_back(std::string("penwidth=") + width);
      attributes.push_back(std::string("label=\"") + label + "\"");
    }
    if (!attributes.empty()) {
      out << " [";
      for (std::size_t k = 0; k < attributes.size(); ++k) out << (k ? ", " : "") << attributes[k];
      out << "]";
    }
    out << ";\n";
  }
  out << "}\n";
  return out.str();
}

}  // namespace pgm
