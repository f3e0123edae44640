// Documents whose numbers come from summaries: every placeholder form on a small hand-made
// summary whose answers are known, and the errors a template author meets.

#include "cli/report_template.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace report_template_tests {
namespace {

using namespace pgm;
using pgm::cli::named_summary;
using pgm::cli::render_report_template;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// Success after prevention of MLE, direct and cross on |D| = 0, 10, 20, and one Mean-Difference.
std::vector<named_summary> summaries() {
  std::vector<aggregated_point> rows;
  const std::vector<std::pair<std::string, std::vector<double>>> lines{
      {"mle", {0.5, 0.7, 0.79}}, {"direct", {0.8, 0.78, 0.8}}, {"cross", {0.6, 0.65, 0.7}}};
  for (const auto& [strategy, values] : lines) {
    for (std::size_t k = 0; k < values.size(); ++k) {
      rows.push_back({"s", "t", strategy, strategy == "mle" ? "0" : "5", 10 * k, experiment_metric::failure_prevention,
                      values[k], 0.01, 3});
    }
  }
  rows.push_back({"s", "t", "mle", "0", 20, experiment_metric::mean_difference, 0.0567, 0.001, 3});
  rows.push_back({"s", "u", "mle", "0", 5000, experiment_metric::chosen_w, 1234.4, 0, 3});
  std::vector<aggregated_point> other{{"s", "t", "mle", "0", 0, experiment_metric::failure_prevention, 0.25, 0, 2}};
  return {{"", rows}, {"bullet", other}};
}

std::string render(const std::string& text) { return render_report_template(text, "t.md", summaries()); }

TEST(report_template_test, single_values_in_each_format) {
  EXPECT_EQ(render("a {{pct:1 s/t/direct/5/0/failure_prevention}} % b"), "a 80.0 % b");
  EXPECT_EQ(render("{{pct:0 s/t/mle/0/0/failure_prevention}}"), "50");
  EXPECT_EQ(render("{{num:3 s/t/mle/0/20/mean_difference}}"), "0.057");
  EXPECT_EQ(render("{{count s/u/mle/0/5000/chosen_w}}"), "1,234");
  EXPECT_EQ(render("{{count 1234567}} {{num:1 0.25}}"), "1,234,567 0.2");
  EXPECT_EQ(render("{{count reps s/t/mle/0/0/failure_prevention}} {{num:2 sd s/t/mle/0/0/failure_prevention}}"),
            "3 0.01");
  EXPECT_EQ(render("{{pct:0 bullet:s/t/mle/0/0/failure_prevention}}"), "25") << "a named summary";
  EXPECT_EQ(render("no placeholder\n"), "no placeholder\n");
  EXPECT_EQ(render("\\{{pct:1 s/t}} stays"), "{{pct:1 s/t}} stays");
}

TEST(report_template_test, rows_max_is_the_largest_size_of_each_target) {
  EXPECT_EQ(render("{{pct:0 s/t/mle/0/max/failure_prevention}}"), "79");
  EXPECT_EQ(render("{{count s/*/mle/0/max/chosen_w}}"), "1,234") << "s/u's largest |D| is 5000";
}

TEST(report_template_test, ranges_differences_and_reductions) {
  EXPECT_EQ(render("{{pct:0 range s/t/direct,cross/5/0/failure_prevention}}"), "60–80");
  EXPECT_EQ(render("{{pct:0 range s/t/direct/5/0,20/failure_prevention}}"), "80")
      << "one number when both ends print alike";
  EXPECT_EQ(render("{{+pct:1 diff s/t/direct/5/0/failure_prevention s/t/mle/0/0/failure_prevention}}"), "+30.0");
  EXPECT_EQ(render("{{+pct:1 diff s/t/mle/0/0/failure_prevention s/t/direct/5/0/failure_prevention}}"), "−30.0");
  EXPECT_EQ(render("{{pct:1 diff 1 s/t/mle/0/0/failure_prevention}}"), "50.0");
  // Paired on the fields both write alike: strategy and w differ, so by scenario, target, rows, metric.
  EXPECT_EQ(render("{{pct:0 min diff s/t/direct,cross/5/0/failure_prevention s/t/mle/0/0/failure_prevention}}"), "10");
  EXPECT_EQ(render("{{pct:0 max abs diff s/t/cross/5/*/failure_prevention s/t/direct/5/*/failure_prevention}}"), "20");
  EXPECT_EQ(render("{{pct:0 min s/t/*/*/*/failure_prevention}} {{pct:0 max s/t/*/*/*/failure_prevention}}"), "50 80");
}

TEST(report_template_test, first_within_finds_where_two_lines_meet) {
  EXPECT_EQ(render("{{count first-within 0.015 s/t/mle/0/*/failure_prevention s/t/direct/5/*/failure_prevention}}"),
            "20");
  EXPECT_EQ(render("{{count first-within 0.1 s/t/mle/0/*/failure_prevention s/t/direct/5/*/failure_prevention}}"),
            "10");
  EXPECT_THAT(
      [] { render("{{count first-within 0.001 s/t/mle/0/*/failure_prevention s/t/direct/5/*/failure_prevention}}"); },
      ThrowsMessage<parse_error>(HasSubstr("never come within 0.001")));
}

TEST(report_template_test, errors_name_the_place_and_what_was_expected) {
  EXPECT_THAT([] { render("line 1\nab {{pct:1 s/t/foo/5/0/failure_prevention}}"); },
              ThrowsMessage<parse_error>(HasSubstr("t.md:2:4: {{pct:1 s/t/foo/5/0/failure_prevention}}: no summary row "
                                                   "matches 's/t/foo/5/0/failure_prevention': strategy 'foo' is none "
                                                   "of those left (mle, direct, cross)")));
  EXPECT_THAT([] { render("{{pct:1 s/t/direct,cross/5/0/failure_prevention}}"); },
              ThrowsMessage<parse_error>(HasSubstr("gives 2 values; reduce them with range, min or max")));
  EXPECT_THAT([] { render("{{percent s/t/mle/0/0/failure_prevention}}"); },
              ThrowsMessage<parse_error>(HasSubstr("unknown format 'percent'")));
  EXPECT_THAT([] { render("{{pct s/t/mle/0/0/failure_prevention}}"); },
              ThrowsMessage<parse_error>(HasSubstr("needs a number of decimals from 0 to 6, e.g. pct:1")));
  EXPECT_THAT([] { render("{{pct:1 s/t/mle/0/0/failure_prevention\n}}"); },
              ThrowsMessage<parse_error>(HasSubstr("t.md:1:1: a placeholder '{{' is not closed by '}}' on its line")));
  EXPECT_THAT([] { render("{{pct:1 sim:s/t/mle/0/0/failure_prevention}}"); },
              ThrowsMessage<parse_error>(HasSubstr("no summary is named 'sim' (named: bullet)")));
  EXPECT_THAT(
      [] { render("{{pct:1 s/t/mle/0/failure_prevention}}"); },
      ThrowsMessage<parse_error>(HasSubstr("has 5 fields; a selector is scenario/target/strategy/w/rows/metric")));
  EXPECT_THAT([] { render("{{pct:1 diff s/t/mle/0/0/failure_prevention}}"); },
              ThrowsMessage<parse_error>(HasSubstr("the expression ends early")));
  EXPECT_THAT([] { render("{{pct:1 s/t/mle/0/0/failure_prevention extra}}"); },
              ThrowsMessage<parse_error>(HasSubstr("unexpected 'extra' after the expression")));
  EXPECT_THAT([] { render("{{pct:1 plus 1}}"); }, ThrowsMessage<parse_error>(HasSubstr("'plus' is neither a number")));
  EXPECT_THAT([] { render("{{pct:1 diff s/t/direct,cross/5/0/failure_prevention s/t/*/*/0/failure_prevention}}"); },
              ThrowsMessage<parse_error>(HasSubstr("diff: more than one row of the second selection pairs with")));
  EXPECT_THAT([] { static_cast<void>(render_report_template("x", "t.md", {})); },
              ThrowsMessage<error>(HasSubstr("at least one summary")));
}

}  // namespace
}  // namespace report_template_tests
