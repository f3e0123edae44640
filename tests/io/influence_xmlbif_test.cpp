// Influence diagrams in XMLBIF (aGrUM's BIFXML) and pgm's JSON model: the published oil
// wildcatter read and solved, written and read back, and every malformed diagram refused with
// its place.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "pgm/decide/solve_decisions.hpp"
#include "pgm/io/influence_file.hpp"
#include "pgm/io/xmlbif.hpp"

namespace pgm::influence_xmlbif_tests {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

const std::string oil_file = std::string(PGM_SOURCE_DIR) + "/tests/data/decisions/oil_wildcatter.xml";

TEST(influence_xmlbif_test, reads_the_oil_wildcatter_and_solves_it_to_its_published_meu) {
  const auto diagram = read_xmlbif_influence_diagram(oil_file);
  EXPECT_EQ(diagram.size(), 4u);
  EXPECT_EQ(diagram.utilities().size(), 2u);
  EXPECT_TRUE(diagram.is_decision(diagram.id("Drill")));
  EXPECT_NEAR(solve_decisions(diagram).meu, 22.5, 1e-12);
}

TEST(influence_xmlbif_test, what_it_writes_reads_back_the_same) {
  const auto diagram = read_xmlbif_influence_diagram(oil_file);
  const auto text = to_xmlbif(diagram);
  EXPECT_THAT(text, AllOf(HasSubstr("TYPE=\"decision\""), HasSubstr("TYPE=\"utility\"")));
  EXPECT_EQ(parse_xmlbif_influence_diagram(text, "written.xml"), diagram);
}

TEST(influence_xmlbif_test, a_bayesian_network_reader_points_to_decide) {
  EXPECT_THAT([] { (void)read_xmlbif(oil_file); },
              ThrowsMessage<parse_error>(AllOf(HasSubstr("oil_wildcatter.xml:"), HasSubstr("pgm decide"))));
}

/// A diagram of a chance variable A, a decision D observing A, and a utility U over (D, A),
/// with `extra` inserted before </NETWORK> and `d_definition` as D's definition.
std::string diagram_text(const std::string& d_definition, const std::string& extra = "",
                         const std::string& u_given = "<GIVEN>D</GIVEN><GIVEN>A</GIVEN>") {
  return R"(<BIF VERSION="0.3"><NETWORK><NAME>n</NAME>
<VARIABLE TYPE="nature"><NAME>A</NAME><OUTCOME>a0</OUTCOME><OUTCOME>a1</OUTCOME></VARIABLE>
<VARIABLE TYPE="decision"><NAME>D</NAME><OUTCOME>d0</OUTCOME><OUTCOME>d1</OUTCOME></VARIABLE>
<VARIABLE TYPE="utility"><NAME>U</NAME></VARIABLE>
<DEFINITION><FOR>A</FOR><TABLE>0.25 0.75</TABLE></DEFINITION>
)" + d_definition +
         "\n<DEFINITION><FOR>U</FOR>" + u_given + "<TABLE>1 2 3 -4</TABLE></DEFINITION>\n" + extra + "</NETWORK></BIF>";
}

TEST(influence_xmlbif_test, a_small_diagram_solves_by_hand) {
  // D sees A: a0 -> d1 (3), a1 -> d0 (2); 0.25·3 + 0.75·2 = 2.25.
  const auto diagram = parse_xmlbif_influence_diagram(
      diagram_text("<DEFINITION><FOR>D</FOR><GIVEN>A</GIVEN></DEFINITION>"), "small.xml");
  EXPECT_DOUBLE_EQ(solve_decisions(diagram).meu, 2.25);
  // Blind: d0 is worth 0.25·1 + 0.75·2 = 1.75, d1 0.25·3 - 0.75·4 = -2.25.
  const auto blind = parse_xmlbif_influence_diagram(diagram_text("<DEFINITION><FOR>D</FOR></DEFINITION>"), "blind.xml");
  EXPECT_DOUBLE_EQ(solve_decisions(blind).meu, 1.75);
  EXPECT_DOUBLE_EQ(value_of_information(blind, "A", "D"), 0.5);
}

