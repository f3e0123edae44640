// `pgm solve` as a user meets it: the four tasks in the competition's result format, a Bayesian
// network in another format, and bad input ending in one line and a non-zero exit without a
// half-written answer.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "pgm/io/bif.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/uai.hpp"
#include "support/program_test.hpp"

namespace pgm::solve_cli_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

// a – b – c, a chain: Z and the marginals by hand below.
constexpr const char* chain = "MARKOV\n3\n2 2 2\n2\n2 0 1\n2 1 2\n\n4\n 1 2 3 4\n\n4\n 1 1 1 5\n";

class solve_cli_test : public pgm::testing::program_test {
 protected:
  void SetUp() override {
    program_test::SetUp();
    std::ofstream(dir_ / "chain.uai") << chain;
    std::ofstream(dir_ / "chain.uai.evid") << "1 2 1\n";
    std::ofstream(dir_ / "chain.uai.query") << "1 0\n";
  }
  std::string model() const { return "--model " + (dir_ / "chain.uai").string(); }
  std::string out() const { return (dir_ / "answer").string(); }
  std::string answer() const { return slurp(dir_ / "answer"); }
};

TEST_F(solve_cli_test, help_names_the_options) {
  const auto r = run("solve --help");
  EXPECT_EQ(r.code, 0);
  for (const char* option : {"--model", "--task", "--evidence", "--evidence-sample", "--query", "--engine",
                             "--heuristic", "--order-restarts", "--seed", "--schedule", "--damping", "--tolerance",
                             "--iterations", "--sweeps", "--burn-in", "--memory-limit", "--out"}) {
    EXPECT_THAT(r.out, HasSubstr(option));
  }
  EXPECT_THAT(r.out, HasSubstr("--time-limit"));
}

TEST_F(solve_cli_test, writes_the_four_answers) {
  // Σ_abc φ(a,b) ψ(b,c): b=0 gives (1+3)(1+1) = 8, b=1 gives (2+4)(1+5) = 36.
  auto r = run("solve " + model() + " --task PR --out " + out());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("PR by jt, exact"));
  EXPECT_NEAR(std::stod(answer().substr(3)), std::log10(44.0), 1e-15);
  // With c = 1: b=0 gives 4·1, b=1 gives 6·5.
  r = run("solve " + model() + " --evidence " + (dir_ / "chain.uai.evid").string() + " --task MAR --engine ve --out " +
          out());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto mar = parse_uai_result(answer(), "answer");
  EXPECT_EQ(mar.task, "MAR");
  ASSERT_EQ(mar.numbers.size(), 10U);
  EXPECT_NEAR(mar.numbers[5], 4.0 / 34.0, 1e-16);  // P(b = 0 | c = 1)
  EXPECT_EQ(mar.numbers[8], 0.0);                  // c observed: a point mass
  EXPECT_EQ(mar.numbers[9], 1.0);
  r = run("solve " + model() + " --task MAP --out " + out());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(answer(), "MAP\n3 1 1 1\n");
  r = run("solve " + model() + " --task MMAP --query " + (dir_ / "chain.uai.query").string() + " --out " + out());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(answer(), "MMAP\n1 1\n");
}

TEST_F(solve_cli_test, reads_a_bayesian_network_in_any_format) {
  const auto network = read_bif(std::string(PGM_NETWORKS_DIR) + "/asia.bif");
  write_network(network, dir_ / "asia.bif");
  const auto r = run("solve --model " + (dir_ / "asia.bif").string() + " --task PR --out " + out());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NEAR(std::stod(answer().substr(3)), 0.0, 1e-15);  // no evidence: P = 1
}

