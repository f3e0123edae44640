// `pgm convert` and every model-reading command reading every format; a header-only CSV as
// zero rows of data when a model gives the states.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "pgm/io/bif.hpp"
#include "pgm/io/net.hpp"
#include "pgm/io/network_file.hpp"
#include "support/program_test.hpp"

namespace pgm::convert_cli_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

using convert_cli_test = pgm::testing::program_test;

const std::filesystem::path sachs = std::filesystem::path(PGM_NETWORKS_DIR) / "sachs.bif";

TEST_F(convert_cli_test, converts_through_every_format_exactly) {
  const auto original = read_network(sachs);
  auto from = sachs;
  for (const auto* name : {"s.xml", "s.net", "s.json", "s.bif"}) {
    const auto r = run("convert " + from.string() + " " + path(name).string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("-> " + path(name).string()));
    EXPECT_THAT(r.out, HasSubstr("11 variables, 178 free parameters"));
    EXPECT_EQ(read_network(path(name)), original) << name;
    from = path(name);
  }
  EXPECT_EQ(slurp(path("s.bif")), to_bif(original));
  const auto r = run("convert " + sachs.string() + " " + path("s.hugin").string() + " --to net");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(parse_net(slurp(path("s.hugin")), "s.hugin"), original);
  EXPECT_EQ(run("convert --help").code, 0);
}

TEST_F(convert_cli_test, refuses_what_it_cannot_write_and_writes_nothing) {
  expect_failure("convert " + sachs.string() + " " + path("s.txt").string(),
                 "not a network file; expected one of .bif, .xml, .xmlbif, .bifxml, .net, .json", path("s.txt"));
  expect_failure("convert " + sachs.string() + " " + path("s.bif").string() + " --to net",
                 "names the bif format but --to says net", path("s.bif"));
  const auto dotted = file("d.bif",
                           "variable x.1 {\n  type discrete [ 2 ] { a, b };\n}\nprobability ( x.1 ) {\n  table 0.5, "
                           "0.5;\n}\n");
  expect_failure("convert " + dotted.string() + " " + path("d.net").string(),
                 "variable 'x.1' cannot be written to NET: NET names hold letters, digits and '_' only", path("d.net"));
  const auto r = run("convert " + dotted.string() + " " + path("d2.bif").string());
  EXPECT_EQ(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("pgm: note: names with '.' (x.1)"));
  const auto structure =
      file("s.json", R"({"format":"pgm-model","version":1,"variables":[{"name":"a","states":["x","y"]}]})");
  expect_failure("convert " + structure.string() + " " + path("s.net").string(), "no tables", path("s.net"));
}

TEST_F(convert_cli_test, says_what_the_target_format_cannot_carry) {
  const auto model = file("m.json", R"({"format":"pgm-model","version":1,"metadata":{"success":"a=y"},
    "variables":[{"name":"a","states":["x","y"]}],"edges":[],
    "tables":[{"variable":"a","parents":[],"values":[[0.5,0.5]]}]})");
  const auto r = run("convert " + model.string() + " " + path("m.bif").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("the success event in the metadata of '" + model.string() + "' is not carried by bif"));
}

TEST_F(convert_cli_test, every_model_reading_command_reads_every_format) {
  ASSERT_EQ(run("convert " + sachs.string() + " " + path("s.net").string()).code, 0);
  ASSERT_EQ(run("convert " + sachs.string() + " " + path("s.xml").string()).code, 0);
  auto r = run("show " + path("s.net").string() + " --variable Akt");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("11 variables, 17 edges, 178 free parameters"));
  r = run("query --model " + path("s.xml").string() + " --query Akt --digits 17");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, run("query --model " + sachs.string() + " --query Akt --digits 17").out);
  r = run("predict --model " + path("s.net").string() + " --success Akt=HIGH --assign Erk=LOW,PKA=AVG");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, run("predict --model " + sachs.string() + " --success Akt=HIGH --assign Erk=LOW,PKA=AVG").out);
  r = run("correspond --prior-model " + path("s.xml").string() + " --target-model " + path("s.net").string());
  EXPECT_EQ(r.code, 0) << r.err;
  // A rounded file is read with a note on the normalization.
  const auto rounded = file("r.net",
                            "node a {\n  states = (\"x\" \"y\" \"z\");\n}\npotential (a) {\n"
                            "  data = (0.3333 0.3333 0.3333);\n}\n");
  r = run("show " + rounded.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("pgm: note: '" + rounded.string() + "': normalized 1 column of 1 table"));
}

TEST_F(convert_cli_test, fit_takes_its_structure_from_any_format) {
  ASSERT_EQ(run("convert " + sachs.string() + " " + path("s.net").string()).code, 0);
  const auto data = file("d.csv",
                         "Akt,Erk,Jnk,Mek,P38,PIP2,PIP3,PKA,PKC,Plcg,Raf\n"
                         "LOW,LOW,LOW,LOW,LOW,LOW,LOW,LOW,LOW,LOW,LOW\nHIGH,AVG,LOW,LOW,LOW,LOW,LOW,LOW,LOW,LOW,LOW\n");
  for (const auto& model : {sachs, path("s.net")}) {
    const auto r =
        run("fit --data " + data.string() + " --model " + model.string() + " --out " + path("f.json").string());
    ASSERT_EQ(r.code, 0) << r.err;
    const auto fitted = read_network(path("f.json"));
    EXPECT_EQ(fitted.structure().edges(), read_network(sachs).structure().edges());
    EXPECT_EQ(fitted.at("Akt").states(), read_network(sachs).at("Akt").states());  // the model's states, not the data's
  }
}

TEST_F(convert_cli_test, a_header_alone_is_zero_rows_when_a_model_gives_the_states) {
  const auto header = file("h.csv", "Akt,Erk,Jnk,Mek,P38,PIP2,PIP3,PKA,PKC,Plcg,Raf\n");
  auto r = run("fit --data " + header.string() + " --model " + sachs.string() + " --out " + path("f.bif").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("from 0 rows"));
  const auto fitted = read_network(path("f.bif"));
  EXPECT_DOUBLE_EQ(fitted.table("Akt").probability("HIGH", {"LOW", "LOW"}), 1.0 / 3);  // uniform (--empty)
  expect_failure(
      "fit --data " + header.string() + " --model " + sachs.string() + " --empty fail --out " + path("g.bif").string(),
      "", path("g.bif"));
  expect_failure("fit --data " + header.string() + " --edges \"Akt->Erk\" --out " + path("e.bif").string(),
                 "h.csv: there are no data rows after the header, so the states of 'Akt' are unknown (a model that "
                 "lists them, e.g. fit --model, allows a header alone)",
                 path("e.bif"));
}

}  // namespace
}  // namespace pgm::convert_cli_tests
