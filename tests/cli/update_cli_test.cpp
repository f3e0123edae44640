// `pgm fit --keep-counts` and `pgm update` as a user runs them: the first day's trials, then the
// second's added, give the network fitted on both days at once; mistakes are refused.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "pgm/io/network_file.hpp"
#include "support/program_test.hpp"

namespace pgm::update_cli_tests {
namespace {

using ::testing::HasSubstr;

class update_cli_test : public pgm::testing::program_test {
 protected:
  void SetUp() override {
    program_test::SetUp();
    std::ofstream(path("day1.csv")) << "xOff,onTop\n0,1\n0,1\n1,0\n2,0\n1,1\n0,1\n";
    std::ofstream(path("day2.csv")) << "xOff,onTop\n2,1\n1,1\n2,0\n";
    std::ofstream(path("both.csv")) << "xOff,onTop\n0,1\n0,1\n1,0\n2,0\n1,1\n0,1\n2,1\n1,1\n2,0\n";
  }

  std::string fit(const std::string& data, const std::string& out, const std::string& more = "") const {
    return "fit --data " + path(data).string() + " --edges xOff-\\>onTop --estimator bayes --prior k2 " + more +
           " --out " + path(out).string();
  }
};

std::vector<double> node_values(const bayesian_network& network, const std::string& name) {
  const auto values = network.table(network.id(name)).values();
  return {values.begin(), values.end()};
}

TEST_F(update_cli_test, a_day_added_equals_both_days_fitted_at_once) {
  ASSERT_EQ(run(fit("day1.csv", "robot.json", "--keep-counts")).code, 0);
  const auto r = run("update --model " + path("robot.json").string() + " --data " + path("day2.csv").string() +
                     " --out " + path("robot.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("updated 2 tables with 3 new rows (9 rows in all)"));
  ASSERT_EQ(run(fit("both.csv", "both.json")).code, 0);
  const auto updated = read_network(path("robot.json"));
  const auto both = read_network(path("both.json"));
  EXPECT_EQ(node_values(updated, "onTop"), node_values(both, "onTop"));
  EXPECT_EQ(node_values(updated, "xOff"), node_values(both, "xOff"));
  // The updated model keeps its counts: a third day can follow.
  EXPECT_EQ(run("update --model " + path("robot.json").string() + " --data " + path("day2.csv").string() +
                " --decay 0.5 --out " + path("day3.json").string())
                .code,
            0);
}

// BIF, XMLBIF and NET keep the counts in a network-level property (peers ignore it), so the
// robot's model can stay in the format its other tools read.
TEST_F(update_cli_test, every_format_keeps_the_counts) {
  ASSERT_EQ(run(fit("both.csv", "both.json")).code, 0);
  const auto both = read_network(path("both.json"));
  for (const std::string extension : {".bif", ".xml", ".net"}) {
    SCOPED_TRACE(extension);
    ASSERT_EQ(run(fit("day1.csv", "robot" + extension, "--keep-counts")).code, 0);
    EXPECT_THAT(slurp(path("robot" + extension)),
                HasSubstr(extension == ".net" ? "pgm_statistics = \"" : "pgm.statistics = "));
    const auto r = run("update --model " + path("robot" + extension).string() + " --data " + path("day2.csv").string() +
                       " --out " + path("updated" + extension).string());
    ASSERT_EQ(r.code, 0) << r.err;
    const auto updated = read_model(path("updated" + extension));
    ASSERT_TRUE(updated.statistics.has_value());
    EXPECT_EQ(updated.statistics->rows, 9.0);
    EXPECT_EQ(node_values(updated.network(), "onTop"), node_values(both, "onTop"));
    EXPECT_EQ(node_values(updated.network(), "xOff"), node_values(both, "xOff"));
  }
  // Converting keeps them, unless --no-properties leaves pgm's properties out.
  ASSERT_EQ(run("convert " + path("robot.bif").string() + " " + path("robot2.xml").string()).code, 0);
  EXPECT_TRUE(read_model(path("robot2.xml")).statistics.has_value());
  const auto bare = run("convert " + path("robot.bif").string() + " " + path("bare.net").string() + " --no-properties");
  ASSERT_EQ(bare.code, 0) << bare.err;
  EXPECT_THAT(bare.err, HasSubstr("are left out with --no-properties"));
  EXPECT_FALSE(read_model(path("bare.net")).statistics.has_value());
}

TEST_F(update_cli_test, mistakes_are_refused_with_a_clear_message_and_no_output) {
  ASSERT_EQ(run(fit("day1.csv", "plain.json")).code, 0);
  ASSERT_EQ(run(fit("day1.csv", "robot.json", "--keep-counts")).code, 0);
  const auto out = path("never.json");
  expect_failure("update --model " + path("plain.json").string() + " --data " + path("day2.csv").string() + " --out " +
                     out.string(),
                 "carries no counts to add the new rows to: fit it with pgm fit --keep-counts", out);
  expect_failure("update --model " + path("robot.json").string() + " --data " + path("day2.csv").string() +
                     " --decay 0 --out " + out.string(),
                 "--decay", out);
  ASSERT_EQ(run(fit("day1.csv", "robot.bif", "--keep-counts")).code, 0);
  auto damaged = slurp(path("robot.bif"));
  damaged.replace(damaged.find("pgm.statistics = ") + 17, 4, "!!!!");
  std::ofstream(path("damaged.bif")) << damaged;
  expect_failure("update --model " + path("damaged.bif").string() + " --data " + path("day2.csv").string() + " --out " +
                     out.string(),
                 "the property pgm.statistics (the counts of pgm fit --keep-counts) is damaged", out);
  std::ofstream(path("bad.csv")) << "xOff,onTop\n7,1\n";
  expect_failure("update --model " + path("robot.json").string() + " --data " + path("bad.csv").string() + " --out " +
                     out.string(),
                 "bad.csv:2:1: column 'xOff': '7' is not a state of 'xOff'", out);
  expect_failure(fit("day1.csv", "em.json", "--keep-counts --missing em"),
                 "--keep-counts does not apply with --missing em", path("em.json"));
  EXPECT_EQ(run("update --help").code, 0);
}

}  // namespace
}  // namespace pgm::update_cli_tests
