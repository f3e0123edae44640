// Writing an experiment's results: the CSV tables (and reading the summary back), the plot
// scripts, the headline numbers, the output folder, and a whole run from C++ without the
// program.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

#include "eval/tiny_scenario.hpp"
#include "pgm/eval/headline.hpp"
#include "pgm/eval/plot.hpp"
#include "pgm/eval/report_writer.hpp"
#include "pgm/eval/result_tables.hpp"
#include "pgm/eval/run_scenarios.hpp"
#include "support/folder_test.hpp"

namespace report_tests {
namespace {

using namespace pgm;
using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;
using ::testing::ThrowsMessage;

void expect_same(const std::vector<aggregated_point>& a, const std::vector<aggregated_point>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].scenario, b[i].scenario);
    EXPECT_EQ(a[i].target, b[i].target);
    EXPECT_EQ(a[i].strategy, b[i].strategy);
    EXPECT_EQ(a[i].weight, b[i].weight);
    EXPECT_EQ(a[i].rows, b[i].rows);
    EXPECT_EQ(a[i].metric, b[i].metric);
    EXPECT_EQ(a[i].mean, b[i].mean) << "the same bits after a round trip";
    EXPECT_EQ(a[i].standard_deviation, b[i].standard_deviation);
    EXPECT_EQ(a[i].repetitions, b[i].repetitions);
  }
}

TEST(result_tables_test, points_and_summary_are_tidy_csv_with_quoted_names) {
  const std::vector<experiment_point> points{
      {"s,1", "t", "mle", "0", 0, 0, experiment_metric::max_difference, 0.1},
      {"s,1", "t", "mle", "0", 0, 1, experiment_metric::max_difference, 1.0 / 3}};
  std::ostringstream out;
  write_points_csv(points, out);
  EXPECT_EQ(out.str(),
            "scenario,target,strategy,w,rows,repetition,metric,value\n"
            "\"s,1\",t,mle,0,0,0,max_difference,0.1\n"
            "\"s,1\",t,mle,0,0,1,max_difference,0.3333333333333333\n");
  std::ostringstream summary;
  write_summary_csv(aggregate(points), summary);
  EXPECT_THAT(summary.str(), StartsWith("scenario,target,strategy,w,rows,metric,mean,sd,repetitions\n\"s,1\",t,mle,"));
  expect_same(parse_summary_csv(summary.str(), "summary.csv"), aggregate(points));
}

