// The CPDAG type, Meek's rules one by one, the CPDAG of a DAG, the Dor–Tarsi extension and
// the structural Hamming distance.

#include "pgm/learn/cpdag.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pgm/learn/orientation.hpp"
#include "pgm/learn/structural_hamming_distance.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::cpdag_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

variable_id id(std::size_t i) { return index_at<variable_id>(i); }

dag make_dag(std::vector<std::string> names, const std::vector<named_edge>& edges) {
  dag g(names);
  for (const auto& e : edges) g.add_edge(e.from, e.to);
  return g;
}

TEST(cpdag_test, marks) {
  cpdag g({"a", "b", "c"});
  g.add_undirected(id(0), id(1));
  g.add_directed(id(1), id(2));
  EXPECT_TRUE(g.undirected(id(0), id(1)));
  EXPECT_TRUE(g.undirected(id(1), id(0)));
  EXPECT_TRUE(g.directed(id(1), id(2)));
  EXPECT_FALSE(g.directed(id(2), id(1)));
  EXPECT_FALSE(g.adjacent(id(0), id(2)));
  EXPECT_EQ(g.edge_count(), 2u);
  EXPECT_EQ(g.directed_edges(), (std::vector<named_edge>{{"b", "c"}}));
  EXPECT_EQ(g.undirected_edges(), (std::vector<named_edge>{{"a", "b"}}));
  EXPECT_EQ(g.parents(id(2)), std::vector<variable_id>{id(1)});
  EXPECT_EQ(g.undirected_neighbours(id(1)), std::vector<variable_id>{id(0)});
  g.orient(id(1), id(0));
  EXPECT_TRUE(g.directed(id(1), id(0)));
  EXPECT_TRUE(g.has_directed_path(id(1), id(2)));
  EXPECT_FALSE(g.has_directed_path(id(2), id(1)));
  g.remove(id(0), id(1));
  EXPECT_FALSE(g.adjacent(id(0), id(1)));
  EXPECT_THROW(cpdag({"a", "a"}), model_error);
  EXPECT_THROW(static_cast<void>(g.id("zz")), model_error);
}

TEST(cpdag_test, meek_r1_r2_r3) {
  std::vector<std::string> conflicts;
  // R1: a -> b - c, a and c not adjacent → b -> c.
  cpdag r1({"a", "b", "c"});
  r1.add_directed(id(0), id(1));
  r1.add_undirected(id(1), id(2));
  apply_meek_rules(r1, conflicts);
  EXPECT_TRUE(r1.directed(id(1), id(2)));
  // R2: a -> b -> c and a - c → a -> c.
  cpdag r2({"a", "b", "c"});
  r2.add_directed(id(0), id(1));
  r2.add_directed(id(1), id(2));
  r2.add_undirected(id(0), id(2));
  apply_meek_rules(r2, conflicts);
  EXPECT_TRUE(r2.directed(id(0), id(2)));
  // R3: a - c -> b, a - d -> b, c and d not adjacent, a - b → a -> b.
  cpdag r3({"a", "b", "c", "d"});
  r3.add_undirected(id(0), id(1));
  r3.add_undirected(id(0), id(2));
  r3.add_undirected(id(0), id(3));
  r3.add_directed(id(2), id(1));
  r3.add_directed(id(3), id(1));
  apply_meek_rules(r3, conflicts);
  EXPECT_TRUE(r3.directed(id(0), id(1)));
  EXPECT_TRUE(r3.undirected(id(0), id(2)));
  EXPECT_TRUE(r3.undirected(id(0), id(3)));
  EXPECT_TRUE(conflicts.empty());
}

TEST(cpdag_test, meek_r4) {
  // d -> c -> b, a - b, a - c, a - d, b and d not adjacent → a -> b.
  cpdag g({"a", "b", "c", "d"});
  g.add_undirected(id(0), id(1));
  g.add_undirected(id(0), id(2));
  g.add_undirected(id(0), id(3));
  g.add_directed(id(3), id(2));
  g.add_directed(id(2), id(1));
  std::vector<std::string> conflicts;
  apply_meek_rules(g, conflicts);
  EXPECT_TRUE(g.directed(id(0), id(1)));
}

TEST(cpdag_test, cpdag_of_chain_fork_collider) {
  const auto chain = cpdag_of(make_dag({"a", "b", "c"}, {{"a", "b"}, {"b", "c"}}));
  EXPECT_EQ(chain.undirected_edges().size(), 2u);
  EXPECT_TRUE(chain.directed_edges().empty());
  const auto fork = cpdag_of(make_dag({"a", "b", "c"}, {{"b", "a"}, {"b", "c"}}));
  EXPECT_EQ(fork, chain);
  const auto collider = cpdag_of(make_dag({"a", "b", "c"}, {{"a", "b"}, {"c", "b"}}));
  EXPECT_EQ(collider.directed_edges(), (std::vector<named_edge>{{"a", "b"}, {"c", "b"}}));
  // A collider followed by a chain: b -> d is compelled by R1.
  const auto longer = cpdag_of(make_dag({"a", "b", "c", "d"}, {{"a", "b"}, {"c", "b"}, {"b", "d"}}));
  EXPECT_EQ(longer.directed_edges(), (std::vector<named_edge>{{"a", "b"}, {"b", "d"}, {"c", "b"}}));
}

TEST(cpdag_test, extension_of_a_chain) {
  cpdag g({"a", "b", "c"});
  g.add_undirected(id(0), id(1));
  g.add_undirected(id(1), id(2));
  const auto edges = extend_to_dag(g);
  ASSERT_EQ(edges.size(), 2u);
  const auto d = make_dag({"a", "b", "c"}, edges);
  EXPECT_EQ(cpdag_of(d), g);  // no v-structure added
}

