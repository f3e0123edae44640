// The `pgm` program as a user meets it: --help everywhere, the main commands, and every kind
// of bad input ending in one clear line on stderr, a non-zero exit and no output file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "pgm/core/file.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "support/program_test.hpp"

namespace pgm::cli_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

namespace fs = std::filesystem;

using cli_test = pgm::testing::program_test;

constexpr const char* stacking =
    "xOff1,yOff1,colour,onTop1\n"
    "0,0,Red,1\n0,1,Blue,1\n1,1,Red,0\n1,0,Green,1\n0,0,Red,1\n1,1,Blue,0\n2,0,Red,0\n";

TEST_F(cli_test, every_command_has_help) {
  for (const std::string command :
       {"", "fit ", "discretize ", "show ", "transfer ", "correspond ", "experiment ", "report ", "simulate ",
        "predict ", "prevent ", "learn-structure ", "convert ", "query ", "score "}) {
    const auto r = run(command + "--help");
    EXPECT_EQ(r.code, 0) << command;
    EXPECT_THAT(r.out, HasSubstr("Usage")) << command;
  }
  const auto none = run("");
  EXPECT_NE(none.code, 0);
}

TEST_F(cli_test, fit_with_edges_writes_bif_and_json) {
  const auto data = file("d.csv", stacking);
  const auto r =
      run("fit --data " + data.string() + " --edges \"xOff1->onTop1,yOff1->onTop1\" --out " + path("f.bif").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("fitted 3 tables"));
  const auto net = read_network(path("f.bif"));
  EXPECT_EQ(net.at("xOff1").states(), (std::vector<std::string>{"0", "1", "2"}));
  // (xOff1=0, yOff1=0): two rows, both onTop1=1; (2, 1) has no data: 0.5.
  EXPECT_DOUBLE_EQ(net.table("onTop1").probability("1", {"0", "0"}), 1.0);
  EXPECT_DOUBLE_EQ(net.table("onTop1").probability("1", {"2", "1"}), 0.5);

  const auto b =
      run("fit --data " + data.string() +
          " --edges \"xOff1->onTop1\" --estimator bayes --prior dirichlet --alpha 2 --out " + path("f.json").string());
  ASSERT_EQ(b.code, 0) << b.err;
  // xOff1=1: onTop1 = 0, 1, 0 → (2 + 1) / (4 + 3).
  EXPECT_DOUBLE_EQ(read_network(path("f.json")).table("onTop1").probability("1", {"1"}), 3.0 / 7);
}

