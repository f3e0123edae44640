// Task files: the shipped tasks load with the columns, tags and structures the paper's
// tasks need; malformed files fail with the file and the JSON path of the problem.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sim/sim_support.hpp"

namespace pgm::sim::task_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::shipped;

TEST(task_test, stacking_tasks_have_the_paper_columns) {
  EXPECT_THAT(shipped("1-stack").names(), ElementsAre("xOff1", "yOff1", "dropOff1", "colorUp1", "colorDown", "onTop1"));
  const auto two = shipped("2-stack");
  EXPECT_THAT(two.names(), ElementsAre("xOff1", "yOff1", "dropOff1", "colorUp1", "colorDown", "onTop1", "xOff2",
                                       "yOff2", "dropOff2", "colorUp2", "onTop2"));
  EXPECT_EQ(two.success, "onTop2");
  std::vector<std::string> edges;
  for (const auto& e : two.structure) edges.push_back(e.from + "->" + e.to);
  EXPECT_THAT(edges, ElementsAre("xOff1->onTop1", "yOff1->onTop1", "xOff1->onTop2", "yOff1->onTop2", "xOff2->onTop2",
                                 "yOff2->onTop2"));
  EXPECT_THAT(two.controllable(), ElementsAre("xOff1", "yOff1", "dropOff1", "xOff2", "yOff2", "dropOff2"));
  EXPECT_EQ(two.at("xOff2").tags, (semantic_tags{"x-offset", "cm", "cubeUp2"}));
  EXPECT_EQ(two.at("colorDown").states, (std::vector<std::string>{"Red", "Blue", "Green", "Orange"}));
  EXPECT_EQ(two.at("onTop1").kind, variable_kind::outcome);
}

TEST(task_test, dropping_tasks_share_their_variables) {
  for (const auto* name : {"drop-plate", "drop-bowl", "drop-glass"}) {
    const auto task = shipped(name);
    EXPECT_THAT(task.names(), ElementsAre("xOff", "yOff", "scalingFactor", "containerColor", "inside")) << name;
    EXPECT_THAT(task.controllable(), ElementsAre("xOff", "yOff")) << name;
    EXPECT_EQ(task.structure.size(), 3U);
    EXPECT_EQ(task.at("scalingFactor").sampling.min, 0.4);
    EXPECT_TRUE(std::holds_alternative<dropping_physics>(task.physics));
  }
}

TEST(task_test, reality_variants_say_they_are_stand_ins) {
  for (const auto* name : {"1-stack-reality", "2-stack-reality"}) {
    const auto task = shipped(name);
    EXPECT_EQ(task.variant, "reality");
    EXPECT_THAT(task.note, HasSubstr("not real data"));
    EXPECT_EQ(task.at("xOff1").sampling.values, (std::vector<double>{0.0, 0.9, 2.2}));
    EXPECT_EQ(task.at("yOff1").sampling.kind, distribution_kind::constant);
  }
}

TEST(task_test, finds_tasks_by_name_and_lists_the_known_ones) {
  const std::vector<std::filesystem::path> dirs{std::filesystem::path(PGM_SOURCE_DIR) / "tasks"};
  EXPECT_EQ(load_task("drop-bowl", dirs).name, "drop-bowl");
  try {
    (void)find_task("9-stack", dirs);
    FAIL();
  } catch (const unknown_name& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown task '9-stack'"));
    EXPECT_THAT(e.what(), HasSubstr("1-stack, 1-stack-reality, 2-stack"));
  }
}

TEST(task_test, reads_the_analytic_model_constants) {
  const auto two = std::get<stacking_physics>(shipped("2-stack").physics);
  EXPECT_GT(two.tipping_margin_later, two.tipping_margin_first);
  EXPECT_GT(two.settle_noise_first, 0);
  // The reality stand-ins keep their own constants: no analytic section, so none of these.
  const auto reality = std::get<stacking_physics>(shipped("2-stack-reality").physics);
  EXPECT_EQ(reality.tipping_margin_first, 0);
  EXPECT_EQ(reality.settle_noise_later, 0);
  EXPECT_EQ(reality.support_margin, 0.25);
  const auto glass = std::get<dropping_physics>(shipped("drop-glass").physics);
  EXPECT_GT(glass.impact_restitution, 0);
  EXPECT_LE(glass.impact_tangential, 1);
}

std::string error_of(const std::string& text) {
  try {
    (void)parse_task(text, "bad.json");
  } catch (const data_error& e) {
    return e.what();
  }
  return "no error";
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) return "pattern not found: " + from;
  return text.replace(at, from.size(), to);
}

