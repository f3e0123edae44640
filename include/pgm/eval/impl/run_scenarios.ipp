#pragma once
// The definitions of pgm/eval/run_scenarios.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/run_scenarios.hpp"

namespace pgm {

PGM_DECL std::vector<experiment_point> run_scenario(const scenario& s, const task_source& source,
                                                    const experiment_options& options) {
  try {
    return run_experiment(s, source, options);
  } catch (const error& e) {
    throw error(s.source.string() + ": " + e.what());
  }
}

PGM_DECL report_files run_scenarios(const std::vector<scenario>& scenarios, const task_source& source,
                                    const std::filesystem::path& folder, const run_scenarios_options& options) {
  auto& group = options.experiment.across_processes ? processes() : lone_process();
  std::optional<report_writer> writer;
  run_agreed(group, [&] {
    if (group.rank() == 0) writer.emplace(folder, report_options{options.render_plots, options.note, options.headline});
  });
  auto experiment = options.experiment;
  experiment.note = options.note;
  for (const auto& s : scenarios) {
    experiment.progress = nullptr;
    if (options.progress) {
      experiment.progress = [&](std::size_t done, std::size_t total) { options.progress(s, done, total); };
    }
    auto points = run_scenario(s, source, experiment);
    if (writer) writer->add(s, std::move(points));
  }
  return writer ? writer->finish() : report_files{};
}

}  // namespace pgm
