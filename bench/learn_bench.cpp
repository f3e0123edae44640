// Counting and fitting one 625-parameter table (4 parents × 5 states, binary child: onTop2 of
// 2-Stack) at the paper's data sizes, beside the simple approach: a std::map keyed by the
// configuration, and the five tables of the fit counted from 64-bit value columns in memory
// (NumPy's, as pgm.fit reads them) beside the same from the byte data set. Reported as ns/row
// (lower is better) and rows/s.

#include <benchmark/benchmark.h>

#include <array>
#include <map>
#include <random>
#include <vector>

#include "check.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/count_values.hpp"
#include "pgm/learn/fit.hpp"

namespace {

constexpr std::size_t five = 5;

/// onTop2 with parents xOff1, yOff1, xOff2, yOff2 of 5 states each, rows drawn uniformly.
const pgm::dataset& stacking_data(std::size_t rows) {
  static std::map<std::size_t, pgm::dataset> cache;
  auto [it, fresh] = cache.try_emplace(rows);
  if (!fresh) return it->second;
  std::mt19937_64 random(rows);
  std::uniform_int_distribution<unsigned> bin(0, five - 1);
  const std::vector<std::string> bins{"0", "1", "2", "3", "4"};
  for (const char* name : {"xOff1", "yOff1", "xOff2", "yOff2"}) {
    std::vector<unsigned> codes(rows);
    for (auto& c : codes) c = bin(random);
    it->second.add(pgm::discrete_column(pgm::variable(name, bins), codes));
  }
  std::vector<unsigned> success(rows);
  for (auto& c : success) c = static_cast<unsigned>(random() & 1U);
  it->second.add(pgm::discrete_column(pgm::variable("onTop2", {"0", "1"}), success));
  return it->second;
}

const std::array<std::string, 4> parents{"xOff1", "yOff1", "xOff2", "yOff2"};

void set_rows_processed(benchmark::State& state, std::size_t rows) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rows));
  state.counters["ns/row"] = benchmark::Counter(static_cast<double>(state.iterations() * rows),
                                                benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void count_625(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = stacking_data(rows);
  const pgm::count_options options{.threads = static_cast<unsigned>(state.range(1)), .min_rows_per_thread = 1};
  std::uint64_t total = 0;
  for (auto _ : state) {
    const auto counts = pgm::count_family(data, "onTop2", parents, options);
    total = counts.total();
    benchmark::DoNotOptimize(counts);
  }
  pgm::bench::check(state, total == rows, "the counts do not add up to the rows");
  set_rows_processed(state, rows);
}

// The simple approach: read each row's codes and bump a map entry keyed by the configuration.
void count_625_naive_map(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = stacking_data(rows);
  std::vector<const pgm::discrete_column*> columns;
  for (const auto& name : parents) columns.push_back(&data.discrete(name));
  const auto& child = data.discrete("onTop2");
  std::uint64_t total = 0;
  for (auto _ : state) {
    std::map<std::array<unsigned, 5>, std::uint64_t> counts;
    for (std::size_t r = 0; r < rows; ++r) {
      ++counts[{columns[0]->code(r), columns[1]->code(r), columns[2]->code(r), columns[3]->code(r), child.code(r)}];
    }
    total = 0;
    for (const auto& [cell, n] : counts) total += n;
    benchmark::DoNotOptimize(counts);
  }
  pgm::bench::check(state, total == rows, "the counts do not add up to the rows");
  set_rows_processed(state, rows);
}

// The five tables of the fit (onTop2 | 4 parents, and each parent), from the byte data set.
void count_fit_tables(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = stacking_data(rows);
  const pgm::count_options options{.threads = static_cast<unsigned>(state.range(1)), .min_rows_per_thread = 1};
  bool every_row = true;
  for (auto _ : state) {
    const auto family = pgm::count_family(data, "onTop2", parents, options);
    every_row = family.total() == rows;
    benchmark::DoNotOptimize(family);
    for (const auto& p : parents) {
      const auto root = pgm::count_family(data, p, {}, options);
      every_row = every_row && root.total() == rows;
      benchmark::DoNotOptimize(root);
    }
  }
  pgm::bench::check(state, every_row, "a table's counts do not add up to the rows");
  set_rows_processed(state, rows);
}

// The same five tables straight from 64-bit columns of the same codes (count_values.hpp).
void count_fit_tables_from_values(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = stacking_data(rows);
  std::vector<std::vector<std::int64_t>> values;
  std::vector<pgm::named_value_column> columns;
  for (const auto& name : {"onTop2", "xOff1", "yOff1", "xOff2", "yOff2"}) {
    const auto& column = data.discrete(name);
    auto& codes = values.emplace_back(rows);
    for (std::size_t r = 0; r < rows; ++r) codes[r] = static_cast<std::int64_t>(column.code(r));
    columns.push_back({name, pgm::value_span<std::int64_t>{codes.data(), rows, 1}});
  }
  const std::vector<pgm::value_family> families{{0, {1, 2, 3, 4}}, {1, {}}, {2, {}}, {3, {}}, {4, {}}};
  const pgm::count_options options{.threads = static_cast<unsigned>(state.range(1)), .min_rows_per_thread = 1};
  bool every_row = true;
  for (auto _ : state) {
    const auto counted = pgm::count_value_families(columns, families, options);
    every_row = counted && counted->tables.size() == families.size();
    if (counted) {
      for (const auto& t : counted->tables) every_row = every_row && t.total() == rows;
    }
    benchmark::DoNotOptimize(counted);
  }
  pgm::bench::check(state, every_row, "a table's counts do not add up to the rows");
  set_rows_processed(state, rows);
}

void fit_625_bdeu(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = stacking_data(rows);
  std::vector<pgm::named_edge> edges;
  for (const auto& p : parents) edges.push_back({p, "onTop2"});
  const auto structure = pgm::structure_from_data(data, edges);
  pgm::fit_options options{.prior = pgm::bdeu_prior{}};
  options.counting = {.threads = static_cast<unsigned>(state.range(1)), .min_rows_per_thread = 1};
  std::size_t tables = 0;
  for (auto _ : state) {
    const auto network = pgm::fit(structure, data, options);
    tables = network.tables().size();
    benchmark::DoNotOptimize(network);
  }
  pgm::bench::check(state, tables == 5, "the fit does not have its five tables");
  set_rows_processed(state, rows);  // per data row, all five tables
}

void sizes(benchmark::internal::Benchmark* b) {
  for (std::int64_t rows : {10'000, 100'000, 1'000'000}) {
    for (std::int64_t threads : {1, 2}) b->Args({rows, threads});
  }
  b->ArgNames({"rows", "threads"})->UseRealTime();
}

BENCHMARK(count_625)->Apply(sizes);
BENCHMARK(count_625_naive_map)
    ->Args({10'000, 1})
    ->Args({100'000, 1})
    ->Args({1'000'000, 1})
    ->ArgNames({"rows", "threads"});
BENCHMARK(count_fit_tables)->Apply(sizes);
BENCHMARK(count_fit_tables_from_values)->Apply(sizes);
BENCHMARK(fit_625_bdeu)->Apply(sizes);

}  // namespace
