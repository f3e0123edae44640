// pgm prevent: predict, explain a predicted failure and suggest the nearest values of the
// controllable variables predicted to succeed.

#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "commands/decide_common.hpp"
#include "pgm/core/text.hpp"
#include "pgm/decide/assignment.hpp"
#include "pgm/decide/explain.hpp"

namespace pgm::cli {
namespace {

struct prevent_arguments {
  decision_arguments decision;
  std::optional<std::string> controllable;  // given but empty is an error, not the default
  double epsilon = 0.8;
  std::string distance = "steps";
};

void run_prevent(const prevent_arguments& args) {
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
  for (const auto& c : responsible) {
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
  std::cout << "predicted success after prevention: " << text::format_short(why.target_predicted) << '\n';
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
  add_decision_options(*cmd, args->decision);
  cmd->add_option("--controllable", args->controllable,
                  "Variables the robot may change, e.g. xOff1,yOff1 (default: every parent of the success variable)");
  cmd->add_option("--epsilon", args->epsilon, "Success threshold, 0 ≤ epsilon < 1: a prediction above it succeeds")
      ->check(number_between(0, 1, false, true))
      ->capture_default_str();
  cmd->add_option("--distance", args->distance,
                  "Nearness: steps (bins moved) or units (Euclidean distance between interval midpoints)")
      ->check(CLI::IsMember(known_distances()))
      ->capture_default_str();
  cmd->callback([args] { run_prevent(*args); });
}

}  // namespace pgm::cli
