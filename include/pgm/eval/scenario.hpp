#pragma once
/// \file
/// A transfer scenario (one row of the paper's Table II) as data: the prior task and its data
/// size, the target tasks with their training and ground-truth sizes, the transferred node pair
/// and correspondences, the strategies and weights, and the protocol's repetitions and subsets.
/// Files live in `tasks/scenarios/<name>.json`; tasks/README.md documents the format.

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/detail/json_reader.hpp"

namespace pgm {

struct scenario_target {
  std::string task;
  std::size_t train_rows = 0;         ///< |D|, cut into `subsets` parts
  std::size_t ground_truth_rows = 0;  ///< |D_GroundTruth|
};

struct scenario {
  std::string name;   ///< as on the command line, e.g. "2-stack-sim"
  std::string title;  ///< as in the paper, e.g. "2-Stack-Simulation"
  std::string prior_task;
  std::size_t prior_rows = 0;  ///< |D′|
  std::string prior_node;
  std::vector<scenario_target> targets;
  std::string target_node;
  std::string map;  ///< correspondence map, pgm::parse_correspondence syntax
  std::vector<std::string> strategies;
  std::vector<double> weights;  ///< 0 is MLE
  std::size_t bins = 5;
  std::size_t subsets = 20;
  std::size_t repetitions = 20;
  double epsilon = 0.8;
  /// Where `--scenario all` runs it (pgm::scenario_catalog): ascending; scenarios without one
  /// come after those with one. Ties and missing orders go by file name.
  std::optional<std::size_t> order;
  std::filesystem::path source;
};

namespace detail {

class scenario_reader : public json_reader {
 public:
  using json_reader::json_reader;

  PGM_DECL scenario read(std::string_view text) const;

 private:
  std::size_t count(const nlohmann::json& value, const std::string& path) const {
    if (!value.is_number_unsigned()) fail(path, "expected a whole number ≥ 0");
    return value.get<std::size_t>();
  }
  /// Rows to simulate: a count within max_simulated_rows.
  PGM_DECL std::size_t rows(const nlohmann::json& value, const std::string& path) const;
};

}  // namespace detail

[[nodiscard]] PGM_DECL scenario parse_scenario(std::string_view text, const std::string& source);

[[nodiscard]] inline scenario load_scenario(const std::filesystem::path& path) {
  return parse_scenario(pgm::read_file(path), path.string());
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/scenario.ipp"
#endif
