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

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/eval/scenario.hpp"

namespace pgm {

/// The `scenarios` folder of the first task folder that has one; io_error naming the folders
/// looked in otherwise.
[[nodiscard]] PGM_DECL std::filesystem::path find_scenario_folder(
    const std::vector<std::filesystem::path>& task_folders);

/// Every scenario file of one folder, in run order.
class scenario_catalog {
 public:
  /// Loads `folder/*.json`; a file that does not read, or two files with one scenario name,
  /// is an error naming the files.
  PGM_DECL explicit scenario_catalog(const std::filesystem::path& folder);

  [[nodiscard]] const std::vector<scenario>& scenarios() const noexcept { return scenarios_; }

  /// The scenario names in run order.
  [[nodiscard]] PGM_DECL std::vector<std::string> names() const;

  /// The scenario of that name; an error listing the known names otherwise.
  [[nodiscard]] PGM_DECL const scenario& at(std::string_view name) const;

 private:
  std::vector<scenario> scenarios_;
};

/// `"all"`: every scenario of the folder in run order; otherwise the one of that name. A named
/// scenario is read from `<name>.json` alone when that file holds it, so that a broken file
/// elsewhere in the folder does not stop it.
[[nodiscard]] PGM_DECL std::vector<scenario> select_scenarios(std::string_view name,
                                                              const std::filesystem::path& folder);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/scenario_catalog.ipp"
#endif
