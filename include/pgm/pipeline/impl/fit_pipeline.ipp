#pragma once
// The definitions of pgm/pipeline/fit_pipeline.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/pipeline/fit_pipeline.hpp"

namespace pgm {

PGM_DECL std::vector<std::string> columns_of(const std::vector<named_edge>& edges) {
  std::vector<std::string> columns;
  for (const auto& e : edges) {
    for (const auto* name : {&e.from, &e.to}) {
      if (std::find(columns.begin(), columns.end(), *name) == columns.end()) columns.push_back(*name);
    }
  }
  return columns;
}

}  // namespace pgm

namespace pgm::detail {

PGM_DECL std::vector<family_names> families_of(const network_structure& structure) {
  std::vector<family_names> families;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    family_names family{structure.at(node).name(), {}};
    for (const auto& parent : structure.parent_variables(node)) family.parents.push_back(parent.name());
    families.push_back(std::move(family));
  }
  return families;
}

PGM_DECL const latent_variable* latent_named(const fit_request& request, std::string_view name) {
  const auto found = std::find_if(request.latent.begin(), request.latent.end(),
                                  [&](const latent_variable& v) { return v.name == name; });
  return found == request.latent.end() ? nullptr : &*found;
}

PGM_DECL const variable* known_states(const fit_request& request, std::string_view name) {
  if (const auto found = request.intervals.find(name); found != request.intervals.end()) return &found->second;
  if (const auto found = request.states.find(name); found != request.states.end()) return &found->second;
  return nullptr;
}

}  // namespace pgm::detail
