// A Markov network in pgm's JSON model (pgm/io/json_model.hpp, "kind": "markov"): round trips to
// the bit, through UAI and back, and every error naming the JSON path and what was expected.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "pgm/io/json_model.hpp"
#include "pgm/io/uai.hpp"
#include "pgm/testing/random_markov_network.hpp"

namespace pgm {
namespace markov_json_test {

using ::testing::HasSubstr;

std::string json_of(const markov_network& model) {
  std::ostringstream out;
  write_markov_json(out, model);
  return out.str();
}

std::string error_of(std::string_view text) {
  try {
    static_cast<void>(parse_markov_json(text, "m.json"));
  } catch (const error& e) {
    return e.what();
  }
  return "no error";
}

std::string model_with(std::string_view factors) {
  return R"({"format": "pgm-model", "version": 1, "kind": "markov",
  "variables": [{"name": "a", "states": ["0", "1"]}, {"name": "b", "states": ["x", "y", "z"]}],
  "factors": [)" +
         std::string(factors) + "]}";
}

TEST(markov_json_test, random_models_round_trip_to_the_bit) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    // A large scale draws values across many orders of magnitude, every digit significant.
    const auto model = testing::random_markov_network(seed, {.variables = 6, .factors = 8, .scale = 30.0});
    const auto text = json_of(model);
    EXPECT_TRUE(declares_markov_network(text));
    EXPECT_EQ(parse_markov_json(text, "m.json"), model) << "seed " << seed;
    // And through UAI, which numbers the same variables.
    EXPECT_EQ(parse_markov_json(json_of(parse_uai(to_uai(model), "m.uai").model), "m.json").factors(), model.factors());
  }
}

TEST(markov_json_test, a_model_reads_as_written_by_hand) {
  const auto model = parse_markov_json(model_with(R"({"scope": ["b", "a"], "values": [1, 2, 3, 4, 5, 0]},
                                                      {"scope": [], "values": [7]})"),
                                       "m.json");
  ASSERT_EQ(model.factor_count(), 2U);
  EXPECT_EQ(model.factor_scope(0), (std::vector{model.id("b"), model.id("a")}));
  EXPECT_EQ(model.factor(0).values(), (std::vector<double>{1, 2, 3, 4, 5, 0}));
  EXPECT_EQ(model.factor(1).values(), (std::vector<double>{7}));
  EXPECT_FALSE(declares_markov_network(R"({"format": "pgm-model", "variables": []})"));
  EXPECT_FALSE(declares_markov_network("not json"));
}

TEST(markov_json_test, errors_name_the_path_and_what_was_expected) {
  EXPECT_THAT(error_of(model_with(R"({"scope": ["a", "c"], "values": [1, 2]})")),
              HasSubstr("m.json: /factors/0/scope/1: 'c' is not a variable of the model"));
  EXPECT_THAT(error_of(model_with(R"({"scope": ["a", "b"], "values": [1, 2]})")), HasSubstr("m.json: /factors/0: "));
  EXPECT_THAT(error_of(model_with(R"({"scope": ["a", "b"], "values": [1, 2]})")), HasSubstr("6"));
  EXPECT_THAT(error_of(model_with(R"({"scope": ["a"], "values": [1, -2]})")), HasSubstr("/factors/0: "));
  EXPECT_THAT(error_of(model_with(R"({"scope": ["a"], "values": [1, -2]})")), HasSubstr("negative"));
  EXPECT_THAT(error_of(model_with(R"({"scope": ["a", "a"], "values": [1, 2, 3, 4]})")), HasSubstr("/factors/0: "));
  EXPECT_THAT(error_of(model_with(R"({"scope": ["a"], "values": [1, "2"]})")), HasSubstr("/factors/0/values"));
  EXPECT_THAT(error_of(model_with(R"({"scope": ["a"], "value": [1, 2]})")), HasSubstr("'value'"));
  EXPECT_THAT(error_of(model_with(R"({"scope": ["a"], "values": [1, NaN]})")), HasSubstr("m.json"));
  EXPECT_THAT(error_of(R"({"format": "pgm-model", "version": 1, "kind": "bayesian", "variables": [], "factors": []})"),
              HasSubstr("/kind: expected \"markov\""));
  // A Bayesian network's reader names what the file holds instead.
  try {
    static_cast<void>(parse_model_json(model_with(""), "m.json"));
    ADD_FAILURE() << "a Markov network read as a Bayesian network";
  } catch (const error& e) {
    EXPECT_THAT(e.what(), HasSubstr("/kind: this file holds a Markov network, not a Bayesian network"));
  }
  // A factor past pgm's table limit is refused before its values are read.
  std::string wide = R"({"format": "pgm-model", "version": 1, "kind": "markov", "variables": [)";
  std::string scope;
  for (int i = 0; i < 25; ++i) {
    wide += std::string(i ? ", " : "") + R"({"name": "v)" + std::to_string(i) + R"(", "states": ["0", "1"]})";
    scope += std::string(i ? ", " : "") + "\"v" + std::to_string(i) + "\"";
  }
  wide += R"(], "factors": [{"scope": [)" + scope + R"(], "values": []}]})";
  EXPECT_THAT(error_of(wide), HasSubstr("/factors/0: a factor of 33554432 cells is more than pgm's limit"));
}

}  // namespace markov_json_test
}  // namespace pgm
