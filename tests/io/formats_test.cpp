// XMLBIF and Hugin NET (pgm/io/xmlbif.hpp, net.hpp) and reading any format by extension
// (pgm/io/network_file.hpp), through the format registry (pgm/io/network_format.hpp). The hand-written files follow the
// styles of the tools that write them: pgmpy and aGrUM for XMLBIF, Hugin and bnlearn's write.net for NET.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pgm/core/file.hpp"
#include "pgm/io/net.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/xmlbif.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::formats_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

bayesian_network tagged_network() {
  const auto x = variable::intervals("xOff1", {-3, -1.4, -0.4, 0.4, 1.4, 3}, {"x-offset", "cm", "cubeUp1"});
  const variable top("onTop1", {"0", "1"});
  return bayesian_network::from_tables(
      {cpt<double>(x, {}), cpt<double>(top, {x}, {0.1, 0.9, 0.2, 0.8, 0.3, 0.7, 0.4, 0.6, 0.5, 0.5})});
}

// pgmpy's XMLBIFWriter output for a two-node network (properties empty, states mangled to
// letters, digits and '_'), with aGrUM's DOCTYPE-less header.
constexpr const char* pgmpy_xmlbif = R"(<?xml version='1.0' encoding='utf-8'?>
<BIF VERSION="0.3">
  <NETWORK>
    <NAME>unknown</NAME>
    <VARIABLE TYPE="nature">
      <NAME>light-on</NAME>
      <OUTCOME>true</OUTCOME>
      <OUTCOME>false</OUTCOME>
      <PROPERTY />
    </VARIABLE>
    <VARIABLE TYPE="nature">
      <NAME>family-out</NAME>
      <OUTCOME>true</OUTCOME>
      <OUTCOME>false</OUTCOME>
      <PROPERTY>position = (112, 69)</PROPERTY>
    </VARIABLE>
    <DEFINITION>
      <FOR>family-out</FOR>
      <TABLE>0.15 0.85 </TABLE>
    </DEFINITION>
    <DEFINITION>
      <FOR>light-on</FOR>
      <GIVEN>family-out</GIVEN>
      <TABLE>0.6 0.4 0.05 0.95 </TABLE>
    </DEFINITION>
  </NETWORK>
</BIF>
)";

TEST(xmlbif_test, reads_what_pgmpy_writes) {
  const auto net = parse_xmlbif(pgmpy_xmlbif, "dog.xml");
  EXPECT_EQ(net.size(), 2u);
  EXPECT_DOUBLE_EQ(net.table("light-on").probability("false", {"true"}), 0.4);
  EXPECT_DOUBLE_EQ(net.table("light-on").probability("true", {"false"}), 0.05);
  EXPECT_DOUBLE_EQ(net.table("family-out").probability("true", {}), 0.15);
}

TEST(xmlbif_test, round_trips_keep_every_bit_and_pgm_properties) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 8, .max_parents = 3, .max_states = 5});
    EXPECT_EQ(parse_xmlbif(to_xmlbif(net), "x.xml"), net);
  }
  const auto net = tagged_network();
  const auto text = to_xmlbif(net);
  EXPECT_THAT(text, HasSubstr("<PROPERTY>edges = -3, -1.4, -0.4, 0.4, 1.4, 3</PROPERTY>"));
  EXPECT_THAT(text, HasSubstr("<PROPERTY>unit = cm</PROPERTY>"));
  EXPECT_THAT(text, HasSubstr("<GIVEN>xOff1</GIVEN>"));
  EXPECT_EQ(parse_xmlbif(text, "x.xml"), net);
  EXPECT_THAT(to_xmlbif(net, {.properties = false}), ::testing::Not(HasSubstr("PROPERTY")));
}

TEST(xmlbif_test, any_name_survives_as_xml_text) {
  const variable a("x<1>&\"q\"", {"light blue", "it's", "a,b;c", "tab\there"});
  const variable b("on.top-1", {"no", "yes"});
  const auto net = bayesian_network::from_tables(
      {cpt<double>(a, {}, {0.2, 0.3, 0.4, 0.1}), cpt<double>(b, {a}, {0.1, 0.9, 0.4, 0.6, 0.5, 0.5, 1, 0})});
  EXPECT_EQ(parse_xmlbif(to_xmlbif(net), "x.xml"), net);
}

