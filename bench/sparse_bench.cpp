// Sparse tables (core/cpt.hpp): a ternary child under 24 binary parents, 2^24 configurations and
// 5·10^7 cells, three times pgm's limit of a dense table, counted and fitted from 10^4 to 10^6 rows
// (at most that many configurations seen), beside the simple approach (a std::map from each
// configuration to its column); and a family of 20 binary parents (3·2^20 cells, within the
// limit) fitted sparse and dense from 10^5 rows. Reported as ns/row and rows/s; "stored" is the
// configurations a table keeps.

#include <benchmark/benchmark.h>

#include <array>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "pgm/learn/estimate.hpp"
#include "pgm/learn/sufficient_statistics.hpp"

// A namespace of its own: the unity build joins this file with learn_bench.cpp.
namespace sparse_bench {
namespace {

/// y (3 states) and `parents` binary parents p0, p1, …, rows drawn uniformly.
const pgm::dataset& wide_data(std::size_t parents, std::size_t rows) {
  static std::map<std::pair<std::size_t, std::size_t>, pgm::dataset> cache;
  auto [it, fresh] = cache.try_emplace({parents, rows});
  if (!fresh) return it->second;
  std::mt19937_64 random(rows + parents);
  std::vector<unsigned> child(rows);
  for (auto& c : child) c = static_cast<unsigned>(random() % 3);
  it->second.add(pgm::discrete_column(pgm::variable("y", {"a", "b", "c"}), child));
  for (std::size_t p = 0; p < parents; ++p) {
    std::vector<unsigned> codes(rows);
    for (auto& c : codes) c = static_cast<unsigned>(random() & 1U);
    it->second.add(pgm::discrete_column(pgm::variable("p" + std::to_string(p), {"0", "1"}), codes));
  }
  return it->second;
}

std::vector<std::string> parent_names(std::size_t parents) {
  std::vector<std::string> names;
  for (std::size_t p = 0; p < parents; ++p) names.push_back("p" + std::to_string(p));
  return names;
}

void set_rows_processed(benchmark::State& state, std::size_t rows) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rows));
  state.counters["ns/row"] = benchmark::Counter(static_cast<double>(state.iterations() * rows),
                                                benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

constexpr std::size_t wide = 24;

void count_sparse_family(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = wide_data(wide, rows);
  const auto names = parent_names(wide);
  std::size_t stored = 0;
  for (auto _ : state) {
    const auto counts = pgm::count_family(data, "y", names);
    stored = counts.stored_configurations().size();
    benchmark::DoNotOptimize(counts);
  }
  state.counters["stored"] = static_cast<double>(stored);
  set_rows_processed(state, rows);
}

// The simple approach: each row's configuration from its codes, its column in a std::map.
void count_sparse_family_naive_map(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = wide_data(wide, rows);
  std::vector<const pgm::discrete_column*> columns;
  for (const auto& name : parent_names(wide)) columns.push_back(&data.discrete(name));
  const auto& child = data.discrete("y");
  for (auto _ : state) {
    std::map<std::size_t, std::array<std::uint64_t, 3>> counts;
    for (std::size_t r = 0; r < rows; ++r) {
      std::size_t u = 0;
      for (const auto* column : columns) u = 2 * u + column->code(r);
      ++counts[u][child.code(r)];
    }
    benchmark::DoNotOptimize(counts);
  }
  set_rows_processed(state, rows);
}

// Counting and the MLE, a sparse table out.
void fit_sparse_family(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = wide_data(wide, rows);
  const auto names = parent_names(wide);
  for (auto _ : state) benchmark::DoNotOptimize(pgm::estimate_mle(pgm::count_family(data, "y", names)));
  set_rows_processed(state, rows);
}

// 20 parents, within the dense limit: the estimate stored sparse (range 1 = 1) or dense (0).
void estimate_20_parents(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto counts = pgm::count_family(wide_data(20, rows), "y", parent_names(20));
  const pgm::estimate_options options{.sparse = state.range(1) != 0};
  for (auto _ : state) benchmark::DoNotOptimize(pgm::estimate(counts, pgm::bdeu_prior{}, options));
  set_rows_processed(state, rows);
}

BENCHMARK(count_sparse_family)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->ArgName("rows")->UseRealTime();
BENCHMARK(count_sparse_family_naive_map)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->ArgName("rows");
BENCHMARK(fit_sparse_family)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->ArgName("rows")->UseRealTime();
BENCHMARK(estimate_20_parents)->Args({100'000, 1})->Args({100'000, 0})->ArgNames({"rows", "sparse"});

}  // namespace
}  // namespace sparse_bench
