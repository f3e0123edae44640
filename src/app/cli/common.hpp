#pragma once
// Helpers shared by the commands of the `pgm` program. The program is thin: commands parse
// their arguments, call the library and print; nothing here computes.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "pgm/core/dynamic_network.hpp"
#include "pgm/core/markov_network.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/discretizer.hpp"
#include "pgm/data/missing.hpp"
#include "pgm/io/csv_counts.hpp"
#include "pgm/io/json_model.hpp"

namespace pgm::cli {

/// "a, b,c" → {"a", "b", "c"}; empty pieces are an error naming `what`.
std::vector<std::string> split_list(std::string_view text, const std::string& what);

/// Throws pgm::io_error unless `path` ends in one of `extensions` (".bif", ".json", …), so
/// that a command fails before doing any work.
void require_extension(const std::filesystem::path& path, const std::vector<std::string>& extensions);

/// --na and --missing, as typed.
struct missing_arguments {
  std::string na = "NA,,?";
  std::string policy = "error";
};

/// Adds --na and --missing (the texts read as missing, and what happens to them) to `cmd`;
/// `em` adds the policy em (for pgm fit).
void add_missing_options(CLI::App& cmd, missing_arguments& args, bool em = false);

/// Notes "dropped N of M rows with a missing value" when the policy drop left rows out.
void note_dropped(std::size_t dropped, std::size_t rows_kept);

/// The missing values --na and --missing ask for.
[[nodiscard]] missing_values missing_of(const missing_arguments& args);

/// How the columns of a model's variables are to be read from a CSV file.
struct data_plan {
  /// Discretize these raw numeric columns with these edges.
  const discretization* raw_intervals = nullptr;
  /// Take the states of these variables as given (from a model).
  const std::vector<variable>* known = nullptr;
  /// What a missing value is and what happens to it.
  missing_values missing = {};
};

/// Reads `columns` of a CSV file as discrete data, discretizing raw columns as planned.
/// "-" reads standard input; gzip data (.csv.gz) is inflated. Notes the rows dropped for a
/// missing value.
dataset read_discrete_data(const std::filesystem::path& path, const std::vector<std::string>& columns,
                           const data_plan& plan);

/// Notes what counting found that the user should know: rows dropped for a missing value,
/// families counted over fewer rows than were read (policy available), values outside the edges
/// of the `binned` columns, columns with nearly as many states as rows.
void note_counts(const family_counts& counts, const discretization& binned);

/// Notes the model's states spelled like a missing value among `columns` (read as the state).
void note_model_states_read_as_missing(const std::vector<std::string>& columns, const data_plan& plan);

/// What --data and --in say about the input files they accept.
inline constexpr const char* data_file_help = " ('-' reads standard input; a .csv.gz is read compressed)";

/// Throws io_error, listing the supported extensions, unless `path` names a network format.
void require_network_extension(const std::filesystem::path& path);

/// A model file of any format (pgm/io/network_file.hpp), printing the reader's notes (tables
/// normalized within the tolerance for rounded files).
model_document read_model_file(const std::filesystem::path& path);

/// A fitted network of any format, printing the reader's notes.
bayesian_network read_network_file(const std::filesystem::path& path);

/// A model of either class a file may hold.
using any_model = std::variant<bayesian_network, markov_network>;

/// Whether `path` names a UAI file (.uai, or .uai.gz read compressed).
[[nodiscard]] bool is_uai(const std::filesystem::path& path);

/// The Markov network a file holds (a MARKOV .uai file, a pgm JSON model of "kind": "markov"), or
/// nothing for a file that holds another model.
[[nodiscard]] std::optional<markov_network> read_markov_network_file(const std::filesystem::path& path);

/// The model a file holds: the Markov network of a MARKOV .uai file or of a pgm JSON model of
/// "kind": "markov", else the Bayesian network of any network format (printing the reader's
/// notes).
[[nodiscard]] any_model read_any_model_file(const std::filesystem::path& path);

/// The dynamic network of a pgm JSON model of "kind": "dynamic", with its statistics when it
/// keeps them; an error naming what the file holds otherwise.
[[nodiscard]] dynamic_model_file read_dynamic_model_file(const std::string& path);

/// Accepts only a whole number in [lo, hi], so that "-5" is an error rather than 2^64 - 5.
CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi);

/// Accepts only a finite number ≥ 0 (docs/limits.md, "Numbers").
CLI::Validator non_negative_number();

/// Accepts only a finite number between `lo` and `hi` (each bound excluded when open; `hi` may
/// be infinite), written as docs/limits.md says ("1,5", "0x1p-3", "nan" and "1e400" are refused
/// with the reason); "-0" is passed on as 0.
CLI::Validator number_between(double lo, double hi, bool lo_open, bool hi_open);

/// Where a command says what it wrote to `output`: standard output, unless `output` is the
/// program's standard output itself (`--out /dev/stdout`, a pipe), whose content the line would
/// spoil; then standard error.
[[nodiscard]] std::ostream& summary_stream(const std::filesystem::path& output);

/// Prints `summary` to summary_stream(output) and makes sure it arrived, for a write's
/// before_replacing: a summary that cannot be written (standard output on a full disk, a closed
/// pipe) then fails the run before `output` is replaced, so a retry starts from the old file.
[[nodiscard]] std::function<void()> summary_before_replacing(std::string summary, std::filesystem::path output);

/// Writes a command's output once all of it is made: to `out` atomically (write_file_atomically),
/// or with `out` empty to standard output, spooled through a temporary file (in memory when none
/// can be made). A failure half way thus writes nothing, and a long output is not held in memory.
void write_output_last(const std::string& out, const std::function<void(std::ostream&)>& write);

/// A number for JSON to 17 significant digits, which reads back to the same double.
[[nodiscard]] std::string json_number(double value);

/// Prints "pgm: note: …" to stderr, for what the user should know but need not act on.
void note(const std::string& text);

/// Whether stderr is a terminal (progress bars only go to terminals).
bool stderr_is_terminal();

void add_fit_command(CLI::App& app);
void add_update_command(CLI::App& app);
void add_discretize_command(CLI::App& app);
void add_show_command(CLI::App& app);
void add_draw_command(CLI::App& app);
void add_plot_table_command(CLI::App& app);
void add_transfer_command(CLI::App& app);
void add_correspond_command(CLI::App& app);
void add_learn_structure_command(CLI::App& app);
void add_score_command(CLI::App& app);
void add_experiment_command(CLI::App& app);
void add_report_command(CLI::App& app);
void add_simulate_command(CLI::App& app);
void add_calibrate_command(CLI::App& app);
void add_predict_command(CLI::App& app);
void add_query_command(CLI::App& app);
void add_convert_command(CLI::App& app);
void add_solve_command(CLI::App& app);
void add_prevent_command(CLI::App& app);
void add_dsep_command(CLI::App& app);
void add_components_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_sample_command(CLI::App& app);
void add_unroll_command(CLI::App& app);
void add_filter_command(CLI::App& app);
void add_decide_command(CLI::App& app);
void add_counterfactual_command(CLI::App& app);

}  // namespace pgm::cli
