#pragma once
// The definitions of pgm/learn/learn_dynamic_structure.hpp: inline in a header-only build, compiled
// once into libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/learn_dynamic_structure.hpp"

namespace pgm::detail {

PGM_DECL structure_context two_slice_context(const std::vector<variable>& templates, structure_context context) {
  for (const auto& into : templates) {
    const auto previous = slice_name(into.name(), -1);
    for (const auto& from : templates) {
      context.knowledge.forbidden.push_back({from.name(), previous});
      if (from.name() != into.name()) context.knowledge.forbidden.push_back({slice_name(from.name(), -1), previous});
    }
  }
  return context;
}

PGM_DECL std::vector<variable> template_variables(const dataset& data, std::span<const std::string> names) {
  std::vector<variable> templates;
  for (const auto& name : names) templates.push_back(data.discrete(name).var());
  return templates;
}

}  // namespace pgm::detail
