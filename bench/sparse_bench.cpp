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

#include "check.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/estimate.hpp"

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
  std::uint64_t total = 0;
  for (auto _ : state) {
    const auto counts = pgm::count_family(data, "y", names);
    stored = counts.stored_configurations().size();
    total = counts.total();
    benchmark::DoNotOptimize(counts);
  }
  pgm::bench::check(state, total == rows && stored > 0 && stored <= rows, "the sparse counts are wrong");
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
  std::uint64_t total = 0;
  for (auto _ : state) {
    std::map<std::size_t, std::array<std::uint64_t, 3>> counts;
    for (std::size_t r = 0; r < rows; ++r) {
      std::size_t u = 0;
      for (const auto* column : columns) u = 2 * u + column->code(r);
      ++counts[u][child.code(r)];
    }
    total = 0;
    for (const auto& [u, column] : counts) total += column[0] + column[1] + column[2];
    benchmark::DoNotOptimize(counts);
  }
  pgm::bench::check(state, total == rows, "the counts do not add up to the rows");
  set_rows_processed(state, rows);
}

// Counting and the MLE, a sparse table out.
void fit_sparse_family(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = wide_data(wide, rows);
  const auto names = parent_names(wide);
  bool sparse = false;
  for (auto _ : state) {
    const auto table = pgm::estimate_mle(pgm::count_family(data, "y", names));
    sparse = table.is_sparse();
    benchmark::DoNotOptimize(table);
  }
  pgm::bench::check(state, sparse, "the table past the dense limit is not sparse");
  set_rows_processed(state, rows);
}

// 20 parents, within the dense limit: the estimate stored sparse (range 1 = 1) or dense (0).
void estimate_20_parents(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto counts = pgm::count_family(wide_data(20, rows), "y", parent_names(20));
  const pgm::estimate_options options{.sparse = state.range(1) != 0};
  double first = 0.0;
  for (auto _ : state) {
    const auto table = pgm::estimate(counts, pgm::bdeu_prior{}, options);
    first = table.column(pgm::config_index(0))[0];
    benchmark::DoNotOptimize(table);
  }
  // Sparse or dense, the same estimate.
  const auto other = pgm::estimate(counts, pgm::bdeu_prior{}, {.sparse = !options.sparse});
  pgm::bench::check(state, first == other.column(pgm::config_index(0))[0], "sparse and dense estimates differ");
  set_rows_processed(state, rows);
}

BENCHMARK(count_sparse_family)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->ArgName("rows")->UseRealTime();
BENCHMARK(count_sparse_family_naive_map)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->ArgName("rows");
BENCHMARK(fit_sparse_family)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->ArgName("rows")->UseRealTime();
BENCHMARK(estimate_20_parents)->Args({100'000, 1})->Args({100'000, 0})->ArgNames({"rows", "sparse"});

}  // namespace
}  // namespace sparse_bench
