// pgm query: P(X | evidence) for every state of the query variables, every marginal at once
// (--all), the most probable explanation (--mpe), or a file of queries answered in one process
// (--queries), by any inference engine; as CSV or JSON.

#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "cli/common.hpp"
#include "cli/component_options.hpp"
#include "pgm/core/file.hpp"
#include "pgm/inference/engine_registry.hpp"
#include "pgm/inference/posterior_table.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/query_batch.hpp"

namespace pgm::cli {
namespace {

struct query_arguments {
  std::string model;
  std::optional<std::string> query;  // given but empty is an error, not "no query"
  std::string evidence;
  std::string soft;
  std::string intervene;
  bool all = false;
  bool mpe = false;
  std::string queries;
  std::string engine = "auto";
  std::size_t samples = sampling_options{}.samples;
  std::uint64_t seed = sampling_options{}.seed;
  std::size_t burn_in = sampling_options{}.burn_in;
  unsigned threads = 0;
  std::string format = "csv";
  int digits = 6;
  std::string out;
};

inference_options options_of(const query_arguments& args) {
  inference_options options;
  options.sampling.samples = args.samples;
  options.sampling.seed = args.seed;
  options.sampling.burn_in = args.burn_in;
  options.sampling.threads = args.threads;
  return options;
}

/// The engines a run uses over one model (either class), each made once, by name.
template <GraphicalModel M>
class engines {
 public:
  engines(std::shared_ptr<const M> model, inference_options options) : model_(std::move(model)), options_(options) {}

  any_inference_engine& get(const std::string& name) {
    auto it = made_.find(name);
    if (it == made_.end()) {
      it = made_.emplace(name, make_engine(name, model_, options_)).first;
      // "auto" says when it could not be exact; the output names the engine either way.
      if (it->second.name() != "jt" && !it->second.note().empty()) note(it->second.note());
    }
    return it->second;
  }

