#pragma once
// The definitions of pgm/sim/task_variant.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/task_variant.hpp"

namespace pgm::sim {

PGM_DECL std::string task_variant_name(std::string_view task, std::string_view variant) {
  constexpr std::string_view suffix = "-reality";
  if (const auto known = known_task_variants(); std::find(known.begin(), known.end(), variant) == known.end()) {
    throw unknown_name("variant", std::string(variant), known);
  }
  const bool named_reality = task.size() > suffix.size() && task.ends_with(suffix);
  if (variant == "reality" && !named_reality) return std::string(task) + std::string(suffix);
  if (variant == "sim" && named_reality) {
    throw error("task '" + std::string(task) + "' is a reality variant; leave out the variant or ask for reality");
  }
  return std::string(task);
}

PGM_DECL task_definition load_task_variant(std::string_view task, std::string_view variant,
                                           const std::vector<std::filesystem::path>& directories) {
  const auto name = task_variant_name(task, variant);
  if (variant == "reality") {
    try {
      static_cast<void>(find_task(name, directories));
    } catch (const unknown_name&) {
      static_cast<void>(find_task(task, directories));  // an unknown base task is reported as such
      throw data_error("task '" + std::string(task) + "' has no reality variant ('" + name + "' is not defined)");
    }
  }
  return load_task(name, directories);
}

}  // namespace pgm::sim
