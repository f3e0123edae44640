// pgm filter: inference over time in a dynamic network, on one episode's data in long form
// (episode,t,<variables>): filtering P(X_t | e_0..t), smoothing P(X_t | e_0..T−1) and prediction
// past the last step, by the interface algorithm (pgm/inference/dynamic_inference.hpp).

#include <cmath>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "cli/episode.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/core/text.hpp"
#include "pgm/inference/dynamic_inference.hpp"
#include "pgm/io/csv.hpp"

namespace pgm::cli {
namespace {

struct filter_arguments {
  std::string model;
  std::string data;
  bool smooth = false;
  bool most_probable = false;
  std::size_t predict = 0;
  std::string query;
  std::string intervene;
  int digits = 6;
  std::string out;
};

/// "x@3=on,y@0=off": do(x = on) at step 3 and do(y = off) at step 0, into `steps` (grown to hold
/// a step past the data, which prediction then reaches).
void add_interventions(const dynamic_network& model, const std::string& list, std::vector<evidence_set>& steps,
                       std::size_t predict) {
  for (const auto& item : split_list(list, "--do")) {
    const auto eq = item.find('=');
    const auto at = item.rfind('@', eq);
    if (eq == std::string::npos || at == std::string::npos) {
      throw error("--do: '" + item + "' is not variable@step=state (e.g. x@3=on)");
    }
    const auto name = item.substr(0, at);
    const auto step_text = item.substr(at + 1, eq - at - 1);
    const auto state = item.substr(eq + 1);
    const auto step = text::parse_double(step_text);
    if (!step || *step < 0 || *step != std::floor(*step) || *step >= static_cast<double>(steps.size() + predict)) {
      throw error("--do: '" + item + "': the step must be a whole number from 0 to " +
                  std::to_string(steps.size() + predict - 1));
    }
    const auto id = template_id(model, name, "--do");
    const auto& v = model.variables()[id.value()];
    state_index s;
    try {
      s = v.state(state);
    } catch (const model_error& e) {
      throw error(std::string("--do: ") + e.what());
    }
    const auto t = static_cast<std::size_t>(*step);
    if (t >= steps.size()) steps.resize(t + 1);
    steps[t].intervened.push_back({id, s});
  }
}

/// The most probable sequence: t,variable,state for the variables asked and not observed nor set,
/// P(x*, e) on standard error.
void write_most_probable(const dynamic_network& model, const most_probable_steps& best,
                         const std::vector<evidence_set>& steps, const std::vector<char>& asked,
                         const filter_arguments& args) {
  std::ostringstream table;
  table << "t,variable,state\n";
  for (std::size_t t = 0; t < best.states.size(); ++t) {
    for (std::size_t i = 0; i < model.size(); ++i) {
      if (!asked[i] || steps[t].fixes(index_at<variable_id>(i))) continue;
      const auto& v = model.variables()[i];
      table << t << ',' << text::csv_escape(v.name(), ',') << ','
            << text::csv_escape(v.states()[best.states[t][i]], ',') << '\n';
    }
  }
  note("P(x*, e) = " + text::format_short(std::exp(best.log_probability), args.digits) +
       ", ln P(x*, e) = " + text::format_double(best.log_probability));
  std::ostringstream summary;
  summary << "the most probable sequence of " << steps.size() << " steps of " << args.data << " -> " << args.out
          << '\n';
  pgm::write_file_atomically(
      args.out, [&](std::ostream& out) { out << table.str(); }, summary_before_replacing(summary.str(), args.out));
}

void run_filter(const filter_arguments& args) {
  pgm::check_output_path(args.out);
  const auto model = read_dynamic_model_file(args.model).model;
  auto steps = read_episode(model, args.data);
  const std::size_t observed_steps = steps.size();
  if (!args.intervene.empty()) add_interventions(model, args.intervene, steps, args.predict);
  if (steps.size() > observed_steps && (args.smooth || args.most_probable)) {
    throw error("--do: a step past the data (" + std::to_string(observed_steps) +
                " steps) is reached only by --predict");
  }
  std::vector<char> asked(model.size(), args.query.empty() ? 1 : 0);
  if (!args.query.empty()) {
    for (const auto& name : split_list(args.query, "--query")) asked[template_id(model, name, "--query").value()] = 1;
  }
  interface_filter filter(model);
  if (args.most_probable) {
    write_most_probable(model, filter.most_probable(steps), steps, asked, args);
    return;
  }
  const std::size_t beyond =
      args.predict > steps.size() - observed_steps ? args.predict - (steps.size() - observed_steps) : 0;
  const auto answer = args.smooth ? filter.smooth(steps) : filter.filter(steps, beyond);
  std::ostringstream table;
  table << "t,variable,state,probability\n";
  for (std::size_t t = 0; t < answer.steps.size(); ++t) {
    const evidence_set none;
    const auto& here = t < steps.size() ? steps[t] : none;
    for (std::size_t i = 0; i < model.size(); ++i) {
      const variable_id id = index_at<variable_id>(i);
      if (!asked[i] || here.fixes(id)) continue;
      const auto& v = model.variables()[i];
      for (std::size_t s = 0; s < v.cardinality(); ++s) {
        table << t << ',' << text::csv_escape(v.name(), ',') << ',' << text::csv_escape(v.states()[s], ',') << ','
              << text::format_short(answer.steps[t][i][s], args.digits) << '\n';
      }
    }
  }
  std::ostringstream summary;
  summary << (args.smooth ? "smoothed " : "filtered ") << observed_steps << " steps of " << args.data;
  if (!args.smooth && answer.steps.size() > observed_steps) {
    summary << " and predicted " << answer.steps.size() - observed_steps << " more";
  }
  summary << " -> " << args.out << " (ln P(evidence) = " << text::format_double(answer.log_evidence_probability)
          << "; interface of " << filter.interface().size() << " variables)\n";
  pgm::write_file_atomically(
      args.out, [&](std::ostream& out) { out << table.str(); }, summary_before_replacing(summary.str(), args.out));
}

}  // namespace

void add_filter_command(CLI::App& app) {
  auto args = std::make_shared<filter_arguments>();
  auto* cmd = app.add_subcommand(
      "filter",
      "Inference over time in a dynamic network (a 2-TBN in pgm's JSON): every variable's distribution at each step "
      "of one episode given the steps so far (filtering) or the whole episode (--smooth), and past its end "
      "(--predict), by two junction trees compiled once, so a step costs the same however long the episode. The data "
      "are in long form, one row per step: episode,t,<variables>, t = 0, 1, … in order, an empty cell unobserved. "
      "Writes t,variable,state,probability for the unobserved variables.\nExample:\n  pgm filter --model tower.json "
      "--data episode.csv --smooth --out marginals.csv");
  cmd->add_option("--model", args->model, "The dynamic network (.json, \"kind\": \"dynamic\")")->required();
  cmd->add_option("--data", args->data,
                  std::string("One episode in long form (episode,t,<variables>)") + data_file_help)
      ->required();
  auto* smooth =
      cmd->add_flag("--smooth", args->smooth, "Condition every step on the whole episode, not on the steps up to it");
  auto* most_probable = cmd->add_flag("--most-probable", args->most_probable,
                                      "Write the most probable sequence instead: t,variable,state for the unobserved "
                                      "variables, P(x*, e) on standard error");
  most_probable->excludes(smooth);
  cmd->add_option("--predict", args->predict, "Steps past the data to predict, without evidence (default 0)")
      ->check(whole_number(0, max_unrolled_variables))
      ->excludes(smooth)
      ->excludes(most_probable);
  cmd->add_option("--query", args->query, "Only these variables, comma-separated (default: every one)");
  cmd->add_option("--do", args->intervene,
                  "Interventions at steps: x@3=on,y@0=off (the variable's table left out there)");
  cmd->add_option("--digits", args->digits, "Significant digits of each probability, 1-17 (17: full precision)")
      ->check(CLI::Range(1, 17));
  cmd->add_option("--out", args->out, "The CSV to write, atomically")->required();
  cmd->callback([args] { run_filter(*args); });
}

}  // namespace pgm::cli
