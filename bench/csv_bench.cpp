// Reading CSV at memory speed: a 10^6-row file of six columns of small integer codes (the shape of
// discretized stacking data), parsed into a data set (MB/s) and counted as `pgm fit` counts it
// (ns/row), beside a copy of the same bytes (the machine's memory speed) and the simple approach:
// getline, split into strings, a std::map keyed by the configuration.
// Run: build/bench/bench_csv (--benchmark_filter=count for the counters only).

#include <benchmark/benchmark.h>

#include <cstring>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "check.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/csv_counts.hpp"

namespace {

constexpr std::size_t million = 1'000'000;

/// xOff1..yOff2 uniform on 0..4, onTop1 and onTop2 functions of them, as CSV text.
const std::string& codes_csv(std::size_t rows) {
  static std::map<std::size_t, std::string> cache;
  auto [it, fresh] = cache.try_emplace(rows);
  if (!fresh) return it->second;
  std::mt19937_64 random(rows);
  auto& text = it->second;
  text = "xOff1,yOff1,xOff2,yOff2,onTop1,onTop2\n";
  for (std::size_t row = 0; row < rows; ++row) {
    const auto a = random() % 5, b = random() % 5, c = random() % 5, d = random() % 5;
    for (auto v : {a, b, c, d, std::uint64_t{a + b < 7}, std::uint64_t{a + b + c + d < 12}}) {
      text += static_cast<char>('0' + v);
      text += ',';
    }
    text.back() = '\n';
  }
  return text;
}

void set_bytes_and_rows(benchmark::State& state, std::size_t bytes, std::size_t rows) {
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
  state.counters["ns/row"] = benchmark::Counter(static_cast<double>(state.iterations() * rows),
                                                benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// The machine's memory speed on the same bytes.
void copy_bytes(benchmark::State& state) {
  const auto& text = codes_csv(million);
  std::string copy(text.size(), '\0');
  for (auto _ : state) {
    std::memcpy(copy.data(), text.data(), text.size());
    benchmark::ClobberMemory();
  }
  pgm::bench::check(state, copy == text, "the copy differs");
  set_bytes_and_rows(state, text.size(), million);
}

// read_csv's parser: the whole data set in memory.
void parse_dataset(benchmark::State& state) {
  const auto& text = codes_csv(million);
  const pgm::csv_options options{.default_kind = pgm::column_kind::discrete,
                                 .threads = static_cast<unsigned>(state.range(0))};
  std::size_t rows = 0;
  for (auto _ : state) {
    const auto data = pgm::parse_csv(text, "bench.csv", options);
    rows = data.rows();
    benchmark::DoNotOptimize(data);
  }
  pgm::bench::check(state, rows == million, "the data set lost rows");
  set_bytes_and_rows(state, text.size(), million);
}

// pgm fit's counter: the two families of the stacking network, never holding the data.
void count_families(benchmark::State& state) {
  const auto& text = codes_csv(million);
  pgm::family_count_request request;
  request.columns = {"xOff1", "yOff1", "xOff2", "yOff2", "onTop1", "onTop2"};
  request.families = {{"onTop1", {"xOff1", "yOff1"}}, {"onTop2", {"xOff1", "yOff1", "xOff2", "yOff2"}}};
  request.threads = static_cast<unsigned>(state.range(0));
  pgm::family_counts counts;
  for (auto _ : state) {
    pgm::csv_reader input(text, "bench.csv");
    counts = pgm::count_csv(input, request);
    benchmark::DoNotOptimize(counts);
  }
  pgm::bench::check(
      state,
      counts.families.size() == 2 && counts.families[0].total() == million && counts.families[1].total() == million,
      "the counts do not add up to the rows");
  set_bytes_and_rows(state, text.size(), million);
}

/// codes_csv with every 20th row's xOff2 missing ("NA").
const std::string& codes_csv_with_na(std::size_t rows) {
  static std::map<std::size_t, std::string> cache;
  auto [it, fresh] = cache.try_emplace(rows);
  if (!fresh) return it->second;
  const auto& text = codes_csv(rows);
  auto& out = it->second;
  std::size_t row = 0;
  for (std::size_t at = 0, end; at < text.size(); at = end + 1, ++row) {
    end = text.find('\n', at);
    const auto line = std::string_view(text).substr(at, end - at);
    if (row > 0 && row % 20 == 0) {
      out += std::string(line.substr(0, 4)) + "NA" + std::string(line.substr(5));  // the third field
    } else {
      out += line;
    }
    out += '\n';
  }
  return out;
}

// The counter under a missing-value policy on data with 5% of the rows missing a value:
// range(0) 0 = drop, 1 = available (each family over its present rows).
void count_families_missing(benchmark::State& state) {
  const auto& text = codes_csv_with_na(million);
  pgm::family_count_request request;
  request.columns = {"xOff1", "yOff1", "xOff2", "yOff2", "onTop1", "onTop2"};
  request.families = {{"onTop1", {"xOff1", "yOff1"}}, {"onTop2", {"xOff1", "yOff1", "xOff2", "yOff2"}}};
  request.threads = 1;
  request.missing.policy = state.range(0) == 0 ? pgm::missing_policy::drop : pgm::missing_policy::available;
  pgm::family_counts counts;
  for (auto _ : state) {
    pgm::csv_reader input(text, "bench.csv");
    counts = pgm::count_csv(input, request);
    benchmark::DoNotOptimize(counts);
  }
  // The result: onTop1 counts every row either way, onTop2 only the 95% present.
  const auto total = [](const pgm::count_table& t) {
    std::uint64_t n = 0;
    for (auto c : t.counts()) n += c;
    return n;
  };
  const std::uint64_t expected_top1 = state.range(0) == 0 ? million - million / 20 : million;
  if (total(counts.families[0]) != expected_top1 || total(counts.families[1]) != million - million / 20) {
    state.SkipWithError("wrong counts");
  }
  set_bytes_and_rows(state, text.size(), million);
}

// The simple approach: a line at a time, split into strings, configurations counted in a map.
void count_families_naive(benchmark::State& state) {
  const auto& text = codes_csv(million);
  std::size_t counted = 0;
  for (auto _ : state) {
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    std::map<std::vector<std::string>, std::size_t> onTop1, onTop2;
    std::vector<std::string> fields;
    while (std::getline(in, line)) {
      fields.clear();
      std::stringstream split(line);
      std::string field;
      while (std::getline(split, field, ',')) fields.push_back(field);
      ++onTop1[{fields[4], fields[0], fields[1]}];
      ++onTop2[{fields[5], fields[0], fields[1], fields[2], fields[3]}];
    }
    counted = 0;
    for (const auto& [configuration, n] : onTop2) counted += n;
    benchmark::DoNotOptimize(onTop1);
    benchmark::DoNotOptimize(onTop2);
  }
  pgm::bench::check(state, counted == million, "the counts do not add up to the rows");
  set_bytes_and_rows(state, text.size(), million);
}

BENCHMARK(copy_bytes)->Unit(benchmark::kMillisecond);
BENCHMARK(parse_dataset)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(count_families)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(count_families_missing)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(count_families_naive)->Unit(benchmark::kMillisecond);

}  // namespace
