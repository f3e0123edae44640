// A transfer scenario of one's own is a JSON file (scenarios/glass-to-mug.json here): the prior
// task, the target tasks, the correspondence, strategies and weights. This runs its protocol
// (paper Sec. IV-B) on simulated data. The prior task, drop-glass, is one of the shipped tasks:
// set PGM_TASKS_DIR to their directory (share/pgm/tasks where pgm is installed).

#include <filesystem>
#include <iostream>
#include <map>
#include <pgm/eval/experiment.hpp>
#include <pgm/eval/scenario.hpp>
#include <pgm/sim/simulator.hpp>
#include <pgm/sim/task_lookup.hpp>

namespace {

// Data and facts of a task, from its file and the analytic simulator.
pgm::task_source simulated(std::vector<std::filesystem::path> directories) {
  return {[directories](const std::string& task, std::size_t rows, std::uint64_t seed) {
            return pgm::sim::simulate(pgm::sim::load_task(task, directories), {.rows = rows, .seed = seed});
          },
          [directories](const std::string& name, const std::string& node) {
            const auto task = pgm::sim::load_task(name, directories);
            pgm::task_facts facts;
            for (const auto& edge : task.structure) {
              if (edge.to == node) facts.parents.push_back(edge.from);
            }
            for (const auto& v : task.variables) {
              facts.tags.emplace(v.name, v.tags);
              if (v.controllable) facts.controllable.insert(v.name);
            }
            return facts;
          }};
}

}  // namespace

int main() {
  try {
    const std::filesystem::path here(PGM_EXAMPLE_DIR);
    const auto scenario = pgm::load_scenario(here / "scenarios" / "glass-to-mug.json");
    auto directories = pgm::sim::default_task_directories();  // $PGM_TASKS_DIR
    directories.insert(directories.begin(), here / "tasks");

    const auto points = pgm::run_experiment(scenario, simulated(directories), {.seed = 1, .automatic_lines = false});
    // Mean-Difference to the ground truth by the number of target rows |D|: the transferred
    // prior helps most where the target task has few trials.
    std::cout << scenario.title << ", Mean-Difference over " << scenario.repetitions << " repetitions\n";
    std::cout << "|D|\tmle\tdirect w=20\n";
    std::map<std::size_t, std::map<std::string, double>> by_rows;
    for (const auto& p : pgm::aggregate(points)) {
      if (p.metric == "mean_difference") by_rows[p.rows][p.strategy + " w=" + p.weight] = p.mean;
    }
    for (const auto& [rows, lines] : by_rows) {
      std::cout << rows << '\t' << lines.at("mle w=0") << '\t' << lines.at("direct w=20") << '\n';
    }
  } catch (const pgm::error& e) {
    std::cerr << "scenario_file: " << e.what() << '\n';
    return 1;
  }
}
