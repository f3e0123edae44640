// `pgm query` as a user meets it: help, CSV and JSON output, digits, a file output, and each
// kind of bad input ending in one line and a non-zero exit without a half-written file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "pgm/inference/variable_elimination.hpp"
#include "pgm/io/network_file.hpp"
#include "support/program_test.hpp"

namespace pgm::query_cli_tests {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// rain → grass: P(rain) = 0.2; P(wet | rain) = 0.9, P(wet | dry) = 0.1; sun is impossible when
// it rains.
bayesian_network garden() {
  const variable rain("rain", {"yes", "no"});
  const variable grass("grass", {"wet", "dry"});
  const variable sun("sun", {"on", "off"});
  return bayesian_network::from_tables({cpt<double>(rain, {}, {0.2, 0.8}),
                                        cpt<double>(grass, {rain}, {0.9, 0.1, 0.1, 0.9}),
                                        cpt<double>(sun, {rain}, {0.0, 1.0, 0.5, 0.5})});
}

class query_cli_test : public pgm::testing::program_test {
 protected:
  void SetUp() override {
    program_test::SetUp();
    write_network(garden(), dir_ / "garden.bif");
  }
  std::string model() const { return "--model " + (dir_ / "garden.bif").string(); }
};

TEST_F(query_cli_test, help_names_the_options) {
  const auto r = run("query --help");
  EXPECT_EQ(r.code, 0);
  for (const char* option : {"--model", "--query", "--evidence", "--soft", "--all", "--mpe", "--queries", "--engine",
                             "--samples", "--seed", "--format", "--digits", "--out"}) {
    EXPECT_THAT(r.out, HasSubstr(option));
  }
}

TEST_F(query_cli_test, prints_every_state_as_csv) {
  const auto r = run("query " + model() + " --query rain --evidence grass=wet");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "rain,probability\nyes,0.692308\nno,0.307692\n");
  const auto joint = run("query " + model() + " --query rain,grass --digits 2");
  EXPECT_EQ(joint.out, "rain,grass,probability\nyes,wet,0.18\nyes,dry,0.02\nno,wet,0.08\nno,dry,0.72\n");
}

TEST_F(query_cli_test, json_with_full_precision_equals_the_library) {
  const auto r = run("query " + model() + " --query rain --evidence 'grass=wet, sun=off' --format json --digits 17");
  EXPECT_EQ(r.code, 0) << r.err;
  const auto document = nlohmann::json::parse(r.out);
  const auto p = query(garden(), {"rain"}, {{"grass", "wet"}, {"sun", "off"}});
  EXPECT_EQ(document["distribution"][0]["probability"].get<double>(), p.probability({"yes"}));
  EXPECT_EQ(document["distribution"][1]["probability"].get<double>(), p.probability({"no"}));
  EXPECT_EQ(document["evidence_probability"].get<double>(), p.evidence_probability);
  EXPECT_EQ(document["evidence"]["sun"], "off");
}

TEST_F(query_cli_test, every_engine_answers_and_json_names_it) {
  // P(rain = yes | grass = wet) = 0.18 / 0.26.
  for (const char* engine : {"jt", "ve", "auto"}) {
    const auto r =
        run("query " + model() + " --query rain --evidence grass=wet --digits 17 --format json --engine " + engine);
    EXPECT_EQ(r.code, 0) << r.err;
    const auto document = nlohmann::json::parse(r.out);
    EXPECT_NEAR(document["distribution"][0]["probability"].get<double>(), 0.18 / 0.26, 1e-15) << engine;
    EXPECT_EQ(document["engine"], std::string(engine) == "auto" ? "jt" : engine);
  }
  const auto sampled = run("query " + model() + " --query rain --evidence grass=wet --engine lw --samples 100000");
  EXPECT_EQ(sampled.code, 0) << sampled.err;
  EXPECT_THAT(sampled.out, HasSubstr("rain,probability,standard_error\nyes,"));
  const auto again = run("query " + model() +
                         " --query rain --evidence grass=wet --engine lw --samples 100000 "
                         "--threads 1");
  EXPECT_EQ(again.out, sampled.out) << "the same seed gives the same numbers on any number of threads";
}

