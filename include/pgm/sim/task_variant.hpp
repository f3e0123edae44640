#pragma once
/// \file
/// A task by name and variant, as `pgm simulate --task --variant` and the Python
/// `pgm.simulate(task, variant=)` name it: "2-stack" with variant "reality" is the task file
/// "2-stack-reality" (the stand-in for the real robot, not real data).

#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/sim/task.hpp"
#include "pgm/sim/task_lookup.hpp"

namespace pgm::sim {

/// The name of `task`'s `variant` ("sim" or "reality"). Throws pgm::error for another variant,
/// or a reality task ("2-stack-reality") asked for as "sim".
[[nodiscard]] inline std::string task_variant_name(std::string_view task, std::string_view variant) {
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

/// Loads `task`'s `variant` from the first directory that has it. Throws unknown_name for an
/// unknown task, data_error for a task without a reality variant.
[[nodiscard]] inline task_definition load_task_variant(std::string_view task, std::string_view variant,
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
