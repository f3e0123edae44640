#pragma once
/// \file
/// The conformance kit of structure learners: a GoogleTest suite that holds a registered
/// learner, chosen by name as a user chooses it, to what every learner promises: a DAG over the
/// data's columns, the same one whatever the threads, background knowledge kept (a required
/// edge present, a forbidden one absent, no edge into an earlier tier), and, for a learner that
/// claims to, the DAG a sample of 5,000 rows was drawn from recovered (every edge of that network
/// is compelled, so its equivalence class holds it alone). Instantiate it in one test source of a
/// program that links GoogleTest:
///
///     #include <pgm/testing/learner_conformance.hpp>
///     using pgm::testing::learner_conformance;  // the macro takes the suite's name unqualified
///     using pgm::testing::learner_case;
///     INSTANTIATE_TEST_SUITE_P(mine, learner_conformance,
///                              ::testing::Values(learner_case{.learner = "chow-liu", .recovers = false}),
///                              pgm::testing::learner_case_name);

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/learn/learn_structure.hpp"
#include "pgm/learn/structure_learner_registry.hpp"
#include "pgm/testing/case_names.hpp"

namespace pgm::testing {

/// One learner as the kit checks it.
struct learner_case {
  /// A choice the registry makes, options included: "hc[score=bdeu]".
  std::string learner;
  /// Whether it finds the network its data were drawn from (false for a learner of a fixed
  /// shape, such as "empty", or of trees).
  bool recovers = true;
};

inline void PrintTo(const learner_case& c, std::ostream* out) { *out << c.learner; }

/// Every registered learner, each checked as the case of `cases` with its name, or as one that
/// recovers where none has it.
[[nodiscard]] inline std::vector<learner_case> registered_learner_cases(const std::vector<learner_case>& cases) {
  return cases_of(structure_learners().names(), cases, [](const learner_case& c) { return c.learner; });
}

[[nodiscard]] inline std::string learner_case_name(const ::testing::TestParamInfo<learner_case>& info) {
  return test_name(info.param.learner);
}

/// a → c ← b, c → d → e with strong tables: c's likely state is a + b, d's whether c is 0, e's
/// d's. The v-structure at c compels every edge.
[[nodiscard]] inline bayesian_network compelled_network() {
  const variable a("a", {"0", "1"}), b("b", {"0", "1"}), c("c", {"0", "1", "2"}), d("d", {"0", "1"}),
      e("e", {"0", "1"});
  const auto likely = [](std::size_t states, std::size_t state) {
    std::vector<double> column(states, 0.1 / static_cast<double>(states - 1));
    column[state] = 0.9;
    return column;
  };
  std::vector<double> c_values, d_values, e_values;
  for (std::size_t u = 0; u < 4; ++u) {
    const auto column = likely(3, u / 2 + u % 2);
    c_values.insert(c_values.end(), column.begin(), column.end());
  }
  for (std::size_t u = 0; u < 3; ++u) {
    const auto column = likely(2, u == 0 ? 1 : 0);
    d_values.insert(d_values.end(), column.begin(), column.end());
  }
  for (std::size_t u = 0; u < 2; ++u) {
    const auto column = likely(2, u);
    e_values.insert(e_values.end(), column.begin(), column.end());
  }
  return bayesian_network::from_tables({cpt<double>(a, {}, {0.5, 0.5}), cpt<double>(b, {}, {0.4, 0.6}),
                                        cpt<double>(c, {a, b}, c_values), cpt<double>(d, {c}, d_values),
                                        cpt<double>(e, {d}, e_values)});
}

class learner_conformance : public ::testing::TestWithParam<learner_case> {
 protected:
  static constexpr std::uint64_t samples = 3;

  [[nodiscard]] structure_result learn(const dataset& data, structure_context context = {}) const {
    return learn_structure(data, make_structure_learner(GetParam().learner), std::move(context));
  }

  [[nodiscard]] static dataset drawn(std::uint64_t seed) { return sample(compelled_network(), 5000, seed); }

  /// The edges as (from, to) pairs, sorted, for comparison.
  [[nodiscard]] static std::set<std::pair<std::string, std::string>> edge_set(const std::vector<named_edge>& edges) {
    std::set<std::pair<std::string, std::string>> result;
    for (const auto& e : edges) result.emplace(e.from, e.to);
    return result;
  }
};

TEST_P(learner_conformance, learns_a_dag_over_the_datas_columns) {
  for (std::uint64_t seed = 1; seed <= samples; ++seed) {
    SCOPED_TRACE("sample " + std::to_string(seed));
    const auto data = drawn(seed);
    const auto names = data.names();
    const auto learned = learn(data);
    network_structure graph(compelled_network().variables());
    for (const auto& e : learned.edges) {
      EXPECT_NE(std::find(names.begin(), names.end(), e.from), names.end()) << e.from;
      EXPECT_NE(std::find(names.begin(), names.end(), e.to), names.end()) << e.to;
      EXPECT_NO_THROW(graph.add_edge(e.from, e.to)) << e.from << " -> " << e.to;  // no repeat, no cycle
    }
  }
}

TEST_P(learner_conformance, the_same_data_give_the_same_dag_whatever_the_threads) {
  const auto data = drawn(1);
  structure_context one, two;
  one.threads = 1;
  two.threads = 2;
  EXPECT_EQ(edge_set(learn(data, one).edges), edge_set(learn(data, two).edges));
}

TEST_P(learner_conformance, background_knowledge_is_kept) {
  const auto data = drawn(2);
  structure_context context;
  context.knowledge.required = {{"a", "e"}};
  context.knowledge.forbidden = {{"c", "d"}, {"d", "c"}};
  context.knowledge.tiers = {{"a", "b"}, {"c", "d", "e"}};
  const auto edges = edge_set(learn(data, context).edges);
  EXPECT_TRUE(edges.contains({"a", "e"}));
  EXPECT_FALSE(edges.contains({"c", "d"}) || edges.contains({"d", "c"}));
  for (const auto* later : {"c", "d", "e"}) {
    EXPECT_FALSE(edges.contains({later, "a"}) || edges.contains({later, "b"})) << "an edge from " << later;
  }
}

TEST_P(learner_conformance, the_network_a_sample_was_drawn_from_is_recovered) {
  if (!GetParam().recovers) {
    // A learner of a fixed shape still learns from the data it is given, without failing.
    EXPECT_NO_THROW(static_cast<void>(learn(drawn(1))));
    return;
  }
  const auto true_edges = compelled_network().structure().edges();
  for (std::uint64_t seed = 1; seed <= samples; ++seed) {
    SCOPED_TRACE("sample " + std::to_string(seed));
    EXPECT_EQ(edge_set(learn(drawn(seed)).edges), edge_set(true_edges));
  }
}

}  // namespace pgm::testing
