#pragma once
/// \file
/// Finding tasks by name: the directories searched by default ($PGM_TASKS_DIR, the source
/// tree's tasks/, the installed share/pgm/tasks), the tasks they hold, and loading one by name.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "pgm/config.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/sim/task.hpp"
#include "pgm/sim/task_file.hpp"

namespace pgm::sim {

/// Where tasks are looked for, in order: $PGM_TASKS_DIR, then the source tree's tasks/ (from
/// a build tree), then the installed ones (pgm/config.hpp).
[[nodiscard]] inline std::vector<std::filesystem::path> default_task_directories() {
  std::vector<std::filesystem::path> result;
  if (const char* env = std::getenv("PGM_TASKS_DIR"); env && *env) result.emplace_back(env);
  if (*config::source_tasks_dir) result.emplace_back(config::source_tasks_dir);
  result.emplace_back(config::installed_tasks_dir);
  return result;
}

/// Names of the tasks (`<name>.json`) in the directories, sorted, without repeats.
[[nodiscard]] inline std::vector<std::string> list_tasks(const std::vector<std::filesystem::path>& directories) {
  std::vector<std::string> names;
  for (const auto& dir : directories) {
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      if (it->path().extension() == ".json") names.push_back(it->path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

/// The file of task `name` in the first directory that has it; throws data_error listing
/// the known tasks otherwise.
[[nodiscard]] inline std::filesystem::path find_task(std::string_view name,
                                                     const std::vector<std::filesystem::path>& directories) {
  if (directories.empty()) {
    throw data_error("no task directory is known; give one with --tasks-dir or PGM_TASKS_DIR");
  }
  for (const auto& dir : directories) {
    const auto candidate = dir / (std::string(name) + ".json");
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
  }
  std::vector<std::string> where;
  for (const auto& dir : directories) where.push_back(dir.string());
  throw unknown_name("task", std::string(name), list_tasks(directories), "looked in " + pgm::detail::join(where));
}

/// Loads task `name` from the first directory that has it.
[[nodiscard]] inline task_definition load_task(std::string_view name,
                                               const std::vector<std::filesystem::path>& directories) {
  return load_task(find_task(name, directories));
}

}  // namespace pgm::sim