 private:
  std::shared_ptr<const M> model_;
  inference_options options_;
  std::map<std::string, any_inference_engine, std::less<>> made_;
};

/// Answers the --queries file into `out`, one query at a time (the caller keeps `out` from its
/// destination until all are answered: on the first failure, nothing is written).
template <GraphicalModel M>
void answer_batch(const query_arguments& args, const std::shared_ptr<const M>& model, std::ostream& out,
                  const posterior_table_options& table) {
  const auto text = pgm::read_file(args.queries);
  query_batch_reader reader(text, args.queries);
  engines<M> made(model, options_of(args));
  bool header = true;
  std::size_t answered = 0, impossible = 0;
  for (query_request request; reader.next(request); ++answered) {
    try {
      auto& engine = made.get(request.engine.empty() ? args.engine : request.engine);
      engine.set_evidence(resolve_evidence(*model, request.observed, request.soft, request.intervened));
      const auto ids = resolve_query(*model, request.query, engine.evidence());
      try {
        write_query_record(out, request, engine.joint(ids), table, header);
      } catch (const impossible_evidence& e) {
        write_impossible_record(out, request, std::string(engine.name()), e.what(), table, header);
        ++impossible;
      }
      header = false;
    } catch (const parse_error&) {
      throw;
    } catch (const error& e) {
      throw parse_error(args.queries, request.line, 1, e.what());
    }
  }
  if (impossible > 0) {
    note(std::to_string(impossible) + " of " + std::to_string(answered) +
         " queries have evidence of probability 0 (their records say so)");
  }
}

void run_query(const query_arguments& args) {
  const posterior_table_options table{parse_posterior_format(args.format), args.digits};
  const int modes = (args.query && !args.mpe) + args.all + args.mpe + !args.queries.empty();
  if (modes != 1) {
    throw CLI::ValidationError(
        "query",
        "ask one thing: --query X[,Y], --all (every marginal), --mpe [--query X,Y] (the most probable states) or "
        "--queries FILE");
  }
  if (!args.queries.empty() && (!args.evidence.empty() || !args.soft.empty() || !args.intervene.empty())) {
    throw CLI::ValidationError(
        "query", "--queries takes each query's evidence from its file, not from --evidence, --soft or --do");
  }
  const auto observed = parse_evidence(args.evidence);
  const auto soft = parse_soft_evidence(args.soft);
  const auto set = parse_intervention(args.intervene);
  const auto variables = args.query ? parse_query_variables(*args.query) : std::vector<std::string>{};
  if (!args.out.empty()) pgm::check_output_path(args.out);
  const auto write = [&]<GraphicalModel M>(std::ostream& out, std::shared_ptr<const M> model) {
    if (!args.queries.empty()) {
      answer_batch(args, model, out, table);
      return;
    }
    engines<M> made(model, options_of(args));
    auto& engine = made.get(args.engine);
    engine.set_evidence(resolve_evidence(*model, observed, soft, set));
    if (args.all) {
      write_marginals_table(out, marginals(engine), observed, table, soft, set);
    } else if (args.mpe) {
      if (!engine.finds_mpe()) static_cast<void>(engine.mpe({}));  // the engine's own refusal
      write_mpe_table(out, most_probable(engine, variables), observed, table, soft, set);
    } else {
      write_posterior_table(out, query(engine, variables), observed, table, soft, set);
    }
  };
  // Everything is computed before anything is written, so a failure leaves no partial output.
  write_output_last(args.out, [&](std::ostream& out) {
    auto model = read_any_model_file(args.model);
    std::visit([&]<GraphicalModel M>(M& held) { write(out, std::make_shared<const M>(std::move(held))); }, model);
  });
}

}  // namespace

void add_query_command(CLI::App& app) {
  auto args = std::make_shared<query_arguments>();
  auto* cmd = app.add_subcommand(
      "query",
      "Print P(X | evidence) for every state of the query variables, every marginal (--all), the most probable "
      "states (--mpe), or the answers to a file of queries (--queries), by junction tree, variable elimination or "
      "sampling.\nExamples:\n  pgm query --model sachs.bif --query Akt,Erk --evidence PKA=HIGH --digits 17 "
      "--format json\n  pgm query --model alarm.bif --all --evidence HR=HIGH --soft BP=0.2:0.3:0.5\n  pgm query "
      "--model alarm.bif --mpe --evidence HR=HIGH\n  pgm query --model alarm.bif --query HR --do CVP=LOW\n  pgm query "
      "--model pathfinder.bif --queries queries.csv\n  pgm query --model Grids_11.uai --all --engine jt\nA MARKOV .uai "
      "file is a Markov network: every engine but lw serves it, and --do is refused (interventions need a DAG).");
  cmd->add_option("--model", args->model, "The model: " + network_file_kinds() + "; a MARKOV .uai is a Markov network")
      ->required();
  cmd->add_option("--query", args->query,
                  "Query variables, e.g. \"X\" or \"X,Y\" (joint distribution; with --mpe, the variables whose most "
                  "probable states are wanted, the others summed out)");
  cmd->add_flag("--all", args->all, "Print the marginal of every variable that is not observed");
  cmd->add_flag("--mpe", args->mpe,
                "Print the most probable joint state of every unobserved variable (or of --query's) and its "
                "probability given the evidence");
  cmd->add_option("--queries", args->queries,
                  "A CSV file of queries (columns query, evidence and optionally soft, engine; one query per line), "
                  "answered in one process: one output record per line, in order (JSON Lines with --format json)");
  cmd->add_option("--evidence", args->evidence, "Observed states, e.g. \"a=s,b=t\" (default: none)");
  cmd->add_option("--do", args->intervene,
                  "Interventions, e.g. \"X=x,Z=z\": each variable set to its state, cut from its parents (graph "
                  "surgery), P(query | do(X=x), evidence)");
  cmd->add_option("--soft", args->soft,
                  "Soft (likelihood) evidence, one weight per state in the variable's order, e.g. \"X=0.2:0.8\": "
                  "P(x | evidence) is multiplied by its weight");
  const auto& registry = engine_registry::instance();
  cmd->add_option("--engine", args->engine,
                  "Inference engine: jt (junction tree), ve (variable elimination), bp (loopy belief propagation), lw "
                  "(likelihood weighting), gibbs (Gibbs sampling), or auto (jt unless its tree is too large, then lw, "
                  "or bp for a Markov network; it says which): " +
                      choices_help(registry.listing()) + " over --samples, --seed and --burn-in")
      ->check(CLI::Validator(
          [&registry](std::string& text) -> std::string {
            try {
              registry.check(text);
              return {};
            } catch (const error& refused) {
              return refused.what();
            }
          },
          "NAME[KEY=VALUE,...]"))
      ->capture_default_str();
  cmd->add_option("--samples", args->samples, "Samples for lw and gibbs")
      ->check(whole_number(1, 1'000'000'000))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of lw and gibbs: the same numbers for a seed, whatever the threads")
      ->check(whole_number(0, UINT64_MAX))
      ->capture_default_str();
  cmd->add_option("--burn-in", args->burn_in, "Sweeps each Gibbs chain discards first")
      ->check(whole_number(0, 100'000'000))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Threads for sampling (0: every core)")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  cmd->add_option("--format", args->format, "Output format: csv or json")
      ->check(CLI::IsMember(known_posterior_formats()))
      ->capture_default_str();
  cmd->add_option("--digits", args->digits, "Significant digits of each probability, 1-17 (17: full precision)")
      ->check(CLI::Range(1, 17))
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Write the table to this file instead of standard output");
  cmd->callback([args] { run_query(*args); });
}

}  // namespace pgm::cli
