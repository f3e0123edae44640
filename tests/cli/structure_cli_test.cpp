// pgm score and the score searches of pgm learn-structure, as a user meets them.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "pgm/core/file.hpp"
#include "pgm/io/json_model.hpp"
#include "support/program_test.hpp"

namespace pgm::structure_cli_tests {
namespace {

using ::testing::HasSubstr;

using structure_cli_test = pgm::testing::program_test;

// The number printed right after `label`.
double number_after(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  EXPECT_NE(at, std::string::npos) << label;
  return at == std::string::npos ? std::nan("") : std::stod(text.substr(at + label.size()));
}

// b follows a: (0,0) (0,1) (1,1) (1,1).
constexpr const char* tiny = "a,b\n0,0\n0,1\n1,1\n1,1\n";

TEST_F(structure_cli_test, score_prints_the_total_and_each_node) {
  const auto data = file("d.csv", tiny);
  ASSERT_EQ(run("fit --data " + data.string() + " --edges \"a->b\" --out " + path("m.bif").string()).code, 0);
  const auto r = run("score --model " + path("m.bif").string() + " --data " + data.string());
  ASSERT_EQ(r.code, 0) << r.err;
  // loglik 4 log(1/2) + 2 log(1/2); 1 + 2 free parameters at log(4)/2 each: -9 log 2.
  EXPECT_THAT(r.out, HasSubstr("bic of " + path("m.bif").string() + " on 4 rows: "));
  EXPECT_NEAR(number_after(r.out, "rows: "), 6 * std::log(0.5) - 1.5 * std::log(4.0), 1e-12);
  EXPECT_NEAR(number_after(r.out, "  a     "), 4 * std::log(0.5) - std::log(4.0) / 2, 1e-12);
  EXPECT_NEAR(number_after(r.out, "  b     "), 2 * std::log(0.5) - std::log(4.0), 1e-12);
  const auto k2 = run("score --model " + path("m.bif").string() + " --data " + data.string() + " --score k2");
  ASSERT_EQ(k2.code, 0) << k2.err;
  // a: 1!/5! 2!2! = 1/30; b | a=0: 1/3! = 1/6, b | a=1: 2!/3! = 1/3.
  EXPECT_NEAR(number_after(k2.out, "rows: "), std::log(1.0 / 30) + std::log(1.0 / 18), 1e-12);
}

TEST_F(structure_cli_test, score_bad_input) {
  const auto data = file("d.csv", tiny);
  ASSERT_EQ(run("fit --data " + data.string() + " --edges \"a->b\" --out " + path("m.bif").string()).code, 0);
  const auto help = run("score --help");
  EXPECT_EQ(help.code, 0);
  for (const char* option : {"--model", "--data", "--score", "--iss", "--threads", "--missing"}) {
    EXPECT_THAT(help.out, HasSubstr(option));
  }
  const auto model = " --model " + path("m.bif").string();
  EXPECT_THAT(help.out, HasSubstr("aic[k=1], bdeu[iss=1], bic, k2, loglik"));
  const auto scored = [&](const std::string& options) {
    return run("score" + model + " --data " + data.string() + " " + options);
  };
  EXPECT_THAT(scored("--score mdl").err, HasSubstr("--score: unknown score 'mdl' (known: aic, bdeu, bic, k2, loglik)"));
  EXPECT_THAT(scored("--score 'bdeu[iss=0]'").err,
              HasSubstr("option iss of the score 'bdeu' must be a number > 0, got '0'"));
  EXPECT_THAT(scored("--score 'bdeu[iss=1'").err, HasSubstr("expected ']' at column 11"));
  EXPECT_THAT(scored("--iss 0").err, HasSubstr("expected a finite number > 0"));
  EXPECT_THAT(scored("--iss 2").err, HasSubstr("--iss: sets the option iss, which the score bic has not"));
  EXPECT_THAT(scored("--score 'bdeu[iss=2]' --iss 3").err,
              HasSubstr("--iss: sets iss, which 'bdeu[iss=2]' sets already; give it once"));
  // The shorthand and the brackets choose the same score.
  const auto shorthand = scored("--score bde --iss 7");
  EXPECT_EQ(shorthand.code, 0) << shorthand.err;
  EXPECT_THAT(shorthand.out, HasSubstr("bdeu (iss 7) of"));
  EXPECT_EQ(shorthand.out, scored("--score 'bdeu[iss=7]'").out);
  const auto other = file("o.csv", "a,c\n0,1\n");
  const auto missing = run("score" + model + " --data " + other.string());
  EXPECT_EQ(missing.code, 1);
  EXPECT_THAT(missing.err, HasSubstr("there is no column 'b'"));
  const auto unseen = file("u.csv", "a,b\n0,2\n");
  EXPECT_NE(run("score" + model + " --data " + unseen.string()).code, 0);
  EXPECT_NE(run("score --data " + data.string()).code, 0);
}

// c depends on a and b, which are independent: a v-structure a -> c <- b.
std::string v_structure() {
  std::string csv = "a,b,c\n";
  std::uint64_t state = 99;
  for (int i = 0; i < 4000; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const int a = static_cast<int>((state >> 33) % 2);
    const int b = static_cast<int>((state >> 40) % 2);
    const double u = static_cast<double>((state >> 11) & 0xFFFFF) / 1048576.0;
    csv += std::to_string(a) + "," + std::to_string(b) + "," + ((u < 0.1 + 0.4 * a + 0.4 * b) ? "1" : "0") + "\n";
  }
  return csv;
}

TEST_F(structure_cli_test, learn_structure_by_score) {
  const auto data = file("v.csv", v_structure());
  for (const std::string algorithm : {"hc", "tabu", "mmhc"}) {
    const auto out = path(algorithm + ".json");
    const auto r = run("learn-structure --algorithm " + algorithm + " --data " + data.string() + " --out " +
                       out.string() + " --threads 1");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("edges (2):\n  a -> c\n  b -> c\n")) << algorithm;
    const auto model = read_model_json(out);
    EXPECT_EQ(model.structure.edges(), (std::vector<named_edge>{{"a", "c"}, {"b", "c"}}));
    // The same on two threads, with restarts.
    const auto two = run("learn-structure --algorithm " + algorithm + " --restarts 3 --perturb 2 --seed 5 --data " +
                         data.string() + " --out " + path("two.json").string() + " --threads 2");
    const auto one = run("learn-structure --algorithm " + algorithm + " --restarts 3 --perturb 2 --seed 5 --data " +
                         data.string() + " --out " + path("one.json").string() + " --threads 1");
    ASSERT_EQ(two.code, 0) << two.err;
    EXPECT_EQ(pgm::read_file(path("two.json")), pgm::read_file(path("one.json")));
  }
  // The score printed is what pgm score says of the learned structure.
  const auto hc = run("learn-structure --algorithm hc --score bdeu --iss 10 --data " + data.string() + " --out " +
                      path("b.json").string());
  ASSERT_EQ(hc.code, 0) << hc.err;
  const auto score = run("score --score bdeu --iss 10 --model " + path("b.json").string() + " --data " + data.string());
  ASSERT_EQ(score.code, 0) << score.err;
  const auto value =
      score.out.substr(score.out.find("rows: ") + 6, score.out.find('\n') - score.out.find("rows: ") - 6);
  EXPECT_THAT(hc.out, HasSubstr("bdeu (iss 10) = " + value + " after"));
  // Starting from the reversed network, the search finds its way to the v-structure.
  ASSERT_EQ(run("learn-structure --algorithm hc --data " + data.string() + " --max-parents 1 --out " +
                path("one_parent.json").string())
                .code,
            0);
  const auto started = run("learn-structure --algorithm hc --start " + path("one_parent.json").string() + " --data " +
                           data.string() + " --out " + path("s.json").string());
  ASSERT_EQ(started.code, 0) << started.err;
  EXPECT_THAT(started.out, HasSubstr("edges (2):\n  a -> c\n  b -> c\n"));
}

TEST_F(structure_cli_test, learn_structure_by_score_bad_input) {
  const auto data = file("v.csv", v_structure());
  const auto help = run("learn-structure --help");
  for (const char* option : {"--algorithm", "--score", "--iss", "--max-parents", "--tabu", "--max-tabu", "--restarts",
                             "--perturb", "--seed", "--start"}) {
    EXPECT_THAT(help.out, HasSubstr(option));
  }
  const auto base = "learn-structure --data " + data.string() + " --out " + path("x.json").string();
  EXPECT_THAT(run(base + " --algorithm ges").err, HasSubstr("--algorithm: unknown structure learner 'ges'"));
  const auto pc_start = run(base + " --start " + path("nope.json").string());
  EXPECT_EQ(pc_start.code, 1);
  EXPECT_THAT(pc_start.err, HasSubstr("--start applies to hc, mmhc and tabu, not pc"));
  // The options set the learner's own: refused where the learner has none.
  const auto alpha = run(base + " --algorithm hc --alpha 0.05");
  EXPECT_EQ(alpha.code, 2);
  EXPECT_THAT(alpha.err, HasSubstr("--alpha: sets the option alpha, which the structure learner hc has not"));
  EXPECT_THAT(
      run(base + " --algorithm 'tabu[tabu=0]'").err,
      HasSubstr("option tabu of the structure learner 'tabu' must be a whole number from 1 to 100000, got '0'"));
  EXPECT_THAT(run(base + " --algorithm 'tabu[tabu=3]' --tabu 4").err,
              HasSubstr("--tabu: sets tabu, which 'tabu[tabu=3]' sets already"));
  EXPECT_THAT(run(base + " --algorithm tabu --tabu 0").err,
              HasSubstr("--tabu: must be a whole number from 1 to 100000, got '0'"));
  const auto forbidden = run(base + " --algorithm hc --forbid \"a->c,b->c,c->a,c->b\"");
  ASSERT_EQ(forbidden.code, 0) << forbidden.err;
  EXPECT_THAT(forbidden.out, HasSubstr("edges (0)"));
  const auto required = run(base + " --algorithm hc --require \"a->b\" --max-parents 1");
  ASSERT_EQ(required.code, 0) << required.err;
  EXPECT_THAT(required.out, HasSubstr("  a -> b\n"));
  const auto cyclic = file("cyclic.json", "");
  EXPECT_NE(run(base + " --algorithm hc --start " + cyclic.string()).code, 0);
  EXPECT_NE(run(base + " --algorithm hc --iss -1").code, 0);
}

TEST_F(structure_cli_test, learn_structure_takes_a_learner_with_its_options) {
  const auto data = file("v.csv", v_structure());
  const auto base = "learn-structure --data " + data.string();
  const auto learned = [&](const std::string& arguments) {
    const auto r = run(base + " " + arguments + " --out " + path("l.json").string());
    EXPECT_EQ(r.code, 0) << arguments << ": " << r.err;
    return pgm::read_file(path("l.json"));
  };
  // The shorthands and the brackets choose the same learner.
  EXPECT_EQ(learned("--algorithm hc --start pc --alpha 0.05"), learned("--algorithm 'hc[start=pc[alpha=0.05]]'"));
  EXPECT_EQ(learned("--algorithm tabu --tabu 3 --score bdeu --iss 4"),
            learned("--algorithm 'tabu[tabu=3,score=bdeu[iss=4]]'"));
  EXPECT_EQ(learned("--algorithm mmhc --test g2 --max-cond 1"),
            learned("--algorithm 'mmhc[test=g2,max_conditioning=1]'"));
  EXPECT_EQ(learned("--algorithm hc --max-parents 0"), learned("--algorithm hc"));
  const auto empty = run(base + " --algorithm empty --require 'a->c' --out " + path("e.json").string());
  ASSERT_EQ(empty.code, 0) << empty.err;
  EXPECT_THAT(empty.out, HasSubstr("empty on "));
  EXPECT_THAT(empty.out, HasSubstr("edges (1):\n  a -> c\n"));
}

TEST_F(structure_cli_test, learn_structure_bootstrap) {
  const auto data = file("v.csv", v_structure());
  const auto base = "learn-structure --algorithm hc --data " + data.string() + " --bootstrap 8 --seed 2 --out ";
  const auto r = run(base + path("b.json").string() + " --threads 2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("hc on 8 bootstrap resamples of 4000 rows, 3 variables"));
  EXPECT_THAT(r.out, HasSubstr("  a -> c  strength 1  direction 1\n"));
  EXPECT_THAT(r.out, HasSubstr("(bnlearn's L1 rule) (2 edges):\n  a -> c\n  b -> c\n"));
  EXPECT_THAT(pgm::read_file(path("b.json")), HasSubstr("\"bootstrap\": 8"));
  ASSERT_EQ(run(base + path("one.json").string() + " --threads 1").code, 0);
  EXPECT_EQ(pgm::read_file(path("one.json")), pgm::read_file(path("b.json")));
  const auto fixed = run(base + path("t.json").string() + " --threshold 0.99");
  ASSERT_EQ(fixed.code, 0) << fixed.err;
  EXPECT_THAT(fixed.out, HasSubstr("averaged network at threshold 0.99 (2 edges)"));
  const auto alone =
      run("learn-structure --data " + data.string() + " --threshold 0.5 --out " + path("x.json").string());
  EXPECT_EQ(alone.code, 1);
  EXPECT_THAT(alone.err, HasSubstr("--threshold applies with --bootstrap"));
  EXPECT_NE(run(base + path("y.json").string() + " --threshold 1.5").code, 0);
}

TEST_F(structure_cli_test, learn_structure_with_a_structure_prior_and_from_pc) {
  const auto data = file("v.csv", v_structure());
  // The prior task's network over other names: x -> z <- y, mapped to a, b, c.
  const auto prior_data = file("p.csv", "x,y,z\n0,0,0\n1,1,1\n0,1,1\n1,0,1\n");
  ASSERT_EQ(
      run("fit --data " + prior_data.string() + " --edges \"x->z,y->z\" --out " + path("prior.bif").string()).code, 0);
  const auto base = "learn-structure --algorithm hc --data " + data.string() + " --prior-model " +
                    path("prior.bif").string() + " --map \"c=z,a==x,b==y\" --out " + path("s.json").string();
  const auto r = run(base + " --prior-weight 2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("the structure prior favours 2 edge(s) by 2 each: a->c, b->c"));
  EXPECT_THAT(r.out, HasSubstr(" + structure prior 4 = "));
  EXPECT_THAT(r.out, HasSubstr("edges (2):\n  a -> c\n  b -> c\n"));
  // A weight beyond any penalty keeps the prior's edges even against the data: here, reversed.
  const auto reversed = file("r.csv", "x,y,z\n0,0,0\n1,1,1\n");
  ASSERT_EQ(run("fit --data " + reversed.string() + " --edges \"z->x,z->y\" --out " + path("rev.bif").string()).code,
            0);
  const auto forced =
      run("learn-structure --algorithm hc --data " + data.string() + " --prior-model " + path("rev.bif").string() +
          " --map \"c=z,a==x,b==y\" --prior-weight 1e6 --out " + path("f.json").string());
  ASSERT_EQ(forced.code, 0) << forced.err;
  EXPECT_THAT(forced.out, HasSubstr("  c -> a\n  c -> b\n"));
  EXPECT_THAT(run("learn-structure --data " + data.string() + " --map a==x --out " + path("m.json").string()).err,
              HasSubstr("--map applies with --prior-model"));
  EXPECT_THAT(run("learn-structure --data " + data.string() + " --prior-model " + path("prior.bif").string() +
                  " --out " + path("m.json").string())
                  .err,
              HasSubstr("--prior-model applies to hc, mmhc and tabu, not pc"));
  // From PC's result.
  const auto from_pc =
      run("learn-structure --algorithm hc --start pc --data " + data.string() + " --out " + path("pc.json").string());
  ASSERT_EQ(from_pc.code, 0) << from_pc.err;
  EXPECT_THAT(from_pc.out, HasSubstr("edges (2):\n  a -> c\n  b -> c\n"));
}

}  // namespace
}  // namespace pgm::structure_cli_tests
