#include "cli/common.hpp"

#include <iostream>

#include <unistd.h>

#include "pgm/core/error.hpp"
#include "pgm/data/csv.hpp"
#include "pgm/detail/text.hpp"

namespace pgm::cli {

std::vector<std::string> split_list(std::string_view text, const std::string& what) {
  auto pieces = detail::split(text, ',');
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
  throw io_error("'" + path.string() + "': expected a file ending in " + detail::join(extensions, " or "));
}

dataset read_discrete_data(const std::filesystem::path& path, const std::vector<std::string>& columns,
                           const data_plan& plan) {
  csv_options options;
  options.columns = columns;
  options.default_kind = column_kind::discrete;
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
  auto data = read_csv(path, options);
  if (plan.raw_intervals) {
    discretization used;
    for (const auto& [name, intervals] : *plan.raw_intervals) {
      if (data.contains(name)) used.emplace(name, intervals);
    }
    data = apply_discretization(data, used);
  }
  return data;
}

void note(const std::string& text) { std::cerr << "pgm: note: " << text << '\n'; }

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) != 0; }

}  // namespace pgm::cli
