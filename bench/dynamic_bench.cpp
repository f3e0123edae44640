// Fitting a dynamic network with tied tables from episodes in long form, sized like the paper: a
// tower's step as three template variables (the offsets xOff, yOff of 5 bins and the binary
// onTop), onTop's transition table over this step's and the last step's offsets (4 parents × 5
// states: 625 parameters), episodes of 10 steps. Reported per long-form row (ns/row), to set
// beside learn_bench's fit_625_bdeu, the static fit of a table of the same shape per row.

#include <benchmark/benchmark.h>

#include <map>
#include <random>
#include <string>
#include <vector>

#include "check.hpp"
#include "pgm/learn/fit_dynamic.hpp"

namespace {

constexpr std::size_t steps_per_episode = 10;

/// Long-form rows: episode, t, xOff, yOff, onTop, drawn uniformly; rows / 10 episodes of 10 steps.
const pgm::dataset& tower_episodes(std::size_t rows) {
  static std::map<std::size_t, pgm::dataset> cache;
  auto [it, fresh] = cache.try_emplace(rows, pgm::dataset("tower.csv"));
  if (!fresh) return it->second;
  std::mt19937_64 random(rows);
  std::vector<unsigned> episode(rows);
  std::vector<double> t(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    episode[r] = static_cast<unsigned>(r / steps_per_episode);
    t[r] = static_cast<double>(r % steps_per_episode);
  }
  it->second.add(pgm::continuous_column("episode", std::vector<double>(episode.begin(), episode.end())));
  it->second.add(pgm::continuous_column("t", t));
  const std::vector<std::string> bins{"0", "1", "2", "3", "4"};
  for (const char* name : {"xOff", "yOff"}) {
    std::vector<unsigned> codes(rows);
    for (auto& c : codes) c = static_cast<unsigned>(random() % bins.size());
    it->second.add(pgm::discrete_column(pgm::variable(name, bins), codes));
  }
  std::vector<unsigned> on_top(rows);
  for (auto& c : on_top) c = static_cast<unsigned>(random() & 1U);
  it->second.add(pgm::discrete_column(pgm::variable("onTop", {"0", "1"}), on_top));
  return it->second;
}

void fit_dynamic_625(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = tower_episodes(rows);
  const auto structure = pgm::dynamic_structure_from_data(
      data, pgm::parse_edge_list("xOff->onTop, yOff->onTop, xOff@-1->onTop, yOff@-1->onTop"));
  pgm::dynamic_fit_options options;
  options.fit.prior = pgm::bdeu_prior{};
  options.fit.counting = {.threads = 1, .min_rows_per_thread = 1};
  std::size_t parameters = 0;
  for (auto _ : state) {
    const auto model = pgm::fit_dynamic(structure, data, options);
    parameters = model.transition_tables().back().size() / 2;
    benchmark::DoNotOptimize(model);
  }
  pgm::bench::check(state, parameters == 625, "onTop's transition table does not have 625 parameters");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rows));
  state.counters["ns/row"] = benchmark::Counter(static_cast<double>(state.iterations() * rows),
                                                benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(fit_dynamic_625)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->ArgName("rows")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
