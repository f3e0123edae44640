// pgm predict: the probability that a planned action succeeds.

#include "pgm/decide/predict.hpp"

#include <iostream>
#include <memory>
#include <string>

#include "cli/common.hpp"
#include "commands/decide_common.hpp"
#include "pgm/core/text.hpp"
#include "pgm/decide/assignment.hpp"

namespace pgm::cli {
namespace {

struct predict_arguments {
  decision_arguments decision;
};

void run_predict(const predict_arguments& args) {
  const auto model = read_decision_model(args.decision.model, args.decision.success);
  const auto planned = read_assignment(args.decision.assign, model.network);
  const auto p =
      predict_success(model.network, model.success, planned, {.marginalize_missing = args.decision.marginalize});
  std::cout << "success: " << model.success.variable << "=" << model.success.state << '\n';
  for (const auto& [name, value] : planned) {
    const auto& v = model.network.at(name);
    std::cout << "  " << name << " = "
              << (std::holds_alternative<double>(value) ? with_unit(v, std::get<double>(value)) + " -> state "
                                                        : std::string("state "))
              << describe_state(v, state_of(v, value).value()) << '\n';
  }
  for (const auto& name : unassigned_parents(model.network, model.success, planned)) {
    std::cout << "  " << name << " summed out (not assigned)\n";
  }
  std::cout << "predicted success probability: " << text::format_short(p) << '\n';
}

}  // namespace

void add_predict_command(CLI::App& app) {
  auto args = std::make_shared<predict_arguments>();
  auto* cmd = app.add_subcommand(
      "predict",
      "Predict the probability that a planned action succeeds.\n"
      "The success event is --success, else a JSON model's \"metadata\": {\"success\": \"onTop2=1\"}, else the "
      "unique variable with parents, no children and a state \"1\".");
  add_decision_options(*cmd, args->decision);
  cmd->callback([args] { run_predict(*args); });
}

}  // namespace pgm::cli
