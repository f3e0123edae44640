#pragma once
// A tiny scenario whose answers are known, and a deterministic task source for it: shared by
// the protocol's tests and those of running and writing a whole experiment.

#include <string>
#include <vector>

#include "pgm/eval/experiment.hpp"

namespace pgm::test {

inline constexpr const char* tiny_scenario = R"({
  "format": "pgm-scenario", "version": 1, "name": "tiny", "title": "Tiny",
  "prior": {"task": "one", "rows": 300, "node": "ok1"},
  "target": {"node": "ok2", "tasks": [{"task": "two", "train_rows": 40, "ground_truth_rows": 260}]},
  "map": "ok2=ok1,x2~x1", "strategies": ["direct", "cross", "minimal"], "weights": [0, 5],
  "subsets": 4, "repetitions": 3
})";

/// Offsets x1, x2 take 0, 1, 2 (a reality-like grid); a cube stays unless its offset is 2, and
/// the stack stands when both do. Rows cycle through the grid, so every data set has all states.
inline task_source deterministic_tasks() {
  return {[](const std::string& task, std::size_t rows, std::uint64_t) {
            std::vector<double> x1(rows), x2(rows);
            std::vector<unsigned> ok(rows);
            for (std::size_t r = 0; r < rows; ++r) {
              x1[r] = static_cast<double>(r % 3);
              x2[r] = static_cast<double>((r / 3) % 3);
              ok[r] = task == "one" ? x1[r] != 2 : (x1[r] != 2 && x2[r] != 2);
            }
            dataset d;
            d.add(continuous_column("x1", x1));
            if (task == "two") d.add(continuous_column("x2", x2));
            d.add(discrete_column(variable(task == "one" ? "ok1" : "ok2", {"0", "1"}), ok));
            return d;
          },
          [](const std::string& task, const std::string&) {
            task_facts f;
            f.parents = task == "one" ? std::vector<std::string>{"x1"} : std::vector<std::string>{"x1", "x2"};
            f.controllable = {"x1", "x2"};
            f.success_state = "1";
            return f;
          }};
}

}  // namespace pgm::test
