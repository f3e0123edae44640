// Runs the example task with the built-in "analytic" back-end and with "ideal-drop"
// (ideal_drop.cpp, a translation unit of its own), both found by name.

#include <filesystem>
#include <iostream>
#include <pgm/sim/simulator.hpp>
#include <pgm/sim/task_file.hpp>

int main() {
  try {
    std::cout << "back-ends:";
    for (const auto& name : pgm::sim::backends()) std::cout << ' ' << name;
    std::cout << '\n';
    const auto task = pgm::sim::load_task(std::filesystem::path(PGM_EXAMPLE_DIR) / "tasks" / "drop-mug.json");
    for (const auto* backend : {"analytic", "ideal-drop"}) {
      const auto data = pgm::sim::simulate(task, {.backend = backend, .rows = 20000, .seed = 1});
      const auto& inside = data.discrete(task.success);
      double successes = 0;
      for (std::size_t row = 0; row < data.rows(); ++row) successes += inside.code(row);
      std::cout << data.source() << ": " << task.success << " = 1 in " << successes / static_cast<double>(data.rows())
                << " of " << data.rows() << " experiments\n";
    }
  } catch (const pgm::error& e) {
    std::cerr << "simulator_backend: " << e.what() << '\n';
    return 1;
  }
}
