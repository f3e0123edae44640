#pragma once
// The definitions of pgm/io/read_options.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/io/read_options.hpp"

namespace pgm::detail {

PGM_DECL void keep_pgm_property(std::string_view text, std::map<std::string, std::string>* properties) {
  const auto eq = text.find('=');
  if (properties == nullptr || eq == std::string_view::npos) return;
  const auto key = text::trim(text.substr(0, eq));
  if (key.starts_with("pgm.")) (*properties)[std::string(key.substr(4))] = std::string(text::trim(text.substr(eq + 1)));
}

PGM_DECL std::optional<std::pair<std::size_t, double>> column_normalizer::normalize(std::span<double> values,
                                                                                    std::size_t child_states) {
  if (child_states == 0) return std::nullopt;
  bool table_changed = false;
  for (std::size_t u = 0; u * child_states < values.size(); ++u) {
    const auto column = values.subspan(u * child_states, std::min(child_states, values.size() - u * child_states));
    double sum = 0;
    bool probabilities = true;
    for (const double value : column) {
      probabilities = probabilities && value >= 0 && std::isfinite(value);
      sum += value;
    }
    if (!probabilities) continue;  // the table's own check names the bad value
    const double deviation = std::abs(sum - 1.0);
    if (deviation <= cpt<double>::default_tolerance) continue;
    if (deviation > tolerance_) return std::make_pair(u, sum);
    for (auto& value : column) value /= sum;
    ++columns_;
    table_changed = true;
    largest_ = std::max(largest_, deviation);
  }
  if (table_changed) ++tables_;
  return std::nullopt;
}

PGM_DECL void column_normalizer::report(const std::string& source, std::vector<std::string>* notes) const {
  if (notes == nullptr || columns_ == 0) return;
  notes->push_back("'" + source + "': normalized " + std::to_string(columns_) + " column" + (columns_ == 1 ? "" : "s") +
                   " of " + std::to_string(tables_) + " table" + (tables_ == 1 ? "" : "s") +
                   " that summed to 1 only within " + text::format_short(tolerance_) + " (largest deviation " +
                   text::format_short(largest_, 3) + ")");
}

}  // namespace pgm::detail
