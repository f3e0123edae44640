// Policies read from CSV: the oil wildcatter's optimal policy and a worse one, worth what
// enumeration of the diagram says they are; the evidence's rows left out; each kind of bad row
// refused naming its line and column.

#include "pgm/io/policy_csv.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pgm/decide/solve_decisions.hpp"
#include "support/influence_diagrams.hpp"

namespace pgm::policy_csv_tests {
namespace {

using ::testing::HasSubstr;
using testing::oil_wildcatter;

const std::string header = "decision,observed,action\n";
const std::string optimal = header +
                            "Test,,yes\n"
                            "Drill,\"Test=yes,Seismic=closed\",yes\n"
                            "Drill,\"Test=yes,Seismic=open\",yes\n"
                            "Drill,\"Test=yes,Seismic=diffuse\",no\n"
                            "Drill,\"Test=no,Seismic=closed\",yes\n"
                            "Drill,\"Test=no,Seismic=open\",yes\n"
                            "Drill,\"Test=no,Seismic=diffuse\",yes\n";

TEST(policy_csv_test, a_policy_read_is_worth_what_enumeration_says) {
  const auto d = oil_wildcatter();
  const auto policies = parse_policy_csv(optimal, "policy.csv", d);
  ASSERT_EQ(policies.size(), 2U);
  EXPECT_EQ(policies[1].observed, (std::vector{d.id("Test"), d.id("Seismic")}));
  EXPECT_EQ(policies[1].actions, (std::vector<std::size_t>{0, 0, 1, 0, 0, 0}));
  EXPECT_NEAR(expected_utility(d, policies), 22.5, 1e-12);
  // Never testing, drilling blind: 0.5·-70 + 0.3·50 + 0.2·200 = 20; rows in any order.
  const auto blind = parse_policy_csv(header + "Drill,,yes\nTest,,no\n", "blind.csv", d);
  EXPECT_NEAR(expected_utility(d, blind), 20.0, 1e-12);
  EXPECT_NEAR(expected_utility(d, blind), testing::expected_utility_by_enumeration(d, blind, {}), 1e-12);
  const auto never = parse_policy_csv(header + "Test,,yes\nDrill,Test=yes,no\nDrill,Test=no,no\n", "never.csv", d);
  EXPECT_NEAR(expected_utility(d, never), testing::expected_utility_by_enumeration(d, never, {}), 1e-12);
}

TEST(policy_csv_test, configurations_the_evidence_rules_out_may_be_left_out) {
  const auto d = oil_wildcatter();
  const std::string tested = header +
                             "Test,,yes\n"
                             "Drill,\"Test=yes,Seismic=closed\",yes\n"
                             "Drill,\"Test=yes,Seismic=open\",yes\n"
                             "Drill,\"Test=yes,Seismic=diffuse\",no\n";
  EXPECT_THAT([&] { (void)parse_policy_csv(tested, "tested.csv", d); },
              ::testing::ThrowsMessage<parse_error>(HasSubstr("tested.csv:3:1: no row for 'Drill' given Test=no")));
  // Under limited memory the same rows read, and the known variables are Drill's parents only.
  const auto limited = parse_policy_csv(optimal, "policy.csv", d, {}, true);
  EXPECT_NEAR(expected_utility(d, limited), 22.5, 1e-12);
}

TEST(policy_csv_test, bad_rows_are_refused_naming_line_and_column) {
  const auto d = oil_wildcatter();
  const auto refuses = [&](const std::string& text, const std::string& message) {
    EXPECT_THAT([&] { (void)parse_policy_csv(text, "p.csv", d); },
                ::testing::ThrowsMessage<parse_error>(HasSubstr(message)))
        << text;
  };
  refuses("decision,observe,action\n", "p.csv:1:1: expected the header decision,observed,action");
  refuses("", "p.csv:1:1: expected the header");
  refuses(header + "Oil,,yes\n", "p.csv:2:1: 'Oil' is not a decision of the diagram (decisions: Test, Drill)");
  refuses(header + "Test,,maybe\n", "p.csv:2:7: 'Test' has no action 'maybe' (actions: yes, no)");
  refuses(header + "Test,,yes\nDrill,Oil=dry,yes\n", "p.csv:3:7: 'Oil' is not known when 'Drill' is taken");
  refuses(header + "Test,,yes\nDrill,Test,yes\n", "p.csv:3:7: expected VARIABLE=STATE, found 'Test'");
  refuses(header + "Test,,yes\nDrill,Test=perhaps,yes\n", "'Test' has no state 'perhaps'");
  refuses(header + "Test,,yes\nDrill,\"Test=yes,Test=no\",yes\n", "'Test' is named twice");
  refuses(header + "Test,,yes\nDrill,Test=yes,yes\nDrill,\"Test=no,Seismic=open\",yes\n",
          "p.csv:4:7: every row of 'Drill' names the variables its first (line 3) names: Test");
  refuses(header + "Test,,yes\nTest,,no\n", "p.csv:3:6: 'Test' already has a row for '' (line 2)");
  refuses(header + "Test,,yes\n", "no policy for the decision 'Drill'");
  refuses(header + "Test,yes\n", "p.csv:2:6: expected 3 fields");
}

TEST(policy_csv_test, a_row_naming_too_many_configurations_is_refused_before_any_table) {
  influence_diagram d;
  std::vector<variable_id> seen;
  std::string observed;
  for (int i = 0; i < 25; ++i) {
    const auto name = "c" + std::to_string(i);
    seen.push_back(d.add_chance(variable(name, {"0", "1"})));
    d.set_table(seen.back(), {}, {0.5, 0.5});
    observed += (i ? "," : "") + name + "=0";
  }
  const auto act = d.add_decision(variable("act", {"a", "b"}));
  d.set_observed(act, seen);
  d.add_utility("U", {act}, {1, 0});
  EXPECT_THAT(
      [&] { (void)parse_policy_csv(header + "act,\"" + observed + "\",a\n", "wide.csv", d); },
      ::testing::ThrowsMessage<parse_error>(HasSubstr("wide.csv:2:5: a policy of 'act' over these variables has "
                                                      "more than 16777216 configurations")));
}

}  // namespace
}  // namespace pgm::policy_csv_tests
