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
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/sim/task.hpp"
#include "pgm/sim/task_file.hpp"

namespace pgm::sim {

/// Where tasks are looked for, in order: $PGM_TASKS_DIR, then the source tree's tasks/ (from
/// a build tree), then the installed ones (pgm/config.hpp).
[[nodiscard]] PGM_DECL std::vector<std::filesystem::path> default_task_directories();

/// Names of the tasks (`<name>.json`) in the directories, sorted, without repeats.
[[nodiscard]] PGM_DECL std::vector<std::string> list_tasks(const std::vector<std::filesystem::path>& directories);

/// The file of task `name` in the first directory that has it; throws data_error listing
/// the known tasks otherwise.
[[nodiscard]] PGM_DECL std::filesystem::path find_task(std::string_view name,
                                                       const std::vector<std::filesystem::path>& directories);

/// Loads task `name` from the first directory that has it.
[[nodiscard]] inline task_definition load_task(std::string_view name,
                                               const std::vector<std::filesystem::path>& directories) {
  return load_task(find_task(name, directories));
}

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/task_lookup.ipp"
#endif
