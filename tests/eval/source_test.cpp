// Task sources: the simulated one reads task files and simulates as pgm::sim::simulate does;
// the cache makes each (task, rows, seed) once.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "eval/tiny_scenario.hpp"
#include "pgm/eval/cached_source.hpp"
#include "pgm/eval/simulated_source.hpp"

namespace source_tests {
namespace {

using namespace pgm;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

std::vector<std::filesystem::path> shipped_tasks() { return {std::filesystem::path(PGM_SOURCE_DIR) / "tasks"}; }

TEST(cached_source_test, each_task_rows_and_seed_is_made_once_and_shared_by_copies) {
  auto calls = std::make_shared<int>(0);
  auto inner = pgm::test::deterministic_tasks();
  const auto make = inner.data;
  inner.data = [calls, make](const std::string& task, std::size_t rows, std::uint64_t seed) {
    ++*calls;
    return make(task, rows, seed);
  };
  const auto source = cached(inner);
  const auto copy = source;
  const auto first = source.data("one", 9, 1);
  EXPECT_EQ(copy.data("one", 9, 1), first);
  EXPECT_EQ(*calls, 1);
  static_cast<void>(source.data("one", 9, 2));
  static_cast<void>(source.data("one", 10, 1));
  static_cast<void>(source.data("two", 9, 1));
  EXPECT_EQ(*calls, 4) << "another seed, size or task is another data set";
  EXPECT_THAT(copy.facts("two", "ok2").parents, ElementsAre("x1", "x2"));
}

TEST(simulated_source_test, data_are_the_simulators_and_facts_the_task_files) {
  const auto source = simulated_source({shipped_tasks(), "analytic", 1});
  const auto data = source.data("2-stack", 200, 11);
  sim::simulate_options options;
  options.rows = 200;
  options.seed = 11;
  EXPECT_EQ(data, sim::simulate(sim::load_task("2-stack", shipped_tasks()), options));
  EXPECT_NE(source.data("2-stack", 200, 12), data);
  const auto facts = source.facts("2-stack", "onTop2");
  EXPECT_THAT(facts.parents, ElementsAre("xOff1", "yOff1", "xOff2", "yOff2"));
  EXPECT_TRUE(facts.controllable.contains("xOff2"));
  EXPECT_FALSE(facts.controllable.contains("onTop2"));
  EXPECT_EQ(facts.tags.at("xOff1").quantity, "x-offset");
}

TEST(simulated_source_test, unknown_tasks_variables_and_back_ends_are_errors) {
  const auto source = simulated_source({shipped_tasks(), "analytic", 1});
  EXPECT_THAT([&] { static_cast<void>(source.facts("2-stack", "nope")); },
              ThrowsMessage<data_error>(HasSubstr("task '2-stack' has no variable 'nope'")));
  EXPECT_THAT([&] { static_cast<void>(source.data("no-such-task", 5, 1)); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown task 'no-such-task'")));
  const auto other = simulated_source({shipped_tasks(), "no-such-backend", 1});
  EXPECT_THAT([&] { static_cast<void>(other.data("1-stack", 5, 1)); },
              ThrowsMessage<unknown_name>(HasSubstr("no-such-backend")));
}

}  // namespace
}  // namespace source_tests