TEST_F(query_cli_test, soft_evidence_all_marginals_and_the_most_probable_states) {
  // Soft evidence 1:3 on grass: P(rain = yes) ∝ 0.2·(0.9 + 3·0.1) = 0.24, P(no) ∝ 0.8·(0.1 + 3·0.9) = 2.24.
  const auto soft = run("query " + model() + " --query rain --soft grass=1:3 --digits 17 --format json");
  EXPECT_EQ(soft.code, 0) << soft.err;
  const auto document = nlohmann::json::parse(soft.out);
  EXPECT_NEAR(document["distribution"][0]["probability"].get<double>(), 0.24 / 2.48, 1e-15);
  EXPECT_EQ(document["soft_evidence"]["grass"][1].get<double>(), 3.0);
  const auto all = run("query " + model() + " --all --evidence grass=wet");
  EXPECT_EQ(all.code, 0) << all.err;
  EXPECT_EQ(all.out,
            "variable,state,probability\nrain,yes,0.692308\nrain,no,0.307692\nsun,on,0.153846\nsun,off,0.846154\n");
  // The most probable states: rain = no, grass = dry, sun on or off (a tie at 0.36, settled the
  // same way every time); of rain alone, no.
  const auto best = run("query " + model() + " --mpe --format json --digits 17");
  EXPECT_EQ(best.code, 0) << best.err;
  const auto mpe = nlohmann::json::parse(best.out);
  EXPECT_EQ(mpe["mpe"]["rain"], "no");
  EXPECT_EQ(mpe["mpe"]["grass"], "dry");
  EXPECT_NEAR(mpe["probability"].get<double>(), 0.36, 1e-15);
  EXPECT_EQ(run("query " + model() + " --mpe --query rain").out, "rain,probability\nno,0.8\n");
}

TEST_F(query_cli_test, interventions_cut_the_variable_from_its_parents) {
  // do(grass = wet) tells nothing of rain: P(rain = yes) stays 0.2; observing it gives 0.692308.
  const auto set = run("query " + model() + " --query rain --do grass=wet --format json --digits 17");
  EXPECT_EQ(set.code, 0) << set.err;
  const auto document = nlohmann::json::parse(set.out);
  EXPECT_EQ(document["distribution"][0]["probability"].get<double>(), 0.2);
  EXPECT_EQ(document["do"]["grass"], "wet");
  // do(rain = yes) sets rain's children's parent: P(sun = on) = 0.
  EXPECT_EQ(run("query " + model() + " --query sun --do rain=yes").out, "sun,probability\non,0\noff,1\n");
  expect_failure("query " + model() + " --query sun --do rain=yes --evidence rain=yes",
                 "'rain' is both intervened on and observed");
  expect_failure("query " + model() + " --query rain --do rain=yes", "'rain' is intervened on");
}

TEST_F(query_cli_test, a_file_of_queries_gives_one_record_per_line_in_order) {
  const auto file = dir_ / "queries.csv";
  std::ofstream(file) << "query,evidence,soft,engine\nrain,grass=wet,,\n\"rain,grass\",,,ve\n"
                         "grass,\"rain=yes,sun=on\",,\nsun,,grass=1:3,lw\n";
  const auto json = run("query " + model() + " --queries " + file.string() + " --format json --samples 1000");
  EXPECT_EQ(json.code, 0) << json.err;
  EXPECT_THAT(json.err, HasSubstr("1 of 4 queries have evidence of probability 0"));
  std::istringstream lines(json.out);
  std::vector<nlohmann::json> records;
  for (std::string line; std::getline(lines, line);) records.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(records.size(), 4U);
  EXPECT_EQ(records[0]["line"], 2);
  EXPECT_NEAR(records[0]["distribution"][0]["probability"].get<double>(), 0.692308, 1e-6);
  EXPECT_EQ(records[1]["engine"], "ve");
  EXPECT_EQ(records[1]["distribution"].size(), 4U);
  EXPECT_EQ(records[2]["evidence_probability"], 0);
  EXPECT_THAT(records[2]["error"].get<std::string>(), HasSubstr("probability 0"));
  EXPECT_EQ(records[3]["engine"], "lw");
  EXPECT_TRUE(records[3]["distribution"][0].contains("standard_error"));
  const auto csv = run("query " + model() + " --queries " + file.string() + " --samples 1000");
  EXPECT_THAT(csv.out, HasSubstr("line,query,evidence,soft,do,engine,evidence_probability,distribution\n"
                                 "2,rain,grass=wet,,,jt,0.26,yes=0.692308;no=0.307692\n"));
  EXPECT_THAT(csv.out, HasSubstr("\n3,\"rain,grass\",,,,ve,1,yes&wet=0.18;yes&dry=0.02;no&wet=0.08;no&dry=0.72\n"));
  // A line that does not parse, or names what the network lacks, fails the run with its place.
  std::ofstream(dir_ / "bad.csv") << "query,evidence\nrain,\ncloud,rain=yes\n";
  expect_failure("query " + model() + " --queries " + (dir_ / "bad.csv").string(),
                 "bad.csv:3:1: the network has no variable 'cloud'");
  std::ofstream(dir_ / "header.csv") << "query,evidense\nrain,grass=wet\n";
  expect_failure("query " + model() + " --queries " + (dir_ / "header.csv").string(),
                 "header.csv:1:7: unknown column 'evidense' (known: query, evidence, soft, do, engine)");
}

