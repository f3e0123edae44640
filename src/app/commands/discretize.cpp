// pgm discretize: bin continuous columns (quantile, equal width or saved edges).

#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

#include "cli/common.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/data/bin_columns.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/json_model.hpp"

namespace pgm::cli {
namespace {

struct discretize_arguments {
  std::string in;
  std::string method = "quantile";
  std::size_t bins = 5;
  std::string columns;
  std::string out;
  std::string edges_out;
  std::string edges_in;
  missing_arguments missing;
};

std::string describe(const variable& v) {
  std::string text;
  for (std::size_t i = 0; i + 1 < v.edges().size(); ++i) {
    text += (i ? ", " : "") + std::string("[") + text::format_short(v.edges()[i]) + ", " +
            text::format_short(v.edges()[i + 1]) + (i + 2 == v.edges().size() ? "]" : ")");
  }
  return text;
}

void run_discretize(const discretize_arguments& args) {
  require_extension(args.out, {".csv"});
  if (!args.edges_out.empty()) require_extension(args.edges_out, {".json"});
  if (args.method == "edges" && args.edges_in.empty()) throw error("--method edges needs --edges-in FILE");
  if (args.method != "edges" && !args.edges_in.empty()) throw error("--edges-in applies to --method edges");
  // Both outputs are checked before either is written, and neither may overwrite the input.
  pgm::check_output_path(args.out);
  if (!args.edges_out.empty()) pgm::check_output_path(args.edges_out);
  for (const auto* output : {&args.out, &args.edges_out}) {
    std::error_code ec;
    if (!output->empty() && std::filesystem::equivalent(*output, args.in, ec)) {
      throw error("'" + *output + "' is the input file; write the result elsewhere");
    }
  }

  // Columns named for binning must be numeric: reading them as such makes a stray word an
  // error at its own line and column instead of a vague complaint about the whole column.
  const auto wanted = args.columns.empty() ? std::vector<std::string>{} : split_list(args.columns, "--columns");
  csv_options options;
  options.missing = missing_of(args.missing);
  if (args.method != "edges") {
    for (const auto& name : wanted) options.kinds.emplace(name, column_kind::continuous);
  }
  const auto [data, dropped] = read_csv_data(args.in, options);
  note_dropped(dropped, data.rows());
  column_binning request;
  request.columns = wanted;
  if (args.method != "edges") request.method = parse_binning(args.method);
  request.bins = args.bins;
  if (args.method == "edges") {
    request.saved = read_discretization_json(args.edges_in);
    request.saved_source = args.edges_in;
  }
  const auto result = bin_columns(data, request);
  for (const auto& [name, distinct] : result.left) {
    note("left '" + name + "' as it is: it has only " + std::to_string(distinct) + " distinct values");
  }
  const auto& fitted = result.edges;
  const auto& binned = result.data;
  // Both outputs are complete in memory before either file is written.
  std::ostringstream csv_text;
  write_csv(binned, csv_text, ',', options.missing.tokens.front());  // missing stays missing
  const auto edges_text = to_json(fitted).dump(2) + "\n";
  std::string summary;
  for (const auto& [name, v] : fitted) {
    summary += name + ": " + std::to_string(v.cardinality()) + " bins " + describe(v) + "\n";
    if (args.method != "edges" && v.cardinality() < args.bins) {
      note("'" + name + "' has ties, so only " + std::to_string(v.cardinality()) + " of " + std::to_string(args.bins) +
           " bins are distinct");
    }
  }
  summary += std::to_string(binned.rows()) + " rows -> " + args.out +
             (args.edges_out.empty() ? "" : ", edges -> " + args.edges_out) + "\n";
  // The edges' file is complete before the data's replaces the old, and the summary is printed
  // before either does: a failure anywhere leaves both files as they were.
  const auto write_data = [&] {
    pgm::write_file_atomically(
        args.out, [&](std::ostream& out) { out << csv_text.str(); }, summary_before_replacing(summary, args.out));
  };
  if (args.edges_out.empty()) {
    write_data();
  } else {
    pgm::write_file_atomically(
        args.edges_out, [&](std::ostream& out) { out << edges_text; }, write_data);
  }
}

}  // namespace

void add_discretize_command(CLI::App& app) {
  auto args = std::make_shared<discretize_arguments>();
  auto* cmd = app.add_subcommand("discretize", "Bin continuous columns into intervals");
  cmd->add_option("--in", args->in, std::string("CSV file with raw (continuous) columns") + data_file_help)->required();
  cmd->add_option("--method", args->method,
                  "quantile (equal frequency, as in the paper), width (equal width) or edges (saved edges)")
      ->check(CLI::IsMember([] {
        auto methods = known_binnings();
        methods.emplace_back("edges");  // saved edges, the program's own choice
        return methods;
      }()))
      ->capture_default_str();
  cmd->add_option("--bins", args->bins, "Number of bins")->check(whole_number(1, 10000))->capture_default_str();
  cmd->add_option("--columns", args->columns,
                  "Columns to bin, e.g. \"xOff1,yOff1\" (default: every numeric column with more distinct "
                  "values than bins)");
  cmd->add_option("--out", args->out,
                  "Discretized CSV; each binned value becomes its bin index 0..bins-1, a missing value "
                  "(--missing available) the first --na text")
      ->required();
  cmd->add_option("--edges-out", args->edges_out, "Where to save the fitted edges (JSON)");
  cmd->add_option("--edges-in", args->edges_in, "Saved edges to apply, with --method edges");
  add_missing_options(*cmd, args->missing);
  cmd->callback([args] { run_discretize(*args); });
}

}  // namespace pgm::cli
