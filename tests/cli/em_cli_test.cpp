// `pgm fit --missing em` as a user runs it: the network it writes is the library's EM on the
// same data, latent variables are declared on the command line, and mistakes are refused.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "pgm/inference/sampling.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/learn/expectation_maximization.hpp"
#include "support/program_test.hpp"

namespace pgm::em_cli_tests {
namespace {

using ::testing::HasSubstr;

using em_cli_test = pgm::testing::program_test;

/// A latent class H over three indicators; the CSV has no H and a tenth of the rest missing.
class em_data : public em_cli_test {
 protected:
  void SetUp() override {
    em_cli_test::SetUp();
    const variable h("H", {"0", "1"});
    const auto indicator = [](const std::string& name) { return variable(name, {"no", "yes"}); };
    truth_ = bayesian_network::from_tables({
        cpt<double>(h, {}, {0.4, 0.6}),
        cpt<double>(indicator("X1"), {h}, {0.9, 0.1, 0.2, 0.8}),
        cpt<double>(indicator("X2"), {h}, {0.8, 0.2, 0.1, 0.9}),
        cpt<double>(indicator("X3"), {h}, {0.7, 0.3, 0.25, 0.75}),
    });
    const auto full = sample(truth_, 600, 5);
    std::mt19937_64 random(7);
    std::ofstream out(path("trials.csv"));
    out << "X1,X2,X3\n";
    for (std::size_t row = 0; row < full.rows(); ++row) {
      for (const char* name : {"X1", "X2", "X3"}) {
        out << (uniform01(random) < 0.1 ? "" : full.discrete(name).label(row)) << (name[1] == '3' ? "\n" : ",");
      }
    }
  }

  bayesian_network truth_;
};

TEST_F(em_data, fit_by_em_writes_the_network_the_library_fits) {
  const auto r = run("fit --data " + path("trials.csv").string() +
                     " --edges \"H->X1,H->X2,H->X3\" --missing em --latent H:2 --restarts 3 --seed 5 --verbose --out " +
                     path("em.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("EM start 1, iteration 0: log-likelihood"));
  EXPECT_THAT(r.err, HasSubstr("distinct rows"));
  const auto written = read_network(path("em.json"));

  csv_options reading;
  reading.default_kind = column_kind::discrete;
  reading.missing.policy = missing_policy::available;
  const auto data = read_csv(path("trials.csv"), reading);
  std::vector<variable> variables;
  for (const auto& name : data.names()) variables.push_back(data.discrete(name).var());
  variables.emplace_back("H", std::vector<std::string>{"0", "1"});
  const network_structure structure(variables, parse_edge_list("H->X1,H->X2,H->X3"));
  const auto expected = expectation_maximization(structure, data, {}, {.restarts = 3, .seed = 5});
  ASSERT_EQ(written.size(), expected.network.size());
  for (std::size_t i = 0; i < written.size(); ++i) {
    const auto a = written.tables()[i].values();
    const auto b = expected.network.tables()[i].values();
    for (std::size_t c = 0; c < a.size(); ++c) EXPECT_NEAR(a[c], b[c], 1e-12);
  }
}

TEST_F(em_data, a_model_names_its_latent_variable_and_hard_em_runs) {
  std::ofstream(path("class.bif")) << "network n {}\n"
                                      "variable H { type discrete [ 2 ] { a, b }; }\n"
                                      "variable X1 { type discrete [ 2 ] { no, yes }; }\n"
                                      "variable X2 { type discrete [ 2 ] { no, yes }; }\n"
                                      "variable X3 { type discrete [ 2 ] { no, yes }; }\n"
                                      "probability ( H ) { table 0.5, 0.5; }\n"
                                      "probability ( X1 | H ) { (a) 0.5, 0.5; (b) 0.5, 0.5; }\n"
                                      "probability ( X2 | H ) { (a) 0.5, 0.5; (b) 0.5, 0.5; }\n"
                                      "probability ( X3 | H ) { (a) 0.5, 0.5; (b) 0.5, 0.5; }\n";
  const auto r = run("fit --data " + path("trials.csv").string() + " --model " + path("class.bif").string() +
                     " --missing em --latent H --hard --estimator bayes --out " + path("hard.bif").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("EM: "));
  EXPECT_EQ(read_network(path("hard.bif")).at("H").states(), (std::vector<std::string>{"a", "b"}));
}

TEST_F(em_data, mistakes_are_refused_with_a_clear_message_and_no_output) {
  const auto data = " --data " + path("trials.csv").string() + " --edges \"H->X1,H->X2\" ";
  const auto out = path("never.json");
  expect_failure("fit" + data + "--latent H:2 --out " + out.string(), "--latent applies with --missing em", out);
  expect_failure("fit" + data + "--missing em --latent H:x --out " + out.string(),
                 "--latent 'H:x': expected NAME:COUNT (e.g. H:3)", out);
  expect_failure("fit" + data + "--missing em --latent H:2 --latent X1:2 --out " + out.string(),
                 "'X1' is declared latent but is a column of the data", out);
  expect_failure("fit" + data + "--missing em --latent H --out " + out.string(),
                 "the latent variable 'H' needs its states", out);
  expect_failure("fit" + data + "--missing em --out " + out.string(), "column 'H'", out);
}

}  // namespace
}  // namespace pgm::em_cli_tests
