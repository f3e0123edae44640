// pgm unroll: a dynamic network (a 2-TBN) as the static network of its first T slices, X@0 … X@(T−1).

#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"

namespace pgm::cli {
namespace {

struct unroll_arguments {
  std::string model;
  std::size_t steps = 0;
  std::string out;
};

void run_unroll(const unroll_arguments& args) {
  const auto to = format_of(args.out);  // fails, listing the extensions, before anything is read
  pgm::check_output_path(args.out);
  const auto dynamic = read_dynamic_model_file(args.model).model;
  // BIF's and NET's names hold letters, digits, '_', '-' and '.' only.
  const bool plain_names = to == network_format("bif") || to == network_format("net");
  const auto network = dynamic.unroll(args.steps, plain_names ? '_' : '@');
  if (plain_names && !dynamic.variables().empty()) {
    const auto& first = dynamic.variables().front().name();
    note(std::string(name_of(to)) + " names cannot hold '@': the slices' variables are named " + first + "_0, " +
         first + "_1, … (" + first + "@0, " + first + "@1, … in JSON and XMLBIF)");
  }
  std::vector<std::string> notes;
  const auto summary = "unrolled " + args.model + " over " + std::to_string(args.steps) + " slices -> " + args.out +
                       " (" + std::string(name_of(to)) + "): " + std::to_string(network.size()) + " variables, " +
                       std::to_string(network.free_parameters()) + " free parameters\n";
  write_network(network, args.out, to,
                {.notes = &notes, .before_replacing = [&, print = summary_before_replacing(summary, args.out)] {
                   for (const auto& line : notes) note(line);
                   print();
                 }});
}

}  // namespace

void add_unroll_command(CLI::App& app) {
  auto args = std::make_shared<unroll_arguments>();
  auto* cmd = app.add_subcommand(
      "unroll",
      "Unroll a dynamic network (a 2-TBN in pgm's JSON, \"kind\": \"dynamic\") over T slices into a Bayesian network "
      "whose variables are X@0 … X@(T-1), in any format pgm writes; every command then reads it.\nExample:\n  pgm "
      "unroll --model tower.json --steps 3 --out tower3.bif");
  cmd->add_option("--model", args->model, "The dynamic network (.json)")->required();
  cmd->add_option("--steps", args->steps, "The number of slices T, at least 1")
      ->required()
      ->check(whole_number(1, max_unrolled_variables));
  cmd->add_option("--out", args->out, "The network to write, atomically; its extension names its format")->required();
  cmd->callback([args] { run_unroll(*args); });
}

}  // namespace pgm::cli
