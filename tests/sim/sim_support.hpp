#pragma once
// Helpers for the simulator tests: loading the shipped tasks, pinning variables to fixed
// values, and success rates per configuration.

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pgm/core/file.hpp"
#include "pgm/sim/analytic_probability.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/task.hpp"
#include "pgm/sim/task_file.hpp"
#include "pgm/sim/task_lookup.hpp"

namespace pgm::sim::testing {

inline task_definition shipped(const std::string& name) {
  return load_task(std::filesystem::path(PGM_SOURCE_DIR) / "tasks" / (name + ".json"));
}

/// 2-Stack with a third cube (xOff3, yOff3, dropOff3, colorUp3, onTop3) released on the
/// second one, the same way, and onTop3 as success.
inline task_definition three_stack() {
  auto doc = nlohmann::json::parse(pgm::read_file(std::filesystem::path(PGM_SOURCE_DIR) / "tasks" / "2-stack.json"));
  doc["name"] = "3-stack";
  auto& variables = doc["variables"];
  const auto count = variables.size();
  for (std::size_t i = 0; i < count; ++i) {
    auto v = variables[i];
    const std::string name = v["name"];
    if (name.back() != '2') continue;
    v["name"] = name.substr(0, name.size() - 1) + "3";
    v["role"] = "cubeUp3";
    variables.push_back(v);
  }
  doc["success"] = "onTop3";
  for (const auto* parent : {"xOff1", "yOff1", "xOff2", "yOff2", "xOff3", "yOff3"}) {
    doc["structure"].push_back(std::string(parent) + " -> onTop3");
  }
  return parse_task(doc.dump(), "3-stack.json");
}

/// The task with each named variable fixed to a value.
inline task_definition pinned(task_definition task, const std::map<std::string, double>& values) {
  for (const auto& [name, value] : values) {
    auto& v = task.variables[task.index(name)];
    v.sampling = distribution{};
    v.sampling.kind = distribution_kind::constant;
    v.sampling.values = {value};
  }
  return task;
}

inline double success_rate(const dataset& data, const std::string& outcome) {
  const auto& c = data.discrete(outcome);
  double n = 0;
  for (std::size_t row = 0; row < data.rows(); ++row) n += c.code(row);
  return data.rows() ? n / static_cast<double>(data.rows()) : 0.0;
}

inline double rate(const task_definition& task, const std::string& backend, std::size_t rows, std::uint64_t seed = 7,
                   const std::string& outcome = {}) {
  simulate_options o;
  o.backend = backend;
  o.rows = rows;
  o.seed = seed;
  o.threads = 2;
  return success_rate(simulate(task, o), outcome.empty() ? task.success : outcome);
}

/// Success count and rows per configuration of binned variables (edges per variable).
struct box_counts {
  std::vector<double> successes;
  std::vector<double> rows;
};

inline box_counts count_by_box(const dataset& data, const std::string& outcome, const std::vector<std::string>& names,
                               const std::vector<double>& edges) {
  const std::size_t bins = edges.size() - 1;
  std::size_t boxes = 1;
  for (std::size_t i = 0; i < names.size(); ++i) boxes *= bins;
  box_counts counts{std::vector<double>(boxes), std::vector<double>(boxes)};
  const auto& success = data.discrete(outcome);
  for (std::size_t row = 0; row < data.rows(); ++row) {
    std::size_t index = 0;
    for (const auto& name : names) {
      const double v = data.continuous(name).values()[row];
      std::size_t b = 0;
      while (b + 1 < bins && v >= edges[b + 1]) ++b;
      index = index * bins + b;
    }
    counts.rows[index] += 1;
    counts.successes[index] += success.code(row);
  }
  return counts;
}

/// The box of configuration `index` (as count_by_box numbers them).
inline variable_box box_of(std::size_t index, const std::vector<std::string>& names, const std::vector<double>& edges) {
  const std::size_t bins = edges.size() - 1;
  variable_box box;
  for (std::size_t i = names.size(); i-- > 0;) {
    const auto b = index % bins;
    index /= bins;
    box[names[i]] = {edges[b], edges[b + 1]};
  }
  return box;
}

}  // namespace pgm::sim::testing
