// A transfer scenario of one's own is a JSON file (scenarios/glass-to-mug.json here): the prior
// task, the target tasks, the correspondence, strategies and weights. This runs its protocol
// (paper Sec. IV-B) on simulated data. The prior task, drop-glass, is one of the shipped tasks:
// set PGM_TASKS_DIR to their directory (share/pgm/tasks where pgm is installed).

#include <filesystem>
#include <iostream>
#include <map>
#include <pgm/eval/experiment.hpp>
#include <pgm/eval/scenario.hpp>
#include <pgm/eval/simulated_source.hpp>
#include <pgm/sim/task_lookup.hpp>

int main() {
  try {
    const std::filesystem::path here(PGM_EXAMPLE_DIR);
    const auto scenario = pgm::load_scenario(here / "scenarios" / "glass-to-mug.json");
    auto directories = pgm::sim::default_task_directories();  // $PGM_TASKS_DIR
    directories.insert(directories.begin(), here / "tasks");

    const auto points = pgm::run_experiment(scenario, pgm::simulated_source({.task_folders = directories}),
                                            {.seed = 1, .automatic_lines = false});
    // Mean-Difference to the ground truth by the number of target rows |D|: the transferred
    // prior helps most where the target task has few trials.
    std::cout << scenario.title << ", Mean-Difference over " << scenario.repetitions << " repetitions\n";
    std::cout << "|D|\tmle\tdirect w=20\n";
    std::map<std::size_t, std::map<std::string, double>> by_rows;
    for (const auto& p : pgm::aggregate(points)) {
      if (p.metric == pgm::experiment_metric::mean_difference) by_rows[p.rows][p.strategy + " w=" + p.weight] = p.mean;
    }
    for (const auto& [rows, lines] : by_rows) {
      std::cout << rows << '\t' << lines.at("mle w=0") << '\t' << lines.at("direct w=20") << '\n';
    }
  } catch (const pgm::error& e) {
    std::cerr << "scenario_file: " << e.what() << '\n';
    return 1;
  }
}