TEST(cpdag_test, extension_keeps_the_class_of_random_dags) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 10, .max_parents = 3});
    const auto truth = cpdag_of(net.graph());
    const auto edges = extend_to_dag(truth);
    const auto extension = make_dag(net.graph().names(), edges);
    EXPECT_EQ(cpdag_of(extension), truth) << "seed " << seed;
    // Directed edges of the CPDAG survive.
    for (const auto& e : truth.directed_edges()) {
      EXPECT_TRUE(extension.has_edge(extension.id(e.from), extension.id(e.to))) << seed;
    }
    const auto structure = extend_to_structure(truth, net.variables());
    EXPECT_EQ(structure.graph(), extension);
  }
}

TEST(cpdag_test, extension_fails_cleanly) {
  // A directed cycle has no extension.
  cpdag g({"a", "b", "c"});
  g.add_directed(id(0), id(1));
  g.add_directed(id(1), id(2));
  g.add_directed(id(2), id(0));
  try {
    static_cast<void>(extend_to_dag(g, true));
    FAIL();
  } catch (const model_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("directed edges form a cycle"));
  }
  // a - b - c - d - a (a 4-cycle of undirected edges) cannot.
  cpdag square({"a", "b", "c", "d"});
  square.add_undirected(id(0), id(1));
  square.add_undirected(id(1), id(2));
  square.add_undirected(id(2), id(3));
  square.add_undirected(id(3), id(0));
  try {
    static_cast<void>(extend_to_dag(square));
    FAIL();
  } catch (const model_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("no extension to a DAG without a new v-structure"));
  }
  std::size_t relaxed = 0;
  const auto edges = extend_to_dag(square, true, &relaxed);
  EXPECT_EQ(edges.size(), 4u);
  EXPECT_EQ(relaxed, 1u);
  EXPECT_NO_THROW(static_cast<void>(make_dag({"a", "b", "c", "d"}, edges)));
}

TEST(cpdag_test, structural_hamming_distance) {
  const auto truth = cpdag_of(make_dag({"a", "b", "c", "d"}, {{"a", "b"}, {"c", "b"}, {"b", "d"}}));
  EXPECT_EQ(structural_hamming_distance(truth, truth), 0u);
  auto learned = truth;
  learned.add_undirected(id(0), id(1));  // a - b instead of a -> b: misoriented
  learned.remove(id(1), id(3));          // missing
  learned.add_undirected(id(0), id(3));  // extra
  const auto parts = hamming_differences(learned, truth);
  EXPECT_EQ(parts.misoriented, 1u);
  EXPECT_EQ(parts.missing, 1u);
  EXPECT_EQ(parts.extra, 1u);
  EXPECT_EQ(structural_hamming_distance(learned, truth), 3u);
  EXPECT_EQ(skeleton_distance(learned, truth), 2u);
  learned.add_directed(id(1), id(0));  // reversed
  EXPECT_EQ(hamming_differences(learned, truth).misoriented, 1u);
  EXPECT_THROW(static_cast<void>(structural_hamming_distance(truth, cpdag({"x"}))), model_error);
}

TEST(cpdag_test, knowledge_orients_edges) {
  background_knowledge k;
  k.tiers = {{"a"}, {"b", "c"}};
  k.required = {{"c", "b"}};
  const edge_constraints constraints(k, {"a", "b", "c", "d"});
  cpdag g({"a", "b", "c", "d"});
  g.add_undirected(id(0), id(1));
  g.add_undirected(id(1), id(2));
  g.add_undirected(id(2), id(3));
  orient_by_knowledge(g, constraints);
  EXPECT_TRUE(g.directed(id(0), id(1)));
  EXPECT_TRUE(g.directed(id(2), id(1)));
  EXPECT_TRUE(g.undirected(id(2), id(3)));
}

TEST(cpdag_test, knowledge_errors) {
  const std::vector<std::string> names{"a", "b", "c"};
  auto message = [&](const background_knowledge& k) {
    try {
      const edge_constraints c(k, names);
      return std::string();
    } catch (const model_error& e) {
      return std::string(e.what());
    }
  };
  EXPECT_THAT(message({.tiers = {{"a", "q"}}}), HasSubstr("unknown variable 'q' in the tiers (variables: a, b, c)"));
  EXPECT_THAT(message({.forbidden = {{"a", "z"}}}), HasSubstr("unknown variable 'z' in the forbidden edges"));
  EXPECT_THAT(message({.required = {{"y", "a"}}}), HasSubstr("unknown variable 'y' in the required edges"));
  EXPECT_THAT(message({.tiers = {{"a"}, {"a"}}}), HasSubstr("'a' is in tier 1 and in tier 2"));
  EXPECT_THAT(message({.forbidden = {{"a", "b"}}, .required = {{"a", "b"}}}),
              HasSubstr("edge a->b is required, but it is forbidden"));
  EXPECT_THAT(message({.tiers = {{"a"}, {"b"}}, .required = {{"b", "a"}}}),
              HasSubstr("required, but the tiers put 'b' after 'a'"));
  EXPECT_THAT(message({.required = {{"a", "b"}, {"b", "a"}}}), HasSubstr("cycle"));
  EXPECT_THAT(parse_tiers("a, b; c;d"), ElementsAre(ElementsAre("a", "b"), ElementsAre("c"), ElementsAre("d")));
  EXPECT_THROW(static_cast<void>(parse_tiers("a;;b")), model_error);
  EXPECT_THROW(static_cast<void>(parse_tiers("a,,b")), model_error);
}

}  // namespace
}  // namespace pgm::cpdag_tests
