// Experiments per second of each task and simulator back-end, on 1 and 2 threads
// (items_per_second). The paper's Unity set-up ran about 83 experiments per second.
// One thread is timed by its CPU time, so that the figure is per core even when other work
// shares the machine; two threads by the wall clock.
// Also the time to integrate the ground truth of all 625 onTop2 configurations of 2-Stack.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "pgm/sim/analytic_probability.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/task_file.hpp"

namespace {

const std::vector<std::string> tasks{"1-stack", "2-stack", "drop-plate", "drop-bowl", "drop-glass"};

pgm::sim::task_definition task(std::size_t i) {
  return pgm::sim::load_task(std::filesystem::path(PGM_SOURCE_DIR) / "tasks" / (tasks[i] + ".json"));
}

void run(benchmark::State& state, const std::string& backend, std::size_t rows) {
  if (!pgm::sim::backend_registry::instance().contains(backend)) {
    state.SkipWithError(("the " + backend + " back-end is not linked into this program").c_str());
    return;
  }
  const auto t = task(static_cast<std::size_t>(state.range(0)));
  pgm::sim::simulate_options o;
  o.backend = backend;
  o.rows = rows;
  o.threads = static_cast<unsigned>(state.range(1));
  double successes = 0;
  for (auto _ : state) {
    ++o.seed;
    const auto data = pgm::sim::simulate(t, o);
    const auto& s = data.discrete(t.success);
    for (std::size_t r = 0; r < data.rows(); ++r) successes += s.code(r);
  }
  state.SetLabel(t.name);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rows));
  const double rate = successes / static_cast<double>(state.iterations() * rows);
  if (rate <= 0.0 || rate >= 1.0) state.SkipWithError("degenerate success rate");
  state.counters["success"] = rate;
}

void analytic(benchmark::State& state) { run(state, "analytic", 200'000); }
BENCHMARK(analytic)->ArgsProduct({{0, 1, 2, 3, 4}, {1}})->Unit(benchmark::kMillisecond);
BENCHMARK(analytic)->ArgsProduct({{0, 1, 2, 3, 4}, {2}})->Unit(benchmark::kMillisecond)->UseRealTime();

// Skipped with a message when the pgm_bullet plugin is not linked (Bullet not installed).
void bullet(benchmark::State& state) { run(state, "bullet", 2'000); }
BENCHMARK(bullet)->ArgsProduct({{0, 1, 2, 3, 4}, {1}})->Unit(benchmark::kMillisecond);
BENCHMARK(bullet)->ArgsProduct({{0, 1, 2, 3, 4}, {2}})->Unit(benchmark::kMillisecond)->UseRealTime();

void ground_truth_625(benchmark::State& state) {
  const auto t = task(1);
  const std::vector<double> e{-3, -1.4, -0.4, 0.4, 1.4, 3};
  double sum = 0;
  for (auto _ : state) {
    for (int a = 0; a < 5; ++a)
      for (int b = 0; b < 5; ++b)
        for (int c = 0; c < 5; ++c)
          for (int d = 0; d < 5; ++d)
            sum += pgm::sim::analytic_success_probability(t, {{"xOff1", {e[a], e[a + 1]}},
                                                              {"yOff1", {e[b], e[b + 1]}},
                                                              {"xOff2", {e[c], e[c + 1]}},
                                                              {"yOff2", {e[d], e[d + 1]}}});
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations() * 625);
}
BENCHMARK(ground_truth_625)->Unit(benchmark::kMillisecond);

}  // namespace
