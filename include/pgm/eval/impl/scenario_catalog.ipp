#pragma once
// The definitions of pgm/eval/scenario_catalog.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/scenario_catalog.hpp"

namespace pgm {

PGM_DECL std::filesystem::path find_scenario_folder(const std::vector<std::filesystem::path>& task_folders) {
  std::error_code ec;
  for (const auto& folder : task_folders) {
    if (std::filesystem::is_directory(folder / "scenarios", ec)) return folder / "scenarios";
  }
  std::vector<std::string> names;
  for (const auto& folder : task_folders) names.push_back(folder.string());
  throw io_error("no scenarios folder under the task folders (" + text::list_for_message(names) +
                 "); give --tasks-dir");
}

PGM_DECL scenario_catalog::scenario_catalog(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    auto s = load_scenario(file);
    for (const auto& other : scenarios_) {
      if (other.name == s.name) {
        throw data_error("the scenario name '" + s.name + "' is used by both " + other.source.string() + " and " +
                         s.source.string());
      }
    }
    scenarios_.push_back(std::move(s));
  }
  // Files are sorted by name already, so a stable sort leaves ties in file order.
  std::stable_sort(scenarios_.begin(), scenarios_.end(), [](const scenario& a, const scenario& b) {
    if (a.order.has_value() != b.order.has_value()) return a.order.has_value();
    return a.order.has_value() && *a.order < *b.order;
  });
}

PGM_DECL std::vector<std::string> scenario_catalog::names() const {
  std::vector<std::string> result;
  for (const auto& s : scenarios_) result.push_back(s.name);
  return result;
}

PGM_DECL const scenario& scenario_catalog::at(std::string_view name) const {
  for (const auto& s : scenarios_) {
    if (s.name == name) return s;
  }
  auto known = names();
  known.emplace_back("all");
  throw unknown_name("scenario", std::string(name), std::move(known));
}

PGM_DECL std::vector<scenario> select_scenarios(std::string_view name, const std::filesystem::path& folder) {
  const auto own_file = folder / (std::string(name) + ".json");
  std::error_code ec;
  if (name != "all" && std::filesystem::is_regular_file(own_file, ec)) {
    auto s = load_scenario(own_file);
    if (s.name == name) return {std::move(s)};
  }
  const scenario_catalog catalog(folder);
  if (name == "all") return catalog.scenarios();
  return {catalog.at(name)};
}

}  // namespace pgm
