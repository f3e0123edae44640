#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pgm/core/bayesian_network.hpp"

namespace pgm::network_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

const variable a("a", {"0", "1"});
const variable b("b", {"0", "1", "2"});
const variable c("c", {"0", "1"});

std::vector<cpt<double>> tables() {
  return {cpt<double>(a, {}, {0.3, 0.7}), cpt<double>(b, {a}), cpt<double>(c, {a, b})};
}

TEST(network_test, from_tables_builds_the_graph) {
  const auto net = bayesian_network::from_tables(tables());
  EXPECT_EQ(net.size(), 3u);
  EXPECT_EQ(net.graph().edge_count(), 3u);
  EXPECT_EQ(net.free_parameters(), 1u + 4u + 6u);
  EXPECT_DOUBLE_EQ(net.table("a").probability("1", std::initializer_list<std::string>{}), 0.7);
}

TEST(network_test, missing_extra_and_duplicate_tables) {
  network_structure s({a, b, c}, {{"a", "b"}, {"a", "c"}, {"b", "c"}});
  auto t = tables();
  t.pop_back();
  EXPECT_THAT([&] { bayesian_network(s, t); }, ThrowsMessage<model_error>(HasSubstr("no table is given for 'c'")));
  t = tables();
  t.push_back(cpt<double>(a, {}));
  EXPECT_THAT([&] { bayesian_network(s, t); }, ThrowsMessage<model_error>(HasSubstr("two tables are given for 'a'")));
  t = tables();
  t.push_back(cpt<double>(variable("z", {"0"}), {}));
  EXPECT_THAT([&] { bayesian_network(s, t); }, ThrowsMessage<model_error>(HasSubstr("not in the network")));
}

TEST(network_test, tables_must_match_the_graph) {
  network_structure s({a, b, c}, {{"a", "b"}, {"a", "c"}});
  EXPECT_THAT([&] { bayesian_network(s, tables()); },
              ThrowsMessage<model_error>(HasSubstr("the table of 'c' has 2 parents, the graph 1")));
  network_structure swapped({a, b, c}, {{"a", "b"}, {"b", "c"}, {"a", "c"}});
  EXPECT_THAT([&] { bayesian_network(swapped, tables()); },
              ThrowsMessage<model_error>(HasSubstr("lists parent 'a' where the graph has 'b'")));
  network_structure other_states({a, variable("b", {"x", "y", "z"}), c}, {{"a", "b"}, {"a", "c"}, {"b", "c"}});
  EXPECT_THAT([&] { bayesian_network(other_states, tables()); },
              ThrowsMessage<model_error>(HasSubstr("describes the variable differently")));
}

TEST(network_test, from_tables_needs_every_parent_table) {
  EXPECT_THAT([] { static_cast<void>(bayesian_network::from_tables({cpt<double>(b, {a})})); },
              ThrowsMessage<model_error>(HasSubstr("'a' is a parent of 'b' but has no table")));
}

TEST(network_test, structure_edges_and_update) {
  network_structure s({a, b}, {{"a", "b"}});
  EXPECT_EQ(s.edges(), (std::vector<named_edge>{{"a", "b"}}));
  s.update_variable(b.with_tags({"q", "cm", ""}));
  EXPECT_EQ(s.at("b").tags().unit, "cm");
  EXPECT_THAT([&] { s.update_variable(variable("b", {"0"})); }, ThrowsMessage<model_error>(HasSubstr("has 3 states")));
  EXPECT_THAT([&] { s.add_edge("b", "a"); }, ThrowsMessage<not_a_dag>(HasSubstr("b -> a -> b")));
}

TEST(network_test, parse_edge_list) {
  EXPECT_EQ(parse_edge_list(" xOff1->onTop1 , yOff1 -> onTop1"),
            (std::vector<named_edge>{{"xOff1", "onTop1"}, {"yOff1", "onTop1"}}));
  EXPECT_THAT([] { static_cast<void>(parse_edge_list("a->b,c-d")); },
              ThrowsMessage<model_error>(HasSubstr("edge 2 ('c-d') is not of the form 'from->to'")));
  EXPECT_THAT([] { static_cast<void>(parse_edge_list("a->b->c")); }, ThrowsMessage<model_error>(HasSubstr("edge 1")));
  EXPECT_THAT([] { static_cast<void>(parse_edge_list(" ")); }, ThrowsMessage<model_error>(HasSubstr("empty")));
}

}  // namespace
}  // namespace pgm::network_tests
