// pgm transfer: the prior table f(θ′) a strategy gives a target node, with no target data —
// what the robot knows zero-shot. pgm correspond: the ranked correspondence proposal.

#include <iostream>
#include <sstream>

#include "cli/common.hpp"
#include "cli/transfer_arguments.hpp"
#include "pgm/core/error.hpp"
#include "pgm/io/cpt_csv.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/transfer/propose.hpp"

namespace pgm::cli {
namespace {

struct transfer_command_arguments {
  std::string edges;
  std::string model;
  std::string intervals_file;
  std::string out;
  bool explain = false;
  transfer_arguments transfer;
};

/// The target's variables without data: from the model file, or for --edges from the
/// intervals file, else the prior's variable of the same name, else the states of its prior
/// counterpart in the map.
network_structure target_structure(const transfer_command_arguments& args, const bayesian_network& prior,
                                   const correspondence* map) {
  if (!args.model.empty()) {
    return read_model_file(args.model).structure;
  }
  const auto edges = parse_edge_list(args.edges);
  std::optional<discretization> intervals;
  if (!args.intervals_file.empty()) intervals = read_discretization_json(args.intervals_file);
  std::vector<std::string> names;
  for (const auto& e : edges) {
    for (const auto* name : {&e.from, &e.to}) {
      if (std::find(names.begin(), names.end(), *name) == names.end()) names.push_back(*name);
    }
  }
  // A transferred node or a related variable is the same quantity as its prior counterpart.
  auto counterpart = [&](const std::string& name) -> const variable* {
    if (!map) return nullptr;
    if (const auto it = map->transferred.find(name); it != map->transferred.end()) return &prior.at(it->second);
    if (const auto related = map->related_to(name)) return &prior.at(*related);
    return nullptr;
  };
  std::vector<variable> variables;
  for (const auto& name : names) {
    if (intervals && intervals->contains(name)) {
      variables.push_back(intervals->at(name));
    } else if (prior.structure().contains(name)) {
      variables.push_back(prior.at(name));
    } else if (const auto* from = counterpart(name)) {
      note("'" + name + "' takes the states of the prior's '" + from->name() + "'");
      variables.push_back(variable::with_edges(name, from->states(), from->edges(), from->tags()));
    } else {
      throw error("the states of '" + name + "' are unknown without data: give them with --intervals or --model");
    }
  }
  return network_structure(std::move(variables), edges);
}

void run_transfer(const transfer_command_arguments& args) {
  require_extension(args.out, {".csv"});
  if (args.transfer.prior_model.empty()) throw error("pgm transfer needs --prior-model");
  if (args.transfer.map.empty()) throw error("pgm transfer needs --map, e.g. --map \"onTop2=onTop1,xOff2~xOff1\"");
  if (args.edges.empty() == args.model.empty()) throw error("give the target structure with --edges or --model");
  const auto prior = read_network_file(args.transfer.prior_model);
  std::optional<correspondence> given;
  if (!args.transfer.map.empty() && args.transfer.map != "auto") given = parse_correspondence(args.transfer.map);
  const auto target = target_structure(args, prior, given ? &*given : nullptr);
  const auto map = given ? *given : resolve_map(args.transfer, prior, target);
  if (map.transferred.size() != 1) {
    throw error("pgm transfer writes one table; the map transfers " + std::to_string(map.transferred.size()) +
                " nodes: run it once per 'target=prior' pair");
  }
  const auto priors = resolve_priors(args.transfer, prior, target, map);
  const auto& [node, transferred] = *priors.begin();
  write_cpt_csv(transferred.table(), args.out);
  std::cout << "prior of '" << node << "' by " << args.transfer.strategy << " from '" << map.transferred.at(node)
            << "': " << transferred.table().configurations() << " configurations -> " << args.out << '\n';
  if (args.explain) {
    const auto& table = transferred.table();
    for (std::size_t u = 0; u < table.configurations(); ++u) {
      const config_index c = index_at<config_index>(u);
      const auto codes = table.parent_codes(c);
      std::string assignment;
      for (std::size_t k = 0; k < codes.size(); ++k) {
        assignment += (k ? ", " : "") + table.parents()[k].name() + "=" + table.parents()[k].states()[codes[k]];
      }
      std::cout << "  u = (" << assignment << ")  <-  u' = (" << transferred.describe_sources(c) << ") ["
                << to_string(transferred.via(c)) << "]\n";
    }
  }
}

struct correspond_arguments {
  std::string prior_model;
  std::string target_model;
  std::size_t top = 10;
};

network_view view_of(const std::string& path, std::optional<model_document>& document,
                     std::optional<bayesian_network>& network) {
  document = read_model_file(path);
  if (document->tables) {
    network = document->network();
    return {&network->structure(), &*network};
  }
  return {&document->structure, nullptr};
}

void run_correspond(const correspond_arguments& args) {
  std::optional<model_document> prior_document, target_document;
  std::optional<bayesian_network> prior_network, target_network;
  const auto prior = view_of(args.prior_model, prior_document, prior_network);
  const auto target = view_of(args.target_model, target_document, target_network);
  const auto ranking = rank_correspondences(target, prior);
  const auto proposal = propose_correspondence(target, prior);  // fails before anything is printed
  std::cout << "related-variable candidates (target ~ prior), best first:\n";
  for (std::size_t i = 0; i < std::min(args.top, ranking.size()); ++i) {
    const auto& c = ranking[i];
    std::ostringstream score;
    score.precision(2);
    score << std::fixed << c.score;
    std::cout << "  " << score.str() << "  " << c.target << " ~ " << c.prior << "  (" << text::join(c.reasons, "; ")
              << ")\n";
  }
  std::cout << "proposal: --map \"" << to_string(proposal) << "\"\n";
}

}  // namespace

void add_transfer_command(CLI::App& app) {
  auto args = std::make_shared<transfer_command_arguments>();
  auto* cmd =
      app.add_subcommand("transfer", "Write the prior table a strategy transfers to a target node, without data");
  auto* edges =
      cmd->add_option("--edges", args->edges, "The target structure as edges, e.g. \"xOff1->onTop2,xOff2->onTop2\"");
  auto* model = cmd->add_option("--model", args->model,
                                "The target structure from a model file instead (" + network_file_kinds() + ")");
  edges->excludes(model);
  model->excludes(edges);
  cmd->add_option("--intervals", args->intervals_file, "Edges file (from pgm discretize) with the target's intervals");
  cmd->add_option("--out", args->out, "The prior table f(θ′) as CSV")->required();
  cmd->add_flag("--explain", args->explain, "Print the prior configuration u′ behind every target configuration u");
  add_transfer_options(*cmd, args->transfer, false);
  cmd->callback([args] { run_transfer(*args); });
}

void add_correspond_command(CLI::App& app) {
  auto args = std::make_shared<correspond_arguments>();
  auto* cmd = app.add_subcommand("correspond", "Rank candidate correspondences between a prior and a target network");
  cmd->add_option("--prior-model", args->prior_model, "The prior task's network (" + network_file_kinds() + ")")
      ->required();
  cmd->add_option("--target-model", args->target_model,
                  "The target task's network or structure (" + network_file_kinds() + ")")
      ->required();
  cmd->add_option("--top", args->top, "How many candidates to list")
      ->check(whole_number(1, 1000000))
      ->capture_default_str();
  cmd->callback([args] { run_correspond(*args); });
}

}  // namespace pgm::cli
