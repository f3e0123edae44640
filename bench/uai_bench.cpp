// The exact solver on the UAI 2014 competition problems of tests/data/uai/MAR, in process, the
// model read and its evidence parsed outside the timed loop: the elimination order's search
// (one greedy run, and the search `pgm solve` runs by default: the greedy order and 32 seeded
// restarts within its budget), and every marginal by the junction tree (the order's search,
// the tree's tables and both propagations). bench/uai/bench_uai.py times the same MAR as whole
// processes beside libDAI and Merlin.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "pgm/core/file.hpp"
#include "pgm/inference/solve.hpp"
#include "pgm/io/uai.hpp"

namespace {

const std::vector<std::string> problems = {"CSP_12",      "DBN_11",          "Grids_11",  "Pedigree_11",
                                           "Promedus_24", "Segmentation_11", "Alchemy_11"};

struct problem {
  pgm::markov_network model;
  pgm::evidence_set observed;
  pgm::interaction_graph graph;
  std::vector<std::size_t> cards;
};

const problem& load(std::size_t index) {
  static std::map<std::size_t, problem> loaded;
  auto it = loaded.find(index);
  if (it != loaded.end()) return it->second;
  const auto base = std::filesystem::path(PGM_UAI_DIR) / "MAR" / (problems[index] + ".uai");
  problem p{pgm::read_uai(base).model, {}, {}, {}};
  auto evid = base;
  evid += ".evid";
  const auto samples = pgm::parse_uai_evidence(pgm::read_file(evid), evid.string(), p.model);
  for (auto [v, s] : samples.front()) {
    p.observed.hard.push_back({v, pgm::index_at<pgm::state_index>(s)});
  }
  p.graph = pgm::interaction_graph_of(p.model.size(), pgm::scopes_of(p.model));
  p.cards = pgm::cardinalities_of(p.model);
  return loaded.emplace(index, std::move(p)).first->second;
}

void greedy_order(benchmark::State& state) {
  const auto& p = load(static_cast<std::size_t>(state.range(0)));
  state.SetLabel(problems[static_cast<std::size_t>(state.range(0))]);
  std::size_t cells = 0;
  for (auto _ : state) {
    auto order = pgm::greedy_elimination(p.graph, p.cards, pgm::elimination_heuristic::min_fill);
    cells = pgm::elimination_cells(order, p.cards);
    benchmark::DoNotOptimize(cells);
  }
  state.counters["cells"] = static_cast<double>(cells);
}
BENCHMARK(greedy_order)->DenseRange(0, 6)->Unit(benchmark::kMicrosecond);

void searched_order(benchmark::State& state) {
  const auto& p = load(static_cast<std::size_t>(state.range(0)));
  state.SetLabel(problems[static_cast<std::size_t>(state.range(0))]);
  const pgm::solve_options defaults;
  std::size_t cells = 0;
  for (auto _ : state) {
    auto order = pgm::searched_elimination(p.graph, p.cards, defaults.heuristic, defaults.search);
    cells = pgm::elimination_cells(order, p.cards);
    benchmark::DoNotOptimize(cells);
  }
  state.counters["cells"] = static_cast<double>(cells);
}
BENCHMARK(searched_order)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

void all_marginals_jt(benchmark::State& state) {
  const auto& p = load(static_cast<std::size_t>(state.range(0)));
  state.SetLabel(problems[static_cast<std::size_t>(state.range(0))]);
  pgm::solve_options options;
  options.engine = pgm::solve_engine::jt;
  for (auto _ : state) {
    auto marginals = pgm::all_marginals(p.model, p.observed, options);
    benchmark::DoNotOptimize(marginals.data());
  }
}
BENCHMARK(all_marginals_jt)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

}  // namespace
