// The back-end registry: a user's back-end ("ideal-drop", docs/examples/extending/ideal_drop.cpp,
// linked into this test as its own translation unit) is found by name and run through
// simulate(); back-ends given as functions; the errors for unknown, missing and repeated names.

#include "pgm/sim/registry.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/sim_support.hpp"

namespace pgm::sim::registry_tests {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;
using testing::shipped;
using ::testing::ThrowsMessage;

simulate_options options(const std::string& backend, std::size_t rows, std::uint64_t seed) {
  simulate_options o;
  o.backend = backend;
  o.rows = rows;
  o.seed = seed;
  o.threads = 2;
  return o;
}

TEST(registry_test, a_users_backend_in_its_own_translation_unit_is_found_by_name) {
  EXPECT_THAT(backends(), Contains("ideal-drop"));
  EXPECT_THAT(backends(), Contains("analytic"));
  EXPECT_TRUE(backend_registry::instance().contains("ideal-drop"));
}

TEST(registry_test, a_users_backend_runs_through_simulate_with_the_shared_driver) {
  const auto task = shipped("drop-glass");
  const auto& physics = std::get<dropping_physics>(task.physics);
  const auto data = simulate(task, options("ideal-drop", 2000, 3));
  EXPECT_EQ(data.source(), "drop-glass (ideal-drop, seed 3)");
  ASSERT_EQ(data.rows(), 2000U);
  // The driver samples the inputs, so they are the analytic back-end's for the same seed.
  const auto analytic = simulate(task, options("analytic", 2000, 3));
  for (const auto* name : {"xOff", "yOff", "scalingFactor"}) {
    EXPECT_TRUE(std::ranges::equal(data.continuous(name).values(), analytic.continuous(name).values())) << name;
  }
  // Every outcome follows the back-end's rule; both outcomes occur.
  std::size_t inside = 0;
  for (std::size_t row = 0; row < data.rows(); ++row) {
    const double clearance =
        data.continuous("scalingFactor").values()[row] * physics.diameter_at_scale_1 / 2 - physics.sphere_diameter / 2;
    const bool expected =
        std::hypot(data.continuous("xOff").values()[row], data.continuous("yOff").values()[row]) < clearance;
    ASSERT_EQ(data.discrete("inside").code(row), expected ? 1U : 0U) << "row " << row;
    inside += expected;
  }
  EXPECT_GT(inside, 0U);
  EXPECT_LT(inside, data.rows());
  // Same seed, same data, whatever the thread count.
  auto one_thread = options("ideal-drop", 2000, 3);
  one_thread.threads = 1;
  EXPECT_EQ(simulate(task, one_thread), data);
}

TEST(registry_test, a_users_backend_reports_a_task_it_cannot_simulate) {
  EXPECT_THAT([] { (void)simulate(shipped("1-stack"), options("ideal-drop", 10, 1)); },
              ThrowsMessage<data_error>(HasSubstr("the ideal-drop back-end simulates dropping tasks; '1-stack'")));
}

TEST(registry_test, a_function_backend_registers_by_name) {
  backend_registry registry;
  registry.add("half-rows", [](const task_definition& task, const simulate_options& o) {
    auto half = o;
    half.rows = o.rows / 2;
    return simulate_analytic(task, half);
  });
  EXPECT_EQ(registry.names(), std::vector<std::string>{"half-rows"});
  EXPECT_EQ(registry.at("half-rows")(shipped("1-stack"), options("half-rows", 10, 1)).rows(), 5U);
}

TEST(registry_test, errors_name_the_backend_and_the_available_ones) {
  backend_registry registry;
  registry.add("analytic", &simulate_analytic);
  EXPECT_THAT([&] { (void)registry.at("unity"); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown simulator back-end 'unity' (known: analytic)")));
  // A program without the Bullet plugin says how to get it.
  EXPECT_THAT([&] { (void)registry.at("bullet"); },
              ThrowsMessage<data_error>(HasSubstr("the bullet back-end was not built (configure with "
                                                  "-DPGM_BUILD_BULLET=ON and libbullet-dev installed")));
  EXPECT_THAT([&] { registry.add("analytic", &simulate_analytic); },
              ThrowsMessage<model_error>(HasSubstr("a simulator back-end named 'analytic' is registered already")));
  EXPECT_THAT([&] { registry.add("", &simulate_analytic); },
              ThrowsMessage<model_error>(HasSubstr("a simulator back-end needs a non-empty name")));
  EXPECT_THAT([&] { registry.add("nothing", backend_function{}); },
              ThrowsMessage<model_error>(HasSubstr("the simulator back-end 'nothing' has no function to run")));
  EXPECT_THAT([] { register_simulator<analytic_simulator> again; },
              ThrowsMessage<model_error>(HasSubstr("named 'analytic' is registered already")));
}

}  // namespace
}  // namespace pgm::sim::registry_tests