TEST(xmlbif_test, errors_are_located) {
  auto fails = [](const std::string& text, const std::string& message) {
    EXPECT_THAT([&] { static_cast<void>(parse_xmlbif(text, "m.xml")); },
                ThrowsMessage<parse_error>(HasSubstr(message)));
  };
  fails("<BIF>\n<NETWORK>\n<VARIABLE>\n</NETWORK>\n</BIF>\n", "m.xml:4:");
  fails("<BIF>\n<NETWORK>\n<VARIABLE>\n</NETWORK>\n</BIF>\n", "invalid XML: Start-end tags mismatch");
  fails("<XBIF/>", "m.xml:1:1: expected the XMLBIF root element <BIF>, found <XBIF>");
  fails("<BIF>\n  <NETWORK>\n  </NETWORK>\n</BIF>", "m.xml:2:3: the file declares no variables");
  const std::string variable_a =
      "<BIF><NETWORK>\n<VARIABLE TYPE=\"nature\"><NAME>a</NAME><OUTCOME>x</OUTCOME><OUTCOME>y</OUTCOME>"
      "</VARIABLE>\n";
  fails(variable_a + "<DEFINITION><FOR>a</FOR><TABLE>0.5 zero</TABLE></DEFINITION>\n</NETWORK></BIF>",
        "m.xml:3:36: expected a probability in the table of 'a', found 'zero'");
  fails(variable_a + "<DEFINITION><FOR>a</FOR><TABLE>0.5 0.2 0.3</TABLE></DEFINITION>\n</NETWORK></BIF>",
        "m.xml:3:25: expected 2 probabilities for 'a' (2 states × 1 parent configurations), found 3");
  fails(variable_a + "<DEFINITION><FOR>a</FOR><GIVEN>b</GIVEN><TABLE>1 0</TABLE></DEFINITION>\n</NETWORK></BIF>",
        "m.xml:3:25: parent 'b' of 'a' is not declared");
  fails(variable_a + "<DEFINITION><FOR>a</FOR><TABLE>0.5 0.6</TABLE></DEFINITION>\n</NETWORK></BIF>",
        "a distribution of 'a' sums to 1.1, not 1 within 0.001");
  fails(variable_a + "</NETWORK></BIF>", "m.xml:2:1: variable 'a' has no table");
  fails("<BIF><NETWORK>\n<VARIABLE TYPE=\"decision\"><NAME>d</NAME><OUTCOME>x</OUTCOME></VARIABLE>\n</NETWORK></BIF>",
        "m.xml:2:1: variable 'd' has TYPE=\"decision\"");
  fails(variable_a + "<DEFINITION><FOR>b</FOR><TABLE>1</TABLE></DEFINITION>\n</NETWORK></BIF>",
        "a table for 'b', which is not declared");
}

// An XMLBIF file with a DTD, as JavaBayes and Weka write them, whose entities stand for a
// state. ElementTree, which pgmpy reads XMLBIF with, expands internal entities (`&two;` is "2")
// and refuses undeclared, external and recursive ones; pgm reads the same network or refuses.
std::string xmlbif_with_dtd(const std::string& declarations, const std::string& state) {
  return "<?xml version=\"1.0\"?>\n<!DOCTYPE BIF [\n  <!ELEMENT BIF ( NETWORK )*>\n  <!ATTLIST BIF VERSION CDATA "
         "#REQUIRED>\n  <!-- <!ENTITY two \"commented out\"> -->\n" +
         declarations +
         "]>\n<BIF VERSION=\"0.3\"><NETWORK>\n<VARIABLE TYPE=\"nature\"><NAME>a</NAME><OUTCOME>1</OUTCOME>"
         "<OUTCOME>" +
         state +
         "</OUTCOME></VARIABLE>\n<DEFINITION><FOR>a</FOR><TABLE>0.25 0.75</TABLE></DEFINITION>\n"
         "</NETWORK></BIF>\n";
}

