// pgm fit: estimate every table of a network from data.

#include <algorithm>
#include <cmath>
#include <exception>
#include <iostream>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "cli/transfer_arguments.hpp"
#include "pgm/core/error.hpp"
#include "pgm/data/csv_counts.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/transfer/prior_weight.hpp"

namespace pgm::cli {
namespace {

struct fit_arguments {
  std::string data;
  std::string edges;
  std::string model;
  std::string estimator = "mle";
  std::string prior;
  std::optional<double> alpha;
  std::optional<double> ess;
  std::string empty = "uniform";
  std::string discretization_file;
  std::string intervals_file;
  unsigned threads = 0;
  std::string out;
  transfer_arguments transfer;
};

/// Sets the weighted prior (eq. 8) of every node the map transfers to, choosing w from the
/// counts when asked.
void add_transferred_priors(const fit_arguments& args, const network_structure& structure,
                            const std::vector<count_table>& counts, fit_options& options) {
  std::optional<double> fixed_weight;
  if (args.transfer.w_prior != "auto") {
    fixed_weight = detail::parse_double(args.transfer.w_prior);
    if (!fixed_weight || !std::isfinite(*fixed_weight) || *fixed_weight < 0) {
      throw error("--w-prior must be a number ≥ 0 or auto, got '" + args.transfer.w_prior + "'");
    }
  }
  const auto prior = read_network(args.transfer.prior_model);
  const auto map = resolve_map(args.transfer, prior, structure);
  const auto priors = resolve_priors(args.transfer, prior, structure, map);
  std::map<std::string, double, std::less<>> weights;
  for (const auto& [node, transferred] : priors) {
    if (!fixed_weight) {
      const auto choice = choose_prior_weight(counts[structure.id(node).value()], transferred.table());
      note("--w-prior auto for '" + node + "': " + choice.reason);
      weights.emplace(node, choice.weight);
    } else {
      weights.emplace(node, *fixed_weight);
    }
  }
  use_transferred_priors(options, priors, weights);
  for (const auto& [node, w] : weights) {
    note("'" + node + "' gets the " + args.transfer.strategy + " prior from '" + map.transferred.at(node) + "' with w = " +
         detail::format_short(w));
  }
}

/// Each node's family by name, in node order, parents in the structure's order.
std::vector<csv_family> families_of(const network_structure& structure) {
  std::vector<csv_family> families;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    const variable_id node(static_cast<variable_id::rep>(i));
    csv_family family{structure.at(node).name(), {}};
    for (const auto& parent : structure.parent_variables(node)) family.parents.push_back(parent.name());
    families.push_back(std::move(family));
  }
  return families;
}

parameter_prior make_prior(const fit_arguments& args) {
  if (args.estimator == "mle") {
    if (!args.prior.empty() || args.alpha || args.ess) {
      throw error("--prior, --alpha and --ess apply to --estimator bayes");
    }
    return no_prior{};
  }
  const auto prior = args.prior.empty() ? std::string("bdeu") : args.prior;
  if (args.alpha && prior != "dirichlet") throw error("--alpha applies to --prior dirichlet");
  if (args.ess && prior != "bdeu") throw error("--ess applies to --prior bdeu");
  if (prior == "dirichlet") return dirichlet_prior{args.alpha.value_or(1.0)};
  if (prior == "k2") return k2_prior{};
  return bdeu_prior{args.ess.value_or(1.0)};
}

void run_fit(const fit_arguments& args) {
  require_extension(args.out, network_extensions);
  fit_options options;
  options.prior = make_prior(args);
  options.estimation.empty = args.empty == "fail" ? empty_configuration::fail : empty_configuration::uniform;
  options.counting.threads = args.threads;

  std::optional<discretization> raw_intervals;
  if (!args.discretization_file.empty()) raw_intervals = read_discretization_json(args.discretization_file);

  // The data are never held in memory: each node's family is counted as the file streams by.
  network_structure structure;
  csv_counts counted;
  if (!args.model.empty()) {
    structure = read_model_json(args.model).structure;
    for (const auto& v : structure.variables()) {
      if (raw_intervals && raw_intervals->contains(v.name())) structure.update_variable(raw_intervals->at(v.name()));
    }
    std::vector<std::string> columns;
    for (const auto& v : structure.variables()) columns.push_back(v.name());
    csv_reader input(args.data);
    counted = count_discrete_data(input, columns, {raw_intervals ? &*raw_intervals : nullptr, &structure.variables()},
                                  families_of(structure), args.threads);
  } else {
    const auto edges = parse_edge_list(args.edges);
    std::vector<std::string> columns;
    for (const auto& e : edges) {
      for (const auto* name : {&e.from, &e.to}) {
        if (std::find(columns.begin(), columns.end(), *name) == columns.end()) columns.push_back(*name);
      }
    }
    csv_reader input(args.data);
    // The families come from the structure over the data's columns in file order (as
    // structure_from_data builds it); a problem with the structure itself, such as a cycle, is
    // reported after any problem with the data, as when the data were read first.
    std::vector<std::string> ordered;
    for (const auto& name : input.header()) {
      if (std::find(columns.begin(), columns.end(), name) != columns.end()) ordered.push_back(name);
    }
    std::vector<variable> placeholders;
    for (const auto& name : ordered) placeholders.emplace_back(name, std::vector<std::string>{"?"});
    std::vector<csv_family> families;
    std::exception_ptr structure_error;
    if (ordered.size() == columns.size()) {  // else counting reports the missing column
      try {
        families = families_of(network_structure(placeholders, edges));
      } catch (const error&) {
        structure_error = std::current_exception();
      }
    }
    counted = count_discrete_data(input, columns, {raw_intervals ? &*raw_intervals : nullptr, nullptr},
                                  std::move(families), args.threads);
    if (structure_error) std::rethrow_exception(structure_error);
    structure = network_structure(counted.variables, edges);
  }
  if (!args.intervals_file.empty()) {
    for (const auto& [name, intervals] : read_discretization_json(args.intervals_file)) {
      if (!structure.contains(name)) continue;
      const auto& own = structure.at(name);
      if (own.states() != intervals.states()) {
        throw data_error("'" + args.intervals_file + "' gives '" + name + "' the states {" +
                         detail::list_for_message(intervals.states()) + "}, the data {" +
                         detail::list_for_message(own.states()) + "}" +
                         (own.cardinality() > intervals.cardinality() ? "; are the columns still raw? use --discretization" : ""));
      }
      structure.update_variable(variable::with_edges(name, own.states(), intervals.edges(), intervals.tags()));
    }
  }
  // The counts under the structure's variables, which may carry intervals and tags.
  std::vector<count_table> counts;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    const variable_id node(static_cast<variable_id::rep>(i));
    auto parents = structure.parent_variables(node);
    const auto& family = counted.families[i];
    bool same_family = family.child().name() == structure.at(node).name() && family.parents().size() == parents.size();
    for (std::size_t k = 0; same_family && k < parents.size(); ++k) {
      same_family = family.parents()[k].name() == parents[k].name();
    }
    if (!same_family) throw std::logic_error("the counted family of '" + family.child().name() + "' is out of order");
    counts.push_back(family.with_variables(structure.at(node), std::move(parents)));
  }
  if (!args.transfer.prior_model.empty()) {
    add_transferred_priors(args, structure, counts, options);
  } else if (!args.transfer.map.empty()) {
    throw error("--map applies with --prior-model");
  }
  const auto network = fit(structure, std::span<const count_table>(counts), options);
  write_network(network, args.out);
  std::cout << "fitted " << network.size() << " tables (" << network.free_parameters()
            << " free parameters) from " << counted.rows << " rows -> " << args.out << '\n';
}

}  // namespace