TEST_F(query_cli_test, writes_a_file_on_request) {
  const auto out = dir_ / "p.csv";
  const auto r = run("query " + model() + " --query grass --out " + out.string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(slurp(out), "grass,probability\nwet,0.26\ndry,0.74\n");
}

TEST_F(query_cli_test, bad_input_is_one_line_and_no_file) {
  const auto out = dir_ / "p.json";
  const auto with_out = " --out " + out.string();
  expect_failure("query " + model() + " --query cloud" + with_out, "the network has no variable 'cloud'", out);
  expect_failure("query " + model() + " --query rain --evidence grass=soaked" + with_out, "soaked", out);
  expect_failure("query " + model() + " --query grass --evidence rain=yes,sun=on" + with_out,
                 "the evidence rain=yes, sun=on has probability 0", out);
  expect_failure("query " + model() + " --query rain --evidence rain=yes" + with_out,
                 "'rain' is both queried and observed", out);
  expect_failure("query " + model() + " --query rain,rain" + with_out, "the query names 'rain' twice", out);
  expect_failure("query " + model() + " --query rain --evidence grass" + with_out,
                 "'grass' is not of the form variable=state", out);
  expect_failure("query " + model() + " --query ''" + with_out, "the query names no variable", out);
  expect_failure("query --model " + (dir_ / "none.bif").string() + " --query rain" + with_out, "none.bif", out);
  expect_failure("query " + model() + " --query rain --out " + (dir_ / "no" / "p.csv").string(), "the directory");
  const auto usage = run("query " + model() + " --query rain --digits 18");
  EXPECT_EQ(usage.code, 2);
  EXPECT_THAT(usage.err, HasSubstr("--digits"));
  const auto format = run("query " + model() + " --query rain --format xml");
  EXPECT_EQ(format.code, 2);
  EXPECT_THAT(format.err, HasSubstr("--format"));
  expect_failure("query " + model() + " --query rain --soft grass=1:2:3" + with_out,
                 "has 3 weights, but 'grass' has 2 states", out);
  expect_failure("query " + model() + " --query rain --soft grass=1:x" + with_out, "the weight 'x'", out);
  expect_failure("query " + model() + " --query rain --soft grass=0:0" + with_out, "every state weight 0", out);
  const auto engine = run("query " + model() + " --query rain --engine magic");
  EXPECT_EQ(engine.code, 2);
  EXPECT_THAT(engine.err, HasSubstr("--engine"));
  const auto two = run("query " + model() + " --query rain --all");
  EXPECT_EQ(two.code, 2);
  EXPECT_THAT(two.err, HasSubstr("ask one thing"));
  const auto none = run("query " + model());
  EXPECT_EQ(none.code, 2);
  EXPECT_THAT(none.err, HasSubstr("ask one thing"));
}

}  // namespace
}  // namespace pgm::query_cli_tests
