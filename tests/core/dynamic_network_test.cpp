// Dynamic networks (pgm/core/dynamic_network.hpp): unrolled over T slices against a forward
// computation by hand, what a malformed 2-TBN is refused for, pgm's JSON of one (a round trip,
// the errors' paths), and `pgm unroll`.

#include "pgm/core/dynamic_network.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "pgm/inference/inference_engine.hpp"
#include "pgm/inference/variable_elimination.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "support/program_test.hpp"

namespace pgm {
namespace dynamic_network_test {

using ::testing::HasSubstr;

const variable a("a", {"off", "on"});
const variable b("b", {"low", "mid", "high"});
const variable a_before("a@-1", {"off", "on"});
const variable b_before("b@-1", {"low", "mid", "high"});

// The first slice: a → b. The transition: a@-1 → a, a → b, b@-1 → b.
bayesian_network first_slice() {
  return bayesian_network::from_tables(
      {cpt<double>(a, {}, {0.3, 0.7}), cpt<double>(b, {a}, {0.5, 0.3, 0.2, 0.1, 0.3, 0.6})});
}

std::vector<cpt<double>> transition_tables() {
  std::vector<double> b_given(2 * 3 * 3);
  for (std::size_t u = 0; u < 6; ++u) {
    const double low = 0.1 + 0.1 * static_cast<double>(u);
    b_given[3 * u] = low;
    b_given[3 * u + 1] = 0.3;
    b_given[3 * u + 2] = 0.7 - low;
  }
  return {cpt<double>(a, {a_before}, {0.9, 0.1, 0.2, 0.8}), cpt<double>(b, {a, b_before}, b_given)};
}

dynamic_network two_slice_network() { return dynamic_network(first_slice(), transition_tables()); }

TEST(dynamic_network_test, unrolls_into_slices_whose_marginals_follow_the_transition) {
  const auto model = two_slice_network();
  const auto unrolled = model.unroll(4);
  ASSERT_EQ(unrolled.size(), 8U);
  EXPECT_EQ(unrolled.variables()[0].name(), "a@0");
  EXPECT_EQ(unrolled.variables()[7].name(), "b@3");
  EXPECT_EQ(unrolled.variables()[7].states(), b.states());
  EXPECT_THAT(unrolled.table("b@2").parents(),
              ::testing::ElementsAre(variable("a@2", a.states()), variable("b@1", b.states())));
  // The first slice's tables at t = 0, the transition's tied ones after.
  EXPECT_EQ(unrolled.table("b@0").probability("high", {"on"}), 0.6);
  EXPECT_EQ(unrolled.table("a@3").probability("on", {"off"}), 0.1);
  EXPECT_EQ(unrolled.table("b@3").probability("low", {"on", "high"}), 0.1 + 0.1 * 5);
  // P(a@t = on) by hand: p ← 0.1 (1 − p) + 0.8 p from p = 0.7.
  variable_elimination engine(unrolled);
  double on = 0.7;
  for (int t = 0; t < 4; ++t) {
    EXPECT_NEAR(marginal(engine, "a@" + std::to_string(t)).probability({"on"}), on, 1e-15) << t;
    on = 0.1 * (1 - on) + 0.8 * on;
  }
  // One slice is the first slice, renamed.
  const auto one = model.unroll(1);
  ASSERT_EQ(one.size(), 2U);
  EXPECT_EQ(one.table("b@0").values()[4], first_slice().table("b").values()[4]);
}

TEST(dynamic_network_test, a_malformed_transition_is_refused_naming_what_is_wrong) {
  const auto with = [](std::vector<cpt<double>> tables) { return dynamic_network(first_slice(), std::move(tables)); };
  auto tables = transition_tables();
  const auto refused = [&](std::vector<cpt<double>> given, const std::string& message) {
    EXPECT_THAT([&] { static_cast<void>(with(std::move(given))); },
                ::testing::ThrowsMessage<model_error>(HasSubstr(message)));
  };
  refused({tables[0]}, "no table for 'b'");
  refused({tables[0], tables[1], tables[1]}, "two tables for 'b'");
  refused({tables[0], tables[1], cpt<double>(variable("c", {"0", "1"}), {})},
          "a table for 'c', which is not a variable of the first slice");
  refused({cpt<double>(a, {variable("a@+1", a.states())}, {0.5, 0.5, 0.5, 0.5}), tables[1]},
          "the parent 'a@+1' of 'a' lies in a later slice");
  refused({cpt<double>(a, {variable("a@-2", a.states())}, {0.5, 0.5, 0.5, 0.5}), tables[1]},
          "lies 2 slices back: pgm's dynamic networks are of order 1");
  refused({cpt<double>(a, {variable("a@x", a.states())}, {0.5, 0.5, 0.5, 0.5}), tables[1]}, "names no slice");
  refused({cpt<double>(a, {variable("z@-1", a.states())}, {0.5, 0.5, 0.5, 0.5}), tables[1]},
          "names no template variable");
  refused({cpt<double>(a, {variable("a@-1", {"0", "1"})}, {0.5, 0.5, 0.5, 0.5}), tables[1]},
          "has other states than 'a' in the first slice");
  // A cycle within a slice: b → a beside a → b.
  refused({cpt<double>(a, {b}, {0.5, 0.5, 0.5, 0.5, 0.5, 0.5}), tables[1]}, "cycle");
  EXPECT_THAT([] { static_cast<void>(two_slice_network().unroll(0)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("at least one slice")));
  EXPECT_THAT([] { static_cast<void>(two_slice_network().unroll(max_unrolled_variables)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("more variables than pgm's limit")));
}

TEST(dynamic_network_test, its_json_reads_back_the_same_and_names_the_path_of_an_error) {
  const auto model = two_slice_network();
  const auto text = to_json(model).dump(2);
  EXPECT_EQ(declared_model_kind(text), "dynamic");
  EXPECT_EQ(parse_dynamic_json(text, "m.json"), model);
  EXPECT_THAT([&] { static_cast<void>(parse_model_json(text, "m.json")); },
              ::testing::ThrowsMessage<data_error>(HasSubstr("pgm unroll makes one of it")));
  auto document = to_json(model);
  document["transition"]["edges"][0] = {"a@+1", "a"};
  EXPECT_THAT([&] { static_cast<void>(parse_dynamic_json(document.dump(), "m.json")); },
              ::testing::ThrowsMessage<data_error>(HasSubstr("m.json: /transition/edges/0: the parent 'a@+1'")));
  document = to_json(model);
  document["transition"]["edges"][0] = {"a", "b@-1"};
  EXPECT_THAT([&] { static_cast<void>(parse_dynamic_json(document.dump(), "m.json")); },
              ::testing::ThrowsMessage<data_error>(HasSubstr("'b@-1' is of another slice")));
  document = to_json(model);
  document["transition"]["tables"].erase(1);
  EXPECT_THAT([&] { static_cast<void>(parse_dynamic_json(document.dump(), "m.json")); },
              ::testing::ThrowsMessage<data_error>(HasSubstr("/transition: the transition has no table for 'b'")));
  document = to_json(model);
  std::reverse(document["transition"]["edges"].begin(), document["transition"]["edges"].end());
  EXPECT_EQ(parse_dynamic_json(document.dump(), "m.json"), model);  // edges in any order
  document["transition"]["edges"].erase(0);
  EXPECT_THAT([&] { static_cast<void>(parse_dynamic_json(document.dump(), "m.json")); },
              ::testing::ThrowsMessage<data_error>(HasSubstr("/transition/edges: the edges differ from the tables'")));
  document = to_json(model);
  document["variables"][0]["name"] = "a@0";
  EXPECT_THAT(
      [&] { static_cast<void>(parse_dynamic_json(document.dump(), "m.json")); },
      ::testing::ThrowsMessage<data_error>(HasSubstr("/variables/0: a template variable's name may not hold '@'")));
  document = to_json(model);
  document["initial"].erase("tables");
  EXPECT_THAT([&] { static_cast<void>(parse_dynamic_json(document.dump(), "m.json")); },
              ::testing::ThrowsMessage<data_error>(HasSubstr("/initial: the first slice needs its tables")));
}

using unroll_cli_test = pgm::testing::program_test;

TEST_F(unroll_cli_test, writes_the_unrolled_network_in_any_format_and_refuses_what_is_not_dynamic) {
  const auto model = file("tower.json", to_json(two_slice_network()).dump(2));
  for (const auto* name : {"t3.json", "t3.xml"}) {
    const auto r = run("unroll --model " + model.string() + " --steps 3 --out " + path(name).string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("unrolled " + model.string() + " over 3 slices"));
    EXPECT_THAT(r.out, HasSubstr("6 variables"));
    EXPECT_EQ(read_network(path(name)), two_slice_network().unroll(3)) << name;
  }
  // BIF's names cannot hold '@': X_t there, and a note says so.
  const auto r = run("unroll --model " + model.string() + " --steps 3 --out " + path("t3.bif").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("named a_0, a_1"));
  EXPECT_EQ(read_network(path("t3.bif")), two_slice_network().unroll(3, '_'));
  EXPECT_EQ(run("unroll --help").code, 0);
  expect_failure("unroll --model " + model.string() + " --steps 0 --out " + path("t0.bif").string(), "--steps",
                 path("t0.bif"));
  const auto static_model = file("s.json", to_json(first_slice()).dump(2));
  expect_failure("unroll --model " + static_model.string() + " --steps 2 --out " + path("s2.bif").string(),
                 "holds a Bayesian network, not a dynamic one", path("s2.bif"));
  expect_failure("show " + model.string(), "pgm unroll makes one of it");
}

TEST_F(unroll_cli_test, the_example_of_docs_dynamic_md_unrolls) {
  const auto page = slurp(std::filesystem::path(PGM_SOURCE_DIR) / "docs" / "dynamic.md");
  const auto begin = page.find("```json\n");
  ASSERT_NE(begin, std::string::npos);
  const auto end = page.find("```", begin + 8);
  const auto model = file("tower.json", page.substr(begin + 8, end - begin - 8));
  const auto r = run("unroll --model " + model.string() + " --steps 3 --out " + path("tower3.bif").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto unrolled = read_network(path("tower3.bif"));
  EXPECT_EQ(unrolled.size(), 6U);
  EXPECT_EQ(unrolled.table("b_2").probability("high", {"on", "low"}), 0.8);
}

}  // namespace dynamic_network_test
}  // namespace pgm