TEST(xmlbif_test, internal_entities_expand_as_pgmpys_parser_expands_them) {
  const auto state_of = [](const std::string& declarations, const std::string& state) {
    return parse_xmlbif(xmlbif_with_dtd(declarations, state), "m.xml").at("a").states()[1];
  };
  EXPECT_EQ(state_of("  <!ENTITY two \"2\">\n", "&two;"), "2");
  EXPECT_EQ(state_of("  <!ENTITY two '2'>\n  <!ENTITY two \"second\">\n", "&two;"), "2");  // the first binds
  EXPECT_EQ(state_of("  <!ENTITY t \"&#x74;&w;\">\n  <!ENTITY w \"wo\">\n", "&t;"), "two");
  EXPECT_EQ(state_of("  <!ENTITY a \"&#38;#65;\">\n", "x&a;&lt;&#x3e;&amp;"), "xA<>&");
  EXPECT_EQ(state_of("", "a<![CDATA[&b]]>c"), "a&bc");  // CDATA stays as written
  EXPECT_EQ(state_of("", "caf&#xE9;"), "caf\xC3\xA9");
  // The same file without entities reads as before.
  EXPECT_EQ(state_of("  <!ENTITY unused \"x\">\n", "2"), "2");
}

TEST(xmlbif_test, entities_pgmpy_refuses_are_refused_and_a_billion_laughs_is_bounded) {
  const auto fails = [](const std::string& declarations, const std::string& state, const std::string& message) {
    EXPECT_THAT([&] { static_cast<void>(parse_xmlbif(xmlbif_with_dtd(declarations, state), "m.xml")); },
                ThrowsMessage<parse_error>(HasSubstr(message)))
        << declarations << state;
  };
  fails("", "&two;", "m.xml:8:68: an undefined entity '&two;'");
  fails("  <!ENTITY x SYSTEM \"file:///etc/passwd\">\n", "&x;",
        "'&x;' is an external entity: pgm reads no other file an XMLBIF file names");
  fails("  <!ENTITY a \"&b;\">\n  <!ENTITY b \"&a;\">\n", "&a;", "the entity 'a' refers to itself");
  fails("  <!ENTITY a \"<i>z</i>\">\n", "&a;", "the entity 'a' holds markup ('<')");
  fails("  <!ENTITY a \"&#60;i&#62;\">\n", "&a;", "the entity 'a' holds markup ('<')");
  fails("  <!ENTITY % p \"<!ENTITY q 'Q'>\">\n  %p;\n", "&q;", "m.xml:6:12: a parameter entity (<!ENTITY % …>)");
  fails("", "a & b", "an '&' that starts no entity or character reference (write &amp; for '&')");
  fails("", "&#0;", "a reference to a character XML does not allow");
  fails("", "&#xD800;", "a reference to a character XML does not allow");
  // pugixml passes a '<' in an attribute's value through; ElementTree refuses the file.
  EXPECT_THAT(
      [] {
        static_cast<void>(parse_xmlbif(R"(<BIF><NETWORK>
<VARIABLE TYPE="a<&amp;"><NAME>a</NAME><OUTCOME>x</OUTCOME></VARIABLE></NETWORK></BIF>)",
                                       "m.xml"));
      },
      ThrowsMessage<parse_error>(HasSubstr("m.xml:2:1: a '<' in an attribute's value (write &lt; for '<')")));
  // `levels` entities, each ten references to the one below, over `text`.
  const auto nested = [](const std::string& text, int levels) {
    std::string declarations = "  <!ENTITY l0 \"" + text + "\">\n";
    for (int level = 1; level <= levels; ++level) {
      std::string references;
      for (int i = 0; i < 10; ++i) references += "&l" + std::to_string(level - 1) + ";";
      declarations += "  <!ENTITY l" + std::to_string(level) + " \"" + references + "\">\n";
    }
    return declarations;
  };
  // Ten levels: 10^10 laughs asked for, refused after 1 MiB.
  fails(nested("laugh", 10), "&l10;",
        "the file's entities expand to more than 1 MiB or nest deeper than 64 levels, pgm's limit");
  // Entities of nothing amplify work, not text: bounded the same way.
  fails(nested("", 12), "&l12;", "pgm's limit of XML entities");
}

// A file in the style of bnlearn's write.net: attributes first, data nested per parent, a
// comment, and a state with a quote escaped as Hugin does.
constexpr const char* bnlearn_net = R"(net {
  name = unknown;
}

node Pollution {
  states = ( "low" "high" );
  label = "Pollution";
  position = (100 200);
}

node Cancer {
  states = ( "True" "Fal\"se" );
}

