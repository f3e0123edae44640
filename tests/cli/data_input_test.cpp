// Data as users have it, for every command that reads a CSV: standard input ("-") and
// gzip-compressed files, with the same results as the plain file; broken gzip and errors deep
// in a large file named by file, line and column.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "pgm/inference/sampling.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/learn/fit.hpp"
#include "support/program_test.hpp"
#include "support/random_csv.hpp"

namespace pgm::data_input_tests {
namespace {

using ::testing::HasSubstr;

using data_input_test = pgm::testing::program_test;

// Two offsets and an outcome, raw and binned, 2000 rows.
std::string raw_trials() {
  std::string csv = "xOff1,yOff1,colour,onTop1\n";
  for (int i = 0; i < 2000; ++i) {
    const double x = (i * 37 % 200) / 40.0 - 2.5;
    const double y = (i * 91 % 200) / 40.0 - 2.5;
    csv += std::to_string(x) + "," + std::to_string(y) + "," + (i % 3 ? "Red" : "Blue") + "," +
           std::to_string(x * x + y * y < 2.0 || i % 7 == 0) + "\n";
  }
  return csv;
}

TEST_F(data_input_test, every_command_reads_standard_input_and_gzip_alike) {
  const auto raw = file("raw.csv", raw_trials());
  ASSERT_EQ(std::system(("gzip -k " + raw.string()).c_str()), 0);
  const auto gz = path("raw.csv.gz");
  // discretize: file, stdin, gzip, gzip on stdin.
  const std::string bins = " --bins 4 --columns xOff1,yOff1 --edges-out ";
  const auto plain =
      run("discretize --in " + raw.string() + bins + path("e.json").string() + " --out " + path("d.csv").string());
  ASSERT_EQ(plain.code, 0) << plain.err;
  for (const std::string& input : {"- < " + raw.string(), gz.string(), "- < " + gz.string()}) {
    const auto r =
        run("discretize --in " + input + bins + path("e2.json").string() + " --out " + path("d2.csv").string());
    ASSERT_EQ(r.code, 0) << input << ": " << r.err;
    EXPECT_EQ(slurp(path("d2.csv")), slurp(path("d.csv"))) << input;
    EXPECT_EQ(slurp(path("e2.json")), slurp(path("e.json"))) << input;
  }
  ASSERT_EQ(std::system(("gzip -k " + path("d.csv").string()).c_str()), 0);
  // fit, with every way of giving the structure and the bins.
  const std::string edges = " --edges \"xOff1->onTop1,yOff1->onTop1,colour->onTop1\"";
  const std::vector<std::pair<std::string, std::string>> fits{
      {path("d.csv").string(), edges + " --intervals " + path("e.json").string()},
      {raw.string(), edges + " --discretization " + path("e.json").string()},
      {path("d.csv").string(), edges + " --estimator bayes --prior bdeu --ess 3"},
  };
  for (const auto& [data, rest] : fits) {
    const auto expected = run("fit --data " + data + rest + " --out " + path("a.json").string());
    ASSERT_EQ(expected.code, 0) << expected.err;
    for (const std::string& input : {"- < " + data, data + ".gz", "- < " + data + ".gz"}) {
      const auto r = run("fit --data " + input + rest + " --out " + path("b.json").string());
      ASSERT_EQ(r.code, 0) << input << rest << ": " << r.err;
      EXPECT_EQ(r.out.substr(0, r.out.find(" -> ")), expected.out.substr(0, expected.out.find(" -> ")));
      EXPECT_EQ(r.err, expected.err) << input << rest;
      EXPECT_EQ(slurp(path("b.json")), slurp(path("a.json"))) << input << rest;
    }
  }
  // fit --model and learn-structure.
  const auto model = run("fit --data " + path("d.csv").string() + " --model " + path("a.json").string() + " --out " +
                         path("m.json").string());
  ASSERT_EQ(model.code, 0) << model.err;
  const auto model_gz = run("fit --data - --model " + path("a.json").string() + " --out " + path("m2.json").string() +
                            " < " + path("d.csv.gz").string());
  ASSERT_EQ(model_gz.code, 0) << model_gz.err;
  EXPECT_EQ(slurp(path("m2.json")), slurp(path("m.json")));
  const auto learned = run("learn-structure --data " + path("d.csv").string() + " --out " + path("l.json").string());
  ASSERT_EQ(learned.code, 0) << learned.err;
  const auto learned_gz =
      run("learn-structure --data - --out " + path("l2.json").string() + " < " + path("d.csv.gz").string());
  ASSERT_EQ(learned_gz.code, 0) << learned_gz.err;
  EXPECT_EQ(slurp(path("l2.json")), slurp(path("l.json")));
}

TEST_F(data_input_test, broken_gzip_is_an_error_naming_the_file_and_writes_nothing) {
  auto csv = testing::make_random_csv(3, {.rows = 3000, .quotes = false}).text;
  const auto data = file("d.csv", csv);
  ASSERT_EQ(std::system(("gzip -k " + data.string()).c_str()), 0);
  const auto whole = slurp(path("d.csv.gz"));
  file("cut.csv.gz", whole.substr(0, whole.size() / 2));
  const std::string edges = " --edges \"c0->c4\" --out ";
  expect_failure("fit --data " + path("cut.csv.gz").string() + edges + path("f.json").string(),
                 "pgm: error: '" + path("cut.csv.gz").string() + "' is truncated", path("f.json"));
  expect_failure("fit --data - " + edges + path("f.json").string() + " < " + path("cut.csv.gz").string(),
                 "pgm: error: '<stdin>' is truncated", path("f.json"));
  expect_failure("discretize --in " + path("cut.csv.gz").string() + " --out " + path("o.csv").string(), "is truncated",
                 path("o.csv"));
  expect_failure("fit --data " + file("plain.csv.gz", "c0,c4\n1,0\n").string() + edges + path("f.json").string(),
                 "plain.csv.gz' is not gzip data", path("f.json"));
  // A problem deep in a file (past its first chunks) is reported at its place.
  std::string big = "a,b\n";
  for (int row = 0; row < 300000; ++row) big += std::to_string(row % 5) + "," + std::to_string(row % 2) + "\n";
  const auto at = big.find('\n', big.size() * 3 / 4) + 1;
  const auto line = 1 + static_cast<std::size_t>(std::count(big.begin(), big.begin() + static_cast<long>(at), '\n'));
  big.insert(at, "3,x,1\n");
  const auto big_file = file("big.csv", big);
  ASSERT_EQ(std::system(("gzip -k " + big_file.string()).c_str()), 0);
  const std::string message = ":" + std::to_string(line) + ":5: expected 2 fields as in the header, found 3";
  expect_failure("fit --data " + big_file.string() + " --edges \"a->b\" --out " + path("f.json").string(),
                 "big.csv" + message, path("f.json"));
  expect_failure("fit --data - --edges \"a->b\" --out " + path("f.json").string() + " < " + path("big.csv.gz").string(),
                 "<stdin>" + message, path("f.json"));
}

// Missing values (issue 18): NA, empty and ? by default; row 2 lacks b, row 4 c, row 5 a.
constexpr const char* incomplete = "a,b,c\nx,0,1\nx,NA,0\ny,1,1\ny,0,\n?,1,0\nx,1,1\n";

TEST_F(data_input_test, missing_values_are_an_error_by_default_naming_line_and_column) {
  const auto data = file("m.csv", incomplete).string();
  const auto out = path("f.json");
  expect_failure("fit --data " + data + " --edges \"b->a,a->c\" --out " + out.string(),
                 "m.csv:3:3: column 'b': 'NA' is a missing value", out);
  // The program says how to read such data: the policies and the texts read as missing.
  EXPECT_THAT(run("fit --data " + data + " --edges \"b->a,a->c\" --out " + out.string()).err,
              HasSubstr("pgm: hint: --missing drop leaves out the rows that have a missing value, --missing available "
                        "counts each table over the rows where its variables are present; --na names the texts read "
                        "as missing (default NA,,?: NA, the empty field and ?)"));
  expect_failure("learn-structure --data " + data + " --out " + out.string(),
                 "m.csv:3:3: column 'b': 'NA' is a missing value", out);
  expect_failure("discretize --in " + data + " --out " + path("o.csv").string(), "m.csv:3:3: column 'b'",
                 path("o.csv"));
  // Only the empty field is missing: NA and ? are states, and the empty field an error at row 4.
  const auto r = run("fit --data " + data + " --edges \"b->a,a->c\" --na '' --out " + out.string());
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("m.csv:5:5: column 'c': the value is empty, a missing value"));
  expect_failure("fit --data " + data + " --edges \"b->a\" --missing pairwise --out " + out.string(),
                 "--missing: pairwise not in {error,drop,available,em}", out);
}

TEST_F(data_input_test, missing_values_dropped_with_a_note) {
  const auto data = file("m.csv", incomplete).string();
  const auto r = run("fit --data " + data + " --edges \"b->a,a->c\" --missing drop --out " + path("f.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(
      r.err,
      HasSubstr("pgm: note: dropped 3 of 6 rows with a missing value (--missing drop; --na names the texts read as "
                "missing)"));
  EXPECT_THAT(r.out, HasSubstr("from 3 rows"));
  // Rows 1, 3 and 6: a | b is x | 0, y | 1, x | 1.
  const auto net = read_network(path("f.json"));
  EXPECT_DOUBLE_EQ(net.table("a").probability("x", {"1"}), 0.5);
  EXPECT_DOUBLE_EQ(net.table("a").probability("x", {"0"}), 1.0);
  // The same rows for learn-structure and discretize.
  const auto l = run("learn-structure --data " + data + " --missing drop --out " + path("l.json").string());
  ASSERT_EQ(l.code, 0) << l.err;
  EXPECT_THAT(l.err, HasSubstr("dropped 3 of 6 rows"));
  EXPECT_THAT(l.out, HasSubstr("PC-stable on 3 rows"));
}

TEST_F(data_input_test, missing_values_available_count_each_family_over_its_rows) {
  const auto data = file("m.csv", incomplete).string();
  const auto r =
      run("fit --data " + data + " --edges \"b->a,a->c\" --missing available --out " + path("f.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("'c' is counted over the 4 of 6 rows where it and its parents are present"));
  // By hand: c | a over rows 1, 2, 3, 6: a = x gives c = 1, 0, 1; a = y gives c = 1.
  const auto net = read_network(path("f.json"));
  EXPECT_DOUBLE_EQ(net.table("c").probability("1", {"x"}), 2.0 / 3);
  EXPECT_DOUBLE_EQ(net.table("c").probability("1", {"y"}), 1.0);
  // b over its five present rows: 0, 1, 0, 1, 1.
  EXPECT_DOUBLE_EQ(net.table("b").probability("1", {}), 3.0 / 5);
  // Standard input and gzip alike.
  ASSERT_EQ(std::system(("gzip -k " + data).c_str()), 0);
  const auto z = run("fit --data - --edges \"b->a,a->c\" --missing available --out " + path("z.json").string() + " < " +
                     data + ".gz");
  ASSERT_EQ(z.code, 0) << z.err;
  EXPECT_EQ(slurp(path("z.json")), slurp(path("f.json")));
}

TEST_F(data_input_test, discretize_keeps_missing_values_missing_as_the_first_na_text) {
  const auto data = file("d.csv", "u,v\n0.5,a\nNA,b\n2.5,a\n1.5,b\n3.5,a\n0.1,b\n0.2,a\n").string();
  const auto r =
      run("discretize --in " + data + " --columns u --bins 2 --missing available --out " + path("o.csv").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(path("o.csv")), "u,v\n0,a\nNA,b\n1,a\n1,b\n1,a\n0,b\n0,a\n");
  const auto dash = run("discretize --in " + data + " --columns u --bins 2 --missing available --na '-,NA' --out " +
                        path("p.csv").string());
  ASSERT_EQ(dash.code, 0) << dash.err;
  EXPECT_EQ(slurp(path("p.csv")), "u,v\n0,a\n-,b\n1,a\n1,b\n1,a\n0,b\n0,a\n");
  // Read back with the same policy, the output gives the same bins.
  const auto again = run("fit --data " + path("o.csv").string() + " --edges \"u->v\" --missing available --out " +
                         path("f.json").string());
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_THAT(again.err, HasSubstr("'v' is counted over the 6 of 7 rows"));
}

// pathfinder declares the state NA in 35 variables: fitting it to its own samples reads NA as
// that state, with a note, rather than refusing the first NA as a missing value (issue 28).
TEST_F(data_input_test, a_state_the_model_spells_like_a_missing_value_is_that_state) {
  const auto model = std::string(PGM_NETWORKS_DIR) + "/pathfinder.bif";
  const auto network = read_network(model);
  const auto sampled = sample(network, 300, 7);
  std::string csv;
  for (const auto& name : sampled.names()) csv += (csv.empty() ? "" : ",") + name;
  csv += '\n';
  std::size_t na = 0;
  for (std::size_t row = 0; row < sampled.rows(); ++row) {
    for (std::size_t c = 0; c < sampled.names().size(); ++c) {
      const auto& column = sampled.discrete(sampled.names()[c]);
      const auto& state = column.var().states()[column.code(row)];
      na += state == "NA";
      csv += (c ? "," : "") + state;
    }
    csv += '\n';
  }
  ASSERT_GT(na, 0U);
  const auto data = file("sample.csv", csv);
  for (const std::string missing : {"error", "drop"}) {
    const auto out = path("fitted-" + missing + ".bif");
    const auto r =
        run("fit --model " + model + " --data " + data.string() + " --missing " + missing + " --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("from 300 rows"));
    EXPECT_THAT(r.err, HasSubstr("pgm: note: 'NA' is a state of the model's variables F2, F78, F3, F4, F5, … (35 in "
                                 "all): read as that state in their columns, not as a missing value (--na names the "
                                 "texts read as missing)"));
    EXPECT_THAT(r.err, ::testing::Not(HasSubstr("dropped")));
    // The counts are those of the sample: the same tables as a fit from the data set in memory.
    const auto fitted = read_network(out);
    const auto expected = fit(network.structure(), sampled, {});
    EXPECT_EQ(fitted.table("Fault").values().size(), expected.table("Fault").values().size());
    for (const auto& table : expected.tables()) {
      const auto& ours = fitted.table(table.child().name());
      for (std::size_t i = 0; i < table.values().size(); ++i) {
        ASSERT_NEAR(ours.values()[i], table.values()[i], 1e-12) << table.child().name();
      }
    }
  }
  // In a column whose variable has no such state, NA is still a missing value.
  const auto small =
      file("small.bif",
           "network n { }\nvariable a {\n  type discrete [ 2 ] { NA, x };\n}\nvariable b {\n  type "
           "discrete [ 2 ] { x, y };\n}\nprobability ( a ) {\n  table 0.5, 0.5;\n}\nprobability ( b | a ) {\n"
           "  ( NA ) 0.5, 0.5;\n  ( x ) 0.5, 0.5;\n}\n");
  const auto gap = file("gap.csv", "a,b\nNA,x\nx,NA\n");
  const auto r = run("fit --model " + small.string() + " --data " + gap.string() + " --out " + path("g.bif").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("pgm: note: 'NA' is a state of the model's variable a: read as that state in its "
                               "column, not as a missing value"));
  EXPECT_THAT(r.err, HasSubstr("gap.csv:3:3: column 'b': 'NA' is a missing value"));
  EXPECT_FALSE(std::filesystem::exists(path("g.bif")));
}

}  // namespace
}  // namespace pgm::data_input_tests
