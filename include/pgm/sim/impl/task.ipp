#pragma once
// The definitions of pgm/sim/task.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/task.hpp"

namespace pgm::sim {

PGM_DECL bool task_definition::contains(std::string_view variable_name) const {
  for (const auto& v : variables) {
    if (v.name == variable_name) return true;
  }
  return false;
}

PGM_DECL std::size_t task_definition::index(std::string_view variable_name) const {
  for (std::size_t i = 0; i < variables.size(); ++i) {
    if (variables[i].name == variable_name) return i;
  }
  throw data_error("task '" + name + "' has no variable '" + std::string(variable_name) + "'");
}

PGM_DECL std::vector<std::string> task_definition::names() const {
  std::vector<std::string> result;
  for (const auto& v : variables) result.push_back(v.name);
  return result;
}

PGM_DECL std::vector<std::string> task_definition::controllable() const {
  std::vector<std::string> result;
  for (const auto& v : variables) {
    if (v.controllable) result.push_back(v.name);
  }
  return result;
}

}  // namespace pgm::sim