node Smoker {
  states = ( "True" "False" );
}

potential ( Pollution ) {
  data = ( 0.9 0.1 );
}

potential ( Smoker ) {
  data = ( 0.3 0.7 );
}

% P(Cancer | Pollution, Smoker): Pollution outermost, Cancer innermost
potential ( Cancer | Pollution Smoker ) {
  data = ((( 0.03 0.97 )( 0.001 0.999 ))
          (( 0.05 0.95 )( 0.02 0.98 )));
}
)";

TEST(net_test, reads_hugin_and_bnlearn_style_files) {
  const auto net = parse_net(bnlearn_net, "cancer.net");
  EXPECT_EQ(net.size(), 3u);
  EXPECT_EQ(net.at("Cancer").states()[1], "Fal\"se");
  const auto& cancer = net.table("Cancer");
  ASSERT_EQ(cancer.parents().size(), 2u);
  EXPECT_EQ(cancer.parents()[0].name(), "Pollution");
  EXPECT_DOUBLE_EQ(cancer.probability("True", {"low", "False"}), 0.001);
  EXPECT_DOUBLE_EQ(cancer.probability("True", {"high", "True"}), 0.05);
  // Hugin's own layout: `discrete node`, attributes after the states, no nesting in the data.
  const auto hugin = parse_net(
      "net\n{\n  node_size = (80 40);\n}\ndiscrete node A\n{\n  label = \"\";\n  states = (\"a\" \"b\");\n}\n"
      "potential (A)\n{\n  data = (0.25 0.75);\n  experience = 1;\n}\n",
      "hugin.net");
  EXPECT_DOUBLE_EQ(hugin.table("A").probability("b", {}), 0.75);
}

TEST(net_test, round_trips_keep_every_bit_and_pgm_attributes) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 8, .max_parents = 3, .max_states = 5});
    EXPECT_EQ(parse_net(to_net(net), "x.net"), net);
  }
  const auto net = tagged_network();
  const auto text = to_net(net);
  EXPECT_THAT(text, HasSubstr("pgm_edges = \"-3 -1.4 -0.4 0.4 1.4 3\";"));
  EXPECT_THAT(text, HasSubstr("pgm_unit = \"cm\";"));
  EXPECT_THAT(text, HasSubstr("potential ( onTop1 | xOff1 )"));
  EXPECT_EQ(parse_net(text, "x.net"), net);
  EXPECT_THAT(to_net(net, {.properties = false}), ::testing::Not(HasSubstr("pgm_")));
  const variable a("a", {"say \"hi\"", "back\\slash", "light blue"});
  const auto quoted = bayesian_network::from_tables({cpt<double>(a, {}, {0.2, 0.3, 0.5})});
  EXPECT_EQ(parse_net(to_net(quoted), "q.net"), quoted);
}

TEST(net_test, data_is_nested_one_level_per_parent) {
  const variable a("a", {"x", "y"});
  const variable b("b", {"u", "v", "w"});
  const variable c("c", {"0", "1"});
  const auto net = bayesian_network::from_tables(
      {cpt<double>(a, {}), cpt<double>(b, {}),
       cpt<double>(c, {a, b}, {0.1, 0.9, 0.2, 0.8, 0.3, 0.7, 0.4, 0.6, 0.5, 0.5, 0.6, 0.4})});
  EXPECT_THAT(to_net(net), HasSubstr("  data = (((0.1 0.9)\n           (0.2 0.8)\n           (0.3 0.7))\n"
                                     "          ((0.4 0.6)\n           (0.5 0.5)\n           (0.6 0.4)));\n"));
}

TEST(net_test, names_net_cannot_hold_are_refused_on_writing) {
  const auto dotted = bayesian_network::from_tables({cpt<double>(variable("x.off-1", {"a", "b"}), {})});
  EXPECT_THAT([&] { static_cast<void>(to_net(dotted)); },
              ThrowsMessage<model_error>(HasSubstr("variable 'x.off-1' cannot be written to NET: NET names hold "
                                                   "letters, digits and '_' only (found '.')")));
  const auto digit = bayesian_network::from_tables({cpt<double>(variable("1x", {"a", "b"}), {})});
  EXPECT_THAT([&] { static_cast<void>(to_net(digit)); },
              ThrowsMessage<model_error>(HasSubstr("NET names start with a letter or '_'")));
  const auto broken = bayesian_network::from_tables({cpt<double>(variable("a", {"two\nlines", "b"}), {})});
  EXPECT_THAT([&] { static_cast<void>(to_net(broken)); }, ThrowsMessage<model_error>(HasSubstr("line break")));
}