TEST_F(solve_cli_test, bad_input_fails_without_an_answer) {
  expect_failure("solve " + model() + " --task MMAP --out " + out(), "--task MMAP needs --query", out());
  expect_failure("solve " + model() + " --task MAR --query " + (dir_ / "chain.uai.query").string() + " --out " + out(),
                 "takes none", out());
  expect_failure("solve " + model() + " --task MARX --out " + out(), "--task", out());
  std::ofstream(dir_ / "bad.evid") << "1 2 7\n";
  expect_failure("solve " + model() + " --task MAR --evidence " + (dir_ / "bad.evid").string() + " --out " + out(),
                 "bad.evid:1:5: the state of variable 2 7 is out of range", out());
  std::ofstream(dir_ / "impossible.uai") << "MARKOV\n1\n2\n1\n1 0\n2\n0 1\n";
  std::ofstream(dir_ / "impossible.evid") << "1 0 0\n";
  expect_failure("solve --model " + (dir_ / "impossible.uai").string() + " --evidence " +
                     (dir_ / "impossible.evid").string() + " --task MAR --out " + out(),
                 "has probability 0", out());
  expect_failure("solve " + model() + " --task MAR --evidence-sample 3 --evidence " +
                     (dir_ / "chain.uai.evid").string() + " --out " + out(),
                 "holds 1 evidence sample", out());
  std::ofstream(dir_ / "truncated.uai") << "MARKOV\n3\n2 2 2\n2\n2 0 1\n";
  expect_failure("solve --model " + (dir_ / "truncated.uai").string() + " --task PR --out " + out(),
                 "truncated.uai:6:1: expected the size of a factor's scope, found the end of the file", out());
}

TEST_F(solve_cli_test, a_model_past_the_memory_limit_is_refused_naming_the_sizes) {
  // A 12 × 12 grid: its junction tree holds some 10^5 cells, more than 1 MiB.
  constexpr int side = 12;
  std::string grid = "MARKOV\n" + std::to_string(side * side) + "\n";
  for (int i = 0; i < side * side; ++i) grid += "2 ";
  grid += "\n" + std::to_string(2 * side * (side - 1)) + "\n";
  std::string tables;
  for (int r = 0; r < side; ++r) {
    for (int c = 0; c < side; ++c) {
      if (c + 1 < side) {
        grid += "2 " + std::to_string(side * r + c) + " " + std::to_string(side * r + c + 1) + "\n";
        tables += "4 1 2 3 4\n";
      }
      if (r + 1 < side) {
        grid += "2 " + std::to_string(side * r + c) + " " + std::to_string(side * r + c + side) + "\n";
        tables += "4 1 2 3 4\n";
      }
    }
  }
  std::ofstream(dir_ / "grid.uai") << grid << tables;
  const auto r =
      run("solve --model " + (dir_ / "grid.uai").string() + " --task PR --engine jt --memory-limit 1 --out " + out());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("more than the memory limit of 1 MiB"));
  EXPECT_THAT(r.err, Not(HasSubstr("hint")));
  EXPECT_FALSE(std::filesystem::exists(out()));
  const auto automatic =
      run("solve --model " + (dir_ / "grid.uai").string() + " --task MAR --memory-limit 1 --out " + out());
  EXPECT_EQ(automatic.code, 0) << automatic.err;
  EXPECT_THAT(automatic.err, HasSubstr("auto chose bp"));
  EXPECT_THAT(automatic.err, HasSubstr("MAR by bp, approximate"));
  EXPECT_THAT(answer(), StartsWith("MAR\n144 2 "));
  const auto fits = run("solve --model " + (dir_ / "grid.uai").string() + " --task PR --out " + out());
  EXPECT_EQ(fits.code, 0) << fits.err;
  EXPECT_THAT(answer(), StartsWith("PR\n"));
}