TEST(task_test, errors_name_the_file_and_the_key) {
  const auto good = pgm::read_file(std::filesystem::path(PGM_SOURCE_DIR) / "tasks" / "1-stack.json");
  EXPECT_NO_THROW((void)parse_task(good, "good.json"));
  EXPECT_THAT(error_of("{ \"format\": "), HasSubstr("bad.json:1:"));
  EXPECT_THAT(error_of(with(good, "\"success\": \"onTop1\"", "\"success\": \"colorDown\"")),
              HasSubstr("bad.json: /success: 'colorDown' is not an outcome variable"));
  EXPECT_THAT(error_of(with(good, "\"sd\": 2.0", "\"sd\": -1")),
              HasSubstr("bad.json: /variables/0/distribution/sd: expected a positive number"));
  EXPECT_THAT(error_of(with(good, "\"type\": \"normal\"", "\"type\": \"gamma\"")),
              HasSubstr("/variables/0/distribution/type: expected \"normal\""));
  EXPECT_THAT(error_of(with(good, "\"variant\": \"sim\"", "\"variant\": \"robot\"")),
              HasSubstr("bad.json: /variant: expected one of sim, reality"));
  EXPECT_THAT(error_of(with(good, "\"format\": \"pgm-task\",", "")),
              HasSubstr("bad.json: /: the key 'format' is missing"));
  EXPECT_THAT(error_of(with(good, "\"xOff1 -> onTop1\"", "\"xOff1 -> nothing\"")),
              HasSubstr("/structure/0: 'nothing' is not a variable of the task"));
  EXPECT_THAT(error_of(with(good, "\"name\": \"dropOff1\"", "\"name\": \"height1\"")),
              HasSubstr("/physics/model: the model \"stacking\" needs the continuous variable 'dropOff1'"));
  EXPECT_THAT(error_of(with(good, "\"cube_size\": 5.0", "\"cube_size\": \"big\"")),
              HasSubstr("/physics/cube_size: expected a number"));
  EXPECT_THAT(error_of(with(good, "\"tipping_margin\": {", "\"tipping_margin\": {\"later\": 2.5,")),
              HasSubstr("/physics/analytic/tipping_margin/later: must be below the supporting half-width"));
  EXPECT_THAT(error_of(with(good, "\"cube_mass\": 0.1", "\"cube_mass\": 0.1, \"time_step\": 0")),
              HasSubstr("/physics/time_step: expected a step in (0, 0.05] seconds"));
  auto document = nlohmann::json::parse(good);
  document["physics"]["analytic"] = 3;
  EXPECT_THAT(error_of(document.dump()), HasSubstr("/physics/analytic: expected an object"));
  const auto glass = pgm::read_file(std::filesystem::path(PGM_SOURCE_DIR) / "tasks" / "drop-glass.json");
  EXPECT_THAT(error_of(with(glass, "\"landing_noise\": 0.5,", "\"landing_noise\": 0.5, \"rim_catch\": 0.7,")),
              HasSubstr("bad.json: /physics/rim_catch: is no longer used"));
  // (The later of two equal keys counts.)
  EXPECT_THAT(error_of(with(glass, "\"tangential\":", "\"restitution\": 1.5, \"tangential\":")),
              HasSubstr("/physics/analytic/restitution: expected a number in [0, 1]"));
  // A misspelt key is named with the one it was likely meant to be, a cycle with its nodes.
  EXPECT_THAT(error_of(with(good, "\"cube_mass\": 0.1", "\"cube_mass\": 0.1, \"time_stp\": 0.01")),
              HasSubstr("bad.json: /physics/time_stp: unknown key 'time_stp'; did you mean 'time_step'? (the keys "
                        "here: model, cube_size, support_margin, release_noise, friction, restitution, cube_mass, "
                        "time_step, analytic)"));
  EXPECT_THAT(error_of(with(good, "\"sd\": 2.0", "\"sd\": 2.0, \"maximum\": 3")),
              HasSubstr("/variables/0/distribution/maximum: unknown key 'maximum' (the keys here: type, mean, sd, "
                        "min, max)"));
  EXPECT_THAT(error_of(with(good, "\"format\": \"pgm-task\",", "\"format\": \"pgm-task\", \"varaint\": \"sim\",")),
              HasSubstr("bad.json: /varaint: unknown key 'varaint'; did you mean 'variant'?"));
  EXPECT_THAT(error_of(with(good, "\"xOff1 -> onTop1\"", "\"xOff1 -> onTop1\", \"onTop1 -> xOff1\"")),
              HasSubstr("/structure/1: the structure is not a DAG: onTop1 -> xOff1 closes the cycle onTop1 -> xOff1 "
                        "-> onTop1"));
  EXPECT_THAT(error_of(with(good, "\"xOff1 -> onTop1\"", "\"xOff1 -> onTop1\", \"xOff1 -> onTop1\"")),
              HasSubstr("/structure/1: edge xOff1 -> onTop1 is given twice"));
  try {
    (void)load_task(std::filesystem::path(PGM_SOURCE_DIR) / "tasks" / "missing.json");
    FAIL();
  } catch (const io_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("missing.json"));
  }
}

}  // namespace
}  // namespace pgm::sim::task_tests