TEST(net_test, errors_are_located) {
  auto fails = [](const std::string& text, const std::string& message) {
    EXPECT_THAT([&] { static_cast<void>(parse_net(text, "m.net")); }, ThrowsMessage<parse_error>(HasSubstr(message)));
  };
  const std::string a = "node a {\n  states = (\"x\" \"y\");\n}\n";
  fails(a + "potential ( a ) {\n  data = (0.5 zero);\n}\n", "m.net:5:15: expected a probability in the data of 'a'");
  fails(a + "potential ( a ) {\n  data = (0.5 0.2 0.3);\n}\n",
        "m.net:5:10: expected 2 probabilities for 'a' (2 states × 1 parent configurations), found 3");
  fails(a + "potential ( a | b ) {\n  data = (0.5 0.5);\n}\n", "m.net:4:17: parent 'b' of 'a' is not declared");
  fails(a + "potential ( a ) {\n  data = (0.5 0.6);\n}\n", "a distribution of 'a' sums to 1.1, not 1 within 0.001");
  fails(a, "m.net:1:6: variable 'a' has no table");
  fails("node a {\n  states = (x y);\n}\n", "m.net:2:13: the states of 'a' must be quoted strings, found 'x'");
  fails("node a {\n  label = \"a;\n}\n", "m.net:2:11: a string is never closed");
  fails("node a {\n  states = (\"x\" \"y\";\n}\n", "m.net:2:20: expected a value, found ';'");
  fails("continuous node c {\n}\n", "m.net:1:1: 'continuous' nodes are not supported");
  fails("class C {\n}\n", "m.net:1:1: object-oriented NET files ('class') are not supported");
  fails(a + "potential ( a b ) {\n}\n", "m.net:4:15: a potential over several nodes");
  fails("", "the file declares no nodes");
  fails(a + a, "m.net:4:6: node 'a' is declared twice");
  fails("node a {\n  label = \"a\";\n}\n", "m.net:1:1: node 'a' has no 'states'");
}

