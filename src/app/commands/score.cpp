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
#include "cli/component_options.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/learn/network_score.hpp"

namespace pgm::cli {
namespace {

struct score_command_arguments {
  std::string model;
  std::string data;
  score_arguments score;
  unsigned threads = 0;
  missing_arguments missing;
};

void run_score(const score_command_arguments& args) {
  const auto score = chosen_score(args.score);
  const auto structure = read_model_file(args.model).structure;
  std::vector<std::string> columns;
  for (const auto& v : structure.variables()) columns.push_back(v.name());
  const auto data = read_discrete_data(args.data, columns, {nullptr, &structure.variables(), missing_of(args.missing)});
  const auto result = score_network(structure, data, score, args.threads);

  std::size_t width = 4;
  for (const auto& v : structure.variables()) width = std::max(width, v.name().size());
  std::ostringstream out;
  out << described(score) << " of " << args.model << " on " << data.rows()
      << " rows: " << text::format_double(result.total) << '\n';
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
  auto args = std::make_shared<score_command_arguments>();
  auto* cmd = app.add_subcommand(
      "score", "Score a network's structure on discrete data (log-likelihood, AIC, BIC, BDeu or K2; larger is better)");
  cmd->add_option("--model", args->model, "The network whose structure is scored: " + network_file_kinds())->required();
  cmd->add_option(
         "--data", args->data,
         std::string("CSV file with a column per variable of the model, read with the model's states") + data_file_help)
      ->required();
  add_score_options(*cmd, args->score);
  cmd->add_option("--threads", args->threads, "Counting threads (0: all cores); the score is the same")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  add_missing_options(*cmd, args->missing);
  cmd->callback([args] { run_score(*args); });
}

}  // namespace pgm::cli