TEST_F(solve_cli_test, query_and_show_read_a_markov_network) {
  // P(b | c=1) ∝ (4·1, 6·5); P(c=1) = Z(c=1)/Z = 34/44.
  for (const char* engine : {"jt", "ve", "auto"}) {
    const auto r = run("query " + model() + " --query v1 --evidence v2=1 --format json --digits 17 --engine " + engine);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("\"evidence_probability\": 0.77272727272727"));
    EXPECT_THAT(r.out, HasSubstr("\"probability\": 0.11764705882352"));
  }
  const auto bp = run("query " + model() + " --all --engine bp --digits 17");
  ASSERT_EQ(bp.code, 0) << bp.err;
  EXPECT_THAT(bp.out, HasSubstr("v1,1,0.81818181818181"));  // 36/44: the chain is a tree, bp is exact
  const auto surgery = run("query " + model() + " --query v1 --do v2=1");
  EXPECT_EQ(surgery.code, 1);
  EXPECT_THAT(surgery.err, HasSubstr("this model is a Markov network"));
  const auto weighting = run("query " + model() + " --query v1 --engine lw");
  EXPECT_EQ(weighting.code, 1);
  EXPECT_THAT(weighting.err, HasSubstr("'lw' does not serve a Markov network"));
  const auto shown = run("show " + (dir_ / "chain.uai").string() + " --variable v2");
  ASSERT_EQ(shown.code, 0) << shown.err;
  EXPECT_THAT(shown.out, HasSubstr("a Markov network of 3 variables, 2 factors, 8 values"));
  EXPECT_THAT(shown.out, HasSubstr("factor 1 over (v1, v2)\n  v1  | 0  1\n  0   | 1  1\n  1   | 1  5\n"));
  EXPECT_THAT(shown.out, Not(HasSubstr("factor 0")));
  // Through pgm's JSON and back to UAI: the same model, the same answers; BIF cannot hold it.
  const auto json = (dir_ / "chain.json").string();
  auto converted = run("convert " + (dir_ / "chain.uai").string() + " " + json);
  ASSERT_EQ(converted.code, 0) << converted.err;
  EXPECT_THAT(slurp(dir_ / "chain.json"), HasSubstr("{\"scope\": [\"v1\", \"v2\"], \"values\": [1, 1, 1, 5]}"));
  converted = run("convert " + json + " " + (dir_ / "again.uai").string());
  ASSERT_EQ(converted.code, 0) << converted.err;
  EXPECT_EQ(parse_uai(slurp(dir_ / "again.uai"), "again.uai").model, parse_uai(chain, "chain.uai").model);
  const auto from_json = run("query --model " + json + " --query v1 --evidence v2=1 --format json --digits 17");
  ASSERT_EQ(from_json.code, 0) << from_json.err;
  EXPECT_THAT(from_json.out, HasSubstr("\"probability\": 0.11764705882352"));
  const auto to_bif = run("convert " + json + " " + (dir_ / "chain.bif").string());
  EXPECT_EQ(to_bif.code, 1);
  EXPECT_THAT(to_bif.err, HasSubstr("holds a Markov network, which bif cannot hold; convert it to .uai or .json"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "chain.bif"));
}

TEST_F(solve_cli_test, the_time_limit_stops_bp_and_gibbs_with_an_answer_and_an_exact_engine_with_nothing) {
  const auto grid = std::string(PGM_SOURCE_DIR) + "/tests/data/uai/MAR/Grids_11.uai";
  // bp on a loopy grid with a tolerance it cannot reach: only the limit stops it.
  auto r = run("solve --model " + grid +
               " --task MAR --engine bp --tolerance 1e-300 --iterations 1000000 --time-limit 0.3 --out " + out());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("not converged"));
  EXPECT_THAT(r.err, HasSubstr("stopped at the time limit"));
  EXPECT_THAT(answer(), StartsWith("MAR\n100 2 "));
  r = run("solve --model " + grid + " --task MAR --engine gibbs --sweeps 100000000 --time-limit 0.3 --out " + out());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("stopped at the time limit"));
  // The junction tree of Grids_11 takes about half a second: a twentieth is not enough.
  std::filesystem::remove(dir_ / "answer");
  r = run("solve --model " + grid + " --task MAR --engine jt --time-limit 0.02 --out " + out());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("did not finish within --time-limit 0.02 s, so nothing was written"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "answer"));
  r = run("solve " + model() + " --task PR --time-limit -1 --out " + out());
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("--time-limit"));
}

}  // namespace
}  // namespace pgm::solve_cli_tests
