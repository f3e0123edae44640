// `pgm dsep`, `pgm check` and `pgm sample` as a user meets them, on the published alarm network and data
// sampled from it: help, the answers, and bad input ending in one line and a non-zero exit.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "pgm/causal/dag_check.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/json_model.hpp"
#include "support/program_test.hpp"

namespace pgm::causal_cli_tests {
namespace {

using ::testing::HasSubstr;

class causal_cli_test : public pgm::testing::program_test {
 protected:
  static std::string alarm() { return (std::filesystem::path(PGM_NETWORKS_DIR) / "alarm.bif").string(); }
};

TEST_F(causal_cli_test, dsep_answers_both_ways) {
  EXPECT_THAT(run("dsep --help").out, HasSubstr("--given"));
  // HR depends on CVP through the heart's state; given CO and the rest of its ancestors' blanket
  // the textbook chain is blocked: HISTORY -> LVFAILURE -> LVEDVOLUME -> CVP.
  const auto open = run("dsep --model " + alarm() + " HISTORY CVP");
  EXPECT_EQ(open.code, 0) << open.err;
  EXPECT_EQ(open.out, "{HISTORY} and {CVP} are d-connected given {}\n");
  const auto blocked = run("dsep --model " + alarm() + " HISTORY CVP --given LVFAILURE");
  EXPECT_EQ(blocked.out, "{HISTORY} and {CVP} are d-separated given {LVFAILURE}\n");
  expect_failure("dsep --model " + alarm() + " HISTORY CVPP", "unknown variable 'CVPP'");
  expect_failure("dsep --model " + alarm() + " HISTORY HISTORY", "disjoint sets: 'HISTORY' is in both X and Y");
  expect_failure("dsep --model " + alarm() + " HISTORY CVP --given CVP",
                 "disjoint sets: 'CVP' is in both Y and the conditioning set");
}

TEST_F(causal_cli_test, check_passes_data_of_the_network_and_rejects_a_wrong_structure) {
  const auto net = read_bif(alarm());
  const auto data_path = dir_ / "alarm.csv";
  {
    std::ofstream out(data_path);
    write_csv(sample(net, 10'000, 1), out);
  }
  const auto good = run("check --model " + alarm() + " --data " + data_path.string() + " --alpha 0.001");
  EXPECT_EQ(good.code, 0) << good.err;
  EXPECT_THAT(good.out, HasSubstr("independences the DAG implies on 10000 rows (chi2, alpha 0.001)"));
  // A wrong structure: HR's edge from CATECHOL left out; the data reject HR _||_ CATECHOL.
  auto wrong = net.structure();
  wrong.remove_edge("CATECHOL", "HR");
  const auto wrong_path = dir_ / "wrong.json";  // a structure-only model, as learn-structure writes one
  write_model_json(to_json(wrong), wrong_path);
  const auto bad =
      run("check --model " + wrong_path.string() + " --data " + data_path.string() + " --alpha 0.001 --format csv");
  EXPECT_EQ(bad.code, 0) << bad.err;
  EXPECT_THAT(bad.out, HasSubstr("x,y,given,statistic,df,p_value,rejected\n"));
  const auto first_row = bad.out.substr(bad.out.find('\n') + 1);
  EXPECT_THAT(first_row.substr(0, first_row.find(',', first_row.find(',') + 1)),
              ::testing::AnyOf(::testing::StrEq("HR,CATECHOL"), ::testing::StrEq("CATECHOL,HR")));
  expect_failure("check --model " + alarm() + " --data " + (dir_ / "none.csv").string(), "none.csv");
  const auto alpha = run("check --model " + alarm() + " --data " + data_path.string() + " --alpha 1.5");
  EXPECT_EQ(alpha.code, 2);
}

TEST_F(causal_cli_test, sample_writes_the_rows_the_library_draws) {
  EXPECT_THAT(run("sample --help").out, HasSubstr("--rows"));
  const auto first = dir_ / "first.csv";
  const auto result = run("sample --model " + alarm() + " --rows 500 --seed 3 --out " + first.string());
  EXPECT_EQ(result.code, 0) << result.err;
  std::ostringstream expected;
  write_csv(sample(read_bif(alarm()), 500, 3), expected);
  std::ifstream in(first);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(written, expected.str());
  EXPECT_EQ(run("sample --model " + alarm() + " --rows 0 --out " + (dir_ / "none.csv").string()).code, 2);
  expect_failure("sample --model " + (dir_ / "missing.bif").string() + " --rows 5 --out " + first.string(),
                 "missing.bif");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "none.csv"));
}

}  // namespace
}  // namespace pgm::causal_cli_tests
