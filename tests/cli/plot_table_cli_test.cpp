// `pgm plot-table` as a user runs it: a fitted table drawn over two parents as PNG, SVG or the
// gnuplot script, the cells' probabilities those of the table, the rows behind them from the
// kept counts; mistakes are refused, and no picture is left behind.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/program_test.hpp"

namespace pgm::plot_table_cli_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

class plot_table_cli_test : public pgm::testing::program_test {
 protected:
  void SetUp() override {
    program_test::SetUp();
    // onTop ← x, y, z: 2 × 2 × 2 configurations, each seen (x + 1) · (y + 2) times with onTop = 1
    // in all but z of them.
    std::ofstream data(path("d.csv"));
    data << "x,y,z,onTop\n";
    for (int x = 0; x < 2; ++x) {
      for (int y = 0; y < 2; ++y) {
        for (int z = 0; z < 2; ++z) {
          for (int k = 0; k < (x + 1) * (y + 2); ++k)
            data << x << ',' << y << ',' << z << ',' << (k < z ? 0 : 1) << '\n';
        }
      }
    }
    data.close();
    const auto fitted = run("fit --data " + path("d.csv").string() +
                            " --edges 'x->onTop,y->onTop,z->onTop' --keep-counts --out " + path("m.json").string());
    ASSERT_EQ(fitted.code, 0) << fitted.err;
    model_ = " --model " + path("m.json").string() + " --node onTop --x x --y y";
  }
  std::string model_;
};

TEST_F(plot_table_cli_test, draws_png_svg_and_the_script_with_the_table_s_numbers) {
  const auto png_run = run("plot-table" + model_ + " --given z=1 --counts --out " + path("t.png").string());
  ASSERT_EQ(png_run.code, 0) << png_run.err;
  EXPECT_THAT(png_run.out, HasSubstr("drew P(onTop = 1) over 2 x 2 cells"));
  const auto png = slurp(path("t.png"));
  EXPECT_THAT(png, StartsWith("\x89PNG\r\n\x1a\n"));
  EXPECT_GT(png.size(), 5000U);

  ASSERT_EQ(run("plot-table" + model_ + " --given z=1 --out " + path("t.svg").string()).code, 0);
  const auto svg = slurp(path("t.svg"));
  EXPECT_THAT(svg, HasSubstr("<svg"));
  for (const char* text : {"onTop", "x", "y", "z = 1"}) EXPECT_THAT(svg, HasSubstr(text));

  // MLE: P(onTop = 1 | x, y, z = 1) = 1 - 1 / ((x + 1)(y + 2)); the cell (x, y) holds the rows
  // (x + 1)(y + 2) with z = 1, or twice that summed over z.
  ASSERT_EQ(run("plot-table" + model_ + " --given z=1 --counts --out " + path("t.gp").string()).code, 0);
  const auto script = slurp(path("t.gp"));
  EXPECT_THAT(script, HasSubstr("0.5 0.5 0 1 0 1 0.5 2\n"));
  EXPECT_THAT(script, HasSubstr("1.5 0.5 1 2 0 1 0.75 4\n"));
  EXPECT_THAT(script, HasSubstr("0.5 1.5 0 1 1 2 0.6666666666666666 3\n"));
  EXPECT_THAT(script, HasSubstr("1.5 1.5 1 2 1 2 0.8333333333333334 6\n"));
  ASSERT_EQ(run("plot-table" + model_ + " --average --counts --state 0 --out " + path("a.gp").string()).code, 0);
  // Averaged over z (equally likely): P(onTop = 0 | x = 0, y = 0) = (0 + 1/2) / 2.
  EXPECT_THAT(slurp(path("a.gp")), HasSubstr("0.5 0.5 0 1 0 1 0.25 4\n"));
}

TEST_F(plot_table_cli_test, mistakes_are_refused_with_a_clear_message_and_no_output) {
  expect_failure("plot-table" + model_ + " --given z=1 --out " + path("t.jpg").string(),
                 "expected a .png or .svg picture, or .gp", path("t.jpg"));
  expect_failure("plot-table" + model_ + " --out " + path("t.png").string(),
                 "give z a state each (e.g. z=0), or average over them", path("t.png"));
  expect_failure("plot-table --model " + path("m.json").string() + " --node onTop --x x --y w --average --out " +
                     path("t.png").string(),
                 "'w' is not a parent of 'onTop' (its parents: x, y, z)", path("t.png"));
  expect_failure("plot-table" + model_ + " --given z=7 --out " + path("t.png").string(),
                 "cannot be binned; give one of its states (0, 1)", path("t.png"));
  ASSERT_EQ(run("convert " + path("m.json").string() + " " + path("m.bif").string() + " --no-properties").code, 0);
  expect_failure("plot-table --model " + path("m.bif").string() +
                     " --node onTop --x x --y y --average --counts --out " + path("t.png").string(),
                 "carries no counts", path("t.png"));
  EXPECT_EQ(run("plot-table --help").code, 0);
}

}  // namespace
}  // namespace pgm::plot_table_cli_tests
