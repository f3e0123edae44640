// pgm/io/dot.hpp: the DOT text names every variable and edge, marks the success and
// controllable variables, draws undirected edges without arrowheads and strengths as widths.

#include "pgm/io/dot.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace pgm::dot_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::ThrowsMessage;

network_structure stacking() {
  const std::vector<std::string> five{"0", "1", "2", "3", "4"};
  return network_structure({variable("xOff2", five), variable("yOff2", five), variable(R"(a"b\c)", {"a", "b"}),
                            variable("onTop2", {"0", "1"})},
                           parse_edge_list("xOff2->onTop2,yOff2->onTop2"));
}

TEST(dot_test, every_variable_and_edge_is_drawn_and_names_are_quoted) {
  const auto text = to_dot(stacking());
  EXPECT_THAT(text, HasSubstr("digraph network {"));
  EXPECT_THAT(text, HasSubstr("\"xOff2\" [label=\"xOff2\\n5 states\"];"));
  EXPECT_THAT(text, HasSubstr(R"("a\"b\\c" [label="a\"b\\c\n2 states"];)"));
  EXPECT_THAT(text, HasSubstr("\"xOff2\" -> \"onTop2\";"));
  EXPECT_THAT(text, HasSubstr("\"yOff2\" -> \"onTop2\";"));
  EXPECT_THAT(text, Not(HasSubstr("dir=none")));
}

TEST(dot_test, names_that_read_as_html_entities_are_drawn_as_written) {
  // Issue #49: Graphviz decodes entities in every string, so "R&amp;D" was drawn as R&D.
  const network_structure structure({variable("R&amp;D", {"0", "1"}), variable("x&lt;1", {"0", "1"})},
                                    {{"R&amp;D", "x&lt;1"}});
  const auto text = to_dot(structure);
  EXPECT_THAT(text, HasSubstr(R"("R&amp;amp;D" -> "x&amp;lt;1";)"));
  EXPECT_THAT(text, HasSubstr(R"("R&amp;amp;D" [label="R&amp;amp;D\n2 states"];)"));
}

TEST(dot_test, success_and_controllable_variables_are_marked) {
  const auto text = to_dot(stacking(), {.success = {"onTop2"}, .controllable = {"xOff2"}});
  EXPECT_THAT(text, HasSubstr("\"onTop2\" [label=\"onTop2\\n2 states\", shape=doubleoctagon"));
  EXPECT_THAT(text, HasSubstr("\"xOff2\" [label=\"xOff2\\n5 states\", shape=box"));
  EXPECT_THAT(text, HasSubstr("\"yOff2\" [label=\"yOff2\\n5 states\"];"));
}

TEST(dot_test, undirected_edges_lose_their_arrowheads_and_strengths_set_the_width) {
  dot_options options;
  options.undirected = {{"onTop2", "xOff2"}};  // either order names the edge
  options.strength[{"yOff2", "onTop2"}] = 0.5;
  const auto text = to_dot(stacking(), options);
  EXPECT_THAT(text, HasSubstr("\"xOff2\" -> \"onTop2\" [dir=none];"));
  EXPECT_THAT(text, HasSubstr("\"yOff2\" -> \"onTop2\" [penwidth=2.25, label=\"0.50\"];"));
}

TEST(dot_test, a_marked_name_that_is_no_variable_is_refused) {
  EXPECT_THAT([] { static_cast<void>(to_dot(stacking(), {.success = {"onTop3"}})); },
              ThrowsMessage<model_error>(HasSubstr("the success variable 'onTop3' is not a variable of the network")));
  EXPECT_THAT([] { static_cast<void>(to_dot(stacking(), {.controllable = {"x"}})); },
              ThrowsMessage<model_error>(HasSubstr("the controllable variable 'x'")));
}

}  // namespace
}  // namespace pgm::dot_tests
