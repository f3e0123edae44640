// Score-based structure search on samples of the published alarm network (37 nodes, 46 arcs):
// hill climbing with BIC at 10^4 and 10^5 rows on 1 and 2 threads, tabu search at 10^4, and the
// throughput of family scoring (count + BIC of one family of 1 to 3 parents) at 10^5 rows. The
// result is checked after the timed loop: the learned CPDAG within a few edges of the truth.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "check.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/learn/family_score_cache.hpp"
#include "pgm/learn/hill_climbing.hpp"
#include "pgm/learn/orientation.hpp"
#include "pgm/learn/structural_hamming_distance.hpp"

namespace {

const pgm::bayesian_network& alarm() {
  static const auto net = pgm::read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / "alarm.bif");
  return net;
}

const pgm::dataset& data(std::size_t rows) {
  static std::map<std::size_t, pgm::dataset> cache;
  auto it = cache.find(rows);
  if (it == cache.end()) it = cache.emplace(rows, pgm::sample(alarm(), rows, 24)).first;
  return it->second;
}

std::vector<const pgm::discrete_column*> columns(const pgm::dataset& d) {
  std::vector<const pgm::discrete_column*> result;
  for (const auto& name : d.names()) result.push_back(&d.discrete(name));
  return result;
}

void search(benchmark::State& state, std::size_t tabu) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& d = data(rows);
  const auto picked = columns(d);
  pgm::search_options options;
  options.tabu = tabu;
  options.threads = static_cast<unsigned>(state.range(1));
  pgm::search_result result;
  for (auto _ : state) {
    result = pgm::hill_climb(picked, options);
    benchmark::DoNotOptimize(result);
  }
  pgm::dag graph(d.names());
  for (const auto& e : result.edges) graph.add_edge(e.from, e.to);
  const auto shd = pgm::structural_hamming_distance(pgm::cpdag_of(graph), pgm::cpdag_of(alarm().graph()));
  if (shd > 40) throw std::runtime_error("hill climbing is far from alarm");
  state.counters["bic"] = result.score;
  state.counters["moves"] = static_cast<double>(result.moves);
  state.counters["families"] = static_cast<double>(result.families_scored);
  state.counters["shd"] = static_cast<double>(shd);
}

void hill_climbing_alarm(benchmark::State& state) { search(state, 0); }
void tabu_alarm(benchmark::State& state) { search(state, 10); }

BENCHMARK(hill_climbing_alarm)
    ->ArgNames({"rows", "threads"})
    ->Args({10'000, 1})
    ->Args({10'000, 2})
    ->Args({100'000, 1})
    ->Args({100'000, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(tabu_alarm)->ArgNames({"rows", "threads"})->Args({10'000, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

// One family counted and scored per iteration (no cache: each key is new to a fresh cache).
void family_scoring_alarm(benchmark::State& state) {
  const auto& d = data(100'000);
  const auto picked = columns(d);
  const auto parents = static_cast<std::size_t>(state.range(0));
  // Child c's family: `parents` parents spread over the columns.
  const auto key_for = [&](std::size_t c) {
    pgm::family_key key{c, {}};
    for (std::size_t k = 1; k <= parents; ++k) key.parents.push_back((c + 7 * k) % picked.size());
    std::sort(key.parents.begin(), key.parents.end());
    key.parents.erase(std::unique(key.parents.begin(), key.parents.end()), key.parents.end());
    return key;
  };
  std::size_t child = 0;
  double sink = 0;
  const pgm::family_score bic;
  for (auto _ : state) {
    pgm::family_score_cache cache(picked, bic, 1);
    const double score = cache.score(key_for(child));
    benchmark::DoNotOptimize(score);
    sink += score;
    child = (child + 1) % picked.size();
  }
  // Not DoNotOptimize(sink) here: GCC may pass a double lvalue through its "+m,r" constraint in a
  // general register and read back garbage.
  // Each family's score against a fresh cache's, computed the same way.
  pgm::family_score_cache fresh(picked, bic, 1);
  double again = 0;
  child = 0;
  for (std::int64_t i = 0; i < state.iterations(); ++i) {
    again += fresh.score(key_for(child));
    child = (child + 1) % picked.size();
  }
  pgm::bench::check(state, std::isfinite(sink) && sink == again, "the family scores differ between two caches");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["rows/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * 100'000.0, benchmark::Counter::kIsRate);
}
BENCHMARK(family_scoring_alarm)->ArgName("parents")->DenseRange(1, 3)->Unit(benchmark::kMicrosecond);

}  // namespace
