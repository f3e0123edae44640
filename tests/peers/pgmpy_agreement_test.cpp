// Agreement with pgmpy, run only where pgmpy imports (tests/CMakeLists.txt): posteriors on the
// published sachs network against pgmpy's VariableElimination, and the Yates-corrected
// chi-square and G² statistics against pgmpy's chi_square and g_sq on a sample of sachs.
// PGM_PYTHON runs tests/peers/pgmpy_oracle.py with PYTHONPATH=PGM_PGMPY_PATH.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pgm/data/csv.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/inference/variable_elimination.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/learn/independence_test.hpp"
#include "support/folder_test.hpp"

namespace pgm {
namespace {

const auto sachs_path = std::filesystem::path(PGM_NETWORKS_DIR) / "sachs.bif";

class pgmpy_agreement_test : public pgm::testing::folder_test {
 protected:
  /// pgmpy's answers to `requests` ("queries" on a network or "ci" on a CSV file).
  nlohmann::json ask_pgmpy(const std::string& mode, const std::filesystem::path& input,
                           const nlohmann::json& requests) const {
    const auto request_file = file("request.json", requests.dump());
    const auto answer_file = path("answer.json");
    const auto command = std::string("PYTHONPATH='") + PGM_PGMPY_PATH + "' " + PGM_PYTHON + " " + PGM_ORACLE + " " +
                         mode + " " + input.string() + " " + request_file.string() + " >" + answer_file.string() +
                         " 2>" + path("oracle.err").string();
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << slurp(path("oracle.err"));
    return nlohmann::json::parse(slurp(answer_file));
  }
};

TEST_F(pgmpy_agreement_test, posteriors_on_sachs_equal_pgmpy_variable_elimination) {
  const auto net = read_bif(sachs_path);
  const std::vector<std::pair<std::vector<std::string>, evidence>> cases{
      {{"Akt"}, {}},
      {{"Akt"}, {{"PKA", "HIGH"}}},
      {{"Raf"}, {{"Mek", "HIGH"}}},  // against the arrows
      {{"Erk", "Akt"}, {{"PKC", "LOW"}, {"Plcg", "AVG"}}},
      {{"P38", "Jnk", "PIP2"}, {{"PIP3", "HIGH"}, {"Erk", "LOW"}}},
  };
  nlohmann::json requests = nlohmann::json::array();
  for (const auto& [variables, observed] : cases) requests.push_back({{"query", variables}, {"evidence", observed}});
  const auto answers = ask_pgmpy("queries", sachs_path, requests);
  ASSERT_EQ(answers.size(), cases.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto ours = query(net, cases[i].first, cases[i].second);
    std::size_t states = 1;
    for (const auto& v : ours.variables) states *= v.cardinality();
    ASSERT_EQ(answers[i].size(), states) << requests[i].dump();
    for (const auto& row : answers[i]) {
      std::vector<std::string> labels;
      for (const auto& v : ours.variables) labels.push_back(row["states"][v.name()].get<std::string>());
      const double difference = std::abs(ours.probability(labels) - row["p"].get<double>());
      largest = std::max(largest, difference);
      EXPECT_LT(difference, 1e-12) << requests[i].dump() << " at " << row["states"].dump();
    }
  }
  std::cout << "largest difference from pgmpy: " << largest << '\n';
}

TEST_F(pgmpy_agreement_test, yates_statistics_equal_pgmpy_chi_square_and_g_sq) {
  // Few rows, so that many strata are sparse and some are 2 x 2.
  const auto net = read_bif(sachs_path);
  const auto data = sample(net, 1000, 11);
  const auto csv = path("sachs.csv");
  write_csv(data, csv);
  struct ci_case {
    std::string x, y;
    std::vector<std::string> z;
  };
  const std::vector<ci_case> cases{{"Raf", "Mek", {}},
                                   {"Raf", "Erk", {"Mek"}},
                                   {"PKA", "Akt", {"Erk", "PKC"}},
                                   {"Plcg", "PIP3", {"PIP2", "PKC", "Jnk"}},
                                   {"P38", "Jnk", {"PKC", "PKA"}},
                                   {"Akt", "Mek", {"Raf", "PKA", "Erk"}}};
  nlohmann::json requests = nlohmann::json::array();
  for (const auto& c : cases) requests.push_back({{"x", c.x}, {"y", c.y}, {"z", c.z}});
  const auto answers = ask_pgmpy("ci", csv, requests);
  ASSERT_EQ(answers.size(), cases.size());
  std::size_t corrected = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    for (const auto test : {ci_test::chi_square, ci_test::g_squared}) {
      const auto theirs = answers[i][std::string(to_string(test))];
      const auto ours = test_independence(data, cases[i].x, cases[i].y, cases[i].z,
                                          {.test = test, .correction = continuity_correction::yates});
      const auto plain = test_independence(data, cases[i].x, cases[i].y, cases[i].z, test);
      corrected += ours.statistic != plain.statistic;
      const double statistic = theirs["statistic"].get<double>();
      EXPECT_NEAR(ours.statistic, statistic, 1e-9 * std::max(1.0, statistic)) << requests[i].dump();
      EXPECT_EQ(ours.df, theirs["df"].get<double>()) << requests[i].dump();
      // pgmpy's p-value of a test with no degrees of freedom is NaN; ours is 1.
      if (ours.df > 0) EXPECT_NEAR(ours.p_value, theirs["p"].get<double>(), 1e-9) << requests[i].dump();
    }
  }
  // The cases must exercise the correction, or the comparison shows nothing about it.
  EXPECT_GT(corrected, 0u);
}

}  // namespace
}  // namespace pgm
