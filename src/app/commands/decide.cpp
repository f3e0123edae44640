// pgm decide: the maximum expected utility of an influence diagram and the policy that reaches
// it, optionally the value of observing a chance variable before a decision; or what acting by a
// policy read from a file is worth.

#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/core/text.hpp"
#include "pgm/decide/solve_decisions.hpp"
#include "pgm/inference/posterior_table.hpp"
#include "pgm/io/influence_file.hpp"
#include "pgm/io/policy_csv.hpp"

namespace pgm::cli {
namespace {

struct decide_arguments {
  std::string model;
  std::string evidence;
  bool limited_memory = false;
  std::string policy_out;
  std::string policy_in;
  std::string format = "text";
  std::string information;
  std::string before;
};

std::string json_string(const std::string& text) { return nlohmann::json(text).dump(); }

/// One row of a policy: each observed variable's state (the evidence's where it is observed
/// evidence), and the action.
struct policy_row {
  std::vector<std::pair<std::string, std::string>> observed;
  std::string action;
};

std::vector<policy_row> rows_of(const influence_diagram& diagram, const decision_policy& policy,
                                const evidence& observed) {
  std::vector<std::pair<std::string, std::string>> fixed;
  for (const auto parent : diagram.parents(policy.decision)) {
    const auto it = observed.find(diagram.at(parent).name());
    if (it != observed.end()) fixed.emplace_back(it->first, it->second);
  }
  std::vector<std::size_t> cards;
  for (const auto id : policy.observed) cards.push_back(diagram.at(id).cardinality());
  const mixed_radix configurations(cards);
  std::vector<policy_row> rows;
  std::vector<std::size_t> states(cards.size());
  for (std::size_t c = 0; c < configurations.size(); ++c) {
    configurations.decode(c, states);
    policy_row row{fixed, diagram.at(policy.decision).states()[policy.actions[c]]};
    for (std::size_t k = 0; k < states.size(); ++k) {
      const auto& v = diagram.at(policy.observed[k]);
      row.observed.emplace_back(v.name(), v.states()[states[k]]);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

void print_text(std::ostream& out, const influence_diagram& diagram, const decision_solution& solution,
                const evidence& observed, const std::optional<double>& information, const decide_arguments& args) {
  out << (solution.local_optimum ? "expected utility (single policy updating, a local optimum): "
                                 : "maximum expected utility: ")
      << text::format_double(solution.meu) << '\n';
  if (solution.local_optimum) {
    out << "  from uniform policies worth " << text::format_double(solution.start_expected_utility) << ", in "
        << solution.rounds << " rounds\n";
  }
  for (const auto& policy : solution.policies) {
    const auto& name = diagram.at(policy.decision).name();
    const auto rows = rows_of(diagram, policy, observed);
    if (rows.size() == 1 && rows[0].observed.empty()) {
      out << name << ": " << rows[0].action << '\n';
      continue;
    }
    out << name << ":\n";
    for (const auto& row : rows) {
      std::vector<std::string> given;
      for (const auto& [variable, state] : row.observed) given.push_back(variable + "=" + state);
      out << "  " << (given.empty() ? std::string("always") : text::join(given, ", ")) << " -> " << row.action << '\n';
    }
  }
  if (information) {
    out << "value of knowing " << args.information << " before " << args.before << ": "
        << text::format_double(*information) << '\n';
  }
}

void print_json(std::ostream& stream, const influence_diagram& diagram, const decision_solution& solution,
                const evidence& observed, const std::optional<double>& information) {
  std::string out = "{\"meu\": " + json_number(solution.meu) + ", \"policies\": {";
  for (std::size_t p = 0; p < solution.policies.size(); ++p) {
    const auto& policy = solution.policies[p];
    out += (p ? ", " : "") + json_string(diagram.at(policy.decision).name()) + ": [";
    const auto rows = rows_of(diagram, policy, observed);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      out += r ? ", {" : "{";
      for (const auto& [variable, state] : rows[r].observed)
        out += json_string(variable) + ": " + json_string(state) + ", ";
      out += "\"action\": " + json_string(rows[r].action) + "}";
    }
    out += "]";
  }
  out += "}, \"local_optimum\": " + std::string(solution.local_optimum ? "true" : "false");
  if (solution.local_optimum) {
    out += ", \"start_expected_utility\": " + json_number(solution.start_expected_utility) +
           ", \"rounds\": " + std::to_string(solution.rounds);
  }
  if (information) out += ", \"value_of_information\": " + json_number(*information);
  stream << out << "}\n";
}

void write_policies(const influence_diagram& diagram, const decision_solution& solution, const evidence& observed,
                    const std::string& path, const std::function<void()>& before_replacing) {
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out << "decision,observed,action\n";
        for (const auto& policy : solution.policies) {
          for (const auto& row : rows_of(diagram, policy, observed)) {
            std::vector<std::string> given;
            for (const auto& [variable, state] : row.observed) given.push_back(variable + "=" + state);
            out << text::csv_escape(diagram.at(policy.decision).name(), ',') << ','
                << text::csv_escape(text::join(given, ","), ',') << ',' << text::csv_escape(row.action, ',') << '\n';
          }
        }
      },
      before_replacing);
}

/// --policy-in: what acting by the policies of a file is worth.
void run_given_policy(const decide_arguments& args, const influence_diagram& diagram, const evidence& observed) {
  const auto policies = read_policy_csv(args.policy_in, diagram, observed, args.limited_memory);
  const double worth = expected_utility(diagram, policies, observed);
  if (args.format == "json") {
    std::cout << "{\"expected_utility\": " << json_number(worth) << "}\n";
  } else {
    std::cout << "expected utility of the policies in " << args.policy_in << ": " << text::format_double(worth) << '\n';
  }
}

void run_decide(const decide_arguments& args) {
  require_extension(args.model, {".xml", ".xmlbif", ".bifxml", ".json"});
  const auto diagram = read_influence_diagram(args.model);
  const auto observed = parse_evidence(args.evidence);
  if (!args.policy_in.empty()) {
    run_given_policy(args, diagram, observed);
    return;
  }
  const decision_options options{.limited_memory = args.limited_memory};
  const auto solution = solve_decisions(diagram, observed, options);
  std::optional<double> information;
  if (!args.information.empty()) {
    information = value_of_information(diagram, args.information, args.before, observed, options);
  }
  std::ostringstream answer;
  args.format == "json" ? print_json(answer, diagram, solution, observed, information)
                        : print_text(answer, diagram, solution, observed, information, args);
  // The answer is printed before the policies' file replaces the old, so a failure leaves it.
  if (args.policy_out.empty()) {
    std::cout << answer.str();
  } else {
    write_policies(diagram, solution, observed, args.policy_out,
                   summary_before_replacing(answer.str(), args.policy_out));
  }
}

}  // namespace

void add_decide_command(CLI::App& app) {
  auto args = std::make_shared<decide_arguments>();
  auto* cmd = app.add_subcommand(
      "decide",
      "Solve an influence diagram: print the maximum expected utility and, for every decision, the best action "
      "given what it observes. With perfect recall (the default) every decision also knows what earlier ones knew "
      "and chose, and the answer is exact; --limited-memory keeps each decision to its parents and climbs by "
      "single policy updating to a local optimum.\nExamples:\n  pgm decide --model oil.xml\n  pgm decide --model "
      "oil.xml --value-of-information Oil --before Drill --format json\n  pgm decide --model oil.xml "
      "--policy-in policy.csv");
  cmd->add_option("--model", args->model,
                  "The influence diagram: XMLBIF with TYPE=\"decision\" and TYPE=\"utility\" variables (aGrUM's "
                  "BIFXML), or pgm's JSON model of \"kind\": \"influence\"")
      ->required();
  cmd->add_option("--evidence", args->evidence,
                  "What is observed before the first decision, e.g. \"a=s,b=t\" (default: nothing)");
  cmd->add_flag("--limited-memory", args->limited_memory,
                "Each decision knows its parents only (a LIMID), solved by single policy updating");
  auto* policy_out = cmd->add_option("--policy-out", args->policy_out,
                                     "Also write the policies as CSV: decision, observed (\"A=a,B=b\"), action");
  auto* policy_in = cmd->add_option("--policy-in", args->policy_in,
                                    "Instead of solving, print the expected utility of acting by the policies of this "
                                    "CSV file (as --policy-out writes them)");
  policy_in->excludes(policy_out);
  cmd->add_option("--format", args->format, "Output: text or json (numbers to 17 significant digits)")
      ->check(CLI::IsMember({"text", "json"}));
  auto* information =
      cmd->add_option("--value-of-information", args->information,
                      "A chance variable whose value of perfect information to print: what knowing it before --before "
                      "(and later) adds to the MEU");
  auto* before =
      cmd->add_option("--before", args->before, "The decision at which --value-of-information's variable is known");
  information->needs(before);
  before->needs(information);
  policy_in->excludes(information);
  cmd->callback([args] { run_decide(*args); });
}

}  // namespace pgm::cli
