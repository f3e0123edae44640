// Limits and numbers of the model and scenario readers (pgm/core/limits.hpp, docs/limits.md):
// a BIF table of 10^9 entries, JSON nested 10^5 deep, a scenario of 10^15 rows, and the
// numbers users type in BIF probabilities.

#include "pgm/core/limits.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "pgm/eval/scenario.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/net.hpp"
#include "pgm/io/xmlbif.hpp"
#include "pgm/sim/task_file.hpp"

namespace pgm::io_limits_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

std::string thousand_states(const std::string& name) {
  std::string text = "variable " + name + " {\n  type discrete [ 1000 ] { ";
  for (int i = 0; i < 1000; ++i) text += (i ? ", s" : "s") + std::to_string(i);
  return text + " };\n}\n";
}

std::string uniform_table(const std::string& name) {
  std::string text = "probability ( " + name + " ) {\n  table ";
  for (int i = 0; i < 1000; ++i) text += i ? ", 0.001" : "0.001";
  return text + ";\n}\n";
}

TEST(limits_test, a_bif_table_of_a_billion_entries_is_refused_before_it_is_allocated) {
  const auto text = "network n { }\n" + thousand_states("a") + thousand_states("b") + thousand_states("y") +
                    uniform_table("a") + uniform_table("b") + "probability ( y | a, b ) {\n  default 1, 0;\n}\n";
  EXPECT_THAT([&] { static_cast<void>(parse_bif(text, "big.bif")); },
              ThrowsMessage<parse_error>(
                  HasSubstr("big.bif:17:15: the table of 'y' would have 1000000000 cells (1000 states × 1000000 parent "
                            "configurations), more than pgm's limit of 16777216 cells per table (docs/limits.md)")));
}

// y with two states under two parents of 4,096 states: 2^25 cells, one over the limit, in every
// format, refused before a value of the table is read (a NET file of this kind peaked at
// 2.2 GB before; issue 28).
std::vector<std::string> states_named(const std::string& stem, int count) {
  std::vector<std::string> states;
  for (int i = 0; i < count; ++i) states.push_back(stem + std::to_string(i));
  return states;
}

const std::string limit_message =
    "the table of 'y' would have 33554432 cells (2 states × 16777216 parent configurations), more than pgm's limit "
    "of 16777216 cells per table (docs/limits.md)";

TEST(limits_test, every_model_format_refuses_a_table_beyond_the_limit_before_reading_it) {
  std::string net;
  std::string xml = "<BIF><NETWORK>\n";
  nlohmann::json json = {
      {"format", "pgm-model"},
      {"version", 1},
      {"edges", nlohmann::json::array({nlohmann::json::array({"a", "y"}), nlohmann::json::array({"b", "y"})})}};
  for (const auto& [name, count] : {std::pair<std::string, int>{"a", 4096}, {"b", 4096}, {"y", 2}}) {
    const auto states = states_named("s", count);
    net += "node " + name + " {\n  states = (";
    xml += "<VARIABLE TYPE=\"nature\"><NAME>" + name + "</NAME>";
    for (const auto& state : states) {
      net += " \"" + state + "\"";
      xml += "<OUTCOME>" + state + "</OUTCOME>";
    }
    net += " );\n}\n";
    xml += "</VARIABLE>\n";
    json["variables"].push_back({{"name", name}, {"states", states}});
  }
  net += "potential ( y | a b ) {\n  data = ( 0.5 0.5 );\n}\n";
  xml += "<DEFINITION><FOR>y</FOR><GIVEN>a</GIVEN><GIVEN>b</GIVEN><TABLE>0.5 0.5</TABLE></DEFINITION>\n";
  xml += "</NETWORK></BIF>\n";
  json["tables"] = {{{"variable", "y"}, {"parents", {"a", "b"}}, {"values", {{0.5, 0.5}}}}};
  EXPECT_THAT([&] { static_cast<void>(parse_net(net, "big.net")); },
              ThrowsMessage<parse_error>(HasSubstr("big.net:10:13: " + limit_message)));
  EXPECT_THAT([&] { static_cast<void>(parse_xmlbif(xml, "big.xml")); },
              ThrowsMessage<parse_error>(HasSubstr("big.xml:5:1: " + limit_message)));
  EXPECT_THAT([&] { static_cast<void>(parse_model_json(json.dump(), "big.json")); },
              ThrowsMessage<data_error>(HasSubstr("big.json: /tables/0: " + limit_message)));
}

