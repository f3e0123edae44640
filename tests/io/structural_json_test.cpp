// Structural models in pgm's JSON model: the documented example read as it says, models written
// and read back equal, and every malformed equation refused by its JSON path.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pgm/causal/counterfactual.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/structural_file.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::structural_json_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// The example of pgm/io/structural_file.hpp.
constexpr const char* example = R"({
  "format": "pgm-model", "version": 1, "kind": "structural",
  "variables": [{"name": "X", "states": ["0", "1"]}, {"name": "Y", "states": ["0", "1"]}],
  "equations": [
    {"variable": "Y", "parents": ["X"], "noise": [0.2, 0.5, 0.3], "values": [["0", "0", "1"], ["0", "1", "1"]]},
    {"variable": "X", "parents": [], "noise": [0.4, 0.6], "values": [["0", "1"]]}
  ]
})";

TEST(structural_json_test, the_documented_example_reads_as_it_says) {
  const auto m = parse_structural_json(example, "example.json");
  const auto y = m.id("Y");
  EXPECT_EQ(m.value(y, 0, 1), 0u);
  EXPECT_EQ(m.value(y, 1, 1), 1u);
  EXPECT_EQ(m.value(y, 0, 2), 1u);
  const auto network = m.network();
  EXPECT_NEAR(network.table("Y").probability("1", {"1"}), 0.8, 1e-15);
  EXPECT_NEAR(network.table("Y").probability("1", {"0"}), 0.3, 1e-15);
}

TEST(structural_json_test, a_model_written_reads_back_equal) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const auto m = monotone_structural_model(testing::random_network(seed, {.nodes = 5}));
    EXPECT_EQ(parse_structural_json(to_json(m).dump(), "back.json"), m) << seed;
  }
}

std::string with(std::string_view from, std::string_view to) {
  std::string text = example;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(structural_json_test, a_malformed_equation_is_refused_by_its_path) {
  const auto refuses = [](const std::string& text, const std::string& what) {
    EXPECT_THAT([&] { (void)parse_structural_json(text, "m.json"); }, ThrowsMessage<data_error>(HasSubstr(what)));
  };
  refuses(with(R"("values": [["0", "1"]])", R"("values": [["0", "2"]])"),
          "m.json: /equations/1/values/0/1: '2' is not a state of 'X'");
  refuses(with(R"(["0", "0", "1"], )", ""), "/equations/0/values: expected 2 rows");
  refuses(with(R"(["0", "0", "1"])", R"(["0", "1"])"), "/equations/0/values/0: expected 3 states");
  refuses(with(R"("parents": ["X"])", R"("parents": ["Z"])"), "/equations/0/parents/0: 'Z' is not among");
  refuses(with(R"("noise": [0.4, 0.6])", R"("noise": [0.4, 0.7])"), "/equations: the noise of 'X' sums to 1.1");
  refuses(with(R"("parents": [], "noise": [0.4, 0.6], "values": [["0", "1"]])",
               R"("parents": ["Y"], "noise": [1], "values": [["0"], ["1"]])"),
          "closes the cycle");
  refuses(with(R"({"variable": "X", "parents": [], "noise": [0.4, 0.6], "values": [["0", "1"]]})",
               R"({"variable": "Y", "parents": [], "noise": [1], "values": [["0"]]})"),
          "/equations/1/variable: 'Y' has a second equation");
  refuses(with(R"(,
    {"variable": "X", "parents": [], "noise": [0.4, 0.6], "values": [["0", "1"]]})",
               ""),
          "/equations: 'X' has no equation");
  refuses(with(R"("kind": "structural")", R"("kind": "markov")"), "/kind: expected \"structural\"");
  refuses(with(R"("noise": [0.2, 0.5, 0.3])", R"("nois": [0.2, 0.5, 0.3])"), "nois");
}

TEST(structural_json_test, the_network_reader_names_what_the_file_holds) {
  EXPECT_THAT([] { (void)parse_model_json(example, "m.json"); },
              ThrowsMessage<data_error>(HasSubstr("holds a structural model")));
}

}  // namespace
}  // namespace pgm::structural_json_tests
