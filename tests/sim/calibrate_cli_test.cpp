// pgm calibrate as a user meets it: help, a fit written atomically or printed, the agreement
// table, and clear errors. The analytic back-end stands in as the reference so that these
// run without Bullet and quickly.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "pgm/sim/task_file.hpp"
#include "support/program_test.hpp"

namespace pgm::calibrate_cli_tests {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

using calibrate_cli_test = pgm::testing::program_test;

TEST_F(calibrate_cli_test, help) {
  const auto r = run("calibrate --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_THAT(r.out, HasSubstr("--check"));
  EXPECT_THAT(r.out, HasSubstr("--out"));
  EXPECT_THAT(r.out, HasSubstr("maximum likelihood"));
}

TEST_F(calibrate_cli_test, writes_the_calibrated_task_file) {
  const auto out = path("1-stack.json");
  const auto r =
      run("calibrate --task 1-stack --backend analytic --rows 3000 --seed 4 --threads 2 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("calibrated 1-stack on 3000 analytic experiments (seed 4)"));
  EXPECT_THAT(r.out, HasSubstr("log-likelihood: "));
  EXPECT_THAT(r.out, HasSubstr("physics/analytic/tipping_margin/first"));
  const auto task = sim::load_task(out);
  EXPECT_EQ(task.name, "1-stack");
  EXPECT_THAT(slurp(out), HasSubstr("fitted by pgm calibrate to 3000 analytic experiments (seed 4)"));
}

TEST_F(calibrate_cli_test, prints_the_task_file_without_out) {
  const auto r = run("calibrate --task drop-glass --backend analytic --rows 1500 --threads 2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("log-likelihood: "));  // the summary, so that stdout is the file
  const auto task = sim::parse_task(r.out, "stdout");
  EXPECT_EQ(task.name, "drop-glass");
}

TEST_F(calibrate_cli_test, prints_the_agreement_table_and_the_containers_order) {
  // The same back-end, seed and rows on both sides: every cell agrees exactly.
  const auto r =
      run("calibrate --check --task drop-plate --task drop-bowl --task drop-glass --backend analytic --rows 3000 "
          "--analytic-rows 3000 --threads 2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("drop-bowl: inside, 3000 analytic rows"));
  EXPECT_THAT(r.out, HasSubstr("xOff              yOff              scalingFactor"));
  EXPECT_THAT(r.out, HasSubstr("mean |diff| over 27 cells: 0.000"));
  EXPECT_THAT(r.out, HasSubstr("ordering by success: analytic bowl > plate > glass; analytic bowl > plate > glass "
                               "(the same)"));
}

TEST_F(calibrate_cli_test, clear_errors_and_no_output) {
  const auto out = path("task.json");
  auto r = run("calibrate --task nothing --backend analytic --rows 10 --out " + out.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("unknown task 'nothing'"));
  r = run("calibrate --task 1-stack --backend analytic --rows 0");
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("--rows"));
  r = run("calibrate --task 1-stack --backend analytic --rows 10 --out " + (dir_ / "no-such-dir" / "t.json").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("does not exist"));
  r = run("calibrate --task 1-stack --backend analytic --rows 10 --out " + path("t.txt").string());
  EXPECT_NE(r.code, 0);
  r = run("calibrate --task 1-stack --task 2-stack --backend analytic --rows 10");
  EXPECT_THAT(r.err, HasSubstr("give one --task to calibrate"));
  r = run("calibrate --check --task 1-stack --backend analytic --rows 10 --out " + out.string());
  EXPECT_THAT(r.err, HasSubstr("--check only prints a table"));
  r = run("calibrate --task 1-stack --backend unity --rows 10 --out " + out.string());
  EXPECT_THAT(r.err, HasSubstr("unknown simulator back-end 'unity'"));
  r = run("calibrate --task 1-stack --backend analytic --rows 100000000 --out " + out.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("100000000 experiments are more than 10000000, pgm's limit of a calibration"));
  EXPECT_FALSE(fs::exists(out));
  // Printing the task file to a full disk fails as writing it does.
  EXPECT_EQ(run_to("calibrate --task 1-stack --backend analytic --rows 200", "/dev/full").code, 1);
}

}  // namespace
}  // namespace pgm::calibrate_cli_tests