// A NET value list nested deeper than JSON's limit is refused, not a stack overflow.
TEST(limits_test, net_lists_nested_a_million_deep_are_refused) {
  const auto text =
      "node a {\n  states = " + std::string(1'000'000, '(') + "\"x\"" + std::string(1'000'000, ')') + ";\n}\n";
  EXPECT_THAT(
      [&] { static_cast<void>(parse_net(text, "deep.net")); },
      ThrowsMessage<parse_error>(HasSubstr("deep.net:2:268: lists nested deeper than 256 levels, pgm's limit")));
}

TEST(limits_test, bif_numbers_of_states_are_whole_numbers_in_digits) {
  for (const std::string count : {"1e300", "nan", "2.0", "-1", "0", "0x2", "99999999999999999999999"}) {
    const auto text = "network n { }\nvariable a {\n  type discrete [ " + count + " ] { s0, s1 };\n}\n";
    EXPECT_THAT([&] { static_cast<void>(parse_bif(text, "n.bif")); },
                ThrowsMessage<parse_error>(HasSubstr("n.bif:3:19: expected the number of states (a whole number ≥ 1), "
                                                     "found '" +
                                                     count + "'")))
        << count;
  }
}

TEST(limits_test, json_nested_a_hundred_thousand_deep_is_refused_where_it_passes_the_limit) {
  const auto deep = std::string(100'000, '[') + std::string(100'000, ']');
  const std::string message = "m.json:1:257: arrays and objects nested deeper than 256 levels, pgm's limit";
  EXPECT_THAT([&] { static_cast<void>(parse_model_json(deep, "m.json")); },
              ThrowsMessage<parse_error>(HasSubstr(message)));
  EXPECT_THAT([&] { static_cast<void>(sim::parse_task("{\"a\":" + deep + "}", "m.json")); },
              ThrowsMessage<parse_error>(HasSubstr("m.json:1:261: arrays and objects nested deeper")));
  // Brackets inside strings do not count; 256 levels are read (and then refused as no model).
  const auto strings = "{\"format\":\"[[[[" + std::string(1000, '{') + "\\\"\"}";
  EXPECT_THAT([&] { static_cast<void>(parse_model_json(strings, "m.json")); },
              ThrowsMessage<data_error>(HasSubstr("m.json: /format: expected \"pgm-model\"")));
  const auto at_limit = std::string(json_max_depth, '[') + std::string(json_max_depth, ']');
  EXPECT_THAT([&] { static_cast<void>(parse_model_json(at_limit, "m.json")); },
              ThrowsMessage<data_error>(HasSubstr("m.json: /: expected an object")));
}

std::string scenario_with_rows(const std::string& rows) {
  return R"({"format": "pgm-scenario", "version": 1, "name": "s", "title": "T",
    "prior": {"task": "one", "rows": )" +
         rows + R"(, "node": "ok1"},
    "target": {"node": "ok2", "tasks": [{"task": "two", "train_rows": 4, "ground_truth_rows": 4}]},
    "map": "ok2=ok1", "strategies": ["direct"], "weights": [0, 5]})";
}

