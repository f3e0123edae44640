// pgm report: a document whose numbers come from experiment summaries (docs/RESULTS.md from
// docs/results/RESULTS.template.md and docs/results/summary.csv), written or checked.

#include <algorithm>
#include <cctype>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "cli/report_template.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/eval/result_tables.hpp"

namespace pgm::cli {
namespace {

struct report_arguments {
  std::string template_file;
  std::vector<std::string> summaries;
  std::string out;
  bool check = false;
};

/// "NAME=FILE" names a summary for the template's "NAME:" selectors; a plain FILE is unnamed.
named_summary read_named_summary(const std::string& argument) {
  const auto equals = argument.find('=');
  const auto name = equals == std::string::npos ? std::string() : argument.substr(0, equals);
  const bool is_name = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
  });
  if (!is_name) return {"", read_summary_csv(argument)};
  return {name, read_summary_csv(argument.substr(equals + 1))};
}

/// The first line where two texts differ, shortened for a message.
std::string first_difference(const std::string& committed, const std::string& generated) {
  const auto lines_of = [](const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    for (auto end = text.find('\n'); end != std::string::npos; start = end + 1, end = text.find('\n', start)) {
      lines.push_back(text.substr(start, end - start));
    }
    if (start < text.size()) lines.push_back(text.substr(start));
    return lines;
  };
  const auto a = lines_of(committed), b = lines_of(generated);
  std::size_t line = 0;
  while (line < a.size() && line < b.size() && a[line] == b[line]) ++line;
  const auto shorten = [](const std::string& text) { return text.size() > 100 ? text.substr(0, 100) + "…" : text; };
  const auto said = [&](const std::vector<std::string>& lines) {
    return line < lines.size() ? "'" + shorten(lines[line]) + "'" : std::string("the end of the file");
  };
  return "line " + std::to_string(line + 1) + " reads " + said(a) + ", the summaries give " + said(b);
}

void run_report(const report_arguments& args) {
  if (!args.out.empty() && !args.check) pgm::check_output_path(args.out);
  std::vector<named_summary> summaries;
  for (const auto& s : args.summaries) summaries.push_back(read_named_summary(s));
  const auto text = render_report_template(pgm::read_file(args.template_file), args.template_file, summaries);
  if (args.out.empty()) {
    std::cout << text;
  } else if (args.check) {
    const auto committed = pgm::read_file(args.out);
    if (committed != text) {
      throw error("'" + args.out + "' is out of date with its summaries: " + first_difference(committed, text) +
                  "; run the same command without --check to regenerate it");
    }
    std::cout << args.out << " matches " << args.template_file << " and its summaries\n";
  } else {
    pgm::write_file_atomically(
        args.out, [&](std::ostream& out) { out << text; },
        summary_before_replacing(args.template_file + " -> " + args.out + "\n", args.out));
  }
}

}  // namespace

void add_report_command(CLI::App& app) {
  auto args = std::make_shared<report_arguments>();
  auto* cmd = app.add_subcommand(
      "report", "Write a document whose numbers come from experiment summaries (docs/RESULTS.md), or --check it");
  cmd->add_option("--template", args->template_file,
                  "Markdown with {{FORMAT EXPRESSION}} placeholders (docs/results/RESULTS.template.md)")
      ->required();
  cmd->add_option(
         "--summary", args->summaries,
         "summary.csv of `pgm experiment`, as FILE or NAME=FILE (for NAME: selectors); the first is the default")
      ->required();
  auto* out = cmd->add_option("--out", args->out, "The document to write (default: standard output)");
  cmd->add_flag("--check", args->check, "Write nothing; fail unless --out already holds what the summaries give")
      ->needs(out);
  cmd->callback([args] { run_report(*args); });
}

}  // namespace pgm::cli
