// pgm dsep: whether two sets of variables are d-separated given a third, on a model's DAG.

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "pgm/causal/d_separation.hpp"
#include "pgm/core/text.hpp"
#include "pgm/io/network_file.hpp"

namespace pgm::cli {
namespace {

struct dsep_arguments {
  std::string model;
  std::string x;
  std::string y;
  std::string given;
};

void run_dsep(const dsep_arguments& args) {
  const auto x = split_list(args.x, "X");
  const auto y = split_list(args.y, "Y");
  const auto z = args.given.empty() ? std::vector<std::string>{} : split_list(args.given, "--given");
  const auto structure = read_model_file(args.model).structure;
  const bool separated = d_separated(structure, x, y, z);
  std::cout << "{" << text::join(x) << "} and {" << text::join(y) << "} are "
            << (separated ? "d-separated" : "d-connected") << " given {" << text::join(z) << "}\n";
}

}  // namespace

void add_dsep_command(CLI::App& app) {
  auto args = std::make_shared<dsep_arguments>();
  auto* cmd = app.add_subcommand("dsep",
                                 "Tell whether the variables X and Y are d-separated given Z in the model's DAG (every "
                                 "path between them blocked), which the DAG then says are independent given Z.\n"
                                 "Example: pgm dsep --model alarm.bif HR CVP --given LVEDVOLUME");
  cmd->add_option("--model", args->model, "The model: " + network_file_kinds() + " (a structure is enough)")
      ->required();
  cmd->add_option("X", args->x, "Variables, e.g. \"A\" or \"A,B\"")->required();
  cmd->add_option("Y", args->y, "Variables, e.g. \"C\" or \"C,D\"")->required();
  cmd->add_option("--given", args->given, "The conditioning variables Z, e.g. \"E,F\" (default: none)");
  cmd->callback([args] { run_dsep(*args); });
}

}  // namespace pgm::cli
