// Success prediction, explanation and the network-level prevention plan on a small stacking
// network whose answers are worked out by hand.

#include "pgm/decide/predict.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pgm/decide/counterfactual_success.hpp"
#include "pgm/decide/explain.hpp"
#include "pgm/decide/success_table.hpp"

namespace pgm::predict_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

const semantic_tags cm{"offset", "cm", ""};

/// x, y ∈ {[-3,-0.4), [-0.4,0.4), [0.4,3)} cm, uniform; colour irrelevant; onTop ← x, y.
bayesian_network stacking() {
  const auto x = variable::intervals("x", {-3, -0.4, 0.4, 3}, cm);
  const auto y = variable::intervals("y", {-3, -0.4, 0.4, 3}, cm);
  const variable colour("colour", {"Red", "Blue"});
  const variable on_top("onTop", {"0", "1"});
  const double third = 1.0 / 3.0;
  // P(onTop = 1 | x, y), y fastest: only near the centre does the cube stay.
  const double p[] = {0.1, 0.3,  0.1,  //
                      0.6, 0.95, 0.5,  //
                      0.1, 0.2,  0.1};
  std::vector<double> values;
  for (double v : p) {
    values.push_back(1 - v);
    values.push_back(v);
  }
  return bayesian_network::from_tables({cpt<double>(x, {}, {third, third, third}),
                                        cpt<double>(y, {}, {third, third, third}), cpt<double>(colour, {}, {0.5, 0.5}),
                                        cpt<double>(on_top, {x, y}, values)});
}

TEST(predict_test, numbers_are_binned_with_the_saved_edges) {
  const auto net = stacking();
  const success_event s{"onTop", "1"};
  EXPECT_DOUBLE_EQ(predict_success(net, s, parse_assignment("x=0.0, y=-0.4", net)), 0.95);  // left-closed
  EXPECT_DOUBLE_EQ(predict_success(net, s, parse_assignment("x=10,y=0.39", net)), 0.2);     // outside: outer bin
  EXPECT_DOUBLE_EQ(predict_success(net, s, parse_assignment("x=@1,y=@2,colour=Red", net)), 0.5);
  EXPECT_DOUBLE_EQ(predict_success(net, s, {{"x", -2.0}, {"y", std::string("1")}}), 0.3);
}

TEST(predict_test, a_rounded_column_is_normalized_as_inference_would) {
  // Published tables are printed to a few digits: this column sums to 1 + 8e-7, inside the
  // tolerance a table is read with, so the stored entry is not the conditional probability.
  const variable a("a", {"0", "1"});
  const variable ok("ok", {"0", "1"});
  const auto net = bayesian_network::from_tables(
      {cpt<double>(a, {}, {0.5, 0.5}), cpt<double>(ok, {a}, {0.5, 0.5, 0.2000004, 0.8000004})});
  const success_event s{"ok", "1"};
  const double normalized = 0.8000004 / 1.0000008;
  const double p = predict_success(net, s, parse_assignment("a=1", net));
  EXPECT_DOUBLE_EQ(p, normalized);
  EXPECT_GT(0.8000004 - p, 6e-7);  // not the stored entry (which is 6.4e-7 higher)
  EXPECT_NEAR(p, query(net, {"ok"}, {{"a", "1"}}).probability({"1"}), 1e-15);
}

TEST(predict_test, default_success_event_is_the_unique_sink_with_state_1) {
  EXPECT_EQ(default_success_event(stacking()), (success_event{"onTop", "1"}));
  const variable a("a", {"0", "1"});
  const variable b("b", {"0", "1"});
  const variable c("c", {"0", "1"});
  const auto two_sinks = bayesian_network::from_tables({cpt<double>(a, {}), cpt<double>(b, {a}), cpt<double>(c, {a})});
  EXPECT_THAT([&] { static_cast<void>(default_success_event(two_sinks)); },
              ThrowsMessage<model_error>(HasSubstr("several variables could be the success variable (b, c)")));
  EXPECT_EQ(parse_success_event("c=0", two_sinks), (success_event{"c", "0"}));
  EXPECT_THROW(static_cast<void>(parse_success_event("c=2", two_sinks)), model_error);
  EXPECT_THROW(static_cast<void>(parse_success_event("c", two_sinks)), model_error);
}

TEST(predict_test, bad_assignments_say_what_is_wrong) {
  const auto net = stacking();
  const success_event s{"onTop", "1"};
  auto fails = [&](const std::string& text, const std::string& message) {
    EXPECT_THAT([&] { static_cast<void>(predict_success(net, s, parse_assignment(text, net))); },
                ThrowsMessage<model_error>(HasSubstr(message)))
        << text;
  };
  fails("z=1,x=0,y=0", "no variable 'z'");
  fails("x=0,y=0,colour=Green", "no state 'Green'");
  fails("x=0,y=0,colour=0.5", "'colour' has no interval edges, so the number 0.5 cannot be binned");
  fails("x=nan,y=0", "'x': nan is not a finite number");
  fails("x=0", "no value is given for y, a parent of 'onTop'");
  fails("x=0,y", "'y' is not of the form name=value");
  fails("x=0,x=1,y=0", "'x' is assigned twice");
  fails("x=0,y=0,onTop=1", "is assigned; it is what is predicted");
  fails("x=@7,y=0", "no state '7'");
}

