// pgm fit: estimate every table of a network from data.

#include "pgm/learn/fit.hpp"

#include <algorithm>
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
#include "pgm/detail/process_group.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/learn/estimator_choice.hpp"
#include "pgm/transfer/transfer_settings.hpp"

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
  missing_arguments missing;
};

/// Sets the weighted prior (eq. 8) of every node the map transfers to, choosing w from the
/// data when asked, and says what was chosen.
void use_prior_model(const fit_arguments& args, const network_structure& structure,
                     const std::vector<count_table>& counts, fit_options& options) {
  const auto settings = settings_of(args.transfer);
  const auto prior = read_network_file(args.transfer.prior_model);
  require_map(args.transfer);
  const auto report =
      pgm::add_transferred_priors(options, structure, std::span<const count_table>(counts), prior, settings);
  if (report.map_proposed) note("--map auto: " + to_string(report.map));
  for (const auto& [node, entry] : report.nodes) {
    if (entry.reason) note("--w-prior auto for '" + node + "': " + *entry.reason);
  }
  for (const auto& [node, entry] : report.nodes) {
    note("'" + node + "' gets the " + args.transfer.strategy + " prior from '" + entry.prior_node +
         "' with w = " + detail::format_short(entry.weight));
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

void run_fit(const fit_arguments& args) {
  require_network_extension(args.out);
  if (args.data == "-" && detail::processes().size() > 1) {
    throw error("--data -: standard input reaches one process only; under mpirun give a file every process can read");
  }
  fit_options options;
  options.prior = prior_of({args.estimator, args.prior, args.alpha, args.ess});
  options.estimation.empty = args.empty == "fail" ? empty_configuration::fail : empty_configuration::uniform;
  options.counting.threads = args.threads;

  std::optional<discretization> raw_intervals;
  if (!args.discretization_file.empty()) raw_intervals = read_discretization_json(args.discretization_file);

  // The data are never held in memory: each node's family is counted as the file streams by.
  network_structure structure;
  csv_counts counted;
  if (!args.model.empty()) {
    structure = read_model_file(args.model).structure;
    for (const auto& v : structure.variables()) {
      if (raw_intervals && raw_intervals->contains(v.name())) structure.update_variable(raw_intervals->at(v.name()));
    }
    std::vector<std::string> columns;
    for (const auto& v : structure.variables()) columns.push_back(v.name());
    csv_reader input(args.data);
    counted = count_discrete_data(
        input, columns, {raw_intervals ? &*raw_intervals : nullptr, &structure.variables(), missing_of(args.missing)},
        families_of(structure), args.threads, detail::processes());
    if (detail::processes().rank() != 0) return;  // process 0 has the counts, fits and writes
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
    counted = count_discrete_data(input, columns,
                                  {raw_intervals ? &*raw_intervals : nullptr, nullptr, missing_of(args.missing)},
                                  std::move(families), args.threads, detail::processes());
    if (detail::processes().rank() != 0) return;  // process 0 has the counts, fits and writes
    if (structure_error) std::rethrow_exception(structure_error);
    structure = network_structure(counted.variables, edges);
  }
  if (!args.intervals_file.empty()) {
    structure =
        with_intervals(std::move(structure), read_discretization_json(args.intervals_file), args.intervals_file);
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
    use_prior_model(args, structure, counts, options);
  } else if (!args.transfer.map.empty()) {
    throw error("--map applies with --prior-model");
  }
  const auto network = fit(structure, std::span<const count_table>(counts), options);
  write_network(network, args.out);
  std::cout << "fitted " << network.size() << " tables (" << network.free_parameters() << " free parameters) from "
            << counted.rows << " rows -> " << args.out << '\n';
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
  auto* model = cmd->add_option("--model", args->model,
                                "The structure (and states) from a model file instead: .bif, .xml, .net or .json");
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
  cmd->add_option("--empty", args->empty, "A parent configuration with no data: uniform (1/J) or fail")
      ->check(CLI::IsMember({"uniform", "fail"}))
      ->capture_default_str();
  auto* raw = cmd->add_option("--discretization", args->discretization_file,
                              "Edges file (from pgm discretize): bin these raw numeric columns with it");
  auto* intervals = cmd->add_option("--intervals", args->intervals_file,
                                    "Edges file whose intervals the already discretized columns hold; "
                                    "saved with the model");
  raw->excludes(intervals);
  cmd->add_option("--threads", args->threads, "Counting threads (0: all cores)")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  cmd->add_option("--out", args->out, "The fitted network: .bif, .xml (XMLBIF), .net (Hugin) or .json")->required();
  add_missing_options(*cmd, args->missing);
  add_transfer_options(*cmd, args->transfer, true);
  cmd->callback([args] {
    if (args->edges.empty() && args->model.empty()) throw error("give the structure with --edges or --model");
    run_fit(*args);
  });
}

}  // namespace pgm::cli
