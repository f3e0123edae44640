#include "pgm/core/dag.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <boost/graph/depth_first_search.hpp>

namespace pgm::dag_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(dag_test, parents_keep_the_order_edges_were_added) {
  dag g({"xOff1", "yOff1", "xOff2", "onTop2"});
  g.add_edge("yOff1", "onTop2");
  g.add_edge("xOff1", "onTop2");
  g.add_edge("xOff2", "onTop2");
  EXPECT_THAT(g.parents(g.id("onTop2")), ElementsAre(g.id("yOff1"), g.id("xOff1"), g.id("xOff2")));
  EXPECT_THAT(g.children(g.id("xOff1")), ElementsAre(g.id("onTop2")));
  EXPECT_EQ(g.edge_count(), 3u);
}

TEST(dag_test, an_edge_closing_a_cycle_is_refused_and_named) {
  dag g({"a", "b", "c"});
  g.add_edge("a", "b");
  g.add_edge("b", "c");
  try {
    g.add_edge("c", "a");
    FAIL() << "expected not_a_dag";
  } catch (const not_a_dag& e) {
    EXPECT_THAT(e.cycle(), ElementsAre("c", "a", "b", "c"));
    EXPECT_THAT(e.what(), HasSubstr("c -> a -> b -> c"));
  }
  EXPECT_EQ(g.edge_count(), 2u);  // unchanged
}

TEST(dag_test, self_loops_and_repeated_edges_are_refused) {
  dag g({"a", "b"});
  EXPECT_THAT([&] { g.add_edge("a", "a"); }, ThrowsMessage<not_a_dag>(HasSubstr("a -> a")));
  g.add_edge("a", "b");
  EXPECT_THAT([&] { g.add_edge("a", "b"); }, ThrowsMessage<model_error>(HasSubstr("given twice")));
}

TEST(dag_test, unknown_and_duplicate_nodes) {
  dag g({"a", "b"});
  EXPECT_THAT([&] { g.add_edge("a", "zz"); },
              ThrowsMessage<model_error>(HasSubstr("unknown variable 'zz' (known: a, b)")));
  EXPECT_THAT([&] { g.add_node("a"); }, ThrowsMessage<model_error>(HasSubstr("already")));
}

TEST(dag_test, remove_edge_reopens_the_way) {
  dag g({"a", "b"});
  g.add_edge("a", "b");
  EXPECT_TRUE(g.remove_edge(g.id("a"), g.id("b")));
  EXPECT_FALSE(g.remove_edge(g.id("a"), g.id("b")));
  g.add_edge("b", "a");
  EXPECT_TRUE(g.has_edge(g.id("b"), g.id("a")));
}

TEST(dag_test, topological_order_puts_parents_first) {
  dag g({"e", "d", "c", "b", "a"});
  g.add_edge("a", "b");
  g.add_edge("b", "c");
  g.add_edge("a", "d");
  g.add_edge("d", "c");
  g.add_edge("c", "e");
  const auto order = g.topological_order();
  ASSERT_EQ(order.size(), 5u);
  std::vector<std::size_t> position(5);
  for (std::size_t i = 0; i < order.size(); ++i) position[order[i].value()] = i;
  for (auto [from, to] : g.edges()) EXPECT_LT(position[from.value()], position[to.value()]);
}

TEST(dag_test, boost_algorithms_run_on_the_graph) {
  dag g({"a", "b", "c"});
  g.add_edge("a", "b");
  std::vector<boost::default_color_type> colours(g.size());
  boost::depth_first_search(g.graph(), boost::color_map(boost::make_iterator_property_map(
                                           colours.begin(), boost::get(boost::vertex_index, g.graph()))));
  EXPECT_EQ(boost::num_vertices(g.graph()), 3u);
  EXPECT_EQ(g.graph()[0], "a");
}

TEST(dag_test, equality_ignores_edge_insertion_order) {
  dag a({"x", "y", "z"});
  dag b({"x", "y", "z"});
  a.add_edge("x", "z");
  a.add_edge("y", "z");
  b.add_edge("y", "z");
  b.add_edge("x", "z");
  EXPECT_EQ(a, b);
  b.add_edge("x", "y");
  EXPECT_NE(a, b);
}

}  // namespace
}  // namespace pgm::dag_tests