TEST(network_file_test, the_extension_chooses_the_format) {
  EXPECT_EQ(format_of("a.bif"), network_format("bif"));
  EXPECT_EQ(format_of("a.xml"), network_format("xmlbif"));
  EXPECT_EQ(format_of("a.XMLBIF"), network_format("xmlbif"));
  EXPECT_EQ(format_of("a.bifxml"), network_format("xmlbif"));
  EXPECT_EQ(format_of("a.net"), network_format("net"));
  EXPECT_EQ(format_of("a.json"), network_format("json"));
  EXPECT_THAT([] { static_cast<void>(format_of("a.dne")); },
              ThrowsMessage<io_error>(HasSubstr("'a.dne': not a network file; expected one of .bif, .xml, .xmlbif, "
                                                ".bifxml, .net, .json, .uai (BIF, XMLBIF, Hugin NET, pgm JSON, UAI)")));
  EXPECT_EQ(network_format_named("net"), network_format("net"));
  EXPECT_THAT([] { static_cast<void>(network_format_named("dsc")); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown network format 'dsc' (known: bif, xmlbif, net, json")));
}

TEST(network_file_test, every_format_reads_back_what_it_writes_and_notes_come_through) {
  const auto dir = std::filesystem::temp_directory_path() / "pgm_formats_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto net = tagged_network();
  for (const auto* name : {"n.bif", "n.xml", "n.net", "n.json"}) {
    write_network(net, dir / name);
    EXPECT_EQ(read_network(dir / name), net) << name;
    const auto document = read_model(dir / name);
    ASSERT_TRUE(document.tables) << name;
    EXPECT_EQ(document.network(), net) << name;
  }
  std::ofstream(dir / "rounded.net") << "node a {\n  states = (\"x\" \"y\" \"z\");\n}\npotential (a) {\n"
                                        "  data = (0.3333 0.3333 0.3333);\n}\n";
  std::vector<std::string> notes;
  EXPECT_NEAR(read_network(dir / "rounded.net", {.notes = &notes}).table("a").probability("y", {}), 1.0 / 3, 1e-15);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("rounded.net': normalized 1 column of 1 table"));
  // A failed write leaves nothing behind.
  const auto dotted = bayesian_network::from_tables({cpt<double>(variable("x.1", {"a", "b"}), {})});
  EXPECT_THROW(write_network(dotted, dir / "bad.net"), model_error);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.net"));
  std::filesystem::remove_all(dir);
}

// A user's format: pgm's JSON behind a header line, under the extension ".pgmx". Registered once
// for the whole test program, as a user's static registration object would be.
network_format_codec wrapped_json_format() {
  constexpr std::string_view header = "pgm-wrapped 1\n";
  const network_format json("json");
  return {.name = "wrapped",
          .title = "wrapped JSON",
          .extensions = {".PGMX"},  // kept in lower case
          .read =
              [=](std::string_view text, const std::string& source, const network_read_options& options) {
                if (!text.starts_with(header)) throw parse_error(source, 1, 1, "expected the line 'pgm-wrapped 1'");
                return json.codec().read(text.substr(header.size()), source, options);
              },
          .write =
              [=](const bayesian_network& network, const network_write_options& options) {
                return std::string(header) + json.codec().write(network, options);
              }};
}

const network_format& wrapped() {
  static const network_format format = [] {
    add_network_format(wrapped_json_format());
    return network_format("wrapped");
  }();
  return format;
}

TEST(network_format_registry_test, a_users_format_is_read_written_and_listed_like_the_built_in_ones) {
  const auto format = wrapped();
  EXPECT_EQ(format_of("n.pgmx"), format);
  EXPECT_EQ(format_to_read("n.PGMX.gz"), format);
  EXPECT_EQ(known_network_formats(), (std::vector<std::string>{"bif", "xmlbif", "net", "json", "uai", "wrapped"}));
  EXPECT_EQ(network_file_kinds(), ".bif, .xml, .net, .json, .uai or .pgmx");
  EXPECT_EQ(network_format_descriptions(),
            "BIF (.bif), XMLBIF (.xml, .xmlbif, .bifxml), Hugin NET (.net), pgm JSON (.json), UAI (.uai) and wrapped "
            "JSON (.pgmx)");

  const auto dir = std::filesystem::temp_directory_path() / "pgm_user_format_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto net = tagged_network();
  write_network(net, dir / "n.pgmx");
  EXPECT_EQ(read_file(dir / "n.pgmx"), "pgm-wrapped 1\n" + to_text(net, network_format("json")));
  EXPECT_EQ(read_network(dir / "n.pgmx"), net);
  EXPECT_EQ(parse_network(to_text(net, format), format, "text"), net);
  std::ofstream(dir / "bad.pgmx") << "{}";
  EXPECT_THAT([&] { static_cast<void>(read_network(dir / "bad.pgmx")); },
              ThrowsMessage<parse_error>(HasSubstr("bad.pgmx:1:1: expected the line 'pgm-wrapped 1'")));
  std::filesystem::remove_all(dir);
}

TEST(network_format_registry_test, a_format_is_refused_without_a_name_an_extension_a_reader_or_a_writer) {
  static_cast<void>(wrapped());
  auto refused = [](network_format_codec codec, const std::string& message) {
    EXPECT_THAT([&] { add_network_format(std::move(codec)); }, ThrowsMessage<model_error>(HasSubstr(message)));
  };
  auto codec = wrapped_json_format();
  refused(codec, "a network format named 'wrapped' is registered already");
  codec.name = "other";
  refused(codec, "the extension .pgmx of the network format 'other' is the format 'wrapped''s already");
  codec.extensions = {".bif"};
  refused(codec, "the extension .bif of the network format 'other' is the format 'bif''s already");
  codec.extensions = {"txt"};
  refused(codec, "the network format 'other' has the extension 'txt'; an extension starts with '.'");
  codec.extensions = {};
  refused(codec, "the network format 'other' needs an extension");
  codec.extensions = {".other"};
  codec.write = nullptr;
  refused(codec, "the network format 'other' needs both a reader and a writer");
  codec.name = "";
  refused(codec, "a network format needs a non-empty name");
  EXPECT_EQ(known_network_formats().size(), 6u);
}

}  // namespace
}  // namespace pgm::formats_tests
