// Structure learning for a dynamic network (pgm/learn/learn_dynamic_structure.hpp): no edge ever
// points into the previous slice, whatever the learner; hill climbing on many episodes of a
// 2-TBN with strong dependencies finds its edges within and between slices.

#include "pgm/learn/learn_dynamic_structure.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
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

/// The episodes `picked` of `data`, built from its codes: episode k of the result is picked[k].
dataset episodes_by_hand(const testing::long_form& data, const dynamic_network& model,
                         const std::vector<std::size_t>& picked) {
  std::vector<double> episode, step;
  std::vector<std::vector<std::uint32_t>> columns(model.size());
  for (std::size_t k = 0; k < picked.size(); ++k) {
    const auto& steps = data.codes[picked[k]];
    for (std::size_t t = 0; t < steps.size(); ++t) {
      episode.push_back(static_cast<double>(k));
      step.push_back(static_cast<double>(t));
      for (std::size_t i = 0; i < model.size(); ++i) columns[i].push_back(steps[t][i]);
    }
  }
  dataset out("resample.csv");
  out.add(continuous_column("episode", episode));
  out.add(continuous_column("t", step));
  for (std::size_t i = 0; i < model.size(); ++i) out.add(discrete_column(model.variables()[i], columns[i]));
  return out;
}

TEST(learn_dynamic_structure_test, the_bootstrap_resamples_whole_episodes_and_counts_each_arc) {
  const auto model = persisting_chain();
  const auto data = testing::sample_long_form(model, 120, 6, 9);  // episodes in order: k is codes[k]
  const std::vector<std::string> names{"a", "b", "c"};
  const auto learner = make_structure_learner("hc");
  const bootstrap_options options{.replicates = 12, .seed = 5};
  const auto result = bootstrap_dynamic_structure(data.data, names, learner, {.threads = 1}, options);
  // Each replicate again, its episodes drawn as the bootstrap draws them but put together here.
  std::map<std::pair<std::string, std::string>, double> adjacent, forward;
  for (std::size_t r = 0; r < options.replicates; ++r) {
    const auto picked = detail::bootstrap_draw(options.seed, r, data.codes.size());
    const auto learned = learn_dynamic_structure(episodes_by_hand(data, model, picked), names, learner);
    for (const auto& e : learned.learned.edges) {
      forward[{e.from, e.to}] += 1.0;
      adjacent[{e.from, e.to}] += 1.0;
      adjacent[{e.to, e.from}] += 1.0;
    }
  }
  ASSERT_EQ(result.arcs.arcs.size(), 6u * 5u);  // ordered pairs of a@-1, b@-1, c@-1, a, b, c
  for (const auto& arc : result.arcs.arcs) {
    SCOPED_TRACE(arc.from + "->" + arc.to);
    const double together = adjacent[{arc.from, arc.to}];
    EXPECT_DOUBLE_EQ(arc.strength, together / 12.0);
    const double direction = together > 0 ? forward[{arc.from, arc.to}] / together : 0.0;
    EXPECT_DOUBLE_EQ(arc.direction, direction);
    if (arc.to.find('@') != std::string::npos) {
      EXPECT_EQ(arc.direction, 0.0);  // no arc runs into the previous slice
    }
  }
  EXPECT_THAT(result.arcs.averaged, Contains(named_edge{"a@-1", "a"}));
  EXPECT_THAT(result.structure.transition.edges(), Contains(named_edge{"a@-1", "a"}));
  // The same for any number of threads.
  const auto two = bootstrap_dynamic_structure(data.data, names, learner, {.threads = 2}, options);
  EXPECT_EQ(two.structure, result.structure);
  EXPECT_THROW(static_cast<void>(bootstrap_dynamic_structure(data.data, names, learner, {}, {.replicates = 0})),
               model_error);
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
  // --bootstrap: the arcs' strengths, and the averaged network's model.
  const auto boot = run("learn-structure --dynamic --algorithm hc --bootstrap 10 --seed 3 --data " + data.string() +
                        " --out " + path("averaged.json").string());
  ASSERT_EQ(boot.code, 0) << boot.err;
  EXPECT_THAT(boot.out, ::testing::HasSubstr("hc on 10 bootstrap resamples of the episodes"));
  EXPECT_THAT(boot.out, ::testing::HasSubstr("a@-1 -> a  strength 1  direction 1"));
  const auto averaged = bootstrap_dynamic_structure(read, std::vector<std::string>{"a", "b", "c"},
                                                    make_structure_learner("hc"), {}, {.replicates = 10, .seed = 3});
  EXPECT_EQ(parse_dynamic_json(slurp(path("averaged.json")), "averaged.json"), fit_dynamic(averaged.structure, read));
  // A structure prior from a static network, mapped onto both slices: c is noise, but a prior
  // that swamps the data keeps c -> b; b -> c@-1, an edge into the previous slice, is dropped.
  const auto prior = file(
      "prior.json",
      to_json(network_structure({variable("c0", {"0", "1"}), variable("c1", {"0", "1"}), variable("b1", {"0", "1"})},
                                {{"c1", "b1"}, {"b1", "c0"}}))
          .dump());
  const auto favoured =
      run("learn-structure --dynamic --algorithm hc --data " + data.string() + " --prior-model " + prior.string() +
          " --map 'b=b1, c==c1, c@-1==c0' --prior-weight 1000 --out " + path("favoured.json").string());
  ASSERT_EQ(favoured.code, 0) << favoured.err;
  EXPECT_THAT(favoured.err, ::testing::HasSubstr("the structure prior favours 1 edge(s) by 1000 each: c->b"));
  const auto learned = structure_of(parse_dynamic_json(slurp(path("favoured.json")), "favoured.json"));
  EXPECT_THAT(learned.transition.edges(), Contains(named_edge{"c", "b"}));
  EXPECT_THAT(learned.initial.edges(), Contains(named_edge{"c", "b"}));
  expect_failure(
      "learn-structure --dynamic --threshold 0.5 --data " + data.string() + " --out " + path("no.json").string(),
      "--threshold applies with --bootstrap", path("no.json"));
}

}  // namespace learn_dynamic_structure_test
}  // namespace pgm
