#pragma once
// The definitions of pgm/eval/scenario.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/scenario.hpp"

namespace pgm::detail {

PGM_DECL scenario scenario_reader::read(std::string_view text) const {
  const auto doc = parse(text);
  check_format(doc, "pgm-scenario");
  only_keys(doc, "",
            {"format", "version", "name", "title", "order", "prior", "target", "map", "strategies", "weights", "bins",
             "subsets", "repetitions", "epsilon"});
  scenario s;
  s.name = string(member(doc, "", "name"), "/name");
  s.title = string(member(doc, "", "title"), "/title");
  const auto& prior = member(doc, "", "prior");
  only_keys(prior, "/prior", {"task", "rows", "node"});
  s.prior_task = string(member(prior, "/prior", "task"), "/prior/task");
  s.prior_rows = rows(member(prior, "/prior", "rows"), "/prior/rows");
  if (s.prior_rows == 0) fail("/prior/rows", "the prior needs at least one row");
  s.prior_node = string(member(prior, "/prior", "node"), "/prior/node");
  const auto& target = member(doc, "", "target");
  only_keys(target, "/target", {"node", "tasks"});
  s.target_node = string(member(target, "/target", "node"), "/target/node");
  std::size_t i = 0;
  for (const auto& t : array(member(target, "/target", "tasks"), "/target/tasks")) {
    const std::string path = "/target/tasks/" + std::to_string(i++);
    only_keys(t, path, {"task", "train_rows", "ground_truth_rows"});
    s.targets.push_back({string(member(t, path, "task"), path + "/task"),
                         rows(member(t, path, "train_rows"), path + "/train_rows"),
                         rows(member(t, path, "ground_truth_rows"), path + "/ground_truth_rows")});
    if (s.targets.back().train_rows == 0 || s.targets.back().ground_truth_rows == 0) {
      fail(path, "train_rows and ground_truth_rows must be positive");
    }
  }
  if (s.targets.empty()) fail("/target/tasks", "needs at least one target task");
  s.map = string(member(doc, "", "map"), "/map");
  s.strategies = strings(member(doc, "", "strategies"), "/strategies");
  if (s.strategies.empty()) fail("/strategies", "needs at least one strategy");
  s.weights = numbers(member(doc, "", "weights"), "/weights");
  for (double w : s.weights) {
    if (!(w >= 0) || !std::isfinite(w)) fail("/weights", "weights must be finite and ≥ 0");
  }
  if (const auto* v = optional_member(doc, "bins")) s.bins = count(*v, "/bins");
  if (const auto* v = optional_member(doc, "subsets")) s.subsets = count(*v, "/subsets");
  if (const auto* v = optional_member(doc, "repetitions")) s.repetitions = count(*v, "/repetitions");
  if (const auto* v = optional_member(doc, "epsilon")) s.epsilon = number(*v, "/epsilon");
  if (const auto* v = optional_member(doc, "order")) s.order = count(*v, "/order");
  if (s.bins < 2) fail("/bins", "needs at least 2 bins");
  if (s.subsets == 0 || s.repetitions == 0) fail("/subsets", "subsets and repetitions must be positive");
  if (s.repetitions > max_repetitions) {
    fail("/repetitions", std::to_string(s.repetitions) + " are more than " + std::to_string(max_repetitions) +
                             ", pgm's limit of repetitions (docs/limits.md)");
  }
  if (s.subsets > max_subsets) {
    fail("/subsets", std::to_string(s.subsets) + " are more than " + std::to_string(max_subsets) +
                         ", pgm's limit of subsets (docs/limits.md)");
  }
  if (!(s.epsilon > 0 && s.epsilon < 1)) fail("/epsilon", "must lie strictly between 0 and 1");
  return s;
}

PGM_DECL std::size_t scenario_reader::rows(const nlohmann::json& value, const std::string& path) const {
  const auto number = count(value, path);
  if (number > max_simulated_rows) {
    fail(path, std::to_string(number) + " rows are more than " + std::to_string(max_simulated_rows) +
                   ", pgm's limit of rows to simulate (docs/limits.md)");
  }
  return number;
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL scenario parse_scenario(std::string_view text, const std::string& source) {
  auto s = detail::scenario_reader(source).read(text);
  s.source = source;
  return s;
}

}  // namespace pgm
