#pragma once
/// \file
/// The conformance kit of simulator back-ends: a GoogleTest suite that holds a registered
/// back-end, on the tasks a case names, to the driver's promises: the same data for a seed
/// whatever the threads, rows made in blocks equal to one run, the same data when spread over
/// the processes pgm runs in, another seed giving other data, and every experiment filling each
/// variable as its kind says (an outcome 0 or 1, a categorical variable one of its states, a
/// continuous one a finite number). Instantiate it in one test source of a program that links
/// GoogleTest:
///
///     #include <pgm/testing/backend_conformance.hpp>
///     using pgm::testing::backend_conformance;  // the macro takes the suite's name unqualified
///     INSTANTIATE_TEST_SUITE_P(mine, backend_conformance,
///                              ::testing::Values(pgm::testing::backend_case{"ideal-drop", {"drop-bowl"}}),
///                              pgm::testing::backend_case_name);

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "pgm/sim/registry.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/task_lookup.hpp"
#include "pgm/testing/case_names.hpp"

namespace pgm::testing {

/// One back-end as the kit checks it.
struct backend_case {
  /// The registered name: "analytic".
  std::string backend;
  /// Tasks it simulates, by name, found in `sim::default_task_directories()` ($PGM_TASKS_DIR first).
  std::vector<std::string> tasks;
  /// Experiments per run: not a multiple of the rows a thread is handed at a time.
  std::size_t rows = 37;
};

inline void PrintTo(const backend_case& c, std::ostream* out) { *out << c.backend; }

/// Every registered back-end on `tasks`, each with `rows` experiments a run.
[[nodiscard]] inline std::vector<backend_case> registered_backend_cases(const std::vector<std::string>& tasks,
                                                                        std::size_t rows = 37) {
  std::vector<backend_case> result;
  for (const auto& name : sim::backend_registry::instance().names()) result.push_back({name, tasks, rows});
  return result;
}

[[nodiscard]] inline std::string backend_case_name(const ::testing::TestParamInfo<backend_case>& info) {
  return test_name(info.param.backend);
}

class backend_conformance : public ::testing::TestWithParam<backend_case> {
 protected:
  [[nodiscard]] sim::simulate_options options(std::uint64_t seed, unsigned threads) const {
    sim::simulate_options o;
    o.backend = GetParam().backend;
    o.rows = GetParam().rows;
    o.seed = seed;
    o.threads = threads;
    return o;
  }

  template <class Check>
  void for_each_task(Check&& check) const {
    const auto directories = sim::default_task_directories();
    for (const auto& name : GetParam().tasks) {
      SCOPED_TRACE("task " + name);
      check(sim::load_task(name, directories));
    }
  }
};

TEST_P(backend_conformance, the_same_seed_gives_the_same_data_whatever_the_threads) {
  for_each_task([&](const sim::task_definition& task) {
    const auto one = sim::simulate(task, options(11, 1));
    ASSERT_EQ(one.rows(), GetParam().rows);
    for (unsigned threads : {2U, 5U})
      EXPECT_EQ(sim::simulate(task, options(11, threads)), one) << threads << " threads";
  });
}

TEST_P(backend_conformance, rows_made_in_blocks_are_the_rows_of_one_run) {
  for_each_task([&](const sim::task_definition& task) {
    const auto whole = sim::simulate(task, options(5, 2));
    auto first = options(5, 2);
    first.rows = GetParam().rows / 2;
    auto second = options(5, 2);
    second.first_row = first.rows;
    second.rows = GetParam().rows - first.rows;
    const auto a = sim::simulate(task, first);
    const auto b = sim::simulate(task, second);
    for (const auto& name : whole.names()) {
      SCOPED_TRACE(name);
      for (std::size_t row = 0; row < whole.rows(); ++row) {
        const auto& part = row < first.rows ? a : b;
        const auto at = row < first.rows ? row : row - first.rows;
        if (whole.is_discrete(name)) {
          EXPECT_EQ(part.discrete(name).code(at), whole.discrete(name).code(row)) << "row " << row;
        } else {
          EXPECT_EQ(part.continuous(name).values()[at], whole.continuous(name).values()[row]) << "row " << row;
        }
      }
    }
  });
}

TEST_P(backend_conformance, spread_over_the_processes_the_data_are_the_same) {
  for_each_task([&](const sim::task_definition& task) {
    auto spread = options(3, 2);
    spread.across_processes = true;
    EXPECT_EQ(sim::simulate(task, spread), sim::simulate(task, options(3, 2)));
  });
}

TEST_P(backend_conformance, another_seed_gives_other_data) {
  for_each_task([&](const sim::task_definition& task) {
    EXPECT_NE(sim::simulate(task, options(1, 2)), sim::simulate(task, options(2, 2)));
  });
}

TEST_P(backend_conformance, every_experiment_fills_each_variable_as_its_kind_says) {
  for_each_task([&](const sim::task_definition& task) {
    const auto data = sim::simulate(task, options(7, 2));
    for (const auto& v : task.variables) {
      SCOPED_TRACE(v.name);
      if (v.kind == sim::variable_kind::continuous) {
        ASSERT_FALSE(data.is_discrete(v.name));
        for (double x : data.continuous(v.name).values()) EXPECT_TRUE(std::isfinite(x)) << x;
        continue;
      }
      ASSERT_TRUE(data.is_discrete(v.name));
      const auto& column = data.discrete(v.name);
      EXPECT_EQ(column.var().states(), v.states);
      for (std::size_t row = 0; row < data.rows(); ++row) {
        EXPECT_FALSE(column.is_missing(row)) << "row " << row;
        EXPECT_LT(column.code(row), v.states.size()) << "row " << row;
      }
    }
  });
}

}  // namespace pgm::testing
