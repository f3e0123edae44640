// pgm score: a network structure's score on discrete data (bnlearn's score() conventions), in
// total and node by node.

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/learn/network_score.hpp"

namespace pgm::cli {
namespace {

struct score_arguments {
  std::string model;
  std::string data;
  std::string score = "bic";
  double iss = 1.0;
  unsigned threads = 0;
  missing_arguments missing;
};

void run_score(const score_arguments& args) {
  const score_choice choice{parse_score_type(args.score), args.iss};
  check_score_choice(choice);
  const auto structure = read_model_file(args.model).structure;
  std::vector<std::string> columns;
  for (const auto& v : structure.variables()) columns.push_back(v.name());
  const auto data = read_discrete_data(args.data, columns, {nullptr, &structure.variables(), missing_of(args.missing)});
  const auto result = score_network(structure, data, choice, args.threads);

  std::size_t width = 4;
  for (const auto& v : structure.variables()) width = std::max(width, v.name().size());
  std::ostringstream out;
  out << to_string(choice.type)
      << (choice.type == score_type::bdeu ? " (iss " + text::format_short(args.iss) + ")" : "") << " of " << args.model
      << " on " << data.rows() << " rows: " << text::format_double(result.total) << '\n';
  out << "  " << std::left << std::setw(static_cast<int>(width)) << "node"
      << "  term\n";
  for (std::size_t i = 0; i < structure.size(); ++i) {
    out << "  " << std::left << std::setw(static_cast<int>(width)) << structure.variables()[i].name() << "  "
        << text::format_double(result.nodes[i]) << '\n';
  }
  std::cout << out.str();
}

}  // namespace

void add_score_command(CLI::App& app) {
  auto args = std::make_shared<score_arguments>();
  auto* cmd = app.add_subcommand(
      "score", "Score a network's structure on discrete data (log-likelihood, AIC, BIC, BDeu or K2; larger is better)");
  cmd->add_option("--model", args->model, "The network whose structure is scored: " + network_file_kinds())->required();
  cmd->add_option(
         "--data", args->data,
         std::string("CSV file with a column per variable of the model, read with the model's states") + data_file_help)
      ->required();
  cmd->add_option("--score", args->score,
                  "bic (loglik - log(n)/2 per parameter), aic (loglik - 1 per parameter), bdeu, k2 or loglik, "
                  "as bnlearn's score()")
      ->check(CLI::IsMember(known_score_types()))
      ->capture_default_str();
  cmd->add_option("--iss", args->iss, "Imaginary sample size of bdeu (bnlearn's iss), a number > 0")
      ->check(number_between(0, std::numeric_limits<double>::infinity(), true, true))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Counting threads (0: all cores); the score is the same")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  add_missing_options(*cmd, args->missing);
  cmd->callback([args] { run_score(*args); });
}

}  // namespace pgm::cli
