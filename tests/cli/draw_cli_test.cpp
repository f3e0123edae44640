// `pgm draw` as a user runs it: SVG, PNG and PDF through Graphviz's dot, DOT text without it;
// a learned structure's undirected edges and strengths come through; mistakes are refused.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/program_test.hpp"

namespace pgm::draw_cli_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

class draw_cli_test : public pgm::testing::program_test {
 protected:
  void SetUp() override {
    program_test::SetUp();
    std::ofstream(path("stack.json")) << R"({"format":"pgm-model","version":1,
              "variables":[{"name":"xOff2","states":["0","1","2"]},{"name":"yOff2","states":["0","1","2"]},
                           {"name":"onTop2","states":["0","1"]}],
              "edges":[["xOff2","onTop2"],["yOff2","onTop2"]],
              "metadata":{"success":"onTop2=1"},
              "learned":{"undirected_in_cpdag":[["yOff2","onTop2"]],
                         "strength":[{"from":"xOff2","to":"onTop2","strength":0.75,"direction":1}]}})";
  }
};

TEST_F(draw_cli_test, draws_svg_png_pdf_and_dot) {
  const auto model = " --model " + path("stack.json").string();
  ASSERT_EQ(run("draw" + model + " --controllable xOff2 --out " + path("s.dot").string()).code, 0);
  const auto dot = slurp(path("s.dot"));
  EXPECT_THAT(dot, HasSubstr("\"onTop2\" [label=\"onTop2\\n2 states\", shape=doubleoctagon"));  // from the metadata
  EXPECT_THAT(dot, HasSubstr("\"xOff2\" [label=\"xOff2\\n3 states\", shape=box"));
  EXPECT_THAT(dot, HasSubstr("\"yOff2\" -> \"onTop2\" [dir=none];"));
  EXPECT_THAT(dot, HasSubstr("\"xOff2\" -> \"onTop2\" [penwidth=3.12, label=\"0.75\"];"));

  const auto svg_run = run("draw" + model + " --out " + path("s.svg").string());
  ASSERT_EQ(svg_run.code, 0) << svg_run.err;
  EXPECT_THAT(svg_run.out, HasSubstr("drew 3 variables and 2 edges"));
  const auto svg = slurp(path("s.svg"));
  EXPECT_THAT(svg, HasSubstr("<svg"));
  for (const char* name : {"xOff2", "yOff2", "onTop2"}) EXPECT_THAT(svg, HasSubstr(name));

  ASSERT_EQ(run("draw" + model + " --out " + path("s.png").string()).code, 0);
  const auto png = slurp(path("s.png"));
  EXPECT_THAT(png, StartsWith("\x89PNG\r\n\x1a\n"));
  EXPECT_GT(png.size(), 2000U);
  ASSERT_EQ(run("draw" + model + " --out " + path("s.pdf").string()).code, 0);
  EXPECT_THAT(slurp(path("s.pdf")), StartsWith("%PDF-"));
}

TEST_F(draw_cli_test, mistakes_are_refused_with_a_clear_message_and_no_output) {
  const auto model = " --model " + path("stack.json").string();
  expect_failure("draw" + model + " --out " + path("s.jpg").string(), "expected a .svg, .png, .pdf or .dot file",
                 path("s.jpg"));
  expect_failure("draw" + model + " --success onTop3 --out " + path("s.svg").string(),
                 "the success variable 'onTop3' is not a variable of the network", path("s.svg"));
  expect_failure("draw" + model + " --controllable xOff9 --out " + path("s.svg").string(),
                 "the controllable variable 'xOff9'", path("s.svg"));
  expect_failure("draw --model " + path("none.json").string() + " --out " + path("s.svg").string(), "none.json",
                 path("s.svg"));
  EXPECT_EQ(run("draw --help").code, 0);
}

}  // namespace
}  // namespace pgm::draw_cli_tests
