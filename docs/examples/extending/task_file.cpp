// A task of one's own is a JSON file (tasks/drop-mug.json here): found by name in a directory,
// read with errors that name the file and the JSON path, and simulated like the shipped tasks.

#include <filesystem>
#include <iostream>
#include <pgm/sim/analytic_probability.hpp>
#include <pgm/sim/simulator.hpp>
#include <pgm/sim/task_file.hpp>
#include <pgm/sim/task_lookup.hpp>

int main() {
  try {
    const std::vector<std::filesystem::path> directories{std::filesystem::path(PGM_EXAMPLE_DIR) / "tasks"};
    std::cout << "tasks:";
    for (const auto& name : pgm::sim::list_tasks(directories)) std::cout << ' ' << name;
    const auto task = pgm::sim::load_task("drop-mug", directories);
    std::cout << "\n" << task.name << ": success '" << task.success << "', the robot controls";
    for (const auto& name : task.controllable()) std::cout << ' ' << name;
    std::cout << '\n';

    // The analytic model's exact success probability, and a simulated rate beside it.
    const auto data = pgm::sim::simulate(task, {.rows = 20000, .seed = 1});
    double successes = 0;
    for (std::size_t row = 0; row < data.rows(); ++row) successes += data.discrete(task.success).code(row);
    std::cout << "P(" << task.success << " = 1): exact " << pgm::sim::analytic_success_probability(task, {})
              << ", simulated " << successes / static_cast<double>(data.rows()) << '\n';

    // A mistake in a file is reported with the file and where in it.
    try {
      (void)pgm::sim::parse_task(R"({"format": "pgm-task", "version": 1, "name": "typo",
                                     "variables": [{"name": "xOff", "kind": "continous"}]})",
                                 "typo.json");
    } catch (const pgm::data_error& e) {
      std::cout << "a broken file: " << e.what() << '\n';
    }
  } catch (const pgm::error& e) {
    std::cerr << "task_file: " << e.what() << '\n';
    return 1;
  }
}
