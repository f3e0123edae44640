// pgm convert: a network from one file format to another (any of pgm/io/network_format.hpp's).

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "pgm/causal/counterfactual.hpp"
#include "pgm/io/decision_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/structural_file.hpp"
#include "pgm/io/uai.hpp"

namespace pgm::cli {
namespace {

struct convert_arguments {
  std::string in;
  std::string out;
  std::string to;
  bool no_properties = false;
  std::string structural;
};

/// A network read as a structural model under an assumption, written in pgm's JSON.
void convert_to_structural(const convert_arguments& args, const network_format& to) {
  if (to != network_format("json")) {
    throw error("a structural model is written in pgm's JSON: name the output .json");
  }
  const auto model = monotone_structural_model(read_network_file(args.in));
  std::size_t noise = 0;
  for (std::size_t i = 0; i < model.size(); ++i) noise += model.equation(index_at<variable_id>(i)).noise.size();
  const auto summary = summary_before_replacing("converted " + args.in + " -> " + args.out + " (a structural model, " +
                                                    args.structural + "): " + std::to_string(model.size()) +
                                                    " variables, " + std::to_string(noise) + " noise states\n",
                                                args.out);
  write_structural_model(model, args.out, summary);
}

/// A Markov network goes to the formats that hold one: UAI (MARKOV) and pgm's JSON.
void convert_markov_network(const convert_arguments& args, const markov_network& model, const network_format& from,
                            const network_format& to) {
  if (std::filesystem::path(args.out).extension() == ".gz") {
    throw error("pgm writes models uncompressed; name the output without .gz");
  }
  const auto summary =
      summary_before_replacing("converted " + args.in + " (" + std::string(name_of(from)) + ", a Markov network) -> " +
                                   args.out + " (" + std::string(name_of(to)) + "): " + std::to_string(model.size()) +
                                   " variables, " + std::to_string(model.factor_count()) + " factors\n",
                               args.out);
  if (to == network_format("uai")) {
    const auto text = to_uai(model);
    pgm::write_file_atomically(
        args.out, [&](std::ostream& out) { out << text; }, summary);
  } else if (to == network_format("json")) {
    pgm::write_file_atomically(
        args.out, [&](std::ostream& out) { write_markov_json(out, model); }, summary);
  } else {
    throw error("'" + args.in + "' holds a Markov network, which " + std::string(name_of(to)) +
                " cannot hold; convert it to .uai or .json");
  }
}

void run_convert(const convert_arguments& args) {
  const auto from = format_to_read(args.in);
  const auto named = find_format_of(args.out);
  // format_of fails, listing the extensions, before anything is read.
  const auto to = args.to.empty() ? format_of(args.out) : network_format_named(args.to);
  if (!args.to.empty() && named && *named != to) {
    throw error("'" + args.out + "' names the " + std::string(name_of(*named)) + " format but --to says " + args.to);
  }
  pgm::check_output_path(args.out);
  if (!args.structural.empty()) {
    convert_to_structural(args, to);
    return;
  }
  if (auto markov = read_markov_network_file(args.in)) {
    convert_markov_network(args, *markov, from, to);
    return;
  }
  const auto model = read_model_file(args.in);
  const auto network = model.network();
  // The counts a network is updated from (pgm fit --keep-counts) go along: in JSON under
  // "statistics", elsewhere in a property peers ignore, which --no-properties leaves out.
  const bool keeps_counts = model.statistics && (to == network_format("json") || !args.no_properties);
  const auto summary = "converted " + args.in + " (" + std::string(name_of(from)) + ") -> " + args.out + " (" +
                       std::string(name_of(to)) + "): " + std::to_string(network.size()) + " variables, " +
                       std::to_string(network.free_parameters()) + " free parameters\n";
  std::vector<std::string> notes;
  const auto report = [&, print = summary_before_replacing(summary, args.out)] {
    for (const auto& line : notes) note(line);
    if (model.statistics && !keeps_counts) {
      note("the counts kept in '" + args.in + "' (for pgm update) are left out with --no-properties");
    }
    if (from == network_format("json") && to != network_format("json") && read_success_metadata(args.in)) {
      note("the success event in the metadata of '" + args.in + "' is not carried by " + std::string(name_of(to)) +
           "; give it to predict and prevent with --success");
    }
    print();
  };
  write_network(network, args.out, to,
                {.properties = !args.no_properties,
                 .notes = &notes,
                 .statistics = keeps_counts ? &*model.statistics : nullptr,
                 .before_replacing = report});
}

}  // namespace

void add_convert_command(CLI::App& app) {
  auto args = std::make_shared<convert_arguments>();
  auto* cmd = app.add_subcommand("convert", "Convert a network between " + network_format_descriptions() +
                                                "; a Markov network between UAI and JSON.\nExamples:\n  pgm convert "
                                                "sachs.bif sachs.net\n  pgm convert Grids_11.uai Grids_11.json");
  cmd->add_option("in", args->in,
                  "The network to read; its extension names its format (.bif.gz and the like are read compressed)")
      ->required();
  cmd->add_option("out", args->out, "The file to write, atomically")->required();
  cmd->add_option("--to", args->to, "The output format (default: from the extension of OUT)")
      ->check(CLI::IsMember(known_network_formats()));
  cmd->add_flag("--no-properties", args->no_properties,
                "Leave out pgm's interval edges and semantic tags (properties and attributes other tools ignore)");
  cmd->add_option("--structural", args->structural,
                  "Write the network as a structural model (pgm's JSON) under this assumption. monotone: every "
                  "variable takes the first state whose cumulative probability exceeds one uniform noise "
                  "(docs/causal.md); pgm counterfactual reads it")
      ->check(CLI::IsMember({"monotone"}));
  cmd->callback([args] { run_convert(*args); });
}

}  // namespace pgm::cli
