// pgm update: add new rows to a fitted network that kept its counts (pgm fit --keep-counts)
// and estimate its tables again under the priors it was fitted with.

#include <filesystem>
#include <memory>
#include <set>
#include <sstream>
#include <string>

#include "cli/common.hpp"
#include "cli/episode.hpp"
#include "pgm/core/process_group.hpp"
#include "pgm/io/csv_source.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/pipeline/dynamic_fit_pipeline.hpp"
#include "pgm/pipeline/fit_pipeline.hpp"

namespace pgm::cli {
namespace {

struct update_arguments {
  std::string model;
  std::string data;
  double decay = 1.0;
  unsigned threads = 0;
  std::string out;
  missing_arguments missing;
};

/// pgm update on a dynamic network: new episodes in long form counted into its statistics.
/// `text` is the model file's, read once.
void run_dynamic_update(const update_arguments& args, const std::string& text) {
  if (args.missing.policy == "drop") {
    throw error(
        "--missing drop leaves gaps in the episodes where it drops a row; a dynamic network is updated with "
        "--missing available (each family counted over the steps where its variables are present)");
  }
  if (std::filesystem::path(args.out).extension() != ".json") {
    throw error("--out: a dynamic network is written as pgm's JSON model (.json), not '" + args.out + "'");
  }
  pgm::check_output_path(args.out);
  const auto file = parse_dynamic_model_json(text, args.model);
  if (!file.statistics) {
    throw error("'" + args.model +
                "' carries no counts to add the new episodes to: fit it with pgm fit --dynamic --keep-counts");
  }
  std::set<std::string> templates;
  for (const auto& v : file.model.variables()) templates.insert(v.name());
  const auto data = read_episodes(args.data, templates, &file.model, missing_of(args.missing), args.threads);
  const auto fitted = update_with_episodes(file.model, *file.statistics, data, args.decay, args.threads);
  std::ostringstream summary;
  summary << "updated a dynamic network of " << fitted.model.size() << " template variables with " << fitted.episodes
          << (fitted.episodes == 1 ? " episode" : " episodes") << " (" << fitted.steps << " steps; "
          << text::format_double(fitted.statistics->initial.rows) << " episodes in all"
          << (args.decay < 1.0 ? ", old ones weighted by the decay" : "") << ") -> " << args.out << '\n';
  write_dynamic_json(fitted.model, args.out, summary_before_replacing(summary.str(), args.out), &*fitted.statistics);
}

void run_update(const update_arguments& args) {
  if (find_format_of(args.model) == network_format("json")) {
    const auto text = read_model_text(args.model);
    // Only a file that names the token can declare the kind (the full scan is left to those).
    if (text.find("\"dynamic\"") != std::string::npos && declared_model_kind(text) == "dynamic") {
      run_dynamic_update(args, text);
      return;
    }
  }
  require_network_extension(args.out);
  if (args.data == "-" && processes().size() > 1) {
    throw error("--data -: standard input reaches one process only; under mpirun give a file every process can read");
  }
  const auto model = read_model_file(args.model);
  if (!model.statistics) {
    throw error("'" + args.model + "' carries no counts to add the new rows to: fit it with pgm fit --keep-counts");
  }
  update_request request;
  request.missing = missing_of(args.missing);
  request.threads = args.threads;
  request.decay = args.decay;
  csv_reader input(args.data);
  csv_source source(input, processes());
  const auto updated_model = update(source, model.structure, *model.statistics, request);
  if (!updated_model.holds_network) return;
  note_counts(updated_model.counts, {});
  std::ostringstream summary;
  summary << "updated " << updated_model.network.size() << " tables with " << updated_model.counts.rows << " new rows ("
          << text::format_double(updated_model.statistics->rows) << " rows in all"
          << (args.decay < 1.0 ? ", old rows weighted by the decay" : "") << ") -> " << args.out << '\n';
  // With --out equal to --model, a run that fails after replacing the model would make a retry
  // count the new rows twice: the summary is written first.
  write_network(updated_model.network, args.out,
                {.statistics = &*updated_model.statistics,
                 .before_replacing = summary_before_replacing(summary.str(), args.out)});
}

}  // namespace

void add_update_command(CLI::App& app) {
  auto args = std::make_shared<update_arguments>();
  auto* cmd = app.add_subcommand(
      "update",
      "Add new rows to a network fitted with --keep-counts and estimate its tables again with the same priors; "
      "a dynamic network's new episodes in long form (episode,t,<variables>).\n"
      "Example: pgm update --model robot.json --data today.csv --out robot.json");
  cmd->add_option("--model", args->model,
                  "The network, fitted with pgm fit --keep-counts (" + network_file_kinds() + ")")
      ->required();
  cmd->add_option("--data", args->data,
                  std::string("CSV file of the new rows, one column per variable of the model") + data_file_help)
      ->required();
  cmd->add_option("--decay", args->decay,
                  "Weight of the old counts, in (0, 1]: 1 equals fitting all the rows at once, less forgets old "
                  "trials (a task that drifts)")
      ->check(number_between(0.0, 1.0, true, false))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Counting threads (0: all cores)")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  cmd->add_option("--out", args->out,
                  "The updated network with its counts (" + network_file_kinds() + "; may be --model itself)")
      ->required();
  add_missing_options(*cmd, args->missing, false);
  cmd->callback([args] { run_update(*args); });
}

}  // namespace pgm::cli
