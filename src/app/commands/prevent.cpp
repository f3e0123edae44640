// pgm prevent: predict, explain a predicted failure and suggest the nearest values of the
// controllable variables predicted to succeed, or (--reward) the move of highest expected utility.

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "cli/episode.hpp"
#include "cli/move_cost_options.hpp"
#include "commands/decide_common.hpp"
#include "pgm/core/text.hpp"
#include "pgm/decide/assignment.hpp"
#include "pgm/decide/counterfactual_success.hpp"
#include "pgm/decide/explain.hpp"
#include "pgm/decide/prevent_by_utility.hpp"
#include "pgm/decide/prevent_over_time.hpp"

namespace pgm::cli {
namespace {

struct prevent_arguments {
  decision_arguments decision;
  std::optional<std::string> controllable;  // given but empty is an error, not the default
  double epsilon = 0.8;
  std::string distance = "steps";
  move_cost_arguments utility;
  std::string format = "text";
  bool dynamic = false;
  std::string data;
  std::size_t steps = 0;
};

/// Each moving variable, from where to where, then the value suggested for every controllable one.
void print_moves(const explanation& why, const bayesian_network& network, const assignment& planned) {
  for (const auto& c : why.responsible()) {
    const auto& v = network.at(c.variable);
    std::cout << "  " << c.variable << ": " << describe_state(v, c.from_state) << " -> "
              << describe_state(v, c.to_state);
    if (c.move) std::cout << " (move " << (*c.move > 0 ? "+" : "") << with_unit(v, *c.move) << ")";
    std::cout << '\n';
  }
  std::cout << "suggested values:\n";
  const auto suggested = suggested_values(why, planned);
  for (const auto& c : why.changes) {
    const auto& v = network.at(c.variable);
    const auto& value = suggested.at(c.variable);
    std::cout << "  " << c.variable << " = ";
    if (const auto* number = std::get_if<double>(&value)) {
      std::cout << with_unit(v, *number) << " (interval " << describe_state(v, c.to_state) << ")";
    } else {
      std::cout << std::get<std::string>(value);
    }
    std::cout << (c.moves() ? "" : " (unchanged)") << '\n';
  }
}

/// What the change would have done for a run of the plan that failed; nothing, with a note, where
/// the success table is too large to read as a structural model (the suggestion stands without it).
std::optional<double> counterfactual_of(const bayesian_network& network, const explanation& why,
                                        const assignment& planned) {
  try {
    return counterfactual_success(network, why, planned);
  } catch (const table_too_large& e) {
    note(std::string("the counterfactual is left out: ") + e.what());
    return std::nullopt;
  }
}

void print_counterfactual(const bayesian_network& network, const explanation& why, const assignment& planned) {
  if (const auto p = counterfactual_of(network, why, planned)) {
    std::cout << "had a run of the plan failed, the change would have made it succeed with probability "
              << text::format_short(*p) << " (counterfactual, the network read as monotone: docs/causal.md)\n";
  }
}

/// The move of highest expected utility (--reward): prevention as a decision.
void print_best_move(const prevent_arguments& args, const prevention_plan& plan, const bayesian_network& network,
                     const assignment& planned, const std::vector<std::string>& controllable) {
  const auto costs = *move_costs_of(args.utility);
  const auto [move, why] = prevent_by_utility(plan, controllable, costs);
  if (args.format == "json") {
    std::string out = "{\"success\": " + nlohmann::json(why.success_variable + "=" + why.success_state).dump() +
                      ", \"predicted\": " + json_number(why.predicted) + ", \"plan\": {";
    for (std::size_t i = 0; i < why.changes.size(); ++i) {
      out += (i ? ", " : "") + nlohmann::json(why.changes[i].variable).dump() + ": " +
             nlohmann::json(why.changes[i].to_label).dump();
    }
    out += "}, \"moves\": [";
    const auto responsible = why.responsible();
    for (std::size_t i = 0; i < responsible.size(); ++i) {
      out += (i ? ", " : "") + nlohmann::json(responsible[i].variable).dump();
    }
    out += "], \"expected_utility\": " + json_number(move.expected_utility) +
           ", \"success_probability\": " + json_number(move.success_probability) +
           ", \"cost\": " + json_number(move.cost);
    if (const auto p = counterfactual_of(network, why, planned))
      out += ", \"counterfactual_success\": " + json_number(*p);
    out += "}";
    std::cout << out << '\n';
    return;
  }
  std::cout << "success: " << why.success_variable << "=" << why.success_state << '\n';
  std::cout << "predicted success probability: " << text::format_short(why.predicted) << '\n';
  std::cout << "best move by expected utility (reward " << text::format_short(costs.reward)
            << " for success, costs per " << cost_unit_label(costs) << "): expected utility "
            << text::format_short(move.expected_utility) << " (success " << text::format_short(move.success_probability)
            << ", cost " << text::format_short(move.cost) << ")\n";
  if (why.responsible().empty()) {
    std::cout << "keep the plan: no move of " << text::join(controllable) << " gains more than it costs\n";
    return;
  }
  print_moves(why, network, planned);
  print_counterfactual(network, why, planned);
}

/// pgm prevent --dynamic: the next step of an episode of a dynamic network.
void run_prevent_over_time(const prevent_arguments& args) {
  const auto refuse = [](bool given, const std::string& option) {
    if (given) throw error("--dynamic: " + option + " does not apply; the episode (--data) gives what is known");
  };
  refuse(!args.decision.assign.empty(), "--assign");
  refuse(args.decision.marginalize, "--marginalize");
  refuse(args.utility.reward.has_value(), "--reward");
  if (args.data.empty()) throw error("--dynamic needs --data, the episode so far in long form (episode,t,<variables>)");
  if (args.decision.success.empty()) throw error("--dynamic needs --success, e.g. --success onTop=1");
  if (!args.controllable || args.controllable->empty()) {
    throw error("--dynamic needs --controllable, the variables set at the next step");
  }
  const auto model = read_dynamic_model_file(args.decision.model).model;
  prevention_over_time_request request;
  request.success = parse_success_event(args.decision.success, model.initial());
  for (const auto& name : split_list(*args.controllable, "--controllable")) {
    request.controllable.push_back(template_id(model, name, "--controllable"));
  }
  request.steps = read_episode(model, args.data);
  request.horizon = args.steps;
  const auto answer = prevent_over_time(model, request);
  const auto last = answer.horizon - 1;
  const auto steps = answer.step == last ? "step " + std::to_string(answer.step)
                                         : "steps " + std::to_string(answer.step) + " to " + std::to_string(last);
  if (args.format == "json") {
    std::string out = "{\"step\": " + std::to_string(answer.step) + ", \"horizon\": " + std::to_string(answer.horizon) +
                      ", \"success\": " + nlohmann::json(args.decision.success).dump() +
                      ", \"planned\": " + (answer.planned ? "true" : "false") +
                      ", \"before\": " + json_number(answer.before) + ", \"best\": {";
    for (std::size_t i = 0; i < answer.best.size(); ++i) {
      out += (i ? ", " : "") + nlohmann::json(answer.best[i].first).dump() + ": " +
             nlohmann::json(answer.best[i].second).dump();
    }
    std::cout << out << "}, \"after\": " << json_number(answer.after) << "}\n";
    return;
  }
  std::cout << "success: " << request.success.variable << "=" << request.success.state << " at " << steps << '\n'
            << "predicted success " << (answer.planned ? "as planned" : "with the next step left to the model") << ": "
            << text::format_short(answer.before) << '\n'
            << "best setting at step " << answer.step << ":";
  for (const auto& [name, state] : answer.best) std::cout << ' ' << name << '=' << state;
  std::cout << "\npredicted success after it: " << text::format_short(answer.after) << '\n';
}

void run_prevent(const prevent_arguments& args) {
  if (args.dynamic) {
    run_prevent_over_time(args);
    return;
  }
  if (!args.data.empty() || args.steps != 0) throw error("--data and --steps apply with --dynamic");
  if (!args.utility.reward && args.format != "text") throw error("--format applies with --reward or --dynamic");
  if (args.decision.assign.empty()) throw CLI::RequiredError("--assign");
  const auto model = read_decision_model(args.decision.model, args.decision.success);
  const auto& network = model.network;
  const auto planned = read_assignment(args.decision.assign, network);
  std::vector<std::string> controllable;
  if (!args.controllable) {
    controllable = default_controllable(network, model.success);
    note("no --controllable given: every parent of '" + model.success.variable + "' may move (" +
         text::join(controllable) + ")");
  } else {
    if (!args.controllable->empty()) controllable = split_list(*args.controllable, "--controllable");
  }
  prevention_options options;
  options.epsilon = args.epsilon;
  options.metric = parse_distance(args.distance);
  const auto plan = plan_prevention(network, model.success, planned, controllable, options,
                                    {.marginalize_missing = args.decision.marginalize});
  if (args.utility.reward) {
    print_best_move(args, plan, network, planned, controllable);
    return;
  }
  const auto& why = plan.why;
  std::cout << "success: " << why.success_variable << "=" << why.success_state << '\n';
  std::cout << "predicted success probability: " << text::format_short(why.predicted) << '\n';
  if (!why.failure_predicted()) {
    std::cout << "no failure predicted (not below epsilon " << text::format_short(why.epsilon) << "); keep the plan\n";
    return;
  }
  std::cout << "failure predicted (below epsilon " << text::format_short(why.epsilon) << ")\n";
  const auto responsible = why.responsible();
  if (responsible.empty()) {
    std::cout << "explanation: no change of the controllable variables (" << text::join(controllable)
              << ") predicts a higher success\n";
    return;
  }
  std::cout << "explanation: "
            << (why.target_succeeds() ? "the smallest change predicted to succeed"
                                      : "no change reaches epsilon; the best one")
            << " (" << why.steps << " bin step" << (why.steps == 1 ? "" : "s");
  if (why.distance_units) std::cout << ", distance " << text::format_short(*why.distance_units);
  std::cout << ")\n";
  print_moves(why, network, planned);
  std::cout << "predicted success after prevention: " << text::format_short(why.target_predicted) << '\n';
  print_counterfactual(network, why, planned);
}

}  // namespace

void add_prevent_command(CLI::App& app) {
  auto args = std::make_shared<prevent_arguments>();
  auto* cmd = app.add_subcommand(
      "prevent",
      "Predict success; below epsilon, explain the failure and suggest the nearest values of the controllable "
      "variables predicted to succeed (breadth-first in bin steps; ties to the higher prediction; if none "
      "exceeds epsilon, the best). A suggestion is judged as an intervention, P(success | do(controllable), the "
      "other assigned variables): the robot sets those variables, and where one has a parent in the network "
      "setting it differs from observing it (docs/decide.md).");
  add_decision_options(*cmd, args->decision, false);
  cmd->add_option("--controllable", args->controllable,
                  "Variables the robot may change, e.g. xOff1,yOff1 (default: every parent of the success variable)");
  cmd->add_option("--epsilon", args->epsilon, "Success threshold, 0 ≤ epsilon < 1: a prediction above it succeeds")
      ->check(number_between(0, 1, false, true))
      ->capture_default_str();
  cmd->add_option("--distance", args->distance,
                  "Nearness: steps (bins moved) or units (Euclidean distance between interval midpoints)")
      ->check(CLI::IsMember(known_distances()))
      ->capture_default_str();
  add_move_cost_options(*cmd, args->utility,
                        "Choose the move of highest expected utility instead: success is worth this much, failure 0, "
                        "less what moving costs (--move-cost)");
  cmd->add_option("--format", args->format,
                  "With --reward or --dynamic: text or json (numbers to 17 significant digits)")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  cmd->add_flag("--dynamic", args->dynamic,
                "A dynamic network (pgm's JSON of \"kind\": \"dynamic\"): having seen an episode's first steps "
                "(--data), the states of --controllable at the next step (the first whose success variable is not "
                "observed) likeliest to make every step up to --steps succeed, each judged as an intervention");
  cmd->add_option("--data", args->data,
                  "With --dynamic: the episode so far in long form (episode,t,<variables>); a row for the step "
                  "decided may give the plan and what else is known then");
  cmd->add_option("--steps", args->steps,
                  "With --dynamic: the steps of the task in all (the success variable must hold at each from the "
                  "next on); default: the next step alone")
      ->check(whole_number(1, 1 << 20));
  cmd->callback([args] { run_prevent(*args); });
}

}  // namespace pgm::cli
