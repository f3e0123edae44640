// `pgm query` as a user meets it: help, CSV and JSON output, digits, a file output, and each
// kind of bad input ending in one line and a non-zero exit without a half-written file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "pgm/inference/variable_elimination.hpp"
#include "pgm/io/network_file.hpp"
#include "support/program_test.hpp"

namespace pgm {
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
  for (const char* option : {"--model", "--query", "--evidence", "--format", "--digits", "--out"}) {
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
}

}  // namespace
}  // namespace pgm
