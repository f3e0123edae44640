// A task of numbered actions as episodes: the layout of its steps, the long form it writes, and
// what pgm fit --dynamic learns from it.

#include "pgm/sim/task_episodes.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/sim_support.hpp"

namespace pgm::sim {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(task_episodes_test, the_tower_has_three_steps_of_one_cube_each) {
  const auto task = testing::shipped("3-stack");
  const auto layout = episode_layout_of(task);
  EXPECT_EQ(layout.steps, 3U);
  EXPECT_EQ(layout.template_names, (std::vector<std::string>{"xOff", "yOff", "dropOff", "colorUp", "onTop"}));
  ASSERT_EQ(layout.columns.size(), 3U);
  for (std::size_t t = 0; t < 3; ++t) {
    const auto n = std::to_string(t + 1);
    EXPECT_EQ(task.variables[layout.columns[t][0]].name, "xOff" + n);
    EXPECT_EQ(task.variables[layout.columns[t][4]].name, "onTop" + n);
  }
  ASSERT_EQ(layout.constants.size(), 1U);
  EXPECT_EQ(task.variables[layout.constants[0]].name, "colorDown");
  EXPECT_EQ(episode_layout_of(testing::shipped("1-stack")).steps, 1U);
}

TEST(task_episodes_test, a_task_that_is_no_sequence_is_refused_by_name) {
  EXPECT_THAT([] { (void)episode_layout_of(testing::shipped("drop-glass")); },
              ThrowsMessage<data_error>(HasSubstr("task 'drop-glass' has no numbered variables")));
  auto gap = testing::shipped("3-stack");
  std::erase_if(gap.variables, [](const task_variable& v) { return v.name == "dropOff2"; });
  EXPECT_THAT([&] { (void)episode_layout_of(gap); },
              ThrowsMessage<data_error>(HasSubstr("'dropOff1' has no 'dropOff2'")));
  auto clash = testing::shipped("2-stack");
  clash.variables[4].name = "xOff";  // colorDown renamed to a template's name
  EXPECT_THAT([&] { (void)episode_layout_of(clash); },
              ThrowsMessage<data_error>(HasSubstr("'xOff' is a variable of its own and the template")));
}

TEST(task_episodes_test, every_step_of_an_episode_is_its_cube) {
  const auto task = testing::shipped("3-stack");
  simulate_options options;
  options.rows = 500;
  options.seed = 4;
  const auto wide = simulate(task, options);
  const auto layout = episode_layout_of(task);
  const auto long_form = episodes_of(wide, task, layout, 1000);
  ASSERT_EQ(long_form.rows(), 1500U);
  EXPECT_EQ(long_form.names(),
            (std::vector<std::string>{"episode", "t", "xOff", "yOff", "dropOff", "colorUp", "onTop", "colorDown"}));
  const auto episode = long_form.continuous("episode").values();
  const auto step = long_form.continuous("t").values();
  for (std::size_t e = 0; e < 500; ++e) {
    for (std::size_t t = 0; t < 3; ++t) {
      const auto row = e * 3 + t;
      const auto n = std::to_string(t + 1);
      ASSERT_EQ(episode[row], static_cast<double>(1000 + e));
      ASSERT_EQ(step[row], static_cast<double>(t));
      ASSERT_EQ(long_form.continuous("xOff").values()[row], wide.continuous("xOff" + n).values()[e]);
      ASSERT_EQ(long_form.continuous("dropOff").values()[row], wide.continuous("dropOff" + n).values()[e]);
      ASSERT_EQ(long_form.discrete("onTop").code(row), wide.discrete("onTop" + n).code(e));
      ASSERT_EQ(long_form.discrete("colorUp").label(row), wide.discrete("colorUp" + n).label(e));
      ASSERT_EQ(long_form.discrete("colorDown").code(row), wide.discrete("colorDown").code(e));
    }
  }
  // A template variable keeps its quantity and unit, not the role of one cube.
  const auto& tags = long_form.continuous("xOff").tags();
  EXPECT_EQ(tags.quantity, "x-offset");
  EXPECT_EQ(tags.role, "");
  EXPECT_EQ(long_form.discrete("colorDown").var().tags().role, "cubeDown");
}

TEST(task_episodes_test, a_fallen_tower_stays_fallen) {
  // onTop at t needs the tower to have stood at t - 1: the timely-shifted failures.
  const auto task = testing::shipped("3-stack");
  simulate_options options;
  options.rows = 20000;
  options.seed = 2;
  const auto data = episodes_of(simulate(task, options), task, episode_layout_of(task));
  const auto& on_top = data.discrete("onTop");
  std::size_t later_failures = 0;
  for (std::size_t row = 0; row < data.rows(); ++row) {
    if (row % 3 == 0) continue;
    ASSERT_FALSE(on_top.code(row - 1) == 0 && on_top.code(row) == 1) << "row " << row;
    later_failures += on_top.code(row - 1) == 1 && on_top.code(row) == 0;
  }
  EXPECT_GT(later_failures, 1000U);  // towers that stood a step and fell at the next
}

}  // namespace
}  // namespace pgm::sim
