#pragma once
// The definitions of pgm/sim/task_lookup.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/task_lookup.hpp"

namespace pgm::sim {

PGM_DECL std::vector<std::filesystem::path> default_task_directories() {
  std::vector<std::filesystem::path> result;
  if (const char* env = std::getenv("PGM_TASKS_DIR"); env && *env) result.emplace_back(env);
  if (*config::source_tasks_dir) result.emplace_back(config::source_tasks_dir);
  result.emplace_back(config::installed_tasks_dir);
  return result;
}

PGM_DECL std::vector<std::string> list_tasks(const std::vector<std::filesystem::path>& directories) {
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

PGM_DECL std::filesystem::path find_task(std::string_view name, const std::vector<std::filesystem::path>& directories) {
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
  throw unknown_name("task", std::string(name), list_tasks(directories), "looked in " + pgm::text::join(where));
}

}  // namespace pgm::sim