TEST(predict_test, missing_parents_are_summed_out_on_request) {
  const auto net = stacking();
  const success_event s{"onTop", "1"};
  const auto p = predict_success(net, s, parse_assignment("x=0", net), {.marginalize_missing = true});
  EXPECT_NEAR(p, (0.6 + 0.95 + 0.5) / 3, 1e-12);
  const std::string given[] = {"x"};
  const auto table = success_table(net, "onTop", given);
  EXPECT_NEAR(table(state_index(1), config_index(1)), p, 1e-12);
  EXPECT_THAT(table.parents(), ElementsAre(net.at("x")));
}

TEST(explain_test, the_smallest_change_in_bins_and_units) {
  const auto net = stacking();
  const auto& table = net.table("onTop");
  const bool both[] = {true, true};
  // (x=0, y=1): 0.3 → the centre (1,1), 0.95, one step in x.
  const auto e = explain(table, 1, 1, both);
  EXPECT_TRUE(e.failure_predicted());
  EXPECT_EQ(e.target, 4u);
  EXPECT_DOUBLE_EQ(e.target_predicted, 0.95);
  EXPECT_TRUE(e.target_succeeds());
  EXPECT_EQ(e.steps, 1u);
  ASSERT_EQ(e.changes.size(), 2u);
  const auto r = e.responsible();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].variable, "x");
  EXPECT_EQ(r[0].unit, "cm");
  EXPECT_EQ(r[0].from_label, "0");
  EXPECT_EQ(r[0].to_label, "1");
  EXPECT_EQ(*r[0].from_interval, (interval{-3, -0.4}));
  EXPECT_EQ(*r[0].to_interval, (interval{-0.4, 0.4}));
  EXPECT_DOUBLE_EQ(*r[0].move, 0.0 - (-1.7));
  EXPECT_DOUBLE_EQ(*e.distance_units, 1.7);
}

TEST(explain_test, plan_on_a_network_uses_the_table_and_fixes_the_rest) {
  const auto net = stacking();
  const success_event s{"onTop", "1"};
  const std::string only_y[] = {"y"};
  // x = 2 (right), y = 0: only y may move; the best in row x=2 is 0.2 at y=1 (none above ε).
  const auto plan = plan_prevention(net, s, parse_assignment("x=1,y=-1", net), only_y);
  EXPECT_EQ(plan.table, net.table("onTop"));
  EXPECT_DOUBLE_EQ(plan.why.predicted, 0.1);
  EXPECT_EQ(plan.why.target, 7u);
  EXPECT_FALSE(plan.why.target_succeeds());
  ASSERT_EQ(plan.why.changes.size(), 1u);
  EXPECT_EQ(plan.why.changes[0].variable, "y");
  EXPECT_THAT([&] { static_cast<void>(plan_prevention(net, s, parse_assignment("x=1", net), only_y)); },
              ThrowsMessage<model_error>(HasSubstr("no value is given for the controllable variable 'y'")));
  const std::string colour[] = {"colour"};
  // A controllable variable that is no parent joins the table; it cannot help.
  const auto other = plan_prevention(net, s, parse_assignment("x=1,y=-1,colour=Red", net), colour);
  EXPECT_EQ(other.table.parents().size(), 3u);
  EXPECT_EQ(other.why.steps, 0u);
  EXPECT_NEAR(other.why.predicted, 0.1, 1e-12);
}

TEST(explain_test, the_change_would_have_saved_a_failed_run_as_monotone_ranks_say) {
  const auto net = stacking();
  const success_event s{"onTop", "1"};
  const std::string both[] = {"x", "y"};
  // (x=0, y=1) succeeds with 0.3, the centre with 0.95. A run that failed had its noise below
  // 0.7 (failure is the lower state); at the centre it fails below 0.05 only.
  const auto planned = parse_assignment("x=-1.7,y=0", net);
  const auto plan = plan_prevention(net, s, planned, both);
  ASSERT_EQ(plan.why.target, 4u);
  EXPECT_NEAR(*counterfactual_success(net, plan.why, planned), (0.7 - 0.05) / 0.7, 1e-12);
  // Only y moves from (x=2, y=0), 0.1 to 0.2.
  const std::string only_y[] = {"y"};
  const auto right = parse_assignment("x=1,y=-1", net);
  EXPECT_NEAR(*counterfactual_success(net, plan_prevention(net, s, right, only_y).why, right), (0.9 - 0.8) / 0.9,
              1e-12);
  // Nothing moves: nothing to say.
  const std::string colour[] = {"colour"};
  const auto red = parse_assignment("x=1,y=-1,colour=Red", net);
  EXPECT_FALSE(counterfactual_success(net, plan_prevention(net, s, red, colour).why, red));
}

}  // namespace
}  // namespace pgm::predict_tests
