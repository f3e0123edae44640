// pgm check: tests every independence a model's DAG implies locally against data, and lists
// the ones the data reject, most significant first.

#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "cli/component_options.hpp"
#include "pgm/causal/dag_check.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/text.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/network_file.hpp"

namespace pgm::cli {
namespace {

struct check_arguments {
  std::string model;
  std::string data;
  std::string test = independence_test().name();
  double alpha = 0.05;
  bool all = false;
  std::string format = "text";
  unsigned threads = 0;
  std::string out;
  missing_arguments missing;
};

std::string independence_text(const implied_independence& t) {
  return t.x + " _||_ " + t.y + (t.given.empty() ? "" : " | " + text::join(t.given));
}

void run_check(const check_arguments& args) {
  if (!args.out.empty()) pgm::check_output_path(args.out);
  const auto structure = read_model_file(args.model).structure;
  std::vector<std::string> columns;
  for (const auto& v : structure.variables()) columns.push_back(v.name());
  const auto data = read_discrete_data(args.data, columns, {.missing = missing_of(args.missing)});
  dag_check_options options;
  options.test = make_independence_test(args.test);
  options.alpha = args.alpha;
  options.threads = args.threads;
  const auto result = check_dag(structure, data, options);
  std::ostringstream out;
  if (args.format == "csv") {
    out << "x,y,given,statistic,df,p_value,rejected\n";
    for (const auto& t : result.tests) {
      if (!args.all && t.result.independent(result.alpha)) continue;
      out << text::csv_escape(t.x, ',') << ',' << text::csv_escape(t.y, ',') << ','
          << text::csv_escape(text::join(t.given, ";"), ',') << ',' << text::format_double(t.result.statistic) << ','
          << text::format_double(t.result.df) << ',' << text::format_double(t.result.p_value) << ','
          << (t.result.independent(result.alpha) ? "no" : "yes") << '\n';
    }
  } else {
    out << "Tested the " << result.tests.size() << " independences the DAG implies on " << data.rows() << " rows ("
        << args.test << ", alpha " << text::format_short(result.alpha) << "): " << result.rejected() << " rejected\n";
    for (const auto& t : result.tests) {
      const bool rejected = !t.result.independent(result.alpha);
      if (!args.all && !rejected) continue;
      out << (rejected ? "  rejected  " : "  kept      ") << independence_text(t) << ": statistic "
          << text::format_short(t.result.statistic) << ", df " << text::format_short(t.result.df) << ", p "
          << text::format_short(t.result.p_value) << '\n';
    }
  }
  if (args.out.empty()) {
    std::cout << out.str();
  } else {
    pgm::write_file_atomically(args.out, [&](std::ostream& file) { file << out.str(); });
  }
}

}  // namespace

void add_check_command(CLI::App& app) {
  auto args = std::make_shared<check_arguments>();
  auto* cmd = app.add_subcommand(
      "check",
      "Test every independence the model's DAG implies (each variable independent of its non-descendants given its "
      "parents, one test per pair of variables without an edge) against data, and list those the data reject, "
      "smallest p-value first.\nExample: pgm check --model alarm.bif --data alarm-10000.csv --alpha 0.01");
  cmd->add_option("--model", args->model, "The model: " + network_file_kinds() + " (a structure is enough)")
      ->required();
  cmd->add_option("--data", args->data, std::string("Discrete data with a column per variable") + data_file_help)
      ->required();
  add_component_option(*cmd, "--test", args->test, "Independence test", independence_tests());
  cmd->add_option("--alpha", args->alpha, "A test with p at most alpha rejects its independence, 0 < alpha < 1")
      ->check(number_between(0, 1, true, true))
      ->capture_default_str();
  cmd->add_flag("--all", args->all, "List every test, not only the rejected ones");
  cmd->add_option("--format", args->format, "Output: text or csv (x,y,given,statistic,df,p_value,rejected)")
      ->check(CLI::IsMember({"text", "csv"}))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Threads (0: every core); the result is the same")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Write the result to this file instead of standard output");
  add_missing_options(*cmd, args->missing);
  cmd->callback([args] { run_check(*args); });
}

}  // namespace pgm::cli
