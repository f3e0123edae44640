#include "cli/common.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>

#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/uai.hpp"

namespace pgm::cli {

std::vector<std::string> split_list(std::string_view text, const std::string& what) {
  auto pieces = text::split(text, ',');
  for (const auto& piece : pieces) {
    if (piece.empty()) throw error(what + " has an empty entry in '" + std::string(text) + "'");
  }
  return pieces;
}

void require_extension(const std::filesystem::path& path, const std::vector<std::string>& extensions) {
  const auto extension = path.extension().string();
  for (const auto& allowed : extensions) {
    if (extension == allowed) return;
  }
  throw io_error("'" + path.string() + "': expected a file ending in " + text::join(extensions, " or "));
}

void require_network_extension(const std::filesystem::path& path) { static_cast<void>(format_of(path)); }

model_document read_model_file(const std::filesystem::path& path) {
  std::vector<std::string> notes;
  auto document = read_model(path, {.notes = &notes});
  for (const auto& line : notes) note(line);
  return document;
}

bayesian_network read_network_file(const std::filesystem::path& path) {
  std::vector<std::string> notes;
  auto network = read_network(path, {.notes = &notes});
  for (const auto& line : notes) note(line);
  return network;
}

bool is_uai(const std::filesystem::path& path) {
  auto name = path.filename().string();
  if (name.ends_with(".gz")) name.resize(name.size() - 3);
  return name.ends_with(".uai");
}

std::optional<markov_network> read_markov_network_file(const std::filesystem::path& path) {
  if (is_uai(path)) {
    auto file = read_uai(path);
    if (file.kind == uai_kind::markov) return std::move(file.model);
  } else if (find_format_of(path) == network_format("json")) {
    const auto text = read_model_text(path);
    if (declares_markov_network(text)) return parse_markov_json(text, path.string());
  }
  return std::nullopt;
}

any_model read_any_model_file(const std::filesystem::path& path) {
  if (auto markov = read_markov_network_file(path)) return std::move(*markov);
  return read_network_file(path);
}

dynamic_model_file read_dynamic_model_file(const std::string& path) {
  if (find_format_of(path) != network_format("json")) {
    throw error("'" + path + "' is not a pgm JSON model: a dynamic network is written in pgm's JSON (docs/dynamic.md)");
  }
  const auto text = read_model_text(path);
  if (const auto kind = declared_model_kind(text); kind != "dynamic") {
    throw error("'" + path + "' holds a " + (kind == "markov" ? "Markov" : "Bayesian") +
                " network, not a dynamic one (\"kind\": \"dynamic\")");
  }
  return parse_dynamic_model_json(text, path);
}

namespace {

// Outside values go to the outer bins by design; many of them suggest the wrong edges, or data
// that was binned already (then --intervals was meant).
void note_outside(const std::string& name, std::size_t outside, std::size_t rows, const variable& intervals) {
  if (outside == 0) return;
  const auto& edges = intervals.edges();
  note(std::to_string(outside) + " of " + std::to_string(rows) + " values of '" + name +
       "' lie outside the edges' range [" + text::format_short(edges.front()) + ", " +
       text::format_short(edges.back()) + "] and count in the outer bins");
}

// A column with nearly as many states as rows is almost surely a raw quantity.
void note_many_states(const variable& v, std::size_t rows) {
  const auto states = v.cardinality();
  if (states > 50 && 2 * states > rows) {
    note("'" + v.name() + "' has " + std::to_string(states) + " distinct values in " + std::to_string(rows) +
         " rows: if it is a continuous quantity, bin it first (pgm discretize, or --discretization)");
  }
}

// A model may declare a state spelled like a missing value (pathfinder has "NA" in 35
// variables): in those columns it is read as the state, and the user is told.
void note_states_spelled_as_missing(const std::vector<std::string>& columns, const data_plan& plan) {
  if (plan.known == nullptr) return;
  for (const auto& token : plan.missing.tokens) {
    std::vector<std::string> variables;
    for (const auto& v : *plan.known) {
      const bool read = std::find(columns.begin(), columns.end(), v.name()) != columns.end();
      const bool binned = plan.raw_intervals != nullptr && plan.raw_intervals->count(v.name()) != 0;
      if (read && !binned && v.find_state(token)) variables.push_back(v.name());
    }
    if (variables.empty()) continue;
    note("'" + token + "' is a state of the model's variable" + (variables.size() == 1 ? " " : "s ") +
         text::list_for_message(variables, 5) + ": read as that state in " +
         (variables.size() == 1 ? "its column" : "their columns") +
         ", not as a missing value (--na names the texts read as missing)");
  }
}

}  // namespace

void note_dropped(std::size_t dropped, std::size_t rows) {
  if (dropped == 0) return;
  note("dropped " + std::to_string(dropped) + " of " + std::to_string(dropped + rows) +
       " rows with a missing value (--missing drop; --na names the texts read as missing)");
}

void add_missing_options(CLI::App& cmd, missing_arguments& args, bool em) {
  cmd.add_option("--na", args.na,
                 "The texts read as missing values, comma-separated; an empty entry (as in the default) is the "
                 "empty field")
      ->capture_default_str();
  auto policies = known_missing_policies();
  if (em) policies.emplace_back("em");
  cmd.add_option("--missing", args.policy,
                 std::string("What a missing value does: error (naming its line and column), drop (leave out the rows "
                             "that have one, with a note)") +
                     (em ? ", available (count each family over the rows where its variables are present) or em "
                           "(expectation-maximization: the missing values, and --latent variables, estimated)"
                         : " or available (count each family, or each independence test, over the rows where its "
                           "variables are present)"))
      ->check(CLI::IsMember(policies))
      ->capture_default_str();
}

missing_values missing_of(const missing_arguments& args) {
  missing_values missing;
  missing.tokens = args.na.empty() ? std::vector<std::string>{""} : text::split(args.na, ',');
  // em keeps every missing value for EM to estimate.
  missing.policy = parse_missing_policy(args.policy == "em" ? "available" : args.policy);
  return missing;
}

void note_counts(const family_counts& counts, const discretization& binned) {
  note_dropped(counts.dropped, counts.rows);
  for (const auto& table : counts.families) {
    const std::uint64_t counted = table.total();
    if (counted < counts.rows) {
      note("'" + table.child().name() + "' is counted over the " + std::to_string(counted) + " of " +
           std::to_string(counts.rows) +
           " rows where it and its parents are present (--missing available; --na names the texts read as missing)");
    }
  }
  for (const auto& [name, outside] : counts.outside) note_outside(name, outside, counts.rows, binned.at(name));
  for (const auto& v : counts.variables) note_many_states(v, counts.rows);
}

void note_model_states_read_as_missing(const std::vector<std::string>& columns, const data_plan& plan) {
  note_states_spelled_as_missing(columns, plan);
}

dataset read_discrete_data(const std::filesystem::path& path, const std::vector<std::string>& columns,
                           const data_plan& plan) {
  csv_options options;
  options.columns = columns;
  options.default_kind = column_kind::discrete;
  options.missing = plan.missing;
  note_states_spelled_as_missing(columns, plan);
  if (plan.known) {
    for (const auto& v : *plan.known) options.variables.emplace(v.name(), v);
  }
  if (plan.raw_intervals) {
    for (const auto& [name, intervals] : *plan.raw_intervals) {
      if (std::find(columns.begin(), columns.end(), name) == columns.end()) continue;
      options.variables.erase(name);
      options.kinds[name] = column_kind::continuous;
    }
  }
  auto [data, dropped] = read_csv_data(path, options);
  note_dropped(dropped, data.rows());
  if (plan.raw_intervals) {
    discretization used;
    for (const auto& [name, intervals] : *plan.raw_intervals) {
      if (!data.contains(name)) continue;
      used.emplace(name, intervals);
      const auto& edges = intervals.edges();
      std::size_t outside = 0;
      for (double v : data.continuous(name).values())
        outside += v < edges.front() || v > edges.back();  // NaN (missing) never is
      note_outside(name, outside, data.rows(), intervals);
    }
    data = apply_discretization(data, used);
  }
  for (const auto& name : data.names()) {
    if (data.is_discrete(name)) note_many_states(data.discrete(name).var(), data.rows());
  }
  return data;
}

std::ostream& summary_stream(const std::filesystem::path& output) {
  struct stat out {};
  struct stat target {};
  const bool same = ::fstat(STDOUT_FILENO, &out) == 0 && ::stat(output.c_str(), &target) == 0 &&
                    out.st_dev == target.st_dev && out.st_ino == target.st_ino;
  return same ? std::cerr : std::cout;
}

std::function<void()> summary_before_replacing(std::string summary, std::filesystem::path output) {
  return [summary = std::move(summary), output = std::move(output)] {
    auto& stream = summary_stream(output);
    errno = 0;
    stream << summary;
    stream.flush();
    const bool failed = !stream || (&stream == &std::cout && (std::fflush(stdout) != 0 || std::ferror(stdout) != 0));
    if (failed) {
      throw io_error("cannot write to standard output" +
                     (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()) + "; '" + output.string() +
                     "' is left as it was");
    }
  };
}

void note(const std::string& text) { std::cerr << "pgm: note: " << text::printable(text) << '\n'; }

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) != 0; }

CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi) {
  const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const auto [end, failure] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (text.empty() || failure != std::errc() || end != text.data() + text.size()) {
          // Digits only: "-0", "+5", "1e3", "0x10" and "1,000" are refused rather than read otherwise.
          return "expected a whole number from " + range + " (digits only), got " + text::quoted_number(text);
        }
        if (value < lo || value > hi) return "expected a whole number from " + range + ", got " + text;
        return {};
      },
      "INT in " + range);
}

CLI::Validator non_negative_number() { return number_between(0, std::numeric_limits<double>::infinity(), false, true); }

CLI::Validator number_between(double lo, double hi, bool lo_open, bool hi_open) {
  const bool unbounded = std::isinf(hi);
  const std::string range = unbounded ? std::string(lo_open ? "> " : "≥ ") + text::format_short(lo)
                                      : std::string(lo_open ? "(" : "[") + text::format_short(lo) + ", " +
                                            text::format_short(hi) + (hi_open ? ")" : "]");
  const std::string expected = unbounded ? "expected a finite number " + range : "expected a number in " + range;
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const auto read = text::parse_double(text);
        if (!read || !std::isfinite(*read)) return expected + ", got " + text::quoted_number(text);
        const double value = *read;
        const bool above_lo = lo_open ? value > lo : value >= lo;
        const bool below_hi = hi_open ? value < hi : value <= hi;
        if (!above_lo || !below_hi) return expected + ", got " + text;
        // CLI11 converts the text again (strtold, then to double): hand it the value pgm read,
        // written exactly (a hex float, "-0" as 0), so that no other reading or rounding happens.
        char exact[40];
        std::snprintf(exact, sizeof exact, "%a", value == 0 ? 0.0 : value);
        text = exact;
        return {};
      },
      "NUMBER " + range);
}

void write_output_last(const std::string& out, const std::function<void(std::ostream&)>& write) {
  if (!out.empty()) {
    pgm::write_file_atomically(out, write);
    return;
  }
  std::error_code ignored;
  const auto folder = std::filesystem::temp_directory_path(ignored);
  const auto path = folder / ("pgm-output-" + std::to_string(std::random_device{}()));
  std::fstream spool;
  if (!folder.empty()) spool.open(path, std::ios::in | std::ios::out | std::ios::trunc | std::ios::binary);
  if (!spool.is_open()) {
    std::ostringstream buffer;
    write(buffer);
    std::cout << buffer.str();
    return;
  }
  // Unlinked at once: the open file stays readable, and nothing is left behind on any exit.
  std::filesystem::remove(path, ignored);
  write(spool);
  spool.flush();
  if (!spool) throw io_error("cannot hold the output in a temporary file in '" + folder.string() + "' (a full disk?)");
  if (spool.tellp() > 0) {
    spool.seekg(0);
    std::cout << spool.rdbuf();
  }
}

std::string json_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace pgm::cli
