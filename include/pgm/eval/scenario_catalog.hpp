#pragma once
/// \file
/// The scenarios a task folder offers: every `scenarios/*.json` under it, loaded, checked for
/// repeated names and put in the order their files give (`"order"`, see tasks/README.md), so
/// that `--scenario all` runs them as the paper lists them without the program knowing names.

#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/eval/scenario.hpp"

namespace pgm {

/// The `scenarios` folder of the first task folder that has one; io_error naming the folders
/// looked in otherwise.
[[nodiscard]] inline std::filesystem::path find_scenario_folder(
    const std::vector<std::filesystem::path>& task_folders) {
  std::error_code ec;
  for (const auto& folder : task_folders) {
    if (std::filesystem::is_directory(folder / "scenarios", ec)) return folder / "scenarios";
  }
  std::vector<std::string> names;
  for (const auto& folder : task_folders) names.push_back(folder.string());
  throw io_error("no scenarios folder under the task folders (" + detail::list_for_message(names) +
                 "); give --tasks-dir");
}

/// Every scenario file of one folder, in run order.
class scenario_catalog {
 public:
  /// Loads `folder/*.json`; a file that does not read, or two files with one scenario name,
  /// is an error naming the files.
  explicit scenario_catalog(const std::filesystem::path& folder) {
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

  [[nodiscard]] const std::vector<scenario>& scenarios() const noexcept { return scenarios_; }

  /// The scenario names in run order.
  [[nodiscard]] std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (const auto& s : scenarios_) result.push_back(s.name);
    return result;
  }

  /// The scenario of that name; an error listing the known names otherwise.
  [[nodiscard]] const scenario& at(std::string_view name) const {
    for (const auto& s : scenarios_) {
      if (s.name == name) return s;
    }
    auto known = names();
    known.emplace_back("all");
    throw unknown_name("scenario", std::string(name), std::move(known));
  }

 private:
  std::vector<scenario> scenarios_;
};

/// `"all"`: every scenario of the folder in run order; otherwise the one of that name. A named
/// scenario is read from `<name>.json` alone when that file holds it, so that a broken file
/// elsewhere in the folder does not stop it.
[[nodiscard]] inline std::vector<scenario> select_scenarios(std::string_view name,
                                                            const std::filesystem::path& folder) {
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
