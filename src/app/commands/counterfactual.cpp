// pgm counterfactual: "had X been x', would Y have happened?". On a structural model (or a
// network read as one under the monotone assumption), the counterfactual distribution itself;
// on a causal network, bounds on the probabilities of necessity and sufficiency (Tian & Pearl).

#include "pgm/causal/counterfactual.hpp"

#include <iostream>
#include <memory>
#include <string>

#include "cli/common.hpp"
#include "pgm/causal/probability_of_causation.hpp"
#include "pgm/core/text.hpp"
#include "pgm/inference/posterior_table.hpp"
#include "pgm/io/structural_file.hpp"

namespace pgm::cli {
namespace {

struct counterfactual_arguments {
  std::string model;
  std::string cause;
  std::string alternative;
  std::string effect;
  std::string evidence;
  std::string intervene;
  std::string query;
  std::string assume;
  std::string format;
  int digits = 6;
  std::string out;
};

/// "X=x" split at its '='.
std::pair<std::string, std::string> variable_and_state(const std::string& text, const std::string& option) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    throw model_error(option + ": expected VARIABLE=STATE, found '" + text + "'");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

/// The counterfactual distribution on --model: a structural model as the file holds it, or a
/// network read as one under --assume.
posterior counterfactual_of(const counterfactual_arguments& args, std::span<const std::string> names,
                            const evidence& observed, const intervention& set) {
  if (holds_structural_model(args.model)) {
    if (!args.assume.empty()) {
      throw CLI::ValidationError("counterfactual", "'" + args.model + "' is a structural model: it needs no --assume");
    }
    return counterfactual_query(read_structural_model(args.model), names, observed, set);
  }
  if (args.assume.empty()) {
    throw error("'" + args.model +
                "' is a causal network, which does not determine counterfactuals: give a structural model (pgm's "
                "JSON of \"kind\": \"structural\", docs/causal.md), read the network as one with --assume monotone, "
                "or bound the probabilities of causation with --cause, --alternative and --effect");
  }
  return monotone_counterfactual_query(read_network_file(args.model), names, observed, set);
}

/// The counterfactual distribution of --query given --evidence, in the world of --do.
void run_distribution(const counterfactual_arguments& args) {
  if (args.query.empty()) throw CLI::ValidationError("counterfactual", "--do asks about --query X[,Y]: name it");
  const auto format = args.format.empty() || args.format == "csv" ? posterior_format::csv : posterior_format::json;
  if (args.format == "text") {
    throw CLI::ValidationError("counterfactual", "a counterfactual distribution prints as csv or json");
  }
  // JSON numbers are written to read back exactly.
  const posterior_table_options table{format, format == posterior_format::json ? 17 : args.digits};
  const auto observed = parse_evidence(args.evidence);
  const auto set = parse_intervention(args.intervene);
  const auto names = parse_query_variables(args.query);
  if (!args.out.empty()) pgm::check_output_path(args.out);
  write_output_last(args.out, [&](std::ostream& out) {
    write_posterior_table(out, counterfactual_of(args, names, observed, set), observed, table, {}, set);
  });
}

/// Tian & Pearl's bounds on PN, PS and PNS.
void run_bounds(const counterfactual_arguments& args) {
  if (args.cause.empty() || args.alternative.empty() || args.effect.empty()) {
    throw CLI::ValidationError("counterfactual",
                               "ask --do X=x' --query Y (a counterfactual distribution), or bound the probabilities of "
                               "causation with all of --cause, --alternative and --effect");
  }
  if (!args.query.empty() || !args.assume.empty()) {
    throw CLI::ValidationError("counterfactual", "--query and --assume go with --do");
  }
  if (args.format == "csv") throw CLI::ValidationError("counterfactual", "the bounds print as text or json");
  const auto network =
      holds_structural_model(args.model) ? read_structural_model(args.model).network() : read_network_file(args.model);
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

void run_counterfactual(const counterfactual_arguments& args) {
  if (!args.intervene.empty()) {
    if (!args.cause.empty() || !args.alternative.empty() || !args.effect.empty()) {
      throw CLI::ValidationError("counterfactual",
                                 "--do asks for a distribution; --cause, --alternative and --effect for bounds: "
                                 "choose one");
    }
    run_distribution(args);
  } else {
    if (!args.out.empty()) throw CLI::ValidationError("counterfactual", "--out goes with --do");
    run_bounds(args);
  }
}

}  // namespace

void add_counterfactual_command(CLI::App& app) {
  auto args = std::make_shared<counterfactual_arguments>();
  auto* cmd = app.add_subcommand(
      "counterfactual",
      "What would have happened? On a structural model, the distribution of --query in the world where --do had been "
      "done, given --evidence of what happened in this one (the twin network, exact). A causal network does not "
      "determine it: read one as a structural model with --assume monotone, or bound the probability of necessity "
      "(had X been the alternative, would Y not have happened, given that both happened), of sufficiency, and of "
      "both, from its observational and interventional distributions (Tian & Pearl 2000).\n"
      "Examples:\n  pgm counterfactual --model tower.json --evidence xOff1=2,onTop1=0 --do xOff1=0 --query onTop1\n"
      "  pgm counterfactual --model fitted.json --assume monotone --evidence xOff1=2,onTop1=0 --do xOff1=0 "
      "--query onTop1\n"
      "  pgm counterfactual --model fitted.json --cause xOff1=4 --alternative 2 --effect onTop1=0");
  cmd->add_option(
         "--model", args->model,
         "A structural model (pgm's JSON of \"kind\": \"structural\") or a causal network: " + network_file_kinds())
      ->required();
  cmd->add_option("--do", args->intervene, "The world asked about: what had been set there, e.g. \"xOff1=0\"");
  cmd->add_option("--query", args->query, "With --do: the variables asked about in that world, e.g. onTop1");
  cmd->add_option("--assume", args->assume,
                  "With --do on a causal network: read it as a structural model under this assumption. monotone: "
                  "every variable takes the first state whose cumulative probability exceeds one uniform noise "
                  "(units keep their rank as the parents change; docs/causal.md)")
      ->check(CLI::IsMember({"monotone"}));
  cmd->add_option("--cause", args->cause, "For bounds: the cause as it happened, VARIABLE=STATE");
  cmd->add_option("--alternative", args->alternative, "For bounds: the cause's state in the world that did not happen");
  cmd->add_option("--effect", args->effect, "For bounds: the effect as it happened, VARIABLE=STATE");
  cmd->add_option("--evidence", args->evidence,
                  "What was observed, e.g. \"a=s,b=t\" (for bounds: of variables the cause does not influence)");
  cmd->add_option("--format", args->format,
                  "Output: csv (default) or json for a distribution; text (default) or json for bounds. JSON "
                  "numbers have 17 significant digits")
      ->check(CLI::IsMember({"text", "csv", "json"}));
  cmd->add_option("--digits", args->digits, "With --do and csv: significant digits of each probability, 1-17")
      ->check(CLI::Range(1, 17))
      ->capture_default_str();
  cmd->add_option("--out", args->out, "With --do: write the table to this file instead of standard output");
  cmd->callback([args] { run_counterfactual(*args); });
}

}  // namespace pgm::cli