void add_fit_command(CLI::App& app) {
  auto args = std::make_shared<fit_arguments>();
  auto* cmd = app.add_subcommand("fit", "Estimate the tables of a network from data (MLE or Bayesian)");
  cmd->add_option("--data", args->data, std::string("CSV file with one column per variable") + data_file_help)
      ->required();
  auto* edges = cmd->add_option("--edges", args->edges,
                                "The structure as edges, e.g. \"xOff1->onTop1,yOff1->onTop1\"; "
                                "states are the values found in the data, sorted (numbers numerically)");
  auto* model = cmd->add_option("--model", args->model, "The structure from a JSON model file instead");
  edges->excludes(model);
  model->excludes(edges);
  cmd->add_option("--estimator", args->estimator, "mle (eq. 3) or bayes (eq. 6)")
      ->check(CLI::IsMember({"mle", "bayes"}))
      ->capture_default_str();
  cmd->add_option("--prior", args->prior, "Prior of the Bayesian estimator: dirichlet, k2 or bdeu (default)")
      ->check(CLI::IsMember({"dirichlet", "k2", "bdeu"}));
  cmd->add_option("--alpha", args->alpha, "Pseudo-count per cell of the dirichlet prior (default 1)")
      ->check(non_negative_number());
  cmd->add_option("--ess", args->ess, "Equivalent sample size of the bdeu prior (default 1)")
      ->check(non_negative_number());
  cmd->add_option("--empty", args->empty,
                  "A parent configuration with no data: uniform (1/J) or fail")
      ->check(CLI::IsMember({"uniform", "fail"}))
      ->capture_default_str();
  auto* raw = cmd->add_option("--discretization", args->discretization_file,
                              "Edges file (from pgm discretize): bin these raw numeric columns with it");
  auto* intervals = cmd->add_option("--intervals", args->intervals_file,
                                    "Edges file whose intervals the already discretized columns hold; "
                                    "saved with the model");
  raw->excludes(intervals);
  cmd->add_option("--threads", args->threads, "Counting threads (0: all cores)")->check(whole_number(0, 1024))->capture_default_str();
  cmd->add_option("--out", args->out, "The fitted network, .bif or .json")->required();
  add_transfer_options(*cmd, args->transfer, true);
  cmd->callback([args] {
    if (args->edges.empty() && args->model.empty()) throw error("give the structure with --edges or --model");
    run_fit(*args);
  });
}

}  // namespace pgm::cli
