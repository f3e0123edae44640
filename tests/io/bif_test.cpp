#include "pgm/io/bif.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pgm/io/network_file.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::bif_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr const char* asia_like = R"(// a comment
network "test net" {
  property author = someone ;
}
variable smoke {
  type discrete [ 2 ] { yes, no };
}
variable bronc { /* block
comment */
  type discrete [ 2 ] { yes, no };
  property position = (1, 2) ;
}
variable xray {
  type discrete [ 3 ] { a, b, c };
}
probability ( smoke ) {
  table 0.5, 0.5;
}
probability ( bronc | smoke ) {
  (yes) 0.6, 0.4;
  (no) 0.3, 0.7;
}
probability ( xray | bronc, smoke ) {
  (no, yes) 0.1 0.2 0.7;
  default 0.2, 0.3, 0.5;
}
)";

TEST(bif_test, reads_tables_defaults_and_properties) {
  const auto net = parse_bif(asia_like, "asia.bif");
  EXPECT_EQ(net.size(), 3u);
  EXPECT_EQ(net.at("xray").states(), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_DOUBLE_EQ(net.table("bronc").probability("yes", {"no"}), 0.3);
  EXPECT_DOUBLE_EQ(net.table("xray").probability("c", {"no", "yes"}), 0.7);
  EXPECT_DOUBLE_EQ(net.table("xray").probability("c", {"yes", "yes"}), 0.5);
  EXPECT_EQ(net.table("xray").parents()[0].name(), "bronc");
}

TEST(bif_test, round_trip_keeps_every_bit_and_pgm_properties) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 8, .max_parents = 3, .max_states = 5});
    EXPECT_EQ(parse_bif(to_bif(net), "x.bif"), net);
  }
  const auto x = variable::intervals("xOff1", {-3, -1.4, -0.4, 0.4, 1.4, 3}, {"x-offset", "cm", "cubeUp1"});
  const variable top("onTop1", {"0", "1"});
  const auto net = bayesian_network::from_tables(
      {cpt<double>(x, {}), cpt<double>(top, {x}, {0.1, 0.9, 0.2, 0.8, 0.3, 0.7, 0.4, 0.6, 0.5, 0.5})});
  const auto text = to_bif(net);
  EXPECT_THAT(text, HasSubstr("property edges = -3, -1.4, -0.4, 0.4, 1.4, 3 ;"));
  EXPECT_THAT(text, HasSubstr("property unit = cm ;"));
  EXPECT_THAT(text, HasSubstr("  (2) 0.3, 0.7;"));
  EXPECT_EQ(parse_bif(text, "x.bif"), net);
  bif_write_options plain;
  plain.properties = false;
  EXPECT_THAT(to_bif(net, plain), ::testing::Not(HasSubstr("property")));
}

TEST(bif_test, errors_are_located) {
  EXPECT_THAT(
      [] {
        static_cast<void>(
            parse_bif("variable a {\n  type discrete [ 2 ] { x, y };\n}\nprobability ( a | b ) {\n}\n", "m.bif"));
      },
      ThrowsMessage<parse_error>(HasSubstr("m.bif:4:19: parent 'b' is not declared")));
  EXPECT_THAT([] { static_cast<void>(parse_bif("variable a {\n  type discrete [ 3 ] { x, y };\n}\n", "m.bif")); },
              ThrowsMessage<parse_error>(HasSubstr("m.bif:2:19: variable 'a' declares 3 states but lists 2")));
  EXPECT_THAT(
      [] {
        static_cast<void>(parse_bif(
            "variable a {\n type discrete [ 2 ] { x, y };\n}\nprobability ( a ) {\n table 0.5, zero;\n}\n", "m.bif"));
      },
      ThrowsMessage<parse_error>(HasSubstr("m.bif:5:13: expected a probability, found 'zero'")));
  EXPECT_THAT([] { static_cast<void>(parse_bif("variable a {\n type discrete [ 2 ] { x, y };\n}\n", "m.bif")); },
              ThrowsMessage<parse_error>(HasSubstr("variable 'a' has no probability block")));
  EXPECT_THAT(
      [] {
        static_cast<void>(parse_bif(
            "variable a {\n type discrete [ 2 ] { x, y };\n}\nprobability ( a ) {\n table 0.5, 0.6;\n}\n", "m.bif"));
      },
      ThrowsMessage<parse_error>(HasSubstr("sums to 1.1")));
  EXPECT_THAT([] { static_cast<void>(parse_bif("", "m.bif")); },
              ThrowsMessage<parse_error>(HasSubstr("declares no variables")));
  EXPECT_THAT(
      [] {
        static_cast<void>(parse_bif("variable a { type discrete [ 2 ] { x, y }; }\nprobability ( a ) {\n", "m.bif"));
      },
      ThrowsMessage<parse_error>(HasSubstr("found the end of the file")));
}

