// PC-stable on the paper's data sizes: 12 five-state variables sampled from a random network
// (up to 3 parents each), 10^5 and 10^6 rows, 1 and 2 threads. Reported as wall time per
// learning run, the number of tests and rows/s. The aim is 10^6 rows in under 2 s on 2 cores.

#include <benchmark/benchmark.h>

#include <map>
#include <stdexcept>

#include "pgm/inference/sampling.hpp"
#include "pgm/learn/pc.hpp"
#include "pgm/learn/structural_hamming_distance.hpp"
#include "pgm/testing/random_network.hpp"

namespace {

const pgm::bayesian_network& network() {
  static const auto net =
      pgm::testing::random_network(12, {.nodes = 12, .max_parents = 3, .min_states = 5, .max_states = 5});
  return net;
}

const pgm::dataset& data(std::size_t rows) {
  static std::map<std::size_t, pgm::dataset> cache;
  auto it = cache.find(rows);
  if (it == cache.end()) it = cache.emplace(rows, pgm::sample(network(), rows, rows)).first;
  return it->second;
}

void pc_stable_12x5(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& d = data(rows);
  const pgm::pc_options options{.test = pgm::make_independence_test("g2"),
                                .alpha = 0.01,
                                .max_conditioning = 3,
                                .threads = static_cast<unsigned>(state.range(1))};
  pgm::pc_result result;
  for (auto _ : state) {
    result = pgm::pc_stable(d, options);
    benchmark::DoNotOptimize(result);
  }
  // The result after the timed loop: the skeleton of the true network.
  const auto parts = pgm::hamming_differences(result.graph, pgm::cpdag_of(network().graph()));
  if (parts.missing + parts.extra > 2) throw std::runtime_error("PC-stable lost the skeleton");
  state.counters["tests"] = static_cast<double>(result.tests);
  state.counters["edges"] = static_cast<double>(result.graph.edge_count());
  state.counters["shd"] = static_cast<double>(parts.total());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rows));
}

BENCHMARK(pc_stable_12x5)
    ->ArgNames({"rows", "threads"})
    ->Args({100'000, 1})
    ->Args({100'000, 2})
    ->Args({1'000'000, 1})
    ->Args({1'000'000, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
