// pgm learn-structure: PC-stable, hill climbing, tabu search or the hybrid (PC's skeleton, then
// hill climbing) on discrete data, through learn_structure (pgm/learn/learn_structure.hpp). PC
// prints the CPDAG (and, on request, why each absent edge is absent); the score searches print
// the score and the DAG. Either writes one DAG as a structure-only JSON model.

#include "pgm/learn/learn_structure.hpp"

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "cli/common.hpp"
#include "cli/component_options.hpp"
#include "pgm/core/correspondence.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/learn/bootstrap.hpp"
#include "pgm/learn/learn_dynamic_structure.hpp"
#include "pgm/learn/pc.hpp"
#include "pgm/learn/structure_prior.hpp"

namespace pgm::cli {
namespace {

/// A map entry's prior side must name a variable of the prior model.
void require_prior_variable(const network_structure& prior, const std::string& name, const std::string& file) {
  if (!prior.contains(name)) throw error("the map names '" + name + "', which is not a variable of '" + file + "'");
}

struct learn_structure_arguments {
  std::string data;
  std::string algorithm{default_structure_learner};
  /// The options that set one option of the learner (or of its start), applied when given:
  /// each flag and the learner option it sets.
  std::vector<std::pair<CLI::Option*, std::string>> learner_options;
  CLI::Option* max_parents = nullptr;
  std::string test_text = independence_test().name();
  CLI::Option* test = nullptr;
  std::string score_text = family_score().name();
  CLI::Option* score = nullptr;
  std::optional<double> iss;
  std::uint64_t seed = 1;
  std::string start;
  std::size_t bootstrap = 0;
  std::string prior_model;
  std::string map;
  double prior_weight = 5.0;
  std::optional<double> threshold;
  std::optional<std::string> correction;
  std::optional<double> min_rows_per_cell;
  std::string tiers;
  std::string forbid;
  std::string require;
  unsigned threads = 0;
  bool explain = false;
  std::string out;
  missing_arguments missing;
  bool dynamic = false;
};

/// --prior-model and --map: the prior network's edges carried over to `target` (the learned
/// variables' names), favoured by --prior-weight each in the score of the search. With
/// --dynamic, an edge into the previous slice is left out: no learner may add it.
void add_structure_prior(const learn_structure_arguments& args, const std::vector<std::string>& target,
                         structure_context& context) {
  if (args.prior_model.empty()) {
    if (!args.map.empty()) throw error("--map applies with --prior-model");
    return;
  }
  const auto prior_structure = read_model_file(args.prior_model).structure;
  const auto map = args.map.empty() ? correspondence{} : parse_correspondence(args.map);
  for (const auto& [t, p] : map.transferred) require_prior_variable(prior_structure, p, args.prior_model);
  for (const auto& [t, p] : map.identical) require_prior_variable(prior_structure, p, args.prior_model);
  for (const auto& [t, p] : map.related) require_prior_variable(prior_structure, p, args.prior_model);
  context.favoured = mapped_prior_edges(prior_structure.edges(), map, target);
  if (args.dynamic) {
    std::erase_if(context.favoured, [](const named_edge& e) { return template_of(e.to) != e.to; });
  }
  context.favour_weight = args.prior_weight;
  std::vector<std::string> shown;
  for (const auto& e : context.favoured) shown.push_back(e.from + "->" + e.to);
  note("the structure prior favours " + std::to_string(shown.size()) + " edge(s) by " +
       text::format_short(args.prior_weight) + " each" + (shown.empty() ? "" : ": " + text::join(shown)));
}

/// "a->b, a@-1->b", as --edges reads them.
std::string edge_list_text(const std::vector<named_edge>& edges) {
  std::vector<std::string> shown;
  for (const auto& e : edges) shown.push_back(e.from + "->" + e.to);
  return text::join(shown);
}

/// Every arc seen in a resample with its strength and direction, then the averaged network.
std::string strengths_text(const bootstrap_result& result, bool threshold_given) {
  std::ostringstream out;
  out << "arc strengths (adjacent in a fraction of the resamples; direction: the fraction of those with the arc):\n";
  for (const auto& a : result.arcs) {
    if (a.strength > 0 && a.direction > 0) {
      out << "  " << a.from << " -> " << a.to << "  strength " << text::format_short(a.strength, 4) << "  direction "
          << text::format_short(a.direction, 4) << '\n';
    }
  }
  out << "averaged network at threshold " << text::format_short(result.threshold, 4)
      << (threshold_given ? "" : " (bnlearn's L1 rule)") << " (" << result.averaged.size() << " edges):\n";
  for (const auto& e : result.averaged) out << "  " << e.from << " -> " << e.to << '\n';
  return out.str();
}

/// pgm learn-structure --dynamic: a dynamic network's structure from episodes in long form, by any
/// learner over the transitions' data, its tables then fitted by MLE.
void run_dynamic_learn(const learn_structure_arguments& args, const structure_learner& learner,
                       const structure_context& context) {
  const auto refuse = [](bool given, const std::string& option) {
    if (given) throw error("--dynamic: " + option + " is not available for dynamic networks yet");
  };
  refuse(!args.start.empty(), "--start");
  refuse(args.missing.policy == "drop", "--missing drop (it would leave gaps in the episodes)");
  const episode_columns columns;
  auto reading = long_form_options(columns);
  reading.missing = missing_of(args.missing);
  reading.threads = args.threads;
  const auto data = read_csv(args.data, reading);
  std::vector<std::string> names;
  for (const auto& name : data.names()) {
    if (name != columns.episode && name != columns.step) names.push_back(name);
  }
  if (names.empty()) throw data_error("'" + args.data + "' has no column besides the episode and the step");
  std::vector<std::string> both;  // the learner's variables: the step before's, then this step's
  for (const auto& name : names) both.push_back(slice_name(name, -1));
  both.insert(both.end(), names.begin(), names.end());
  auto with_prior = context;
  add_structure_prior(args, both, with_prior);
  std::ostringstream out;
  dynamic_structure structure;
  std::vector<named_edge> edges;
  if (args.bootstrap > 0) {
    auto result = bootstrap_dynamic_structure(data, names, learner, with_prior,
                                              {args.bootstrap, args.seed, args.threshold}, columns);
    out << learner.name() << " on " << result.arcs.replicates << " bootstrap resamples of the episodes\n"
        << strengths_text(result.arcs, args.threshold.has_value());
    structure = std::move(result.structure);
    edges = std::move(result.arcs.averaged);
  } else {
    if (args.threshold) throw error("--threshold applies with --bootstrap");
    auto learned = learn_dynamic_structure(data, names, learner, with_prior, columns);
    structure = std::move(learned.structure);
    edges = std::move(learned.learned.edges);
  }
  const auto counts = count_dynamic(structure, data, columns);
  const auto model = fit_dynamic(structure, counts);
  out << learner.name() << " over " << names.size() << " template variables and the step before each, from "
      << counts.episodes << " episodes (" << counts.steps << " steps): " << edges.size() << " edges -> " << args.out
      << "\n  --edges \"" << edge_list_text(edges) << "\"\n";
  write_dynamic_json(model, args.out, summary_before_replacing(out.str(), args.out));
  note("the tables of " + args.out + " are fitted by MLE; pgm fit --dynamic --model " + args.out +
       " refits them with another prior");
}

/// Each option of a component as a member of `object`, under its name.
void add_options(nlohmann::json& object, const option_values& options) {
  for (std::size_t i = 0; i < options.declarations().size(); ++i) {
    std::visit([&](const auto& value) { object[options.declarations()[i].name] = value; }, options.values()[i]);
  }
}

/// The built-in tests' settings as PC's summary line has always shown them, other options as
/// "key value": ", yates correction, independent below 5 rows per cell".
std::string test_settings(const independence_test& test) {
  std::string shown;
  const auto& options = test.options();
  for (std::size_t i = 0; i < options.declarations().size(); ++i) {
    const auto& name = options.declarations()[i].name;
    const auto& value = options.values()[i];
    if (name == "correction") {
      if (options.word(name) != "none") shown += ", " + options.word(name) + " correction";
    } else if (name == "min_rows_per_cell") {
      if (options.number(name) > 0)
        shown += ", independent below " + text::format_short(options.number(name)) + " rows per cell";
    } else {
      shown += ", " + name + " " + format_option_value(value);
    }
  }
  return shown;
}

/// The rows per cell below which the test declares independence untested (0 for a test
/// without that option).
double min_rows_per_cell(const independence_test& test) {
  return test.options().declares("min_rows_per_cell") ? test.options().number("min_rows_per_cell") : 0.0;
}

std::string format_set(const cpdag& graph, const std::vector<variable_id>& given) {
  std::vector<std::string> names;
  for (auto v : given) names.push_back(graph.name(v));
  return "{" + text::join(names) + "}";
}

/// The search's heading: "tabu search", "hill climbing", or a user's learner's name.
std::string search_heading(const std::string& learner) {
  if (learner == "tabu") return "tabu search";
  if (learner == "mmhc") return "hybrid (PC-stable skeleton, then hill climbing)";
  if (learner == "hc") return "hill climbing";
  return learner;
}

void write_searched(const learn_structure_arguments& args, const structure_learner& learner,
                    const structure_context& context, const dataset& data, const structure_result& learned) {
  const auto& result = *learned.search;
  const auto& options = learner.options();
  std::ostringstream out;
  out << search_heading(learner.name()) << " on " << data.rows() << " rows, " << data.size() << " variables";
  std::optional<family_score> score;
  if (options.declares("score")) score = make_score(options.component("score"));
  if (score) out << ": " << described(*score);
  out << " = " << text::format_double(result.score - result.prior_bonus);
  if (!context.favoured.empty()) {
    out << " + structure prior " << text::format_double(result.prior_bonus) << " = "
        << text::format_double(result.score);
  }
  out << " after " << result.moves << " moves";
  if (result.restarts > 0) out << " over " << result.restarts << " restarts";
  out << " (" << result.families_scored << " families scored, " << result.cache_hits << " from the cache)\n";
  out << "edges (" << result.edges.size() << "):\n";
  for (const auto& e : result.edges) out << "  " << e.from << " -> " << e.to << '\n';

  std::vector<variable> variables;
  for (const auto& name : data.names()) variables.push_back(data.discrete(name).var());
  const network_structure structure(variables, result.edges);
  auto document = to_json(structure);
  document["learned"] = {{"algorithm", learner.name()},
                         {"score", score ? score->name() : std::string()},
                         {"score_value", result.score - result.prior_bonus},
                         {"rows", data.rows()},
                         {"moves", result.moves},
                         {"restarts", result.restarts},
                         {"seed", options.declares("seed") ? options.count("seed") : std::size_t{0}}};
  if (score) add_options(document["learned"], score->options());
  if (options.declares("tabu")) document["learned"]["tabu"] = options.count("tabu");
  write_model_json(document, args.out, summary_before_replacing(out.str() + "-> " + args.out + "\n", args.out));
}

void write_bootstrap(const learn_structure_arguments& args, const structure_learner& learner,
                     const structure_context& context, const dataset& data) {
  const auto names = data.names();
  const auto result = bootstrap_structure(data, names, learner, context, {args.bootstrap, args.seed, args.threshold});
  std::ostringstream out;
  out << learner.name() << " on " << result.replicates << " bootstrap resamples of " << data.rows() << " rows, "
      << data.size() << " variables\n"
      << strengths_text(result, args.threshold.has_value());

  std::vector<variable> variables;
  for (const auto& name : names) variables.push_back(data.discrete(name).var());
  auto document = to_json(network_structure(variables, result.averaged));
  document["learned"] = {{"algorithm", learner.name()},   {"bootstrap", result.replicates},
                         {"threshold", result.threshold}, {"seed", args.seed},
                         {"rows", data.rows()},           {"strength", nlohmann::json::array()}};
  for (const auto& a : result.arcs) {
    if (a.strength > 0 && a.direction > 0) {
      document["learned"]["strength"].push_back(
          {{"from", a.from}, {"to", a.to}, {"strength", a.strength}, {"direction", a.direction}});
    }
  }
  write_model_json(document, args.out, summary_before_replacing(out.str() + "-> " + args.out + "\n", args.out));
}

/// A learner that reports neither PC's tests nor a search's score: its edges.
void write_learned(const learn_structure_arguments& args, const structure_learner& learner, const dataset& data,
                   const structure_result& learned) {
  std::ostringstream out;
  out << learner.name() << " on " << data.rows() << " rows, " << data.size() << " variables\n";
  out << "edges (" << learned.edges.size() << "):\n";
  for (const auto& e : learned.edges) out << "  " << e.from << " -> " << e.to << '\n';
  std::vector<variable> variables;
  for (const auto& name : data.names()) variables.push_back(data.discrete(name).var());
  auto document = to_json(network_structure(variables, learned.edges));
  document["learned"] = {{"algorithm", learner.name()}, {"rows", data.rows()}};
  add_options(document["learned"], learner.options());
  write_model_json(document, args.out, summary_before_replacing(out.str() + "-> " + args.out + "\n", args.out));
}

/// The learner the arguments choose: --algorithm with each option given that sets one of its
/// options, or of the PC that --start pc starts from.
structure_learner chosen_learner(const learn_structure_arguments& args) {
  std::vector<component_setting> settings;
  if (args.start == "pc") settings.push_back({"--start", "start", "pc"});
  if (args.test->count() > 0 || args.correction || args.min_rows_per_cell) {
    const auto rows =
        args.min_rows_per_cell ? std::optional(text::format_double(*args.min_rows_per_cell)) : std::nullopt;
    const auto test = chosen_with(
        independence_tests(), args.test_text,
        {{"--correction", "correction", args.correction}, {"--min-rows-per-cell", "min_rows_per_cell", rows}});
    settings.push_back({"--test", "test", test.text()});
  }
  if (args.score->count() > 0 || args.iss) {
    const auto iss = args.iss ? std::optional(text::format_double(*args.iss)) : std::nullopt;
    settings.push_back({"--score", "score", chosen_with(scores(), args.score_text, {{"--iss", "iss", iss}}).text()});
  }
  if (const auto limit = given_value(*args.max_parents)) {
    settings.push_back({"--max-parents", "max_parents", *limit == "0" ? "unlimited" : *limit});
  }
  // --seed seeds the bootstrap as well, so it goes to the learner only when the learner has a seed.
  const bool seeded = structure_learners().choose(args.algorithm).options.declares("seed");
  for (const auto& [option, key] : args.learner_options) {
    if (key != "seed" || seeded) settings.push_back({option->get_name(), key, given_value(*option)});
  }
  try {
    return make_structure_learner(args.algorithm, settings);
  } catch (const error& refused) {
    throw CLI::ValidationError(refused.what());
  }
}

/// "hc, mmhc and tabu": the learners that declare the option `key`.
std::string learners_declaring(const std::string& key) {
  std::vector<std::string> names;
  for (const auto& name : structure_learners().names()) {
    const auto options = structure_learners().find(name)->options;
    if (std::any_of(options.begin(), options.end(), [&](const auto& option) { return option.name == key; })) {
      names.push_back(name);
    }
  }
  const auto last = names.back();
  names.pop_back();
  return names.empty() ? last : text::join(names) + " and " + last;
}

void run_learn_structure(const learn_structure_arguments& args) {
  require_extension(args.out, {".json"});
  const auto learner = chosen_learner(args);
  // A start network is for a search that declares a start; a structure prior, a score bonus,
  // for a learner with a score.
  if (!args.start.empty() && !learner.options().declares("start")) {
    throw error("--start applies to " + learners_declaring("start") + ", not " + learner.name());
  }
  if (!args.prior_model.empty() && !learner.options().declares("score")) {
    throw error("--prior-model applies to " + learners_declaring("score") + ", not " + learner.name());
  }
  structure_context context;
  context.threads = args.threads;
  if (!args.tiers.empty()) context.knowledge.tiers = parse_tiers(args.tiers);
  if (!args.forbid.empty()) context.knowledge.forbidden = parse_edge_list(args.forbid);
  if (!args.require.empty()) context.knowledge.required = parse_edge_list(args.require);
  if (!args.start.empty() && args.start != "pc") context.start = read_model_file(args.start).structure.edges();

  if (args.dynamic) {
    run_dynamic_learn(args, learner, context);
    return;
  }
  const auto data = read_discrete_data(args.data, {}, {.missing = missing_of(args.missing)});
  if (data.size() < 2) throw data_error("'" + args.data + "' has fewer than two columns; nothing to learn");
  add_structure_prior(args, data.names(), context);
  if (args.bootstrap > 0) {
    write_bootstrap(args, learner, context, data);
    return;
  }
  if (args.threshold) throw error("--threshold applies with --bootstrap");
  const auto learned = learn_structure(data, learner, context);
  if (learned.search) {
    write_searched(args, learner, context, data, learned);
    return;
  }
  if (!learned.pc || !learner.options().declares("test")) {
    write_learned(args, learner, data, learned);
    return;
  }
  const auto& result = *learned.pc;
  const auto& graph = result.graph;
  const auto test = make_independence_test(learner.options().component("test"));
  const auto alpha = learner.options().number("alpha");
  const auto max_conditioning = learner.options().count("max_conditioning");

  std::ostringstream out;
  out << "PC-stable on " << data.rows() << " rows, " << data.size() << " variables: " << result.tests << " tests ("
      << test.name() << ", alpha " << text::format_short(alpha) << ", conditioning sets up to " << max_conditioning
      << test_settings(test);
  out << ")\n";
  const auto directed = graph.directed_edges();
  const auto undirected = graph.undirected_edges();
  out << "directed edges (" << directed.size() << "):\n";
  for (const auto& e : directed) out << "  " << e.from << " -> " << e.to << '\n';
  out << "undirected edges (" << undirected.size() << "):\n";
  for (const auto& e : undirected) out << "  " << e.from << " - " << e.to << '\n';
  if (args.explain) {
    out << "absent edges (" << result.removed.size() << "):\n";
    for (const auto& s : result.removed) {
      out << "  no " << graph.name(s.x) << " - " << graph.name(s.y) << ": ";
      if (s.by_knowledge) {
        out << "forbidden both ways by background knowledge\n";
        continue;
      }
      if (s.test.too_few_rows) {
        out << "independent given " << format_set(graph, s.given) << " (too few rows: " << s.test.rows << " < "
            << text::format_short(min_rows_per_cell(test)) << " per cell)\n";
        continue;
      }
      out << "independent given " << format_set(graph, s.given) << " (" << test.name() << " = "
          << text::format_short(s.test.statistic, 5) << ", df = " << text::format_short(s.test.df)
          << ", p = " << text::format_short(s.test.p_value, 4) << ")\n";
    }
  }
  for (const auto& conflict : result.conflicts) note("orientation conflict: " + conflict);

  // A fitted model needs a DAG: take one member of the CPDAG's class.
  const std::size_t relaxed = learned.relaxed;
  const auto& edges = learned.edges;
  std::vector<variable> variables;
  for (const auto& name : data.names()) variables.push_back(data.discrete(name).var());
  const network_structure structure(variables, edges);
  auto document = to_json(structure);
  document["learned"] = {{"algorithm", "pc-stable"}, {"test", test.name()},
                         {"alpha", alpha},           {"max_conditioning", max_conditioning},
                         {"rows", data.rows()},      {"undirected_in_cpdag", nlohmann::json::array()}};
  add_options(document["learned"], test.options());
  for (const auto& e : undirected) document["learned"]["undirected_in_cpdag"].push_back({e.from, e.to});
  if (undirected.empty()) {
    out << "every edge is oriented; the DAG is the CPDAG";
  } else {
    out << "extended the CPDAG to a DAG: " << undirected.size() << " undirected edge(s) oriented"
        << (relaxed ? "" : " without adding a v-structure");
  }
  out << " -> " << args.out << '\n';
  write_model_json(document, args.out, summary_before_replacing(out.str(), args.out));
  if (relaxed > 0) {
    note("the CPDAG has no extension without a new v-structure (orientation conflicts); " + std::to_string(relaxed) +
         " node(s) were given new v-structures to make it a DAG");
  }
}

}  // namespace

void add_learn_structure_command(CLI::App& app) {
  auto args = std::make_shared<learn_structure_arguments>();
  auto* cmd = app.add_subcommand("learn-structure",
                                 "Learn a causal structure from discrete data: PC-stable, hill climbing, tabu search "
                                 "or the hybrid");
  cmd->add_option("--data", args->data,
                  std::string("CSV file of discrete data, one column per variable") + data_file_help)
      ->required();
  add_component_option(*cmd, "--algorithm", args->algorithm,
                       "The structure learner: pc (PC-stable), hc (hill climbing), tabu (tabu search), mmhc "
                       "(PC-stable's skeleton restricts hill climbing), empty, or a registered one. The options below "
                       "set the learner's own",
                       structure_learners());
  const auto declared = [](const std::string& learner, const std::string& key) {
    return declared_option(structure_learners(), learner, key);
  };
  const auto learner_option = [&](const std::string& flag, const std::string& learner, const std::string& key,
                                  const std::string& help) {
    args->learner_options.emplace_back(add_declared_option(*cmd, flag, declared(learner, key), help), key);
  };
  args->score = add_component_option(*cmd, "--score", args->score_text,
                                     "The decomposable score of hc, tabu and mmhc, as bnlearn's score() defines it "
                                     "('bde' is bdeu)",
                                     scores());
  cmd->add_option("--iss", args->iss, "Shorthand for --score bdeu[iss=N]: bdeu's imaginary sample size, a number > 0")
      ->check(number_between(0, std::numeric_limits<double>::infinity(), true, true));
  args->max_parents = add_declared_option(*cmd, "--max-parents", declared("hc", "max_parents"),
                                          "The most parents a node may get (0 or unlimited: no limit)");
  learner_option("--tabu", "tabu", "tabu", "Tabu list length of --algorithm tabu (bnlearn's default)");
  learner_option("--max-tabu", "tabu", "max_tabu",
                 "Moves in a row without improving on the best network before tabu search stops");
  learner_option("--restarts", "hc", "restarts", "Random restarts after the search converges");
  learner_option("--perturb", "hc", "perturb", "Random moves that perturb the network at each restart");
  auto* seed =
      cmd->add_option("--seed", args->seed, "Seed of the restarts' perturbations and of the bootstrap resamples")
          ->check(whole_number(0, UINT64_MAX))
          ->capture_default_str();
  args->learner_options.emplace_back(seed, "seed");
  cmd->add_option("--bootstrap", args->bootstrap,
                  "Learn on N bootstrap resamples (seeded by --seed, in parallel): print each arc's strength and "
                  "direction (bnlearn's boot.strength) and write the averaged network")
      ->check(whole_number(0, 100000))
      ->capture_default_str();
  cmd->add_option("--threshold", args->threshold,
                  "Strength above which the averaged network keeps an arc (default: bnlearn's L1 rule)")
      ->check(number_between(0, 1, false, false));
  cmd->add_option("--prior-model", args->prior_model,
                  "A related task's network (" + network_file_kinds() +
                      "): favour the edges that --map carries over "
                      "to this data's variables (hc, tabu, mmhc; with --dynamic, to both slices' "
                      "variables: \"b=b1, a@-1==a1\")");
  cmd->add_option("--map", args->map,
                  "Correspondence of this data's variables (left) to the prior's (right), as pgm fit's: "
                  "\"onTop2=onTop1,xOff2~xOff1\"; variables with equal names correspond without an entry");
  cmd->add_option("--prior-weight", args->prior_weight, "Score bonus per favoured edge in the network, 0 to 1e12")
      ->check(number_between(0.0, max_favour_weight, false, false))
      ->capture_default_str();
  cmd->add_option("--start", args->start,
                  "Start hc, tabu or mmhc from this network's structure (" + network_file_kinds() +
                      "), or from "
                      "PC-stable's result on the data with 'pc' (its --test, --alpha, --max-cond), instead of the "
                      "empty graph");
  args->test =
      add_component_option(*cmd, "--test", args->test_text, "Independence test of pc and mmhc", independence_tests());
  learner_option("--alpha", "pc", "alpha",
                 "Significance level, strictly between 0 and 1: an edge goes when a test has p > alpha");
  cmd->add_option("--correction", args->correction,
                  "Shorthand for --test NAME[correction=C]: none, or yates as pgmpy applies it");
  cmd->add_option("--min-rows-per-cell", args->min_rows_per_cell,
                  "Shorthand for --test NAME[min_rows_per_cell=K]: declare independence, untested, when a test has "
                  "fewer rows than K per cell of its table (5: bnlearn's rule; 0: always test)")
      ->check(non_negative_number());
  learner_option("--max-cond", "pc", "max_conditioning", "Largest conditioning set tried");
  cmd->add_option("--tiers", args->tiers,
                  "Tiers, earliest first, e.g. \"xOff1,yOff1;onTop1;onTop2\": no edge points into an "
                  "earlier tier");
  cmd->add_option("--forbid", args->forbid, "Edges that may not exist, e.g. \"a->b,c->d\"");
  cmd->add_option("--require", args->require, "Edges that must exist, e.g. \"xOff1->onTop1\"");
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores); the result is the same")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  cmd->add_flag("--explain", args->explain, "Also print the test that removed each absent edge");
  cmd->add_option("--out", args->out,
                  "The learned structure, a .json model without tables (with --dynamic, a dynamic model with its "
                  "tables fitted by MLE)")
      ->required();
  cmd->add_flag("--dynamic", args->dynamic,
                "Learn a dynamic network (a 2-TBN) from episodes in long form (columns episode, t and the variables): "
                "the learner runs over each step's variables and the step before's (x@-1), which stay roots, so an "
                "edge between slices runs forward; the first slice takes the edges within a slice. --tiers, --forbid "
                "and --require name both slices' variables (\"a@-1->b\"); --bootstrap resamples whole episodes");
  add_missing_options(*cmd, args->missing);
  cmd->callback([args] { run_learn_structure(*args); });
}

}  // namespace pgm::cli