TEST(bif_test, a_cycle_names_the_file_and_the_block_that_closes_it) {
  const std::string text =
      "variable a { type discrete [ 2 ] { x, y }; }\nvariable b { type discrete [ 2 ] { x, y }; }\n"
      "probability ( a | b ) { table 0.5, 0.5, 0.5, 0.5; }\nprobability ( b | a ) { table 0.5, 0.5, 0.5, 0.5; }\n";
  EXPECT_THAT([&] { static_cast<void>(parse_bif(text, "loop.bif")); },
              ThrowsMessage<parse_error>(HasSubstr("loop.bif:4:15: the probability block of 'b' closes a cycle: "
                                                   "adding this edge closes the cycle a -> b -> a")));
}

TEST(bif_test, missing_configurations_and_parent_tables) {
  const std::string head =
      "variable a { type discrete [ 2 ] { x, y }; }\nvariable b { type discrete [ 2 ] { x, y }; }\n"
      "probability ( a ) { table 0.5, 0.5; }\n";
  EXPECT_THAT([&] { static_cast<void>(parse_bif(head + "probability ( b | a ) {\n (x) 0.5, 0.5;\n}\n", "m.bif")); },
              ThrowsMessage<parse_error>(HasSubstr("misses a parent configuration and has no 'default' line")));
  EXPECT_THAT(
      [&] { static_cast<void>(parse_bif(head + "probability ( b | a ) {\n table 0.5, 0.5, 0.5, 0.5;\n}\n", "m.bif")); },
      ThrowsMessage<parse_error>(HasSubstr("which has parents, is ordered differently")));
  EXPECT_THAT([&] { static_cast<void>(parse_bif(head + "probability ( b | a ) {\n (z) 0.5, 0.5;\n}\n", "m.bif")); },
              ThrowsMessage<parse_error>(HasSubstr("m.bif:5:2: 'z' is not a state of 'a'")));
  EXPECT_THAT([&] { static_cast<void>(parse_bif(head + "probability ( b | a ) {\n (x) 0.5;\n}\n", "m.bif")); },
              ThrowsMessage<parse_error>(HasSubstr("expected 2 probabilities for 'b', found 1")));
}

TEST(bif_test, names_bif_cannot_hold_are_refused_on_writing) {
  auto one = [](std::string name, std::vector<std::string> states) {
    return bayesian_network::from_tables({cpt<double>(variable(std::move(name), std::move(states)), {})});
  };
  EXPECT_THAT(
      [&] {
        static_cast<void>(to_bif(one("a", {"light blue", "red"})));
      },
      ThrowsMessage<model_error>(HasSubstr("state 'light blue' of 'a' cannot be written to BIF: BIF states "
                                           "cannot hold spaces")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(to_bif(one("a", {"say\"hi\"", "red"})));
      },
      ThrowsMessage<model_error>(HasSubstr("BIF states cannot hold '\"'")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(to_bif(one("a", {"x,y", "red"})));
      },
      ThrowsMessage<model_error>(HasSubstr("BIF states cannot hold ','")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(to_bif(one("a", {"x//y", "red"})));
      },
      ThrowsMessage<model_error>(HasSubstr("start comments")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(to_bif(one("my\"var", {"x", "y"})));
      },
      ThrowsMessage<model_error>(HasSubstr("variable name 'my\"var' cannot be written to BIF: BIF names hold "
                                           "letters, digits, '_', '-' and '.' only (found '\"')")));
}

TEST(bif_test, names_with_dash_and_dot_and_states_with_punctuation_are_written_and_read_back) {
  const variable a("x-off.1", {"<=0.5", "a+b", "1e-3"});
  const variable b("on-top", {"no", "yes"});
  const auto net = bayesian_network::from_tables(
      {cpt<double>(a, {}, {0.2, 0.3, 0.5}), cpt<double>(b, {a}, {0.1, 0.9, 0.4, 0.6, 0.5, 0.5})});
  std::vector<std::string> notes;
  const auto text = to_bif(net, {.notes = &notes});
  EXPECT_EQ(parse_bif(text, "x.bif"), net);
  ASSERT_EQ(notes.size(), 1u);  // the name with '.', which pgmpy cannot read in probability lines
  EXPECT_THAT(notes[0], HasSubstr("names with '.' (x-off.1)"));
  EXPECT_THAT(notes[0], HasSubstr("pgmpy 0.1.26 cannot read them"));
  notes.clear();
  static_cast<void>(to_bif(bayesian_network::from_tables({cpt<double>(b, {}, {0.5, 0.5})}), {.notes = &notes}));
  EXPECT_TRUE(notes.empty());
}

