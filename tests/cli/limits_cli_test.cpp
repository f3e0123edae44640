// The program at pgm's limits and with the numbers users type (docs/limits.md): a clear error,
// a non-zero exit and no output file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstddef>
#include <fstream>
#include <string>

#include "pgm/io/network_file.hpp"
#include "support/program_test.hpp"

namespace pgm::limits_cli_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

using limits_cli_test = pgm::testing::program_test;

// The sanitizers' shadow memory and quarantine are not the program's: memory is compared only
// in a plain build.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool measures_memory = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool measures_memory = false;
#else
constexpr bool measures_memory = true;
#endif
#else
constexpr bool measures_memory = true;
#endif

constexpr std::size_t mib = std::size_t{1} << 20;

// Writes `head`, then `piece` until the text holds `bytes`, then `tail`, gzip-compressed as it
// goes: a model that inflates to tens of MiB from a file of some 100 KiB.
void write_gzip(const std::filesystem::path& at, const std::string& head, const std::string& piece, std::size_t bytes,
                const std::string& tail) {
  z_stream stream{};
  ASSERT_EQ(deflateInit2(&stream, 1, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::ofstream file(at, std::ios::binary);
  std::string block;
  while (block.size() < (std::size_t{1} << 16)) block += piece;
  std::string out(std::size_t{1} << 17, '\0');
  const auto feed = [&](const std::string& text, int flush) {
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
    stream.avail_in = static_cast<uInt>(text.size());
    do {
      stream.next_out = reinterpret_cast<Bytef*>(out.data());
      stream.avail_out = static_cast<uInt>(out.size());
      deflate(&stream, flush);
      file.write(out.data(), static_cast<std::streamsize>(out.size() - stream.avail_out));
    } while (stream.avail_out == 0);
  };
  feed(head, Z_NO_FLUSH);
  for (std::size_t written = head.size(); written + block.size() + tail.size() < bytes; written += block.size()) {
    feed(block, Z_NO_FLUSH);
  }
  feed(tail, Z_FINISH);
  deflateEnd(&stream);
}

// Two raw continuous columns of 5,000 distinct values taken as labels: y | x would need
// 5000 × 5000 = 2.5·10^7 cells (and OOM-killed the program at 8·10^8 before the limit).
TEST_F(limits_cli_test, fit_on_raw_continuous_columns_is_refused_with_a_hint_to_discretize) {
  std::string csv = "x,y\n";
  for (int i = 0; i < 5000; ++i) csv += std::to_string(i * 0.001) + "," + std::to_string(i * 0.37 + 0.5) + "\n";
  const auto data = file("raw.csv", csv);
  const auto out = path("f.bif");
  const auto r = run("fit --threads 2 --data " + data.string() + " --edges \"x->y\" --out " + out.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("the table of 'y' would have 25000000 cells (5000 states × 5000 parent "
                               "configurations), more than pgm's limit of 16777216 cells per table"));
  EXPECT_THAT(r.err, HasSubstr("hint: a variable with that many states is usually a continuous column read as "
                               "labels; bin it with --discretization (or pgm discretize) first"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

// EM and the scores on a family of 40 binary parents, 2^40 configurations seen by 6 rows:
// EM refuses it by name (it said "out of memory"), the score sums over the rows' columns (it
// looped over 2^40 of them), and neither hints at binning columns, which is not the cause.
TEST_F(limits_cli_test, em_refuses_and_scores_sum_over_a_family_of_forty_parents) {
  std::string header = "c", edges;
  for (int p = 0; p < 40; ++p) {
    header += ",p" + std::to_string(p);
    edges += (p ? "," : "") + std::string("p") + std::to_string(p) + "->c";
  }
  std::string csv = header + "\n";
  for (int r = 0; r < 6; ++r) {
    csv += r == 0 ? "" : std::to_string(r % 2);
    for (int p = 0; p < 40; ++p) csv += "," + std::to_string((r + p) % 2);
    csv += "\n";
  }
  const auto data = file("wide.csv", csv);
  const auto em =
      run("fit --data " + data.string() + " --edges \"" + edges + "\" --missing em --out " + path("em.json").string());
  EXPECT_EQ(em.code, 1);
  EXPECT_THAT(em.err, HasSubstr("EM holds every table dense, and the table of 'c' with 40 parents has 2199023255552 "
                                "cells, more than pgm's limit of 16777216"));
  EXPECT_THAT(em.err, Not(HasSubstr("hint")));
  EXPECT_FALSE(std::filesystem::exists(path("em.json")));
  const auto fitted =
      run("fit --data " + data.string() + " --edges \"" + edges + "\" --missing drop --out " + path("m.json").string());
  ASSERT_EQ(fitted.code, 0) << fitted.err;
  const auto scored =
      run("score --model " + path("m.json").string() + " --data " + data.string() + " --missing drop --score bdeu");
  ASSERT_EQ(scored.code, 0) << scored.err;
  EXPECT_THAT(scored.out, HasSubstr("bdeu (iss 1) of "));
}

// y under 26 binary parents: 2^26 configurations × 2 states, past the dense limit, from 2,000
// rows. pgm fit counts it sparse; JSON keeps it so, BIF refuses it, sampling answers queries, and
// exact inference once the evidence reduces the family to what fits.
TEST_F(limits_cli_test, a_family_past_the_dense_limit_is_fitted_sparse) {
  std::string csv = "y";
  std::string edges;
  for (int p = 0; p < 26; ++p) {
    csv += ",p" + std::to_string(p);
    edges += (p ? "," : "") + std::string("p") + std::to_string(p) + "->y";
  }
  csv += "\n";
  std::uint64_t state = 7;
  for (int r = 0; r < 2000; ++r) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    csv += (state >> 63) ? "1" : "0";
    for (int p = 0; p < 26; ++p) csv += ((state >> (20 + p)) & 1U) ? ",1" : ",0";
    csv += "\n";
  }
  const auto data = file("wide.csv", csv);
  const auto model = path("m.json");
  const auto fitted = run("fit --data " + data.string() + " --edges \"" + edges + "\" --out " + model.string());
  ASSERT_EQ(fitted.code, 0) << fitted.err;
  const auto shown = run("show " + model.string() + " --variable y");
  EXPECT_THAT(shown.out, HasSubstr("P(y | p0, p1,"));
  EXPECT_THAT(shown.out, HasSubstr(", stored sparse: 2000 of 67108864 parent configurations, the rest alike"));
  EXPECT_THAT(shown.out, HasSubstr("any other"));

  const auto bif = path("m.bif");
  const auto refused = run("fit --data " + data.string() + " --edges \"" + edges + "\" --out " + bif.string());
  EXPECT_EQ(refused.code, 1);
  EXPECT_THAT(refused.err, HasSubstr("writing BIF, which has no sparse form (pgm's JSON model has), needs every table "
                                     "dense, and the table of 'y', stored sparse (2000 of 67108864 parent "
                                     "configurations), would have 134217728 cells"));
  EXPECT_FALSE(std::filesystem::exists(bif));

  const auto exact = run("query --model " + model.string() + " --query y --engine ve");
  EXPECT_EQ(exact.code, 1);
  EXPECT_THAT(exact.err, HasSubstr("the table of 'y' with the evidence entered still has 134217728 cells, more than "
                                   "pgm's limit of 16777216 (docs/limits.md): observe more of its parents, or use "
                                   "the sampling engines (lw, gibbs)"));
  // Every parent observed: P(y | u) is a lookup of u's column (the first row's configuration,
  // stored, whose y is its only value seen: MLE gives it probability 1).
  const auto row = csv.find('\n') + 1;
  std::string first_row;
  for (std::size_t p = 0; p < 26; ++p) {
    first_row += (p ? ",p" : "p") + std::to_string(p) + "=" + csv[row + 2 + 2 * p];
  }
  const auto lookup =
      run("query --model " + model.string() + " --query y --engine ve --digits 17 --evidence " + first_row);
  ASSERT_EQ(lookup.code, 0) << lookup.err;
  EXPECT_THAT(lookup.out, HasSubstr(std::string("\n") + csv[row] + ",1\n"));
  const auto sampled = run("query --model " + model.string() + " --query y --evidence p0=1 --engine lw");
  ASSERT_EQ(sampled.code, 0) << sampled.err;
  EXPECT_THAT(sampled.out, HasSubstr("y,"));
}

TEST_F(limits_cli_test, number_options_refuse_what_is_not_plainly_a_number) {
  const auto model = file("m.bif", R"(network n { }
variable a { type discrete [ 2 ] { 0, 1 }; }
probability ( a ) { table 0.2, 0.8; }
)");
  const auto data = file("d.csv", "a,b\n0,1\n1,0\n0,0\n1,1\n");
  const auto fit = "fit --data " + data.string() + " --edges \"a->b\" --estimator bayes --prior dirichlet --out " +
                   path("f.bif").string() + " --alpha ";
  expect_failure(fit + "nan", "--alpha: must be a number >= 0, got 'nan' (NaN is not accepted)", path("f.bif"));
  expect_failure(fit + "1e400", "got '1e400' (out of the range of a double", path("f.bif"));
  expect_failure(fit + "0x1p-3", "got '0x1p-3' (hexadecimal is not accepted", path("f.bif"));
  expect_failure(fit + "1,5", "got '1,5' (a comma is no decimal mark: write 1.5)", path("f.bif"));
  expect_failure(fit + "-1", "--alpha: must be a number >= 0, got '-1'", path("f.bif"));
  const auto minus_zero = run(fit + "-0");  // -0 is 0: the maximum-likelihood table
  ASSERT_EQ(minus_zero.code, 0) << minus_zero.err;
  EXPECT_DOUBLE_EQ(read_network(path("f.bif")).table("b").probability("1", {"0"}), 0.5);

  const auto learn = "learn-structure --data " + data.string() + " --out " + path("s.json").string() + " --alpha ";
  expect_failure(learn + "nan", "--alpha: must be a number > 0 and < 1, got 'nan' (NaN is not accepted)",
                 path("s.json"));
  expect_failure(learn + "1", "--alpha: must be a number > 0 and < 1, got '1'", path("s.json"));
  expect_failure(learn + "0,05", "got '0,05' (a comma is no decimal mark: write 0.05)", path("s.json"));

  const auto prevent = "prevent --model " + model.string() + " --assign a=0 --success a=1 --controllable a --epsilon ";
  expect_failure(prevent + "nan", "--epsilon: expected a number in [0, 1), got 'nan'");
  expect_failure(prevent + "0x1p-1", "got '0x1p-1' (hexadecimal is not accepted");
  expect_failure(prevent + "1", "expected a number in [0, 1), got 1");

  const auto simulate = "simulate --task 1-stack --out " + path("s.csv").string() + " --rows ";
  expect_failure(simulate + "1e3", "expected a whole number from 1 to 1000000000 (digits only), got '1e3'",
                 path("s.csv"));
  expect_failure(simulate + "1,000",
                 "got '1,000' (neither thousands separators nor a decimal comma are accepted: write 1000 or 1.000)",
                 path("s.csv"));
  expect_failure(simulate + "10 --seed -0",
                 "expected a whole number from 0 to 18446744073709551615 (digits only), "
                 "got '-0'",
                 path("s.csv"));
  expect_failure(simulate + "0x10", "got '0x10' (hexadecimal is not accepted", path("s.csv"));
}

// Issue #49: counts and seeds that would wrap, and numbers past what a computation can hold, are
// refused naming the option and its range, or answered.
TEST_F(limits_cli_test, counts_and_seeds_do_not_wrap_and_extreme_numbers_are_answered_or_refused) {
  const auto model = file("m.bif", R"(network n { }
variable a { type discrete [ 2 ] { 0, 1 }; }
variable b { type discrete [ 2 ] { 0, 1 }; }
probability ( a ) { table 0.2, 0.8; }
probability ( b | a ) { (0) 0.3, 0.7; (1) 0.6, 0.4; }
)");
  const auto data = file("d.csv", "a,b\n0,1\n1,0\n0,0\n1,1\n1,1\n");
  const auto query = "query --model " + model.string() + " --query a --evidence b=1 --engine gibbs ";
  for (const char* option : {"--seed", "--burn-in", "--samples", "--threads"}) {
    const auto wrapped = run(query + option + " -1");
    EXPECT_EQ(wrapped.code, 2) << option;
    EXPECT_THAT(wrapped.err, HasSubstr(std::string(option) + ": expected a whole number from")) << option;
  }
  const auto beyond = run(query + "--seed 18446744073709551616");
  EXPECT_EQ(beyond.code, 2);
  EXPECT_THAT(beyond.err, HasSubstr("expected a whole number from 0 to 18446744073709551615"));
  const auto largest = run(query + "--seed 18446744073709551615 --samples 100");
  EXPECT_EQ(largest.code, 0) << largest.err;
  for (const auto& command : {"sample --model " + model.string() + " --rows 5 --out " + path("r.csv").string(),
                              "learn-structure --data " + data.string() + " --out " + path("s.json").string()}) {
    const auto r = run(command + " --seed -1");
    EXPECT_EQ(r.code, 2) << command;
    EXPECT_THAT(r.err, HasSubstr("--seed: expected a whole number from 0 to 18446744073709551615")) << command;
  }
  // BDeu with an imaginary sample size near a double's largest: its limit, the uniform table's
  // likelihood, 5 ln(1/2) + 5 ln(1/2) for the empty network.
  const auto score = run("score --model " + model.string() + " --data " + data.string() + " --score bdeu --iss 1e306");
  ASSERT_EQ(score.code, 0) << score.err;
  EXPECT_THAT(score.out, Not(HasSubstr("nan")));
  EXPECT_THAT(score.out, Not(HasSubstr("inf")));
  const auto weight = run("learn-structure --data " + data.string() + " --out " + path("w.json").string() +
                          " --algorithm hc --prior " + model.string() + " --prior-weight 1e308");
  EXPECT_EQ(weight.code, 2);
  EXPECT_THAT(weight.err, HasSubstr("--prior-weight: expected a number in [0, 1e+12], got 1e308"));
  EXPECT_FALSE(std::filesystem::exists(path("w.json")));
}

// Issue #49: a name that stands for nothing is refused, not silently kept.
TEST_F(limits_cli_test, a_latent_or_mapped_name_that_stands_for_nothing_is_refused) {
  const auto data = file("d.csv", "a,b\n0,1\n1,0\n0,0\n1,1\n1,1\n");
  const auto out = path("f.json");
  expect_failure("fit --data " + data.string() + " --edges \"a->b\" --missing em --latent Hq:2 --out " + out.string(),
                 "the latent variable 'Hq' is in no edge", out);
  const auto prior = file("p.json", R"({"format": "pgm-model", "version": 1,
    "variables": [{"name": "a", "states": ["0", "1"]}, {"name": "b", "states": ["0", "1"]}], "edges": [["a", "b"]]})");
  const auto learn = "learn-structure --data " + data.string() + " --algorithm hc --prior-model " + prior.string() +
                     " --out " + path("s.json").string() + " --map ";
  expect_failure(learn + "zGhost=a", "the map's transferred node 'zGhost' is not a variable of the data",
                 path("s.json"));
  expect_failure(learn + "a=zGhost", "the map names 'zGhost', which is not a variable of", path("s.json"));
  const auto fine = run(learn + "b=b");
  EXPECT_EQ(fine.code, 0) << fine.err;
}

// Issue #49: a small compressed model whose table runs far past its declared size is refused
// in memory in proportion to its text (once for the text, once more for XML's parser), not
// to the values it lists (the BIF reader held 52 million of them, JSON a document of 16 bytes
// a value, twice).
TEST_F(limits_cli_test, a_compressed_model_that_lists_too_many_values_is_refused_in_proportion_to_its_text) {
  const std::string values = "0.5 ";
  const auto inflated = 40 * mib;
  std::string row_of_zeros;  // rows of 2^15 values: past the limit of a file's values, not an array's
  for (int k = 0; k < (1 << 15) - 1; ++k) row_of_zeros += "0,";
  row_of_zeros += "0],[";
  struct model {
    std::string name, head, piece, tail, message;
  };
  const std::vector<model> models{
      {"m.bif", "network n { }\nvariable a { type discrete [ 2 ] { x, y }; }\nprobability ( a ) {\n  table ", "0.5, ",
       "0.5;\n}\n", "expected 2 probabilities for 'a', found "},
      {"m.xml",
       "<?xml version=\"1.0\"?>\n<BIF VERSION=\"0.3\"><NETWORK><NAME>n</NAME><VARIABLE TYPE=\"nature\"><NAME>a</NAME>"
       "<OUTCOME>x</OUTCOME><OUTCOME>y</OUTCOME></VARIABLE><DEFINITION><FOR>a</FOR><TABLE>",
       values, "0.5</TABLE></DEFINITION></NETWORK></BIF>\n",
       "expected 2 probabilities for 'a' (2 states × 1 parent configurations), found "},
      {"m.net", "net {}\nnode a { states = (\"x\" \"y\"); }\npotential (a) { data = (", values, ");}\n",
       "expected 2 probabilities for 'a' (2 states × 1 parent configurations), found "},
      {"m.json",
       R"({"format": "pgm-model", "version": 1, "variables": [{"name": "a", "states": ["x", "y"]}], "edges": [],)"
       R"( "tables": [{"variable": "a", "parents": [], "values": [[)",
       "0,", "0]]}]}\n", "an array of more than 16777216 values, pgm's limit of cells per table"},
      {"many.json",
       R"({"format": "pgm-model", "version": 1, "variables": [{"name": "a", "states": ["x", "y"]}], "edges": [],)"
       R"( "tables": [{"variable": "a", "parents": [], "values": [[)",
       row_of_zeros, "0]]}]}\n", "more than 33554432 values, pgm's limit of a JSON file"}};
  const auto small = run("show " + std::string(PGM_NETWORKS_DIR) + "/asia.bif");
  ASSERT_EQ(small.code, 0) << small.err;
  for (const auto& m : models) {
    const auto at = path(m.name + ".gz");
    const auto bytes = m.name == "many.json" ? 70 * mib : m.name == "m.json" ? 48 * mib : inflated;
    write_gzip(at, m.head, m.piece, bytes, m.tail);
    EXPECT_LT(std::filesystem::file_size(at), bytes / 100) << m.name;
    const auto r = run("show " + at.string());
    EXPECT_EQ(r.code, 1) << m.name;
    EXPECT_THAT(r.err, HasSubstr(m.message)) << m.name;
    if (measures_memory) {
      const auto text_kib = static_cast<long>(bytes / 1024);
      EXPECT_LT(r.peak_kib, small.peak_kib + text_kib * 5 / 2) << m.name << ": " << r.err;
    }
  }
}

// Issue #49: a long --queries file is answered one query at a time, and its answers spooled to
// a temporary file until all are made (it held every query and every answer: 1.7 GB for 34 MB).
TEST_F(limits_cli_test, a_long_query_file_is_answered_in_memory_that_does_not_grow_with_it) {
  const std::string asia = std::string(PGM_NETWORKS_DIR) + "/asia.bif";
  std::string text = "query,evidence\n";
  const std::vector<std::string> lines{"either,smoke=yes\n", "\"lung,tub\",\"asia=no,xray=yes\"\n", "dysp,\n"};
  std::size_t queries = 0;
  for (; text.size() < 3 * mib; ++queries) text += lines[queries % lines.size()];
  const auto few = file("few.csv", "query,evidence\n" + lines[0]);
  const auto many = file("many.csv", text);
  const auto one = run("query --model " + asia + " --queries " + few.string());
  ASSERT_EQ(one.code, 0) << one.err;
  const auto all = run("query --model " + asia + " --queries " + many.string());
  ASSERT_EQ(all.code, 0) << all.err;
  EXPECT_EQ(static_cast<std::size_t>(std::count(all.out.begin(), all.out.end(), '\n')), queries + 1);
  const auto to_file =
      run("query --model " + asia + " --queries " + many.string() + " --out " + path("a.csv").string());
  ASSERT_EQ(to_file.code, 0) << to_file.err;
  EXPECT_EQ(slurp(path("a.csv")), all.out);
  if (measures_memory) {
    EXPECT_LT(all.peak_kib, one.peak_kib + 2 * static_cast<long>(text.size() / 1024));
  }

  // A bad record at the end: nothing is printed, and no file is written.
  const auto bad = file("bad.csv", text + "nosuch,\n");
  const auto r = run("query --model " + asia + " --queries " + bad.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr(":" + std::to_string(queries + 2) + ":1: "));
  EXPECT_EQ(r.out, "");
  expect_failure("query --model " + asia + " --queries " + bad.string() + " --out " + path("b.csv").string(), "nosuch",
                 path("b.csv"));
}

// Issue #49: a latent variable of a million states ran EM for minutes in 1.75 GB.
TEST_F(limits_cli_test, a_latent_variable_has_at_most_a_thousand_states) {
  const auto data = file("d.csv", "a,b\n0,1\n1,0\n0,0\n1,1\n1,1\n");
  const auto out = path("f.json");
  const auto fit = "fit --data " + data.string() + " --edges \"H->a,H->b\" --missing em --out " + out.string();
  expect_failure(fit + " --latent H:999999",
                 "the latent variable 'H' has 999999 states, more than pgm's limit of 1000 for a latent variable", out);
  const auto r = run(fit + " --latent H:1000 --max-iterations 2");
  EXPECT_EQ(r.code, 0) << r.err;
}

// A model path that is a device without end is refused at pgm's limit of a file read whole,
// not read until memory runs out (issue 28).
TEST_F(limits_cli_test, a_model_that_never_ends_is_refused_at_the_file_limit) {
  std::filesystem::create_symlink("/dev/zero", path("zero.bif"));
  std::filesystem::create_symlink("/dev/zero", path("zero.json"));
  for (const auto& model : {path("zero.bif"), path("zero.json")}) {
    expect_failure("show " + model.string(),
                   "cannot read '" + model.string() +
                       "': it is larger than 256 MiB, pgm's limit of a file it reads whole (models, tasks, scenarios; "
                       "docs/limits.md)");
  }
}

}  // namespace
}  // namespace pgm::limits_cli_tests