TEST(influence_xmlbif_test, a_malformed_diagram_is_refused_with_its_place) {
  const auto refused = [](const std::string& text, const std::string& message) {
    EXPECT_THAT([&] { (void)parse_xmlbif_influence_diagram(text, "bad.xml"); },
                ThrowsMessage<parse_error>(AllOf(HasSubstr("bad.xml:"), HasSubstr(message))))
        << text;
  };
  refused(diagram_text("<DEFINITION><FOR>D</FOR><TABLE>0.5 0.5</TABLE></DEFINITION>"),
          "the decision 'D' has a <TABLE>");
  refused(diagram_text("<DEFINITION><FOR>D</FOR><GIVEN>U</GIVEN></DEFINITION>"),
          "the utility 'U' is given as a parent of 'D'");
  refused(diagram_text("<DEFINITION><FOR>D</FOR><GIVEN>A</GIVEN></DEFINITION>", "",
                       "<GIVEN>D</GIVEN><GIVEN>A</GIVEN><GIVEN>U</GIVEN>"),
          "the utility 'U' is given as a parent of 'U'");
  refused(diagram_text("<DEFINITION><FOR>D</FOR><GIVEN>B</GIVEN></DEFINITION>"), "unknown variable 'B'");
  const std::string b =
      R"(<VARIABLE TYPE="nature"><NAME>B</NAME><OUTCOME>b0</OUTCOME><OUTCOME>b1</OUTCOME></VARIABLE>)";
  refused(diagram_text("<DEFINITION><FOR>D</FOR><GIVEN>B</GIVEN></DEFINITION>",
                       b + "<DEFINITION><FOR>B</FOR><GIVEN>D</GIVEN><TABLE>0.5 0.5 0.5 0.5</TABLE></DEFINITION>"),
          "closes the cycle");
  refused(diagram_text("", b), "the chance variable 'B' has no <DEFINITION>");
  refused(diagram_text("", R"(<VARIABLE TYPE="deterministic"><NAME>C</NAME></VARIABLE>)"),
          R"(expected "nature", "decision" or "utility")");
  refused(diagram_text("", "", "<GIVEN>D</GIVEN>"), "the utility 'U' has 4 values; its 1 parents need 2");
  // A raw control character, which XML (and pgmpy's expat) refuses, and which a diagram could
  // not be written back with (the fuzzer's finding).
  std::string control = diagram_text("");
  control.replace(control.find("a0"), 2, "a\x02");
  refused(control, "a control character (byte 2) that XML does not allow");
  std::string latin = diagram_text("");
  latin.replace(latin.find("a0"), 2, "a\x93");
  refused(latin, "bytes that are not UTF-8");
  influence_diagram written;
  const auto a = written.add_chance(variable("A", {"a\x02", "a1"}));
  written.set_table(a, {}, {0.5, 0.5});
  written.set_observed(written.add_decision(variable("D", {"d0", "d1"})), {a});
  written.add_utility("U", {a}, {1, 2});
  EXPECT_THAT([&] { (void)to_xmlbif(written); },
              ThrowsMessage<model_error>(HasSubstr("holds a control character, which XML cannot hold")));
  // A decision without a definition observes nothing.
  EXPECT_DOUBLE_EQ(solve_decisions(parse_xmlbif_influence_diagram(diagram_text(""), "blind.xml")).meu, 1.75);
}

TEST(influence_json_test, what_it_writes_reads_back_the_same) {
  const auto diagram = read_xmlbif_influence_diagram(oil_file);
  const auto json = to_json(diagram);
  EXPECT_EQ(json["kind"], "influence");
  EXPECT_EQ(json["decisions"][1]["observes"], (nlohmann::json{"Test", "Seismic"}));
  EXPECT_EQ(parse_influence_json(json.dump(), "oil.json"), diagram);
}

TEST(influence_json_test, a_malformed_diagram_is_refused_with_its_json_path) {
  auto json = to_json(read_xmlbif_influence_diagram(oil_file));
  const auto refused = [](const nlohmann::json& document, const std::string& message) {
    EXPECT_THAT([&] { (void)parse_influence_json(document.dump(), "bad.json"); },
                ThrowsMessage<data_error>(AllOf(HasSubstr("bad.json: "), HasSubstr(message))))
        << document.dump();
  };
  auto other = json;
  other["kind"] = "markov";
  refused(other, "/kind: expected \"influence\"");
  other = json;
  other["decisions"].push_back(other["decisions"][0]);
  refused(other, "/decisions/2: 'Test' is listed twice");
  other = json;
  other["utilities"][1]["parents"][0] = "Payoff";
  refused(other, "/utilities/1/parents/0: 'Payoff' is not a chance or decision variable");
  other = json;
  other["tables"][0]["values"][0][0] = 0.9;
  refused(other, "/tables/0: column 0 of the table of 'Oil' sums to 1.4");
  other = json;
  other["decisions"][1]["observes"].push_back("Oil");
  EXPECT_NEAR(solve_decisions(parse_influence_json(other.dump(), "clairvoyant.json")).meu, 55, 1e-12);
}

}  // namespace
}  // namespace pgm::influence_xmlbif_tests
