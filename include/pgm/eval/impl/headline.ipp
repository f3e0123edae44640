#pragma once
// The definitions of pgm/eval/headline.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/headline.hpp"

namespace pgm {

PGM_DECL std::vector<headline_entry> prevention_at_zero_data(const std::vector<aggregated_point>& summary,
                                                             const std::string& scenario_name,
                                                             const std::string& target) {
  std::vector<headline_entry> entries;
  std::set<std::string, std::less<>> shown;
  for (const auto& p : summary) {
    if (p.scenario != scenario_name || p.target != target || p.rows != 0 ||
        p.metric != experiment_metric::failure_prevention)
      continue;
    if (shown.insert(p.strategy).second) entries.push_back({p.strategy, p.mean});
  }
  return entries;
}

PGM_DECL std::string headline(const scenario& s, const std::string& target,
                              const std::vector<aggregated_point>& summary) {
  std::string text = s.title + ", " + target + ": success after prevention at |D| = 0:";
  for (const auto& entry : prevention_at_zero_data(summary, s.name, target)) {
    text += "  " + entry.strategy + " " + text::format_short(100 * entry.success, 3) + "%";
  }
  return text;
}

}  // namespace pgm