TEST_F(cli_test, fit_from_a_model_file_and_show) {
  const auto data = file("d.csv", stacking);
  ASSERT_EQ(run("fit --data " + data.string() + " --edges \"xOff1->onTop1\" --out " + path("a.json").string()).code, 0);
  const auto r = run("fit --data " + data.string() + " --model " + path("a.json").string() +
                     " --estimator bayes --prior k2 --out " + path("b.bif").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto shown = run("show " + path("b.bif").string());
  ASSERT_EQ(shown.code, 0) << shown.err;
  EXPECT_THAT(shown.out, HasSubstr("P(onTop1 | xOff1)"));
  EXPECT_THAT(shown.out, HasSubstr("0.8000"));  // xOff1=0: onTop1 = 1, 1, 1 → K2 (1 + 3) / (2 + 3)
}

TEST_F(cli_test, discretize_then_fit_keeps_the_edges) {
  std::string raw = "x,onTop\n";
  for (int i = 0; i < 100; ++i) raw += std::to_string(i * 0.1) + "," + std::to_string(i % 3 == 0) + "\n";
  const auto in = file("raw.csv", raw);
  const auto r = run("discretize --in " + in.string() + " --bins 4 --out " + path("disc.csv").string() +
                     " --edges-out " + path("edges.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("left 'onTop' as it is"));
  const auto f = run("fit --data " + path("disc.csv").string() + " --edges \"x->onTop\" --intervals " +
                     path("edges.json").string() + " --out " + path("m.json").string());
  ASSERT_EQ(f.code, 0) << f.err;
  const auto net = read_network(path("m.json"));
  EXPECT_EQ(net.at("x").edges().size(), 5u);
  // The raw data with the saved edges gives the same network.
  const auto g = run("fit --data " + in.string() + " --edges \"x->onTop\" --discretization " +
                     path("edges.json").string() + " --out " + path("m2.json").string());
  ASSERT_EQ(g.code, 0) << g.err;
  EXPECT_EQ(read_network(path("m2.json")), net);
}

TEST_F(cli_test, missing_column) {
  const auto data = file("d.csv", stacking);
  expect_failure("fit --data " + data.string() + " --edges \"zOff->onTop1\" --out " + path("f.bif").string(),
                 "there is no column 'zOff' (columns: xOff1, yOff1, colour, onTop1)", path("f.bif"));
}

TEST_F(cli_test, cycle_in_edges) {
  const auto data = file("d.csv", stacking);
  expect_failure("fit --data " + data.string() + " --edges \"xOff1->onTop1,onTop1->yOff1,yOff1->xOff1\" --out " +
                     path("f.bif").string(),
                 "closes the cycle yOff1 -> xOff1 -> onTop1 -> yOff1", path("f.bif"));
}

TEST_F(cli_test, malformed_edges) {
  const auto data = file("d.csv", stacking);
  expect_failure("fit --data " + data.string() + " --edges \"xOff1=>onTop1\" --out " + path("f.bif").string(),
                 "edge 1 ('xOff1=>onTop1') is not of the form 'from->to'", path("f.bif"));
}

TEST_F(cli_test, nan_in_data) {
  const auto data = file("d.csv", "x,y\n1,0\nNaN,1\n");
  expect_failure("fit --data " + data.string() + " --edges \"x->y\" --out " + path("f.bif").string(),
                 "d.csv:3:1: column 'x': 'NaN'", path("f.bif"));
}

TEST_F(cli_test, non_numeric_value_in_a_numeric_column) {
  const auto data = file("raw.csv", "x,y\n1.5,0\n2.5,1\nabc,0\n3.5,1\n4.5,0\n5.5,1\n");
  expect_failure("discretize --in " + data.string() + " --columns x --bins 2 --out " + path("o.csv").string(),
                 "raw.csv:4:1: column 'x': expected a number, got 'abc'", path("o.csv"));
  const auto edges = file(
      "e.json",
      R"({"format":"pgm-discretization","version":1,"variables":[{"name":"x","states":["0","1"],"edges":[0,2,6]}]})");
  expect_failure("fit --data " + data.string() + " --edges \"x->y\" --discretization " + edges.string() + " --out " +
                     path("f.bif").string(),
                 "raw.csv:4:1: column 'x': expected a number, got 'abc'", path("f.bif"));
}

TEST_F(cli_test, empty_file_and_header_only) {
  expect_failure("fit --data " + file("e.csv", "").string() + " --edges \"a->b\" --out " + path("f.bif").string(),
                 "e.csv:1:1: the file is empty", path("f.bif"));
  expect_failure("fit --data " + file("h.csv", "a,b\n").string() + " --edges \"a->b\" --out " + path("f.bif").string(),
                 "h.csv: there are no data rows", path("f.bif"));
  expect_failure("fit --data " + path("absent.csv").string() + " --edges \"a->b\" --out " + path("f.bif").string(),
                 "cannot open", path("f.bif"));
}

TEST_F(cli_test, ragged_rows) {
  expect_failure(
      "fit --data " + file("r.csv", "a,b\n0,1\n1\n").string() + " --edges \"a->b\" --out " + path("f.bif").string(),
      "r.csv:3:1: expected 2 fields as in the header, found 1", path("f.bif"));
}

TEST_F(cli_test, a_failed_fit_leaves_an_existing_output_alone) {
  const auto out = file("f.bif", "previous");
  const auto r = run("fit --data " + file("d.csv", stacking).string() + " --edges \"q->onTop1\" --out " + out.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(slurp(out), "previous");
}

TEST_F(cli_test, three_hundred_states) {
  std::string csv = "id,ok\n";
  for (int i = 0; i < 900; ++i) csv += "item" + std::to_string(i % 300) + "," + std::to_string(i % 2) + "\n";
  const auto r =
      run("fit --data " + file("w.csv", csv).string() + " --edges \"id->ok\" --out " + path("f.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(read_network(path("f.json")).at("id").cardinality(), 300u);
}

TEST_F(cli_test, usage_errors) {
  const auto data = file("d.csv", stacking);
  auto r = run("fit --data " + data.string() + " --edges \"x->y\" --model m.json --out f.bif");
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("excludes"));
  r = run("fit --data " + data.string() + " --out f.bif");
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("--edges or --model"));
  r = run("fit --data " + data.string() + " --edges \"xOff1->onTop1\" --prior k2 --out " + path("f.bif").string());
  EXPECT_THAT(r.err, HasSubstr("apply to the bayes estimator"));
  r = run("fit --data " + data.string() + " --edges \"xOff1->onTop1\" --out " + path("f.txt").string());
  EXPECT_THAT(r.err, HasSubstr("not a network file; expected one of .bif, .xml, .xmlbif, .bifxml, .net, .json"));
  r = run("show " + path("nothing.bif").string());
  EXPECT_THAT(r.err, HasSubstr("cannot open"));
  EXPECT_THAT(r.err, Not(HasSubstr("internal")));
}

namespace transfer_cli {

// A 1-Stack prior and 2-Stack target data on 2 bins per offset: the prior says a centred
// cube (bin 1) stays with 0.9 and an offset one with 0.2.
constexpr const char* one_stack =
    "xOff1,yOff1,onTop1\n"
    "1,1,1\n1,1,1\n1,1,1\n1,1,1\n1,1,1\n1,1,1\n1,1,1\n1,1,1\n1,1,1\n1,1,0\n"
    "0,1,0\n0,1,0\n0,1,0\n0,1,0\n0,1,1\n1,0,0\n1,0,0\n1,0,0\n1,0,0\n1,0,1\n"
    "0,0,0\n0,0,0\n0,0,0\n0,0,0\n0,0,1\n";
constexpr const char* two_stack =
    "xOff1,yOff1,xOff2,yOff2,onTop2\n"
    "1,1,1,1,1\n1,1,1,1,0\n1,1,0,0,0\n";
constexpr const char* edges = "xOff1->onTop2,yOff1->onTop2,xOff2->onTop2,yOff2->onTop2";

}  // namespace transfer_cli

TEST_F(cli_test, fit_with_a_transferred_prior) {
  using namespace transfer_cli;
  ASSERT_EQ(run("fit --data " + file("one.csv", one_stack).string() +
                " --edges \"xOff1->onTop1,yOff1->onTop1\" --out " + path("one.json").string())
                .code,
            0);
  const auto r = run("fit --data " + file("two.csv", two_stack).string() + " --edges \"" + edges + "\" --prior-model " +
                     path("one.json").string() + " --strategy minimal --map \"onTop2=onTop1,xOff2~xOff1,yOff2~yOff1\"" +
                     " --w-prior 2 --out " + path("two.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto net = read_network(path("two.json"));
  const auto& table = net.table("onTop2");
  // u = (1,1,1,1): M = [1, 1], f = 0.9 → (2·0.9 + 1) / (2 + 2).
  EXPECT_DOUBLE_EQ(table.probability("1", std::vector<std::string>{"1", "1", "1", "1"}), (2 * 0.9 + 1) / 4);
  // u = (1,1,0,1): no data, minimal of direct 0.9 and cross P(1 | 0,1) = 0.2 → 0.2 exactly.
  EXPECT_EQ(table.probability("1", std::vector<std::string>{"1", "1", "0", "1"}), 0.2);
  EXPECT_THAT(r.err, HasSubstr("'onTop2' gets the minimal prior from 'onTop1' with w = 2"));

  const auto automatic =
      run("fit --data " + path("two.csv").string() + " --edges \"" + edges + "\" --prior-model " +
          path("one.json").string() + " --map auto --w-prior auto --out " + path("auto.json").string());
  ASSERT_EQ(automatic.code, 0) << automatic.err;
  EXPECT_THAT(automatic.err, HasSubstr("--map auto: onTop2=onTop1,xOff2~xOff1,yOff2~yOff1"));
  EXPECT_THAT(automatic.err, HasSubstr("maximizes the marginal likelihood of the 3 target rows"));
}

TEST_F(cli_test, transfer_writes_the_zero_shot_prior_and_correspond_proposes_the_map) {
  using namespace transfer_cli;
  ASSERT_EQ(run("fit --data " + file("one.csv", one_stack).string() +
                " --edges \"xOff1->onTop1,yOff1->onTop1\" --out " + path("one.json").string())
                .code,
            0);
  const auto r = run("transfer --edges \"" + std::string(edges) + "\" --prior-model " + path("one.json").string() +
                     " --strategy cross --map \"onTop2=onTop1,xOff2~xOff1,yOff2~yOff1\" --explain --out " +
                     path("prior.csv").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("u = (xOff1=1, yOff1=1, xOff2=0, yOff2=1)  <-  u' = (xOff1=0, yOff1=1) [cross]"));
  const auto csv = pgm::read_file(path("prior.csv"));
  EXPECT_THAT(csv, HasSubstr("xOff1,yOff1,xOff2,yOff2,onTop2,probability\n"));
  EXPECT_THAT(csv, HasSubstr("1,1,0,1,1,0.2\n"));
  ASSERT_EQ(run("fit --data " + file("two.csv", two_stack).string() + " --edges \"" + edges + "\" --out " +
                path("two.json").string())
                .code,
            0);
  const auto c =
      run("correspond --prior-model " + path("one.json").string() + " --target-model " + path("two.json").string());
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_THAT(c.out, HasSubstr("proposal: --map \"onTop2=onTop1,xOff2~xOff1,yOff2~yOff1\""));
}

TEST_F(cli_test, transfer_errors_name_the_problem) {
  using namespace transfer_cli;
  ASSERT_EQ(run("fit --data " + file("one.csv", one_stack).string() +
                " --edges \"xOff1->onTop1,yOff1->onTop1\" --out " + path("one.json").string())
                .code,
            0);
  const auto data = file("two.csv", two_stack).string();
  const std::string base =
      "fit --data " + data + " --edges \"" + edges + "\" --prior-model " + path("one.json").string();
  expect_failure(base + " --map \"onTop2=onTop1,xOff3~xOff1\" --out " + path("f.json").string(),
                 "the map's related variable 'xOff3' is not a variable of the target network", path("f.json"));
  expect_failure(base + " --strategy bogus --map \"onTop2=onTop1\" --out " + path("f.json").string(),
                 "unknown transfer strategy 'bogus' (known: cross, direct, minimal)", path("f.json"));
  expect_failure(base + " --strategy cross --map \"onTop2=onTop1\" --out " + path("f.json").string(),
                 "Cross-Replacement leaves the prior's parent 'xOff1' of 'onTop1' unassigned", path("f.json"));
  expect_failure(base + " --map \"onTop2=onTop1\" --w-prior -1 --out " + path("f.json").string(),
                 "--w-prior must be a number ≥ 0 or auto", path("f.json"));
  expect_failure(base + " --out " + path("f.json").string(), "--prior-model needs --map", path("f.json"));
  // fit and transfer refuse a node mapped to the prior counterpart of its own parent alike.
  const std::string same = "map entry 'onTop2=xOff1': the prior's 'xOff1' already stands for 'xOff1'";
  expect_failure(base + " --map \"onTop2=xOff1\" --out " + path("f.json").string(), same, path("f.json"));
  expect_failure("transfer --edges \"xOff1->onTop2,yOff1->onTop2\" --prior-model " + path("one.json").string() +
                     " --map \"onTop2=xOff1\" --out " + path("p.csv").string(),
                 same, path("p.csv"));
}

TEST_F(cli_test, pseudo_counts_too_large_to_normalize_are_refused) {
  const auto data = file("d.csv", stacking);
  expect_failure("fit --data " + data.string() + " --edges \"xOff1->onTop1\" --estimator bayes --prior dirichlet" +
                     " --alpha 1e308 --out " + path("f.json").string(),
                 "add up to more than the largest finite number (1.7976931348623157e+308)", path("f.json"));
}

// ---- learn-structure --------------------------------------------------------------------

// onTop1 <- xOff1, yOff1 (success likelier near the middle bin); colour independent. The rows
// cycle through every (x, y, colour) combination so that the data are deterministic.
std::string learnable_stacking() {
  std::string csv = "xOff1,yOff1,colour,onTop1\n";
  const char* colours[] = {"Red", "Blue", "Green"};
  std::uint64_t state = 12345;
  for (int i = 0; i < 3000; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const int x = static_cast<int>((state >> 33) % 5);
    const int y = static_cast<int>((state >> 40) % 5);
    const int c = static_cast<int>((state >> 47) % 3);
    const double u = static_cast<double>((state >> 11) & 0xFFFFF) / 1048576.0;
    const double p = std::max(0.05, 0.95 - 0.2 * (std::abs(x - 2) + std::abs(y - 2)));
    csv += std::to_string(x) + "," + std::to_string(y) + "," + colours[c] + "," + (u < p ? "1" : "0") + "\n";
  }
  return csv;
}

TEST_F(cli_test, learn_structure_help) {
  const auto r = run("learn-structure --help");
  EXPECT_EQ(r.code, 0);
  for (const char* option : {"--data", "--test", "--alpha", "--max-cond", "--tiers", "--forbid", "--require",
                             "--threads", "--explain", "--out", "--correction", "--min-rows-per-cell"}) {
    EXPECT_THAT(r.out, HasSubstr(option));
  }
}

TEST_F(cli_test, learn_structure_finds_the_parents_and_explains) {
  const auto data = file("d.csv", learnable_stacking());
  const auto r = run("learn-structure --data " + data.string() + " --test g2 --alpha 0.01 --explain --out " +
                     path("m.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("directed edges (2):\n  xOff1 -> onTop1\n  yOff1 -> onTop1\n"));
  EXPECT_THAT(r.out, HasSubstr("undirected edges (0)"));
  EXPECT_THAT(r.out, HasSubstr("no xOff1 - yOff1: independent given {} (g2 = "));
  EXPECT_THAT(r.out, HasSubstr("no colour - onTop1: independent given"));
  EXPECT_THAT(r.out, HasSubstr("df = "));
  EXPECT_THAT(r.out, HasSubstr("-> " + path("m.json").string()));
  const auto model = read_model_json(path("m.json"));
  EXPECT_FALSE(model.tables);
  EXPECT_EQ(model.structure.edges(), (std::vector<named_edge>{{"xOff1", "onTop1"}, {"yOff1", "onTop1"}}));
  EXPECT_EQ(model.structure.size(), 4u);
  // Without --explain the absent edges are not listed; the learned model can be fitted.
  const auto quiet = run("learn-structure --data " + data.string() + " --out " + path("q.json").string());
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_THAT(quiet.out, Not(HasSubstr("absent edges")));
  const auto f =
      run("fit --data " + data.string() + " --model " + path("m.json").string() + " --out " + path("f.bif").string());
  ASSERT_EQ(f.code, 0) << f.err;
  EXPECT_THAT(f.out, HasSubstr("fitted 4 tables"));
}

TEST_F(cli_test, learn_structure_peer_options) {
  const auto data = file("d.csv", learnable_stacking());
  // 3000 rows; the smallest table (colour, onTop1) has 6 cells: 600 rows per cell drops every edge.
  const auto sparse = run("learn-structure --data " + data.string() + " --min-rows-per-cell 600 --explain --out " +
                          path("s.json").string());
  ASSERT_EQ(sparse.code, 0) << sparse.err;
  EXPECT_THAT(sparse.out, HasSubstr("independent below 600 rows per cell"));
  EXPECT_THAT(sparse.out, HasSubstr("directed edges (0)"));
  EXPECT_THAT(sparse.out, HasSubstr("no xOff1 - onTop1: independent given {} (too few rows: 3000 < 600 per cell)"));
  EXPECT_EQ(read_model_json(path("s.json")).structure.edges().size(), 0u);
  const auto yates =
      run("learn-structure --data " + data.string() + " --correction yates --out " + path("y.json").string());
  ASSERT_EQ(yates.code, 0) << yates.err;
  EXPECT_THAT(yates.out, HasSubstr(", yates correction)"));
  EXPECT_THAT(yates.out, HasSubstr("directed edges (2):\n  xOff1 -> onTop1\n  yOff1 -> onTop1\n"));
  const auto out = path("e.json");
  const auto bad = run("learn-structure --data " + data.string() + " --correction williams --out " + out.string());
  EXPECT_EQ(bad.code, 2);
  EXPECT_THAT(bad.err, HasSubstr("--correction"));
  expect_failure("learn-structure --data " + data.string() + " --min-rows-per-cell -1 --out " + out.string(),
                 "--min-rows-per-cell", out);
}

TEST_F(cli_test, learn_structure_extends_undirected_edges) {
  // A chain a -> b -> c: the CPDAG is a - b - c, and the model holds one of its DAGs.
  std::string csv = "a,b,c\n";
  std::uint64_t state = 99;
  auto draw = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>((state >> 11) & 0xFFFFF) / 1048576.0;
  };
  for (int i = 0; i < 4000; ++i) {
    const int a = draw() < 0.5;
    const int b = draw() < 0.85 ? a : 1 - a;
    const int c = draw() < 0.85 ? b : 1 - b;
    csv += std::to_string(a) + "," + std::to_string(b) + "," + std::to_string(c) + "\n";
  }
  const auto data = file("chain.csv", csv);
  const auto r = run("learn-structure --data " + data.string() + " --threads 2 --out " + path("m.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("undirected edges (2):\n  a - b\n  b - c\n"));
  EXPECT_THAT(r.out,
              HasSubstr("extended the CPDAG to a DAG: 2 undirected edge(s) oriented without adding a v-structure"));
  EXPECT_EQ(read_model_json(path("m.json")).structure.edges().size(), 2u);
  // Tiers orient the chain c -> b -> a.
  const auto t = run("learn-structure --data " + data.string() + " --tiers \"c;b;a\" --out " + path("t.json").string());
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_THAT(t.out, HasSubstr("directed edges (2):\n  b -> a\n  c -> b\n"));
  // Required and forbidden edges.
  const auto k = run("learn-structure --data " + data.string() +
                     " --require \"a->c\" --forbid \"b->a\" --explain --out " + path("k.json").string());
  ASSERT_EQ(k.code, 0) << k.err;
  EXPECT_THAT(k.out, HasSubstr("a -> b"));
  EXPECT_THAT(k.out, HasSubstr("a -> c"));
}

TEST_F(cli_test, learn_structure_errors) {
  const auto data = file("d.csv", stacking);
  const auto out = path("m.json");
  expect_failure("learn-structure --data " + data.string() + " --tiers \"xOff1;onTop9\" --out " + out.string(),
                 "unknown variable 'onTop9' in the tiers (variables: xOff1, yOff1, colour, onTop1)", out);
  expect_failure("learn-structure --data " + data.string() + " --forbid \"xOff1->nope\" --out " + out.string(),
                 "unknown variable 'nope' in the forbidden edges", out);
  expect_failure("learn-structure --data " + data.string() + " --require \"who->onTop1\" --out " + out.string(),
                 "unknown variable 'who' in the required edges", out);
  expect_failure("learn-structure --data " + data.string() + " --require \"xOff1=onTop1\" --out " + out.string(),
                 "is not of the form 'from->to'", out);
  expect_failure("learn-structure --data " + data.string() + " --tiers \"xOff1;;onTop1\" --out " + out.string(),
                 "tier 2 is empty", out);
  expect_failure("learn-structure --data " + data.string() + " --out " + path("m.bif").string(),
                 "expected a file ending in .json", path("m.bif"));
  expect_failure("learn-structure --data " + data.string() + " --test fisher --out " + out.string(), "fisher", out);
  expect_failure("learn-structure --data " + data.string() + " --alpha 2 --out " + out.string(), "alpha", out);
  expect_failure("learn-structure --data " + data.string() +
                     " --require \"xOff1->onTop1\" --forbid \"xOff1->onTop1\" --out " + out.string(),
                 "edge xOff1->onTop1 is required, but it is forbidden", out);
  expect_failure("learn-structure --data " + path("absent.csv").string() + " --out " + out.string(), "cannot open",
                 out);
}

TEST_F(cli_test, counts_must_be_whole_numbers_in_range) {
  for (const std::string& arguments :
       {"simulate --task 1-stack --rows -5 --out " + path("s.csv").string(),
        "simulate --task 1-stack --rows 18446744073709551615 --out " + path("s.csv").string(),
        "experiment --scenario 2-stack-reality --reps 0 --out " + path("r").string(),
        "experiment --scenario 2-stack-reality --reps 100000 --out " + path("r").string(),  // kept in memory
        std::string("calibrate --task 1-stack --rows 2000000000"),
        "discretize --in x.csv --bins 0 --out " + path("o.csv").string()}) {
    const auto r = run(arguments);
    EXPECT_EQ(r.code, 2) << arguments;
    EXPECT_THAT(r.err, HasSubstr("expected a whole number from")) << arguments;
  }
  EXPECT_FALSE(fs::exists(path("r")));
}

TEST_F(cli_test, experiment_output_folder_is_checked_first) {
  const auto a_file = file("a.csv", "x\n1\n");
  expect_failure("experiment --scenario 2-stack-reality --reps 1 --out " + a_file.string(), "is a file, not a folder");
  expect_failure("experiment --scenario 2-stack-reality --reps 1 --out " + path("missing/results").string(),
                 "the folder '" + path("missing").string() + "' does not exist", path("missing"));
  expect_failure("experiment --scenario bogus --out " + path("r").string(), "unknown scenario 'bogus'", path("r"));
}

// --reward and --move-cost add the rule of highest expected utility's metrics; a cost of a
// variable the target cannot move is noted, a malformed one refused before anything is written.
TEST_F(cli_test, experiment_with_move_costs_scores_both_prevention_rules) {
  const std::string base = "experiment --scenario 2-stack-reality --reps 1 --threads 1 --no-auto";
  const auto r = run(base + " --reward 1 --move-cost xOff1=0.01,xOff2=0.01,colour=3 --out " + path("r").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("the cost of moving 'colour' is left out: it is no controllable parent of 'onTop2'"));
  const auto summary = slurp(path("r/summary.csv"));
  for (const auto* metric : {",prevention_cost,", ",utility_prevention,", ",utility_prevention_cost,"}) {
    EXPECT_THAT(summary, HasSubstr(metric));
  }
  expect_failure(base + " --reward 1 --move-cost xOff1 --out " + path("bad").string(),
                 "--move-cost: expected NAME=COST, found 'xOff1'", path("bad"));
  const auto needs = run(base + " --move-cost xOff1=1 --out " + path("bad").string());
  EXPECT_EQ(needs.code, 2);
  EXPECT_THAT(needs.err, HasSubstr("--move-cost requires --reward"));
}

// --data-cache keeps each task's data between runs; a later run reads them and gets the same
// results. Without it, nothing but the results folder is written.
TEST_F(cli_test, experiment_data_cache_is_written_once_and_read_by_a_later_run) {
  const std::string base = "experiment --scenario 2-stack-reality --reps 1 --threads 1 --no-auto --out ";
  auto entries = [this] {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(path(""))) names.insert(e.path().filename().string());
    names.erase("stdout.txt");
    names.erase("stderr.txt");
    return names;
  };
  const auto plain = run(base + path("plain").string());
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_EQ(entries(), std::set<std::string>{"plain"});

  const auto cache = path("cache").string();
  const auto first = run(base + path("first").string() + " --data-cache " + cache);
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_THAT(first.err, HasSubstr("wrote"));
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(cache)) files.insert(e.path().filename().string());
  // The prior's data (135 rows of 1-stack-reality) and the target's (45 + 180 of 2-stack-reality).
  using ::testing::AllOf;
  using ::testing::EndsWith;
  using ::testing::StartsWith;
  EXPECT_THAT(files, ::testing::ElementsAre(
                         AllOf(StartsWith("1-stack-reality.analytic.seed-"), EndsWith(".rows-135.pgmdata")),
                         AllOf(StartsWith("2-stack-reality.analytic.seed-"), EndsWith(".rows-225.pgmdata"))));
  const auto second = run(base + path("second").string() + " --data-cache " + cache);
  ASSERT_EQ(second.code, 0) << second.err;
  EXPECT_THAT(second.err, HasSubstr("read"));
  EXPECT_THAT(second.err, ::testing::Not(HasSubstr("wrote")));
  EXPECT_EQ(slurp(path("second/summary.csv")), slurp(path("first/summary.csv")));
  EXPECT_EQ(slurp(path("first/summary.csv")), slurp(path("plain/summary.csv")));

  // A cache file cut short is an error naming it, not data.
  const auto file_path = fs::path(cache) / *files.begin();
  const auto bytes = slurp(file_path);
  std::ofstream(file_path, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  expect_failure(base + path("third").string() + " --data-cache " + cache, file_path.string() + ": truncated");
}

TEST_F(cli_test, report_writes_and_checks_a_document_from_summaries) {
  const std::string header = "scenario,target,strategy,w,rows,metric,mean,sd,repetitions\n";
  const auto summary = file("summary.csv", header + "s,t,mle,0,0,failure_prevention,0.5,0.1,20\n");
  const auto other = file("other.csv", header + "s,t,mle,0,0,failure_prevention,0.25,0.1,20\n");
  const auto page = file("page.md",
                         "# Results\nMLE prevents {{pct:1 s/t/mle/0/0/failure_prevention}} %, "
                         "elsewhere {{pct:0 b:s/t/mle/0/0/failure_prevention}} %.\n");
  const auto sources =
      " --template " + page.string() + " --summary " + summary.string() + " --summary b=" + other.string();
  const auto printed = run("report" + sources);
  EXPECT_EQ(printed.code, 0) << printed.err;
  EXPECT_EQ(printed.out, "# Results\nMLE prevents 50.0 %, elsewhere 25 %.\n");
  const auto out = path("RESULTS.md").string();
  ASSERT_EQ(run("report" + sources + " --out " + out).code, 0);
  EXPECT_EQ(slurp(out), printed.out);
  const auto checked = run("report" + sources + " --out " + out + " --check");
  EXPECT_EQ(checked.code, 0) << checked.err;
  EXPECT_THAT(checked.out, HasSubstr("matches"));
  // A number edited by hand (or a summary that changed) is found.
  file("RESULTS.md", "# Results\nMLE prevents 51.0 %, elsewhere 25 %.\n");
  expect_failure("report" + sources + " --out " + out + " --check",
                 "is out of date with its summaries: line 2 reads 'MLE prevents 51.0 %");
  EXPECT_EQ(run("report" + sources + " --check").code, 2) << "--check needs --out";
}

TEST_F(cli_test, report_errors_name_the_template_place_and_write_nothing) {
  const auto summary = file("summary.csv",
                            "scenario,target,strategy,w,rows,metric,mean,sd,repetitions\n"
                            "s,t,mle,0,0,failure_prevention,0.5,0.1,20\n");
  const auto page = file("page.md", "ok\n  {{pct:1 s/t/direct/0/0/failure_prevention}}\n");
  expect_failure(
      "report --template " + page.string() + " --summary " + summary.string() + " --out " + path("out.md").string(),
      page.string() + ":2:3: {{pct:1 s/t/direct/0/0/failure_prevention}}: no summary row matches", path("out.md"));
  expect_failure("report --template " + page.string() + " --summary " + path("none.csv").string(), "none.csv");
}

TEST_F(cli_test, a_number_too_large_for_a_double_in_json_is_a_parse_error) {
  const auto model = file("m.json", R"({"format": "pgm-model", "version": 1,
  "variables": [{"name": "a", "states": ["0", "1"]}], "edges": [],
  "tables": [{"variable": "a", "parents": [], "values": [[1e999, 0.5]]}]})");
  expect_failure("show " + model.string(), "m.json:3:59: number out of range: '1e999'");
}

TEST_F(cli_test, discretize_checks_every_output_before_writing_any) {
  const auto data = file("raw.csv", "x,y\n1.5,0\n2.5,1\n3.5,0\n4.5,1\n");
  expect_failure("discretize --in " + data.string() + " --columns x --bins 2 --out " + path("o.csv").string() +
                     " --edges-out " + path("missing/e.json").string(),
                 "the directory '" + path("missing").string() + "' does not exist", path("o.csv"));
  expect_failure("discretize --in " + data.string() + " --columns x --bins 2 --out " + data.string(),
                 "is the input file");
  EXPECT_EQ(slurp(data), "x,y\n1.5,0\n2.5,1\n3.5,0\n4.5,1\n");
}

// Output lost on the way to standard output (a full disk, /dev/full) is a failure: exit 1 and
// a message, whichever command printed it (issue 28).
TEST_F(cli_test, a_failed_write_to_standard_output_exits_1) {
  const std::string sachs = std::string(PGM_NETWORKS_DIR) + "/sachs.bif";
  const auto summary = file("summary.csv",
                            "scenario,target,strategy,w,rows,metric,mean,sd,repetitions\n"
                            "s,t,mle,0,0,failure_prevention,0.5,0.1,20\n");
  const auto page = file("page.md", "{{pct:1 s/t/mle/0/0/failure_prevention}}\n");
  const auto data = file("d.csv", stacking);
  for (const auto& command : std::vector<std::string>{
           "query --model " + sachs + " --query Akt", "show " + sachs, "convert " + sachs + " /dev/stdout --to bif",
           "predict --model " + sachs + " --assign PKA=LOW --success Akt=HIGH --marginalize",
           "report --template " + page.string() + " --summary " + summary.string(),
           "fit --data " + data.string() + " --edges xOff1-\\>onTop1 --out " + path("f.bif").string(), "fit --help"}) {
    const auto written = run(command);
    ASSERT_EQ(written.code, 0) << command << ": " << written.err;
    ASSERT_FALSE(written.out.empty()) << command;
    const auto lost = run_to(command, "/dev/full");
    EXPECT_EQ(lost.code, 1) << command;
    EXPECT_THAT(lost.err, HasSubstr("cannot write")) << command;
  }
  // Written to standard output, a model is all that is there: what was done goes to stderr.
  const auto converted = run("convert " + sachs + " /dev/stdout --to json");
  ASSERT_EQ(converted.code, 0) << converted.err;
  EXPECT_EQ(parse_network(converted.out, network_format("json"), "stdout"), read_network(sachs));
  EXPECT_THAT(converted.err, HasSubstr("converted " + sachs + " (bif) -> /dev/stdout (json)"));
}

// A summary that cannot reach standard output fails the run before its file is replaced, so a
// retry starts from the old one (issue 49: pgm update --out = --model counted new rows twice).
TEST_F(cli_test, a_summary_lost_on_standard_output_leaves_the_file_as_it_was) {
  const auto data = file("d.csv", stacking);
  const auto model = path("m.json").string();
  const auto fitted = run("fit --data " + data.string() + " --edges xOff1-\\>onTop1 --keep-counts --out " + model);
  ASSERT_EQ(fitted.code, 0) << fitted.err;
  const auto before = slurp(model);
  const auto lost = run_to("update --model " + model + " --data " + data.string() + " --out " + model, "/dev/full");
  EXPECT_EQ(lost.code, 1);
  EXPECT_THAT(lost.err, HasSubstr("cannot write to standard output"));
  EXPECT_THAT(lost.err, HasSubstr("is left as it was"));
  EXPECT_EQ(slurp(model), before);
  const auto updated = run("update --model " + model + " --data " + data.string() + " --out " + model);
  ASSERT_EQ(updated.code, 0) << updated.err;
  EXPECT_NE(slurp(model), before);

  const auto learned = path("s.json").string();
  std::ofstream(learned) << "old";
  for (const char* algorithm : {"hc", "pc"}) {
    const auto r = run_to("learn-structure --data " + data.string() + " --algorithm " + algorithm + " --out " + learned,
                          "/dev/full");
    EXPECT_EQ(r.code, 1) << algorithm;
    EXPECT_EQ(slurp(learned), "old") << algorithm;
  }

  // Every command that writes a file and says so on standard output, the same rule.
  const std::string sachs = std::string(PGM_NETWORKS_DIR) + "/sachs.bif";
  const auto raw = file("raw.csv", "x,y\n1.5,0\n2.5,1\n3.5,0\n4.5,1\n");
  const auto summary = file("summary.csv",
                            "scenario,target,strategy,w,rows,metric,mean,sd,repetitions\n"
                            "s,t,mle,0,0,failure_prevention,0.5,0.1,20\n");
  const auto page = file("page.md", "{{pct:1 s/t/mle/0/0/failure_prevention}}\n");
  const auto oil = std::string(PGM_SOURCE_DIR) + "/tests/data/decisions/oil_wildcatter.xml";
  const auto grid = std::string(PGM_SOURCE_DIR) + "/tests/data/uai/MAR/Alchemy_11.uai";
  const auto old = [&](const std::string& name) {
    std::ofstream(path(name)) << "old";
    return path(name).string();
  };
  for (const auto& [command, outputs] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"fit --data " + data.string() + " --edges xOff1-\\>onTop1 --out " + old("f.bif"), {"f.bif"}},
           {"convert " + sachs + " " + old("c.json"), {"c.json"}},
           {"convert " + grid + " " + old("c.uai"), {"c.uai"}},
           {"discretize --in " + raw.string() + " --columns x --bins 2 --out " + old("o.csv") + " --edges-out " +
                old("e.json"),
            {"o.csv", "e.json"}},
           {"draw --model " + sachs + " --out " + old("d.dot"), {"d.dot"}},
           {"report --template " + page.string() + " --summary " + summary.string() + " --out " + old("r.md"),
            {"r.md"}},
           {"simulate --task 1-stack --rows 10 --out " + old("s.csv"), {"s.csv"}},
           {"solve --model " + grid + " --task PR --out " + old("p.PR"), {"p.PR"}},
           {"decide --model " + oil + " --policy-out " + old("policy.csv"), {"policy.csv"}}}) {
    const auto r = run_to(command, "/dev/full");
    EXPECT_EQ(r.code, 1) << command << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr("cannot write to standard output")) << command;
    for (const auto& output : outputs) EXPECT_EQ(slurp(path(output)), "old") << command << ": " << output;
    const auto written = run(command);
    EXPECT_EQ(written.code, 0) << command << ": " << written.err;
    for (const auto& output : outputs) EXPECT_NE(slurp(path(output)), "old") << command << ": " << output;
  }
}

// A message that quotes a bad file's bytes shows control characters escaped: a terminal never
// obeys an escape sequence from a data file (issue 28).
TEST_F(cli_test, bytes_a_message_quotes_from_a_file_are_escaped) {
  const auto model = file("m.bif",
                          "network n { }\nvariable a {\n  type discrete [ 2 ] { x, y };\n}\n"
                          "probability ( a ) {\n  table 0.5, 0.5;\n}\n");
  const auto data = file("d.csv", "a\nx\n\x1b[2Jgone\xe9\n");
  const auto r = run("fit --model " + model.string() + " --data " + data.string() + " --out " + path("f.bif").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("'\\x1b[2Jgone\\xe9' is not a state of 'a'"));
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos);
}

}  // namespace
}  // namespace pgm::cli_tests
