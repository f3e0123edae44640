// The posterior as a table (CSV and JSON, digits) and the parsers of --query and --evidence,
// on a two-node network whose answers are worked out by hand.

#include "pgm/inference/posterior_table.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace pgm::posterior_table_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// rain → grass: P(rain) = 0.2; P(wet | rain) = 0.9, P(wet | dry) = 0.1.
bayesian_network garden() {
  const variable rain("rain", {"yes", "no"});
  const variable grass("grass", {"wet", "dry, brown"});
  return bayesian_network::from_tables(
      {cpt<double>(rain, {}, {0.2, 0.8}), cpt<double>(grass, {rain}, {0.9, 0.1, 0.1, 0.9})});
}

std::string table_text(const posterior& p, const evidence& e, posterior_table_options options) {
  std::ostringstream out;
  write_posterior_table(out, p, e, options);
  return out.str();
}

TEST(posterior_table_test, csv_lists_every_joint_state_last_variable_fastest) {
  const auto net = garden();
  const auto p = query(net, {"rain", "grass"});
  EXPECT_EQ(table_text(p, {}, {}),
            "rain,grass,probability\n"
            "yes,wet,0.18\n"
            "yes,\"dry, brown\",0.02\n"
            "no,wet,0.08\n"
            "no,\"dry, brown\",0.72\n");
}

TEST(posterior_table_test, digits_round_and_17_reads_back_exactly) {
  const auto net = garden();
  const evidence wet{{"grass", "wet"}};
  const auto p = query(net, {"rain"}, wet);  // P(rain | wet) = 0.18 / 0.26
  const double exact = 0.18 / 0.26;
  EXPECT_THAT(table_text(p, wet, {posterior_format::csv, 3}), HasSubstr("yes,0.692\n"));
  const auto full = table_text(p, wet, {posterior_format::csv, 17});
  const auto line = full.substr(full.find("yes,") + 4);
  EXPECT_EQ(std::stod(line.substr(0, line.find('\n'))), p.probability({"yes"}));
  EXPECT_NEAR(p.probability({"yes"}), exact, 1e-15);
}

TEST(posterior_table_test, json_carries_query_evidence_and_distribution) {
  const auto net = garden();
  const evidence wet{{"grass", "wet"}};
  const auto p = query(net, {"rain"}, wet);
  const auto document = nlohmann::json::parse(table_text(p, wet, {posterior_format::json, 17}));
  EXPECT_EQ(document["query"], nlohmann::json::array({"rain"}));
  EXPECT_EQ(document["evidence"]["grass"], "wet");
  EXPECT_DOUBLE_EQ(document["evidence_probability"].get<double>(), 0.26);
  ASSERT_EQ(document["distribution"].size(), 2U);
  EXPECT_EQ(document["distribution"][1]["rain"], "no");
  EXPECT_EQ(document["distribution"][1]["probability"].get<double>(), p.probability({"no"}));
  // Labels that need escaping stay valid JSON.
  const auto joint = query(net, {"grass"});
  const auto text = table_text(joint, {}, {posterior_format::json, 6});
  EXPECT_EQ(nlohmann::json::parse(text)["distribution"][1]["grass"], "dry, brown");
}

TEST(posterior_table_test, parsers_read_the_command_line_forms) {
  EXPECT_THAT(parse_query_variables(" X , Y"), ElementsAre("X", "Y"));
  EXPECT_EQ(parse_evidence("a=s, b = t"), (evidence{{"a", "s"}, {"b", "t"}}));
  EXPECT_TRUE(parse_evidence("").empty());
  EXPECT_EQ(parse_posterior_format("json"), posterior_format::json);
}

TEST(posterior_table_test, errors_name_what_is_wrong) {
  EXPECT_THAT([] { static_cast<void>(parse_query_variables(" ")); },
              ThrowsMessage<model_error>(HasSubstr("the query names no variable")));
  EXPECT_THAT([] { static_cast<void>(parse_query_variables("X,,Y")); },
              ThrowsMessage<model_error>(HasSubstr("'X,,Y' has an empty variable name")));
  EXPECT_THAT([] { static_cast<void>(parse_evidence("a=s,b")); },
              ThrowsMessage<model_error>(HasSubstr("'b' is not of the form variable=state")));
  EXPECT_THAT([] { static_cast<void>(parse_evidence("a=s,a=t")); },
              ThrowsMessage<model_error>(HasSubstr("'a' is observed twice")));
  EXPECT_THAT([] { static_cast<void>(parse_posterior_format("xml")); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown output format 'xml' (known: csv, json)")));
  const auto net = garden();
  const auto p = query(net, {"rain"});
  std::ostringstream out;
  EXPECT_THAT(
      [&] {
        write_posterior_table(out, p, {}, {posterior_format::csv, 18});
      },
      ThrowsMessage<model_error>(HasSubstr("digits must be between 1 and 17, got 18")));
  EXPECT_TRUE(out.str().empty());
  const variable named("probability", {"a", "b"});
  const auto clash = bayesian_network::from_tables({cpt<double>(named, {}, {0.5, 0.5})});
  EXPECT_THAT([&] { write_posterior_table(out, query(clash, {"probability"}), {}); },
              ThrowsMessage<model_error>(HasSubstr("share its name with the probability column")));
}

}  // namespace
}  // namespace pgm::posterior_table_tests
