// pgm learn-structure: PC-stable on discrete data; prints the CPDAG (and, on request, why each
// absent edge is absent) and writes one DAG of its class as a structure-only JSON model.

#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "pgm/core/error.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/learn/pc.hpp"

namespace pgm::cli {
namespace {

struct learn_structure_arguments {
  std::string data;
  std::string test = "chi2";
  double alpha = 0.01;
  std::string correction = "none";
  double min_rows_per_cell = 0.0;
  std::size_t max_conditioning = 3;
  std::string tiers;
  std::string forbid;
  std::string require;
  unsigned threads = 0;
  bool explain = false;
  std::string out;
  missing_arguments missing;
};

std::string format_set(const cpdag& graph, const std::vector<variable_id>& given) {
  std::vector<std::string> names;
  for (auto v : given) names.push_back(graph.name(v));
  return "{" + detail::join(names) + "}";
}

void run_learn_structure(const learn_structure_arguments& args) {
  require_extension(args.out, {".json"});
  pc_options options;
  options.test = parse_ci_test(args.test);
  options.alpha = args.alpha;
  options.correction = parse_continuity_correction(args.correction);
  options.min_rows_per_cell = args.min_rows_per_cell;
  options.max_conditioning = args.max_conditioning;
  options.threads = args.threads;
  if (!args.tiers.empty()) options.knowledge.tiers = parse_tiers(args.tiers);
  if (!args.forbid.empty()) options.knowledge.forbidden = parse_edge_list(args.forbid);
  if (!args.require.empty()) options.knowledge.required = parse_edge_list(args.require);

  const auto data = read_discrete_data(args.data, {}, {.missing = missing_of(args.missing)});
  if (data.size() < 2) throw data_error("'" + args.data + "' has fewer than two columns; nothing to learn");
  const auto result = pc_stable(data, options);
  const auto& graph = result.graph;

  std::ostringstream out;
  out << "PC-stable on " << data.rows() << " rows, " << data.size() << " variables: " << result.tests << " tests ("
      << to_string(options.test) << ", alpha " << detail::format_short(options.alpha) << ", conditioning sets up to "
      << options.max_conditioning;
  if (options.correction != continuity_correction::none) out << ", " << to_string(options.correction) << " correction";
  if (options.min_rows_per_cell > 0) {
    out << ", independent below " << detail::format_short(options.min_rows_per_cell) << " rows per cell";
  }
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
            << detail::format_short(options.min_rows_per_cell) << " per cell)\n";
        continue;
      }
      out << "independent given " << format_set(graph, s.given) << " (" << to_string(options.test) << " = "
          << detail::format_short(s.test.statistic, 5) << ", df = " << detail::format_short(s.test.df)
          << ", p = " << detail::format_short(s.test.p_value, 4) << ")\n";
    }
  }
  for (const auto& conflict : result.conflicts) note("orientation conflict: " + conflict);

  // A fitted model needs a DAG: take one member of the CPDAG's class.
  std::size_t relaxed = 0;
  const auto edges = extend_to_dag(graph, true, &relaxed);
  std::vector<variable> variables;
  for (const auto& name : data.names()) variables.push_back(data.discrete(name).var());
  const network_structure structure(variables, edges);
  auto document = to_json(structure);
  document["learned"] = {{"algorithm", "pc-stable"},
                         {"test", to_string(options.test)},
                         {"alpha", options.alpha},
                         {"correction", to_string(options.correction)},
                         {"min_rows_per_cell", options.min_rows_per_cell},
                         {"max_conditioning", options.max_conditioning},
                         {"rows", data.rows()},
                         {"undirected_in_cpdag", nlohmann::json::array()}};
  for (const auto& e : undirected) document["learned"]["undirected_in_cpdag"].push_back({e.from, e.to});
  write_model_json(document, args.out);

  std::cout << out.str();
  if (undirected.empty()) {
    std::cout << "every edge is oriented; the DAG is the CPDAG";
  } else {
    std::cout << "extended the CPDAG to a DAG: " << undirected.size() << " undirected edge(s) oriented"
              << (relaxed ? "" : " without adding a v-structure");
  }
  std::cout << " -> " << args.out << '\n';
  if (relaxed > 0) {
    note("the CPDAG has no extension without a new v-structure (orientation conflicts); " + std::to_string(relaxed) +
         " node(s) were given new v-structures to make it a DAG");
  }
}

}  // namespace

void add_learn_structure_command(CLI::App& app) {
  auto args = std::make_shared<learn_structure_arguments>();
  auto* cmd = app.add_subcommand("learn-structure", "Learn a causal structure from discrete data with PC-stable");
  cmd->add_option("--data", args->data,
                  std::string("CSV file of discrete data, one column per variable") + data_file_help)
      ->required();
  cmd->add_option("--test", args->test, "Independence test: chi2 (Pearson) or g2 (likelihood ratio)")
      ->check(CLI::IsMember({"chi2", "g2"}))
      ->capture_default_str();
  cmd->add_option("--alpha", args->alpha,
                  "Significance level, strictly between 0 and 1: an edge goes when a test has p > alpha")
      ->check(number_between(0, 1, true, true))
      ->capture_default_str();
  cmd->add_option("--correction", args->correction,
                  "Continuity correction of 2x2 strata: none, or yates as pgmpy applies it")
      ->check(CLI::IsMember({"none", "yates"}))
      ->capture_default_str();
  cmd->add_option("--min-rows-per-cell", args->min_rows_per_cell,
                  "Declare independence, untested, when a test has fewer rows than K per cell of its table "
                  "(5: bnlearn's rule; 0: always test)")
      ->check(non_negative_number())
      ->capture_default_str();
  cmd->add_option("--max-cond", args->max_conditioning, "Largest conditioning set tried")
      ->check(whole_number(0, 64))
      ->capture_default_str();
  cmd->add_option("--tiers", args->tiers,
                  "Tiers, earliest first, e.g. \"xOff1,yOff1;onTop1;onTop2\": no edge points into an "
                  "earlier tier");
  cmd->add_option("--forbid", args->forbid, "Edges that may not exist, e.g. \"a->b,c->d\"");
  cmd->add_option("--require", args->require, "Edges that must exist, e.g. \"xOff1->onTop1\"");
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores); the result is the same")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  cmd->add_flag("--explain", args->explain, "Also print the test that removed each absent edge");
  cmd->add_option("--out", args->out, "The learned structure, a .json model without tables")->required();
  add_missing_options(*cmd, args->missing);
  cmd->callback([args] { run_learn_structure(*args); });
}

}  // namespace pgm::cli
