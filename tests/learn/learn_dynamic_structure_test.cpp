// Structure learning for a dynamic network (pgm/learn/learn_dynamic_structure.hpp): no edge ever
// points into the previous slice, whatever the learner; hill climbing on many episodes of a
// 2-TBN with strong dependencies finds its edges within and between slices.

#include "pgm/learn/learn_dynamic_structure.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "pgm/io/csv.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/learn/structure_learner_registry.hpp"
#include "support/long_form.hpp"
#include "support/program_test.hpp"
#include "support/random_dynamic_network.hpp"

namespace pgm {
namespace learn_dynamic_structure_test {

using ::testing::Contains;
using ::testing::Not;

std::vector<std::string> names_of(const dynamic_network& model) {
  std::vector<std::string> names;
  for (const auto& v : model.variables()) names.push_back(v.name());
  return names;
}

TEST(learn_dynamic_structure_test, no_learner_points_an_edge_into_the_previous_slice) {
  for (const std::string learner : {"hc", "tabu", "pc"}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const auto model = testing::random_dynamic(seed, 3 + seed % 2);
      const auto data = testing::sample_long_form(model, 200, 6, seed);
      const auto names = names_of(model);
      const auto result = learn_dynamic_structure(data.data, names, make_structure_learner(learner));
      for (const auto& edge : result.learned.edges) {
        EXPECT_EQ(edge.to.find('@'), std::string::npos) << learner << " " << edge.from << "->" << edge.to;
      }
      EXPECT_EQ(result.structure.variables().size(), names.size());
      // Every learned edge is in the structure, within a slice in both slices.
      for (const auto& edge : result.learned.edges) {
        EXPECT_TRUE(result.structure.transition.graph().has_edge(result.structure.transition.id(edge.from),
                                                                 result.structure.transition.id(edge.to)));
        if (edge.from.find('@') == std::string::npos) {
          EXPECT_THAT(result.structure.initial.edges(), Contains(named_edge{edge.from, edge.to}));
        }
      }
    }
  }
}

/// a persists from step to step (a@-1 -> a), b copies a (a -> b), c is noise.
dynamic_network persisting_chain() {
  const variable a("a", {"0", "1"});
  const variable b("b", {"0", "1"});
  const variable c("c", {"0", "1"});
  network_structure first_structure({a, b, c}, {{"a", "b"}});
  const bayesian_network first(
      first_structure,
      {cpt<double>(a, {}, {0.5, 0.5}), cpt<double>(b, {a}, {0.95, 0.05, 0.05, 0.95}), cpt<double>(c, {}, {0.5, 0.5})});
  const auto a_before = detail::renamed(a, "a@-1");
  const dynamic_network model(first, {cpt<double>(a, {a_before}, {0.9, 0.1, 0.1, 0.9}),
                                      cpt<double>(b, {a}, {0.95, 0.05, 0.05, 0.95}), cpt<double>(c, {}, {0.5, 0.5})});
  return model;
}

TEST(learn_dynamic_structure_test, hill_climbing_finds_a_strong_chain_through_time) {
  const auto data = testing::sample_long_form(persisting_chain(), 500, 10, 4);
  const std::vector<std::string> names{"a", "b", "c"};
  const auto result = learn_dynamic_structure(data.data, names, make_structure_learner("hc"));
  const auto& edges = result.learned.edges;
  EXPECT_THAT(edges, Contains(named_edge{"a@-1", "a"}));
  EXPECT_TRUE(std::count(edges.begin(), edges.end(), named_edge{"a", "b"}) +
                  std::count(edges.begin(), edges.end(), named_edge{"b", "a"}) ==
              1);
  for (const auto& edge : edges) {
    EXPECT_NE(edge.from, "c");
    EXPECT_NE(edge.to, "c");
  }
  EXPECT_THAT(edges, Not(Contains(named_edge{"b@-1", "b"})));  // b depends on the past only through a
}

using learn_dynamic_structure_cli_test = pgm::testing::program_test;

// pgm learn-structure --dynamic prints the learned edges as --edges reads them and writes the
// model fit_dynamic gives with them; what it does not take is refused, nothing written.
TEST_F(learn_dynamic_structure_cli_test, prints_the_edges_and_writes_the_fitted_model) {
  std::ostringstream csv;
  write_csv(testing::sample_long_form(persisting_chain(), 500, 10, 4, true).data, csv);
  const auto data = file("chain.csv", csv.str());
  const auto r =
      run("learn-structure --dynamic --algorithm hc --data " + data.string() + " --out " + path("chain.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("from 500 episodes"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("--edges \"a@-1->a, a->b\""));
  const auto read = read_csv(data, long_form_options());
  // Every column besides the episode's and the step's is a template variable, c too.
  const auto structure = dynamic_structure_of(
      {read.discrete("a").var(), read.discrete("b").var(), read.discrete("c").var()}, parse_edge_list("a@-1->a, a->b"));
  const auto written = parse_dynamic_json(slurp(path("chain.json")), "chain.json");
  EXPECT_EQ(written, fit_dynamic(structure, read));
  expect_failure(
      "learn-structure --dynamic --bootstrap 5 --data " + data.string() + " --out " + path("no.json").string(),
      "--dynamic: --bootstrap is not available", path("no.json"));
}

}  // namespace learn_dynamic_structure_test
}  // namespace pgm
