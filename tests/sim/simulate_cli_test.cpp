// pgm simulate as a user meets it: help, a run, clear errors, and output written atomically.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "pgm/io/csv.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/task_episodes.hpp"
#include "pgm/sim/task_file.hpp"
#include "support/program_test.hpp"

namespace pgm::simulate_cli_tests {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

using simulate_cli_test = pgm::testing::program_test;

TEST_F(simulate_cli_test, help) {
  const auto r = run("simulate --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_THAT(r.out, HasSubstr("--backend"));
  EXPECT_THAT(r.out, HasSubstr("Simulator back-end: analytic"));  // the registered ones, by name
  EXPECT_THAT(r.out, HasSubstr("--variant"));
}

TEST_F(simulate_cli_test, writes_the_raw_data) {
  const auto out = path("raw.csv");
  const auto r = run("simulate --task 2-stack --rows 2000 --seed 9 --threads 2 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("simulated 2000 experiments of 2-stack"));
  EXPECT_EQ(r.err, "");  // no progress bar when stderr is not a terminal
  const auto data = read_csv(out);
  EXPECT_EQ(data.rows(), 2000U);
  EXPECT_EQ(data.names(), (std::vector<std::string>{"xOff1", "yOff1", "dropOff1", "colorUp1", "colorDown", "onTop1",
                                                    "xOff2", "yOff2", "dropOff2", "colorUp2", "onTop2"}));
  // The same seed with one thread writes the same bytes.
  const auto again = path("again.csv");
  ASSERT_EQ(run("simulate --task 2-stack --rows 2000 --seed 9 --threads 1 --out " + again.string()).code, 0);
  EXPECT_EQ(slurp(out), slurp(again));
}

TEST_F(simulate_cli_test, reality_variant_is_labelled) {
  const auto out = path("reality.csv");
  const auto r = run("simulate --task 1-stack --variant reality --rows 135 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("1-stack-reality"));
  EXPECT_THAT(r.err, HasSubstr("stand-in for the real robot, not real data"));
}

TEST_F(simulate_cli_test, clear_errors_and_no_output) {
  const auto out = path("raw.csv");
  auto r = run("simulate --task 9-stack --rows 10 --out " + out.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err,
              HasSubstr("unknown task '9-stack'; did you mean '1-stack'? (known: 1-stack, 1-stack-reality, 2-stack"));
  r = run("simulate --task drop-glass --variant reality --rows 10 --out " + out.string());
  EXPECT_THAT(r.err, HasSubstr("task 'drop-glass' has no reality variant"));
  r = run("simulate --task 1-stack --backend unity --rows 10 --out " + out.string());
  EXPECT_THAT(r.err, HasSubstr("unknown simulator back-end 'unity'"));
  r = run("simulate --task 1-stack --rows 10 --out " + path("raw.txt").string());
  EXPECT_NE(r.code, 0);
  r = run("simulate --task 1-stack --rows 10 --tasks-dir " + dir_.string() + " --out " + out.string());
  EXPECT_THAT(r.err, HasSubstr("unknown task '1-stack'"));
  EXPECT_FALSE(fs::exists(out));
  r = run("simulate --task 1-stack --rows 10 --out " + (dir_ / "no-such-dir" / "raw.csv").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("does not exist"));
}

TEST_F(simulate_cli_test, output_is_replaced_atomically) {
  const auto out = path("raw.csv");
  std::ofstream(out) << "previous\n";
  // A failing run leaves the old file as it was, and no temporary files behind.
  EXPECT_NE(run("simulate --task nothing --rows 10 --out " + out.string()).code, 0);
  EXPECT_EQ(slurp(out), "previous\n");
  ASSERT_EQ(run("simulate --task drop-bowl --rows 100 --out " + out.string()).code, 0);
  EXPECT_THAT(slurp(out), HasSubstr("xOff,yOff,scalingFactor,containerColor,inside\n"));
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_)) ++files;
  EXPECT_EQ(files, 3U);  // raw.csv, stdout.txt, stderr.txt
}

// More rows than one block: written as they are made, the file is byte for byte the one the
// library writes for the data set made in one piece (issue 28: memory grew with --rows).
TEST_F(simulate_cli_test, rows_beyond_a_block_are_written_as_they_come_and_equal_one_piece) {
  const auto out = path("many.csv");
  const auto r = run("simulate --task 1-stack --rows 300001 --seed 3 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto task = sim::load_task(fs::path(PGM_SOURCE_DIR) / "tasks" / "1-stack.json");
  std::ostringstream one;
  write_csv(sim::simulate(task, {.rows = 300'001, .seed = 3}), one);
  EXPECT_TRUE(slurp(out) == one.str());
}

// Episodes numbered on across blocks: the file equals the long form of the data made in one piece.
TEST_F(simulate_cli_test, long_form_numbers_episodes_across_blocks) {
  const auto out = path("episodes.csv");
  const auto r = run("simulate --task 1-stack --rows 300001 --seed 3 --long-form --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("as episodes of 1 steps"));
  const auto task = sim::load_task(fs::path(PGM_SOURCE_DIR) / "tasks" / "1-stack.json");
  std::ostringstream one;
  write_csv(sim::episodes_of(sim::simulate(task, {.rows = 300'001, .seed = 3}), task, sim::episode_layout_of(task)),
            one);
  EXPECT_TRUE(slurp(out) == one.str());
}

// The tower's episodes, binned, are what pgm fit --dynamic learns a tied model from.
TEST_F(simulate_cli_test, the_towers_episodes_fit_a_dynamic_network) {
  const auto raw = path("tower.csv"), binned = path("binned.csv"), model = path("tower.json");
  auto r = run("simulate --task 3-stack --rows 2000 --seed 5 --long-form --out " + raw.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(slurp(raw), HasSubstr("episode,t,xOff,yOff,dropOff,colorUp,onTop,colorDown\n0,0,"));
  ASSERT_EQ(run("discretize --in " + raw.string() + " --columns xOff,yOff --bins 5 --out " + binned.string()).code, 0);
  r = run("fit --dynamic --data " + binned.string() +
          " --edges \"xOff->onTop, yOff->onTop, onTop@-1->onTop, xOff@-1->onTop\" --out " + model.string());
  ASSERT_EQ(r.code, 0) << r.err;
  // A tower that has fallen stays fallen: the tied table says so, whatever the offsets.
  ASSERT_EQ(run("unroll --model " + model.string() + " --steps 3 --out " + path("u.json").string()).code, 0);
  r = run("query --model " + path("u.json").string() + " --query onTop@2 --evidence onTop@1=0 --digits 17");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("onTop@2,probability\n0,1\n1,0\n"));
}

TEST_F(simulate_cli_test, long_form_needs_numbered_actions) {
  const auto out = path("drop.csv");
  const auto r = run("simulate --task drop-glass --rows 10 --long-form --out " + out.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("task 'drop-glass' has no numbered variables"));
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace pgm::simulate_cli_tests