TEST(limits_test, a_scenario_asking_for_a_quadrillion_rows_is_refused) {
  EXPECT_THAT([] { static_cast<void>(parse_scenario(scenario_with_rows("1000000000000000"), "s.json")); },
              ThrowsMessage<data_error>(HasSubstr("s.json: /prior/rows: 1000000000000000 rows are more than "
                                                  "1000000000, pgm's limit of rows to simulate (docs/limits.md)")));
  EXPECT_EQ(parse_scenario(scenario_with_rows("1000000000"), "s.json").prior_rows, max_simulated_rows);
  EXPECT_THAT([] { static_cast<void>(parse_scenario(scenario_with_rows("1e3"), "s.json")); },
              ThrowsMessage<data_error>(HasSubstr("/prior/rows: expected a whole number ≥ 0")));
  EXPECT_THAT([] { static_cast<void>(parse_scenario(scenario_with_rows("1e400"), "s.json")); },
              ThrowsMessage<parse_error>(HasSubstr("number out of range: '1e400'")));
  // Repetitions and subsets: every point is kept until the tables are written (issue 28).
  auto many = scenario_with_rows("10");
  many.replace(many.find("\"weights\""), 9, "\"repetitions\": 5000, \"weights\"");
  EXPECT_THAT([&] { static_cast<void>(parse_scenario(many, "s.json")); },
              ThrowsMessage<data_error>(HasSubstr(
                  "s.json: /repetitions: 5000 are more than 1000, pgm's limit of repetitions (docs/limits.md)")));
  auto parts = scenario_with_rows("10");
  parts.replace(parts.find("\"weights\""), 9, "\"subsets\": 101, \"weights\"");
  EXPECT_THAT([&] { static_cast<void>(parse_scenario(parts, "s.json")); },
              ThrowsMessage<data_error>(HasSubstr("s.json: /subsets: 101 are more than 100, pgm's limit of subsets")));
}

std::string bif_with(const std::string& probabilities) {
  return "network n { }\nvariable a {\n  type discrete [ 2 ] { s0, s1 };\n}\nprobability ( a ) {\n  table " +
         probabilities + ";\n}\n";
}

TEST(numbers_in_models_test, bif_probabilities_follow_the_rule) {
  const auto fails = [](const std::string& values, const std::string& message) {
    EXPECT_THAT([&] { static_cast<void>(parse_bif(bif_with(values), "n.bif")); },
                ThrowsMessage<parse_error>(HasSubstr(message)))
        << values;
  };
  fails("nan, 1", "n.bif:6:9: expected a probability, found 'nan' (NaN is not accepted)");
  fails("0.5, inf", "n.bif:6:14: expected a probability, found 'inf' (infinities are not accepted)");
  fails("1e400, 0", "found '1e400' (out of the range of a double");
  fails("0x1p-1, 0x1p-1", "found '0x1p-1' (hexadecimal is not accepted");
  const auto net = parse_bif(bif_with("-0, 1"), "n.bif");
  EXPECT_EQ(net.table("a").probability("s0", {}), 0.0);
  EXPECT_EQ(parse_bif(bif_with("5e-1, .5"), "n.bif").table("a").probability("s1", {}), 0.5);
}

TEST(numbers_in_models_test, json_has_no_nan_hex_or_overflowing_numbers) {
  const auto model = [](const std::string& values) {
    return R"({"format":"pgm-model","version":1,"variables":[{"name":"a","states":["0","1"]}],"edges":[],)"
           R"("tables":[{"variable":"a","parents":[],"values":[[)" +
           values + "]]}]}";
  };
  EXPECT_THAT([&] { static_cast<void>(parse_model_json(model("NaN, 1"), "m.json")); },
              ThrowsMessage<parse_error>(HasSubstr("m.json:1:")));
  EXPECT_THAT([&] { static_cast<void>(parse_model_json(model("0x1p-1, 0.5"), "m.json")); },
              ThrowsMessage<parse_error>(HasSubstr("invalid JSON")));
  EXPECT_THAT([&] { static_cast<void>(parse_model_json(model("1e400, 0"), "m.json")); },
              ThrowsMessage<parse_error>(HasSubstr("number out of range: '1e400'")));
  EXPECT_EQ(parse_model_json(model("-0, 1"), "m.json").network().table("a").probability("0", {}), 0.0);
}

}  // namespace
}  // namespace pgm::io_limits_tests
