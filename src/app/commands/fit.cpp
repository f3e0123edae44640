// pgm fit: estimate every table of a network from data.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "cli/component_options.hpp"
#include "cli/episode.hpp"
#include "cli/transfer_arguments.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/process_group.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/csv_source.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/learn/estimator_choice.hpp"
#include "pgm/learn/family_source.hpp"
#include "pgm/learn/fit_dynamic.hpp"
#include "pgm/learn/parameter_prior_registry.hpp"
#include "pgm/pipeline/dynamic_fit_pipeline.hpp"
#include "pgm/pipeline/fit_pipeline.hpp"
#include "pgm/transfer/transfer_settings.hpp"

namespace pgm::cli {
namespace {

struct fit_arguments {
  std::string data;
  std::string edges;
  std::string model;
  std::string estimator = "mle";
  std::string prior = std::string(default_parameter_prior);
  // --alpha and --ess: shorthands for an option of the prior, read with given_value.
  CLI::Option* alpha = nullptr;
  CLI::Option* ess = nullptr;
  std::string empty = "uniform";
  std::string discretization_file;
  std::string intervals_file;
  unsigned threads = 0;
  std::string out;
  transfer_arguments transfer;
  missing_arguments missing;
  // --missing em
  std::vector<std::string> latent;
  std::size_t restarts = 1;
  std::uint64_t seed = 0;
  std::size_t max_iterations = 100;
  double tolerance = 1e-6;
  bool hard = false;
  bool verbose = false;
  bool keep_counts = false;
  bool dynamic = false;
  // --dynamic with --prior-model: the first slice's own transfer.
  std::string initial_map;
  std::string initial_strategy;
};

/// --latent NAME:COUNT (states 0 … COUNT-1), NAME=STATE,STATE,… or NAME (a model's states).
latent_variable latent_of(const std::string& text) {
  const auto bad = [&] {
    return error("--latent '" + text + "': expected NAME:COUNT (e.g. H:3), NAME=STATE,STATE,... or NAME");
  };
  if (const auto eq = text.find('='); eq != std::string::npos) {
    auto states = text::split(text.substr(eq + 1), ',');
    if (eq == 0 || states.empty()) throw bad();
    return {text.substr(0, eq), std::move(states)};
  }
  if (const auto colon = text.find(':'); colon != std::string::npos) {
    const auto count = text.substr(colon + 1);
    if (colon == 0 || count.empty() || count.size() > 6 || count.find_first_not_of("0123456789") != std::string::npos ||
        std::stoul(count) < 1) {
      throw bad();
    }
    latent_variable latent{text.substr(0, colon), {}};
    for (unsigned long k = 0; k < std::stoul(count); ++k) latent.states.push_back(std::to_string(k));
    return latent;
  }
  if (text.empty()) throw bad();
  return {text, {}};
}

em_options em_options_of(const fit_arguments& args) {
  em_options options;
  options.kind = args.hard ? em_kind::hard : em_kind::soft;
  options.tolerance = args.tolerance;
  options.max_iterations = args.max_iterations;
  options.restarts = args.restarts;
  options.seed = args.seed;
  options.threads = args.threads;
  if (args.verbose) {
    options.on_step = [](const em_step& step) {
      note("EM start " + std::to_string(step.restart + 1) + ", iteration " + std::to_string(step.iteration) +
           ": log-likelihood " + text::format_double(step.log_likelihood) +
           (step.objective != step.log_likelihood ? ", objective " + text::format_double(step.objective) : ""));
    };
  }
  return options;
}

/// Says which priors were transferred, with which weights, and how they were chosen.
void note_transfer(const transfer_report& report, const std::string& strategy) {
  if (report.map_proposed) note("--map auto: " + to_string(report.map));
  for (const auto& [node, entry] : report.nodes) {
    if (entry.reason) note("--w-prior auto for '" + node + "': " + *entry.reason);
  }
  for (const auto& [node, entry] : report.nodes) {
    note("'" + node + "' gets the " + strategy + " prior from '" + entry.prior_node +
         "' with w = " + text::format_short(entry.weight));
  }
}

/// The prior (--estimator, --prior and its shorthands), the empty-configuration rule and the
/// counting threads.
void set_estimation(const fit_arguments& args, fit_options& options) {
  options.prior =
      prior_of({args.estimator,
                args.prior,
                {{"--alpha", "alpha", given_value(*args.alpha)}, {"--ess", "ess", given_value(*args.ess)}}});
  options.estimation.empty = parse_empty_configuration(args.empty);
  options.counting.threads = args.threads;
}

/// The options of a static fit that a dynamic one does not take yet, each with why.
void refuse_static_only(const fit_arguments& args) {
  const auto refuse = [](bool given, const std::string& what) {
    if (given) throw error("--dynamic: " + what);
  };
  refuse(args.hard, "--hard is not available for dynamic networks; their EM is soft");
  refuse(args.missing.policy == "drop",
         "--missing drop leaves gaps in the episodes where it drops a row; --missing available counts each family "
         "over the steps where its variables are present");
  refuse(!args.discretization_file.empty() || !args.intervals_file.empty(),
         "--discretization and --intervals are not available for dynamic networks yet: bin the columns first "
         "(pgm discretize)");
  refuse(processes().size() > 1, "a dynamic network is fitted in one process, not under mpirun");
}

/// The options that apply to --dynamic only, refused without it.
void refuse_dynamic_only(const fit_arguments& args) {
  if (!args.initial_map.empty() || !args.initial_strategy.empty()) {
    throw error("--initial-map and --initial-strategy apply with --dynamic (the first slice's own transfer)");
  }
}

/// A latent variable is in no column: one that the data hold is refused, as a static fit does.
void refuse_latent_columns(const std::string& path, const std::vector<latent_variable>& latent) {
  if (latent.empty() || path == "-") return;
  const auto header = csv_reader(path).header();
  for (const auto& v : latent) {
    if (std::find(header.begin(), header.end(), v.name) != header.end()) {
      throw error("--latent '" + v.name + "': " + path + " has a column '" + v.name +
                  "'; a latent variable is one the data do not hold (its missing values are estimated by "
                  "--missing em without --latent)");
    }
  }
}

/// pgm fit --dynamic: a 2-TBN with tied tables from episodes in long form (episode,t,<variables>).
void run_dynamic_fit(const fit_arguments& args) {
  refuse_static_only(args);
  if (std::filesystem::path(args.out).extension() != ".json") {
    throw error("--out: a dynamic network is written as pgm's JSON model (.json), not '" + args.out +
                "'; pgm unroll then writes it unrolled in any format");
  }
  pgm::check_output_path(args.out);
  const bool em = args.missing.policy == "em";
  if (!em && !args.latent.empty()) throw error("--latent applies with --missing em");
  if (em && args.keep_counts) {
    throw error(
        "--keep-counts does not apply with --missing em: EM's counts are expectations under its tables, which new "
        "episodes would change");
  }
  std::vector<latent_variable> latent;
  for (const auto& text : args.latent) latent.push_back(latent_of(text));
  const auto is_latent = [&](const std::string& name) {
    return std::any_of(latent.begin(), latent.end(), [&](const latent_variable& v) { return v.name == name; });
  };
  dynamic_structure structure;
  std::optional<dynamic_network> given;
  std::vector<named_edge> edges;
  std::set<std::string> templates;  // the columns read besides the episode's and the step's
  if (!args.model.empty()) {
    given = read_dynamic_model_file(args.model).model;
    structure = structure_of(*given);
    for (const auto& v : latent) static_cast<void>(template_id(*given, v.name, "--latent"));
    for (const auto& v : given->variables()) {
      if (!is_latent(v.name())) templates.insert(v.name());
    }
  } else {
    edges = parse_edge_list(args.edges);
    for (const auto& [from, to] : edges) {
      for (const auto& name : {template_of(from), template_of(to)}) {
        if (!is_latent(name)) templates.insert(name);
      }
    }
  }
  refuse_latent_columns(args.data, latent);
  const auto data =
      read_episodes(args.data, templates, given ? &*given : nullptr, missing_of(args.missing), args.threads);
  if (!given) {
    std::vector<variable> hidden;
    for (const auto& v : latent) {
      if (v.states.empty()) throw error("--latent '" + v.name + "' needs its states (NAME:COUNT or NAME=STATE,...)");
      hidden.emplace_back(v.name, v.states);
    }
    structure = dynamic_structure_from_data(data, edges, hidden);
  }
  dynamic_fit_request request;
  set_estimation(args, request.options.fit);
  request.keep_statistics = args.keep_counts;
  if (em) request.em = dynamic_em_options{.em = em_options_of(args)};
  std::optional<bayesian_network> prior;
  if (!args.transfer.prior_model.empty()) {
    prior = read_network_file(args.transfer.prior_model);
    require_map(args.transfer);
    request.prior_network = &*prior;
    request.transfer = settings_of(args.transfer);
    if (!args.initial_map.empty()) request.initial_map = args.initial_map;
    if (!args.initial_strategy.empty()) request.initial_strategy = args.initial_strategy;
  } else if (!args.transfer.map.empty() || !args.initial_map.empty() || !args.initial_strategy.empty()) {
    throw error("--map, --initial-map and --initial-strategy apply with --prior-model");
  }
  const auto fitted = fit_from_episodes(structure, data, request);
  if (fitted.em) note(summary_of(*fitted.em));
  if (fitted.transfer) note_transfer(*fitted.transfer, args.transfer.strategy);
  std::ostringstream summary;
  summary << "fitted a dynamic network of " << fitted.model.size() << " template variables from " << fitted.episodes
          << (fitted.episodes == 1 ? " episode" : " episodes") << " (" << fitted.steps << " steps; "
          << fitted.steps - fitted.episodes << " transitions counted into the tied tables) -> " << args.out << '\n';
  write_dynamic_json(fitted.model, args.out, summary_before_replacing(summary.str(), args.out),
                     fitted.statistics ? &*fitted.statistics : nullptr);
}

void run_fit(const fit_arguments& args) {
  if (args.dynamic) {
    run_dynamic_fit(args);
    return;
  }
  refuse_dynamic_only(args);
  require_network_extension(args.out);
  if (args.data == "-" && processes().size() > 1) {
    throw error("--data -: standard input reaches one process only; under mpirun give a file every process can read");
  }
  fit_request request;
  set_estimation(args, request.options);
  request.missing = missing_of(args.missing);
  const bool em = args.missing.policy == "em";
  if (em) {
    request.em = em_options_of(args);
    for (const auto& text : args.latent) request.latent.push_back(latent_of(text));
    if (args.keep_counts) {
      throw error(
          "--keep-counts does not apply with --missing em: EM's counts are expectations under its tables, "
          "which new rows would change");
    }
  } else if (!args.latent.empty()) {
    throw error("--latent applies with --missing em");
  }
  request.keep_statistics = args.keep_counts;
  if (!args.discretization_file.empty()) request.bin = read_discretization_json(args.discretization_file);
  if (!args.intervals_file.empty()) {
    request.intervals = read_discretization_json(args.intervals_file);
    request.intervals_source = args.intervals_file;
  }
  std::vector<variable> known;
  const auto is_latent = [&](const std::string& name) {
    return std::any_of(request.latent.begin(), request.latent.end(),
                       [&](const latent_variable& v) { return v.name == name; });
  };
  if (!args.model.empty()) {
    auto structure = read_model_file(args.model).structure;
    std::vector<std::string> columns;
    for (const auto& v : structure.variables()) {
      if (is_latent(v.name())) continue;
      columns.push_back(v.name());
      known.push_back(request.bin.contains(v.name()) ? request.bin.at(v.name()) : v);
    }
    note_model_states_read_as_missing(columns, {&request.bin, &known, request.missing});
    request.structure = std::move(structure);
  } else {
    request.structure = parse_edge_list(args.edges);
  }
  std::optional<bayesian_network> prior;
  if (!args.transfer.prior_model.empty()) {
    prior = read_network_file(args.transfer.prior_model);
    require_map(args.transfer);
    request.prior_network = &*prior;
    request.transfer = settings_of(args.transfer);
  } else if (!args.transfer.map.empty()) {
    throw error("--map applies with --prior-model");
  }
  fit_result fitted;
  if (em) {
    // EM reads the rows at every iteration: they are held in memory.
    if (processes().size() > 1) throw error("--missing em runs in one process, not under mpirun");
    // Every column is read, so that a latent variable that is one is refused.
    const auto data =
        read_discrete_data(args.data, {}, {&request.bin, args.model.empty() ? nullptr : &known, request.missing});
    dataset_source source(data);
    fitted = fit(source, request);
    note(summary_of(*fitted.em));
  } else {
    // The data are never held in memory: each node's family is counted as the file streams
    // by, over every process under mpirun; process 0 fits and writes.
    csv_reader input(args.data);
    csv_source source(input, processes());
    fitted = fit(source, request);
    if (!fitted.holds_network) return;
    note_counts(fitted.counts, request.bin);
  }
  if (fitted.transfer) note_transfer(*fitted.transfer, args.transfer.strategy);
  const auto summary = "fitted " + std::to_string(fitted.network.size()) + " tables (" +
                       std::to_string(fitted.network.free_parameters()) + " free parameters) from " +
                       std::to_string(fitted.counts.rows) + " rows -> " + args.out + "\n";
  write_network(fitted.network, args.out,
                {.statistics = fitted.statistics ? &*fitted.statistics : nullptr,
                 .before_replacing = summary_before_replacing(summary, args.out)});
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
                                "The structure (and states) from a model file instead: " + network_file_kinds());
  edges->excludes(model);
  model->excludes(edges);
  cmd->add_option("--estimator", args->estimator, "mle (eq. 3) or bayes (eq. 6)")
      ->check(CLI::IsMember(known_estimators()))
      ->capture_default_str();
  add_component_option(*cmd, "--prior", args->prior, "The Bayesian estimator's prior", parameter_priors());
  args->alpha = add_declared_option(*cmd, "--alpha", declared_option(parameter_priors(), "dirichlet", "alpha"),
                                    "Shorthand for --prior dirichlet[alpha=N]: the pseudo-count of every cell");
  args->ess = add_declared_option(*cmd, "--ess", declared_option(parameter_priors(), "bdeu", "ess"),
                                  "Shorthand for --prior bdeu[ess=N]: the equivalent sample size");
  cmd->add_option("--empty", args->empty, "A parent configuration with no data: uniform (1/J) or fail")
      ->check(CLI::IsMember(known_empty_configurations()))
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
  cmd->add_option("--out", args->out, "The fitted network: " + network_file_kinds())->required();
  add_missing_options(*cmd, args->missing, true);
  cmd->add_option("--latent", args->latent,
                  "With --missing em: a variable in no column of the data, as NAME:COUNT (states 0..COUNT-1), "
                  "NAME=STATE,STATE,... or, with --model, NAME (the model's states); repeat for more");
  cmd->add_option("--restarts", args->restarts,
                  "With --missing em and --latent: random starts of the latent tables; the best is kept")
      ->check(whole_number(1, 1000))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "With --missing em: seed of the random starts")
      ->check(whole_number(0, UINT64_MAX))
      ->capture_default_str();
  cmd->add_option("--max-iterations", args->max_iterations, "With --missing em: the most M-steps per start")
      ->check(whole_number(0, 1000000))
      ->capture_default_str();
  cmd->add_option("--tolerance", args->tolerance,
                  "With --missing em: stop when the log-likelihood (plus the prior's term) changes by at most this "
                  "fraction")
      ->check(non_negative_number())
      ->capture_default_str();
  cmd->add_flag("--hard", args->hard,
                "With --missing em: hard EM (each incomplete row completed by its most probable values)");
  cmd->add_flag("--verbose", args->verbose, "With --missing em: print the log-likelihood of every iteration");
  cmd->add_flag(
      "--keep-counts", args->keep_counts,
      "Keep the counts and priors in the model (in JSON under \"statistics\", in BIF, XMLBIF and NET as a "
      "property peers ignore; a dynamic network's under \"statistics\" too), so that pgm update can add new data "
      "(or episodes) to it");
  add_transfer_options(*cmd, args->transfer, true);
  cmd->add_flag("--dynamic", args->dynamic,
                "Fit a dynamic network (a 2-TBN, written as pgm's JSON model) from episodes in long form: columns "
                "episode, t (0, 1, … within an episode) and the variables, one row per episode and step. --edges "
                "\"a->b\" lies within a slice, \"a@-1->b\" runs from the step before; --model takes a dynamic "
                "model's structure. Each variable's transition table is tied: every step after the first of every "
                "episode counts towards it. --prior-model transfers into both slices (a previous slice's parent "
                "has counterparts of its own: \"onTop=onTop1,xOff~xOff1,xOff@-1==xOff1\"). --missing em estimates "
                "missing values and --latent template variables over whole episodes");
  cmd->add_option("--initial-map", args->initial_map,
                  "With --dynamic and --prior-model: the first slice's own map (default: --map less its x@-1 "
                  "entries), or none to leave the first slice to the data");
  cmd->add_option("--initial-strategy", args->initial_strategy,
                  "With --dynamic and --prior-model: the first slice's own strategy (default: --strategy)");
  cmd->callback([args] {
    if (args->edges.empty() && args->model.empty()) throw error("give the structure with --edges or --model");
    run_fit(*args);
  });
}

}  // namespace pgm::cli
