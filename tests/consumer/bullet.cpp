// Links pgm::bullet and runs a few Bullet experiments of a shipped task (PGM_TASK_FILE): the
// back-end registered itself as "bullet" when its objects were linked in.
#include <filesystem>
#include <iostream>
#include <pgm/sim/bullet.hpp>
#include <pgm/sim/simulator.hpp>
#include <pgm/sim/task_file.hpp>

int main() {
  try {
    const auto task = pgm::sim::load_task(std::filesystem::path(PGM_TASK_FILE));
    const auto data = pgm::sim::simulate(task, {.backend = "bullet", .rows = 20, .seed = 1, .threads = 1});
    std::cout << "bullet: " << data.rows() << " experiments of " << task.name << '\n';
    return data.rows() == 20 ? 0 : 1;
  } catch (const pgm::error& e) {
    std::cerr << "consumer_bullet: " << e.what() << '\n';
    return 1;
  }
}