TEST(result_tables_test, a_broken_summary_is_an_error_naming_line_and_column) {
  EXPECT_THAT([] { static_cast<void>(parse_summary_csv("scenario,target,strategy,w,rows,metric,mean\n", "s.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("s.csv:1:1: the header has no column 'sd'")));
  const std::string header = "scenario,target,strategy,w,rows,metric,mean,sd,repetitions\n";
  EXPECT_THAT([&] { static_cast<void>(parse_summary_csv(header + "a,b,mle,0,10,max_difference,x,0,3\n", "s.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("s.csv:2:29: column 'mean': expected a finite number, got 'x'")));
  EXPECT_THAT([&] { static_cast<void>(parse_summary_csv(header + "a,b,mle,0,-1,max_difference,1,0,3\n", "s.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("column 'rows': expected a whole number, got '-1'")));
  EXPECT_THAT([&] { static_cast<void>(parse_summary_csv(header + "a,b,mle,0,1,max_difference,1,0\n", "s.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("expected 9 fields as in the header, found 8")));
  EXPECT_THAT([&] { static_cast<void>(parse_summary_csv(header + "a,b,mle,0,1,max_diference,1,0,3\n", "s.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("s.csv:2:13: column 'metric': unknown metric 'max_diference'; did "
                                                   "you mean 'max_difference'? (known: max_difference, "
                                                   "mean_difference, failure_prevention, chosen_w, prevention_cost, "
                                                   "utility_prevention, utility_prevention_cost)")));
  EXPECT_THAT([] { static_cast<void>(parse_summary_csv("", "s.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("the file is empty")));
}

std::vector<aggregated_point> tiny_summary() {
  const auto s = parse_scenario(pgm::test::tiny_scenario, "tiny.json");
  return aggregate(run_experiment(s, pgm::test::deterministic_tasks(), {.threads = 1}));
}

TEST(plot_test, one_panel_per_strategy_and_metric_with_the_legend_outside) {
  auto s = parse_scenario(pgm::test::tiny_scenario, "tiny.json");
  s.title = "Bob's tiny";
  const auto script = gnuplot_script(s, "two", tiny_summary(), "out/tiny-two");
  EXPECT_THAT(script, HasSubstr("set multiplot layout 3,3 title 'Bob''s tiny: two'"));
  EXPECT_THAT(script, HasSubstr("set key outside right"));
  EXPECT_THAT(script, Not(HasSubstr("set key top right")));
  EXPECT_THAT(script, HasSubstr("set output 'out/tiny-two.png'"));
  EXPECT_THAT(script, HasSubstr("set output 'out/tiny-two.svg'"));
  std::size_t plots = 0;
  for (auto at = script.find("\nplot "); at != std::string::npos; at = script.find("\nplot ", at + 1)) ++plots;
  EXPECT_EQ(plots, 2U * 9) << "3 metrics × 3 strategies, once per terminal";
  EXPECT_THAT(script, HasSubstr("title 'MLE'"));
  EXPECT_THAT(script, HasSubstr("title 'w = 5'"));
  EXPECT_THAT(script, HasSubstr("title 'oracle'"));
  // |D| runs 0, 10, …, 40: five points per line.
  EXPECT_THAT(script, HasSubstr("$d0 << EOD\n0 "));
  EXPECT_THAT(script, HasSubstr("\n40 "));
}

TEST(headline_test, success_at_zero_data_once_per_strategy_in_summary_order) {
  const auto s = parse_scenario(pgm::test::tiny_scenario, "tiny.json");
  std::vector<aggregated_point> summary{
      {"tiny", "two", "oracle", "0", 0, experiment_metric::failure_prevention, 1.0, 0, 3},
      {"tiny", "two", "mle", "0", 0, experiment_metric::failure_prevention, 0.123456, 0, 3},
      {"tiny", "two", "mle", "0", 10, experiment_metric::failure_prevention, 0.9, 0, 3},
      {"tiny", "two", "direct", "5", 0, experiment_metric::max_difference, 0.5, 0, 3},
      {"tiny", "two", "direct", "5", 0, experiment_metric::failure_prevention, 0.5, 0, 3},
      {"tiny", "two", "direct", "20", 0, experiment_metric::failure_prevention, 0.7, 0, 3},
      {"other", "two", "cross", "5", 0, experiment_metric::failure_prevention, 0.7, 0, 3}};
  const auto entries = prevention_at_zero_data(summary, "tiny", "two");
  ASSERT_EQ(entries.size(), 3U);
  EXPECT_EQ(entries[2].strategy, "direct");
  EXPECT_EQ(entries[2].success, 0.5) << "the first weight listed";
  EXPECT_EQ(headline(s, "two", summary),
            "Tiny, two: success after prevention at |D| = 0:  oracle 100%  mle 12.3%  direct 50%");
}

class report_writer_test : public pgm::testing::folder_test {};

TEST_F(report_writer_test, the_folder_is_checked_at_once_and_made_only_when_there_is_something_to_write) {
  const auto a_file = file("a.csv", "x\n");
  EXPECT_THAT([&] { report_writer w(a_file); }, ThrowsMessage<io_error>(HasSubstr("is a file, not a folder")));
  EXPECT_THAT([&] { report_writer w(dir_ / "missing" / "out"); },
              ThrowsMessage<io_error>(HasSubstr("the folder '" + (dir_ / "missing").string() + "' does not exist")));
  EXPECT_THAT([&] { report_writer w(""); }, ThrowsMessage<io_error>(HasSubstr("no output folder")));
  report_writer writer(dir_ / "out");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out"));
}

TEST_F(report_writer_test, a_cpp_program_runs_an_experiment_into_a_folder) {
  const auto s = parse_scenario(pgm::test::tiny_scenario, "tiny.json");
  std::vector<std::string> headlines, notes;
  std::vector<std::size_t> progress;
  run_scenarios_options options;
  options.experiment.seed = 3;
  options.experiment.threads = 2;
  options.headline = [&](const std::string& line) { headlines.push_back(line); };
  options.note = [&](const std::string& text) { notes.push_back(text); };
  options.progress = [&](const scenario& running, std::size_t done, std::size_t total) {
    EXPECT_EQ(running.name, "tiny");
    EXPECT_EQ(total, 3U);
    progress.push_back(done);
  };
  const auto files = run_scenarios({s}, pgm::test::deterministic_tasks(), dir_ / "out", options);

  const auto expected = run_experiment(s, pgm::test::deterministic_tasks(), {.seed = 3, .threads = 1});
  EXPECT_EQ(files.points, expected.size());
  EXPECT_EQ(files.points_csv, dir_ / "out" / "points.csv");
  EXPECT_FALSE(files.plots_rendered);
  std::ostringstream points;
  write_points_csv(expected, points);
  EXPECT_EQ(slurp(files.points_csv), points.str());
  expect_same(read_summary_csv(files.summary_csv), aggregate(expected));
  EXPECT_THAT(slurp(dir_ / "out" / "tiny-two.gp"),
              HasSubstr("set output '" + (dir_ / "out" / "tiny-two.png").string()));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out" / "tiny-two.png")) << "rendering was not asked for";
  EXPECT_THAT(headlines, ElementsAre(headline(s, "two", aggregate(expected))));
  EXPECT_THAT(headlines[0], HasSubstr("minimal 100%"));
  EXPECT_EQ(progress.back(), 3U);
  for (const auto& n : notes) EXPECT_THAT(n, StartsWith("tiny: "));
}

TEST_F(report_writer_test, the_renderer_draws_each_written_script_and_a_failure_is_a_note) {
  const auto s = parse_scenario(pgm::test::tiny_scenario, "tiny.json");
  std::vector<std::string> rendered, notes;
  report_options options;
  options.render_plots = [&](const std::filesystem::path& script) {
    rendered.push_back(slurp(script));
    return false;
  };
  options.note = [&](const std::string& text) { notes.push_back(text); };
  report_writer writer(dir_ / "out", options);
  writer.add(s, run_experiment(s, pgm::test::deterministic_tasks(), {.seed = 3, .threads = 1}));
  EXPECT_TRUE(writer.finish().plots_rendered);
  ASSERT_THAT(rendered, ElementsAre(HasSubstr("set output '" + (dir_ / "out" / "tiny-two.svg").string())));
  EXPECT_EQ(rendered[0], slurp(dir_ / "out" / "tiny-two.gp")) << "the script is written before it is rendered";
  EXPECT_THAT(notes, ElementsAre("the plot script " + (dir_ / "out" / "tiny-two.gp").string() + " failed to render"));
}

TEST_F(report_writer_test, a_failing_scenario_names_its_file_and_writes_nothing) {
  const auto s = parse_scenario(pgm::test::tiny_scenario, "tiny.json");
  auto source = pgm::test::deterministic_tasks();
  source.data = [](const std::string& task, std::size_t, std::uint64_t) -> dataset {
    throw data_error("no data for " + task);
  };
  run_scenarios_options options;
  EXPECT_THAT([&] { static_cast<void>(run_scenarios({s}, source, dir_ / "out", options)); },
              ThrowsMessage<error>(HasSubstr("tiny.json: no data for one")));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out"));
}

}  // namespace
}  // namespace report_tests
