// pgm sample: rows drawn from a network by forward sampling, as CSV — data whose generating
// network is known, to try learning, checking and fitting on.

#include <cstdint>
#include <memory>
#include <string>

#include "cli/common.hpp"
#include "pgm/core/file.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/network_file.hpp"

namespace pgm::cli {
namespace {

struct sample_arguments {
  std::string model;
  std::size_t rows = 0;
  std::uint64_t seed = 0;
  std::string out;
};

void run_sample(const sample_arguments& args) {
  const auto network = read_network_file(args.model);
  const auto data = sample(network, args.rows, args.seed);
  pgm::write_file_atomically(args.out, [&](std::ostream& file) { write_csv(data, file); });
}

}  // namespace

void add_sample_command(CLI::App& app) {
  auto args = std::make_shared<sample_arguments>();
  auto* cmd = app.add_subcommand("sample",
                                 "Draw rows from a network by forward sampling and write them as CSV, a column per "
                                 "variable in the network's order (bnlearn's rbn, pgmpy's simulate).\n"
                                 "Example: pgm sample --model alarm.bif --rows 10000 --seed 1 --out alarm.csv");
  cmd->add_option("--model", args->model, "The network: " + network_file_kinds())->required();
  // Every row is held until the file is written: 10^7 rows of 37 variables take 1.5 GB.
  cmd->add_option("--rows", args->rows, "Number of rows (held in memory until written, 4 bytes a cell)")
      ->check(whole_number(1, 10'000'000))
      ->required();
  cmd->add_option("--seed", args->seed, "Random seed; the same seed gives the same rows")
      ->check(whole_number(0, UINT64_MAX))
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Output CSV file (written atomically)")->required();
  cmd->callback([args] { run_sample(*args); });
}

}  // namespace pgm::cli