TEST(bif_test, a_quoted_semicolon_in_a_property_is_part_of_its_value) {
  const std::string text =
      "network n {\n  property label = \"a; b\" ;\n}\nvariable a {\n  type discrete [ 2 ] { x, y };\n"
      "  property note = \"one; two\" ;\n  property unit = cm ;\n}\nprobability ( a ) {\n  table 0.5, 0.5;\n}\n";
  const auto net = parse_bif(text, "q.bif");
  EXPECT_EQ(net.at("a").tags().unit, "cm");
  EXPECT_THAT([] { static_cast<void>(parse_bif("network n {\n property label = \"a;\n}\n", "q.bif")); },
              ThrowsMessage<parse_error>(HasSubstr("q.bif:")));
}

TEST(bif_test, probability_blocks_may_come_before_their_variables) {
  const std::string text =
      "network n {\n}\nprobability ( b | a ) {\n  (x) 0.6, 0.4;\n  (y) 0.3, 0.7;\n}\nprobability ( a ) {\n  table "
      "0.2, 0.8;\n}\nvariable b {\n  type discrete [ 2 ] { u, v };\n}\nvariable a {\n  type discrete [ 2 ] { x, y "
      "};\n}\n";
  const auto net = parse_bif(text, "late.bif");
  EXPECT_EQ(net.variables()[0].name(), "b");  // variables in declaration order
  EXPECT_DOUBLE_EQ(net.table("b").probability("v", {"y"}), 0.7);
  EXPECT_THAT(
      [] {
        static_cast<void>(
            parse_bif("probability ( c ) {\n  table 1;\n}\nvariable a {\n  type discrete [ 1 ] { x };\n}\n"
                      "probability ( a ) {\n  table 1;\n}\n",
                      "late.bif"));
      },
      ThrowsMessage<parse_error>(HasSubstr("late.bif:1:15: probability block for 'c', which is not declared")));
}

TEST(bif_test, rounded_tables_are_normalized_within_the_tolerance_and_said_so) {
  const std::string head = "variable a {\n  type discrete [ 3 ] { x, y, z };\n}\nprobability ( a ) {\n  table ";
  std::vector<std::string> notes;
  const auto net = parse_bif(head + "0.3333, 0.3333, 0.3333;\n}\n", "r.bif", {.notes = &notes});
  EXPECT_NEAR(net.table("a").probability("x", {}), 1.0 / 3, 1e-15);
  double sum = 0;
  for (const double v : net.table("a").values()) sum += v;
  EXPECT_NEAR(sum, 1.0, 1e-15);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("'r.bif': normalized 1 column of 1 table that summed to 1 only within 0.001"));
  // Within 1e-6 a column is kept as written, so round trips stay exact, and nothing is said.
  notes.clear();
  const auto exact = parse_bif(head + "0.3, 0.3, 0.4000001;\n}\n", "r.bif", {.notes = &notes});
  EXPECT_EQ(exact.table("a").probability("z", {}), 0.4000001);
  EXPECT_TRUE(notes.empty());
  // Beyond the tolerance the file is refused, at the line of the numbers.
  EXPECT_THAT(
      [&] { static_cast<void>(parse_bif(head + "0.3, 0.3, 0.402;\n}\n", "r.bif")); },
      ThrowsMessage<parse_error>(HasSubstr("r.bif:5:3: a distribution of 'a' sums to 1.002, not 1 within 0.001")));
  EXPECT_NO_THROW(static_cast<void>(parse_bif(head + "0.3, 0.3, 0.402;\n}\n", "r.bif", {.tolerance = 0.01})));
}

TEST(bif_test, writing_is_atomic) {
  const auto dir = std::filesystem::temp_directory_path() / "pgm_bif_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto path = dir / "net.bif";
  std::ofstream(path) << "old content";
  const auto bad = bayesian_network::from_tables({cpt<double>(variable("a", {"light blue", "red"}), {})});
  EXPECT_THROW(write_network(bad, path), model_error);
  std::ifstream in(path);
  std::string content((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(content, "old content");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);  // no temporary left
  const auto good = bayesian_network::from_tables({cpt<double>(variable("a", {"blue", "red"}), {})});
  EXPECT_THAT([&] { write_network(good, dir / "missing" / "net.bif"); },
              ThrowsMessage<io_error>(HasSubstr("does not exist")));
  EXPECT_THAT([&] { write_network(good, dir / "net.txt"); },
              ThrowsMessage<io_error>(
                  HasSubstr("not a network file; expected one of .bif, .xml, .xmlbif, .bifxml, .net, .json")));
  EXPECT_THAT([&] { static_cast<void>(read_network(dir / "nothing.bif")); },
              ThrowsMessage<io_error>(HasSubstr("cannot open")));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pgm::bif_tests
