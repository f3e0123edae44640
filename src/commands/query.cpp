// pgm query: the full distribution P(X | evidence) by variable elimination, as CSV or JSON.

#include <iostream>
#include <memory>
#include <string>

#include "cli/common.hpp"
#include "pgm/detail/file.hpp"
#include "pgm/inference/posterior_table.hpp"
#include "pgm/io/network_file.hpp"

namespace pgm::cli {
namespace {

struct query_arguments {
  std::string model;
  std::string query;
  std::string evidence;
  std::string format = "csv";
  int digits = 6;
  std::string out;
};

void run_query(const query_arguments& args) {
  const posterior_table_options options{parse_posterior_format(args.format), args.digits};
  const auto variables = parse_query_variables(args.query);
  const auto observed = parse_evidence(args.evidence);
  if (!args.out.empty()) detail::check_output_path(args.out);
  const auto network = read_network_file(args.model);
  const auto result = pgm::query(network, variables, observed);
  if (args.out.empty()) {
    write_posterior_table(std::cout, result, observed, options);
  } else {
    detail::write_file_atomically(args.out,
                                  [&](std::ostream& out) { write_posterior_table(out, result, observed, options); });
  }
}

}  // namespace

void add_query_command(CLI::App& app) {
  auto args = std::make_shared<query_arguments>();
  auto* cmd = app.add_subcommand("query",
                                 "Print P(X | evidence) for every state of the query variables, by variable "
                                 "elimination.\nExample: pgm query --model sachs.bif --query Akt,Erk --evidence "
                                 "PKA=HIGH --digits 17 --format json");
  cmd->add_option("--model", args->model, "The network: .bif, .xml, .net or .json")->required();
  cmd->add_option("--query", args->query, "Query variables, e.g. \"X\" or \"X,Y\" (joint distribution)")->required();
  cmd->add_option("--evidence", args->evidence, "Observed states, e.g. \"a=s,b=t\" (default: none)");
  cmd->add_option("--format", args->format, "Output format: csv or json")
      ->check(CLI::IsMember({"csv", "json"}))
      ->capture_default_str();
  cmd->add_option("--digits", args->digits, "Significant digits of each probability, 1-17 (17: full precision)")
      ->check(CLI::Range(1, 17))
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Write the table to this file instead of standard output");
  cmd->callback([args] { run_query(*args); });
}

}  // namespace pgm::cli
