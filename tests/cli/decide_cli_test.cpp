// `pgm predict` and `pgm prevent` as a user meets them: help, the printed prediction,
// explanation and suggestion, and each kind of bad input ending in one line and exit code 1.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "pgm/io/network_file.hpp"
#include "support/program_test.hpp"

namespace pgm::decide_cli_tests {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

class decide_cli_test : public pgm::testing::program_test {
 protected:
  void SetUp() override {
    program_test::SetUp();
    const auto x = variable::intervals("xOff1", {-3, -0.4, 0.4, 3}, {"x-offset", "cm", "cubeUp1"});
    const auto y = variable::intervals("yOff1", {-3, -0.4, 0.4, 3}, {"y-offset", "cm", "cubeUp1"});
    const variable colour("colour", {"Red", "Blue"});
    const variable on_top("onTop1", {"0", "1"});
    const double p[] = {0.1, 0.3, 0.1, 0.6, 0.95, 0.5, 0.1, 0.2, 0.1};
    std::vector<double> values;
    for (double v : p) {
      values.push_back(1 - v);
      values.push_back(v);
    }
    const double third = 1.0 / 3.0;
    const auto net = bayesian_network::from_tables(
        {cpt<double>(x, {}, {third, third, third}), cpt<double>(y, {}, {third, third, third}),
         cpt<double>(colour, {}, {0.5, 0.5}), cpt<double>(on_top, {x, y}, values)});
    write_network(net, model());
    write_network(net, dir_ / "model.bif");
  }
  fs::path model() const { return dir_ / "model.json"; }

  void expect_error(const std::string& arguments, const std::string& message) const {
    const auto r = run(arguments);
    EXPECT_EQ(r.code, 1) << arguments;
    EXPECT_THAT(r.err, HasSubstr(message)) << arguments;
  }
};

TEST_F(decide_cli_test, help) {
  for (const std::string command : {"predict", "prevent"}) {
    const auto r = run(command + " --help");
    EXPECT_EQ(r.code, 0);
    EXPECT_THAT(r.out, HasSubstr("--assign"));
  }
}

TEST_F(decide_cli_test, predict_prints_the_probability) {
  const auto r = run("predict --model " + model().string() + " --assign 'xOff1=0.3,yOff1=-1.2,colour=Red'");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("success: onTop1=1"));
  EXPECT_THAT(r.out, HasSubstr("xOff1 = 0.3 cm -> state 1 [-0.4, 0.4) cm"));
  EXPECT_THAT(r.out, HasSubstr("predicted success probability: 0.6\n"));
  const auto bif =
      run("predict --model " + (dir_ / "model.bif").string() + " --assign 'xOff1=@1,yOff1=@1' --success onTop1=0");
  EXPECT_EQ(bif.code, 0) << bif.err;
  EXPECT_THAT(bif.out, HasSubstr("predicted success probability: 0.05\n"));
  const auto summed = run("predict --model " + model().string() + " --assign xOff1=0 --marginalize");
  EXPECT_THAT(summed.out, HasSubstr("yOff1 summed out"));
  EXPECT_THAT(summed.out, HasSubstr("predicted success probability: 0.683333"));
}

TEST_F(decide_cli_test, prevent_explains_and_suggests) {
  const auto r =
      run("prevent --model " + model().string() + " --assign 'xOff1=-1,yOff1=0.1' --controllable xOff1,yOff1");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("predicted success probability: 0.3\n"));
  EXPECT_THAT(r.out, HasSubstr("failure predicted"));
  EXPECT_THAT(r.out, HasSubstr("xOff1: 0 [-3, -0.4) cm -> 1 [-0.4, 0.4) cm (move +1.7 cm)"));
  EXPECT_THAT(r.out, HasSubstr("xOff1 = 0 cm (interval 1 [-0.4, 0.4) cm)"));
  EXPECT_THAT(r.out, HasSubstr("yOff1 = 0.1 cm (interval 1 [-0.4, 0.4) cm) (unchanged)"));
  EXPECT_THAT(r.out, HasSubstr("predicted success after prevention: 0.95"));
  const auto fine = run("prevent --model " + model().string() + " --assign 'xOff1=0,yOff1=0' --distance units");
  EXPECT_EQ(fine.code, 0) << fine.err;
  EXPECT_THAT(fine.out, HasSubstr("no failure predicted"));
  EXPECT_THAT(fine.err, HasSubstr("every parent of 'onTop1' may move"));
  const auto low =
      run("prevent --model " + model().string() + " --assign 'xOff1=2,yOff1=-1' --controllable yOff1 --epsilon 0.5");
  EXPECT_THAT(low.out, HasSubstr("no change reaches epsilon; the best one"));
}

TEST_F(decide_cli_test, bad_input_is_one_clear_line) {
  const auto m = " --model " + model().string();
  expect_error("predict" + m + " --assign 'xOff=0,yOff1=0'", "no variable 'xOff'");
  expect_error("predict" + m + " --assign 'xOff1=0,yOff1=0,colour=Pink'", "no state 'Pink'");
  expect_error("predict" + m + " --assign 'xOff1=0,yOff1=0,colour=0.5'", "'colour' has no interval edges");
  expect_error("predict" + m + " --assign 'xOff1=nan,yOff1=0'", "nan is not a finite number");
  expect_error("predict" + m + " --assign 'xOff1=0'", "no value is given for yOff1");
  expect_error("predict" + m + " --assign 'xOff1=0,yOff1=0' --success onTop1=2", "no state '2'");
  expect_error("prevent" + m + " --assign 'xOff1=0' --controllable yOff1", "controllable variable 'yOff1'");
  expect_error("prevent" + m + " --assign 'xOff1=0,yOff1=0' --controllable zz", "no variable 'zz'");
  expect_error("prevent" + m + " --assign 'xOff1=0,yOff1=0,colour=Red' --controllable colour --distance units",
               "'colour' has no interval edges");
  expect_error("predict --model " + (dir_ / "absent.json").string() + " --assign x=1", "absent.json");
  // Success is a prediction above epsilon, which no probability exceeds at 1: a usage error,
  // before the model is read (the library refuses it too: prevent_test).
  for (const std::string epsilon : {"2", "1", "-0.5", "nan"}) {
    const auto r = run("prevent" + m + " --assign 'xOff1=0,yOff1=0' --epsilon " + epsilon);
    EXPECT_EQ(r.code, 2) << epsilon;
    EXPECT_THAT(r.err, HasSubstr("--epsilon: expected a number in [0, 1)")) << epsilon;
  }
  // Given but empty is not the same as absent (every parent).
  expect_error("prevent" + m + " --assign 'xOff1=0,yOff1=0' --controllable ''",
               "no variable is controllable, so nothing can be changed: name at least one");
}

}  // namespace
}  // namespace pgm::decide_cli_tests
