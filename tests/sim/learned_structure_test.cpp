// Issue 5's check on simulated data: PC-stable on 2-Stack data from the analytic simulator finds
// the four offsets as the parents of onTop2 and leaves the colours unconnected.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pgm/data/discretizer.hpp"
#include "pgm/learn/pc.hpp"
#include "pgm/sim/simulator.hpp"
#include "sim/sim_support.hpp"

namespace learned_structure_tests {
namespace {

using namespace pgm;
using ::testing::UnorderedElementsAre;

TEST(learned_structure_test, two_stack_parents_of_on_top2_are_the_four_offsets) {
  const auto task = pgm::sim::testing::shipped("2-stack");
  sim::simulate_options options;
  options.rows = 100'000;
  options.seed = 3;
  const auto raw = sim::simulate(task, options);
  const std::vector<std::string> continuous{"xOff1", "yOff1", "dropOff1", "xOff2", "yOff2", "dropOff2"};
  const auto data = apply_discretization(raw, fit_discretization(raw, continuous, binning::quantile, 5));

  pc_options pc;
  pc.test = make_independence_test("g2");
  pc.alpha = 0.01;
  // Outcomes come last, and the second cube's outcome is read as the paper's model reads it:
  // a function of the offsets, not of whether the first cube stayed.
  pc.knowledge.tiers = {
      {"xOff1", "yOff1", "dropOff1", "colorUp1", "xOff2", "yOff2", "dropOff2", "colorUp2", "colorDown"},
      {"onTop1"},
      {"onTop2"}};
  pc.knowledge.forbidden = {{"onTop1", "onTop2"}};
  const auto learned = pc_stable(data, pc).graph;

  auto names = [&](const std::vector<variable_id>& ids) {
    std::vector<std::string> result;
    for (auto id : ids) result.push_back(learned.name(id));
    return result;
  };
  EXPECT_THAT(names(learned.parents(learned.id("onTop2"))), UnorderedElementsAre("xOff1", "yOff1", "xOff2", "yOff2"));
  EXPECT_THAT(names(learned.parents(learned.id("onTop1"))), UnorderedElementsAre("xOff1", "yOff1"));
  for (const auto* colour : {"colorUp1", "colorUp2", "colorDown"}) {
    EXPECT_TRUE(learned.adjacent_nodes(learned.id(colour)).empty()) << colour;
  }
}

}  // namespace
}  // namespace learned_structure_tests
