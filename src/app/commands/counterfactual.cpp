// pgm counterfactual: bounds on the probabilities of necessity and sufficiency of a cause for an
// effect on a causal network (Tian & Pearl).

#include <iostream>
#include <memory>
#include <string>

#include "cli/common.hpp"
#include "pgm/causal/probability_of_causation.hpp"
#include "pgm/core/text.hpp"
#include "pgm/inference/posterior_table.hpp"

namespace pgm::cli {
namespace {

struct counterfactual_arguments {
  std::string model;
  std::string cause;
  std::string alternative;
  std::string effect;
  std::string evidence;
  std::string format = "text";
};

/// "X=x" split at its '='.
std::pair<std::string, std::string> variable_and_state(const std::string& text, const std::string& option) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    throw model_error(option + ": expected VARIABLE=STATE, found '" + text + "'");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

void run_counterfactual(const counterfactual_arguments& args) {
  const auto network = read_network_file(args.model);
  const auto [cause, cause_state] = variable_and_state(args.cause, "--cause");
  const auto [effect, effect_state] = variable_and_state(args.effect, "--effect");
  const auto terms = causation_terms_of(network, cause, cause_state, args.alternative, effect, effect_state,
                                        parse_evidence(args.evidence));
  const auto b = bound_causation(terms);
  if (args.format == "json") {
    std::cout << "{\"pn_lower\": " << json_number(b.pn_lower) << ", \"pn_upper\": " << json_number(b.pn_upper)
              << ", \"ps_lower\": " << json_number(b.ps_lower) << ", \"ps_upper\": " << json_number(b.ps_upper)
              << ", \"pns_lower\": " << json_number(b.pns_lower) << ", \"pns_upper\": " << json_number(b.pns_upper)
              << "}\n";
    return;
  }
  const auto range = [](double lower, double upper) {
    return "[" + text::format_short(lower) + ", " + text::format_short(upper) + "]";
  };
  const auto yes = effect + "=" + effect_state;
  std::cout << "necessity   PN  = P(not " << yes << " had " << cause << " been " << args.alternative << " | " << cause
            << "=" << cause_state << ", " << yes << ") in " << range(b.pn_lower, b.pn_upper) << '\n'
            << "sufficiency PS  = P(" << yes << " had " << cause << " been " << cause_state << " | " << cause << "="
            << args.alternative << ", not " << yes << ") in " << range(b.ps_lower, b.ps_upper) << '\n'
            << "both        PNS in " << range(b.pns_lower, b.pns_upper) << '\n';
}

}  // namespace

void add_counterfactual_command(CLI::App& app) {
  auto args = std::make_shared<counterfactual_arguments>();
  auto* cmd = app.add_subcommand(
      "counterfactual",
      "Was X the cause of Y? Bound the probability of necessity (had X been the alternative, would Y not have "
      "happened, given that both happened), of sufficiency, and of both, from the network's observational and "
      "interventional distributions (Tian & Pearl 2000): a causal network does not identify them.\n"
      "Example: pgm counterfactual --model fitted.json --cause xOff1=4 --alternative 2 --effect onTop1=0");
  cmd->add_option("--model", args->model, "The causal network: " + network_file_kinds())->required();
  cmd->add_option("--cause", args->cause, "The cause as it happened, VARIABLE=STATE")->required();
  cmd->add_option("--alternative", args->alternative, "The cause's state in the world that did not happen")->required();
  cmd->add_option("--effect", args->effect, "The effect as it happened, VARIABLE=STATE")->required();
  cmd->add_option("--evidence", args->evidence,
                  "What else was observed, of variables the cause does not influence, e.g. \"a=s,b=t\"");
  cmd->add_option("--format", args->format, "Output: text or json (numbers to 17 significant digits)")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  cmd->callback([args] { run_counterfactual(*args); });
}

}  // namespace pgm::cli
