// EM (pgm/learn/expectation_maximization.hpp) on alarm (37 variables, 509 parameters) from
// rows sampled from it with a fifth of the values removed at random: one iteration (the start's
// E-step, one M-step, the next E-step) at 10^3–10^5 rows, with the junction tree answering the
// E-step's queries beside the simple approach, variable elimination afresh per query; and a run
// to convergence. Reported as ns/row (lower is better) and rows/s. The check after the loop
// compares the two engines' log-likelihoods.

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <stdexcept>
#include <vector>

#include "check.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/inference/variable_elimination.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/learn/expectation_maximization.hpp"

namespace {

const pgm::bayesian_network& alarm() {
  static const auto network = pgm::read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / "alarm.bif");
  return network;
}

/// `rows` rows sampled from alarm, each value missing with probability 0.2.
const pgm::dataset& alarm_with_gaps(std::size_t rows) {
  static std::map<std::size_t, pgm::dataset> cache;
  auto [it, fresh] = cache.try_emplace(rows);
  if (!fresh) return it->second;
  const auto full = pgm::sample(alarm(), rows, 11);
  std::mt19937_64 random(rows);
  for (const auto& name : full.names()) {
    const auto& column = full.discrete(name);
    std::vector<std::uint8_t> codes(rows);
    std::size_t missing = 0;
    for (std::size_t row = 0; row < rows; ++row) {
      const bool gap = pgm::uniform01(random) < 0.2;
      codes[row] = gap ? pgm::missing_code<std::uint8_t> : static_cast<std::uint8_t>(column.code(row));
      missing += gap;
    }
    it->second.add(pgm::discrete_column(column.var(), pgm::code_vector(std::move(codes)), std::in_place, missing));
  }
  return it->second;
}

void set_rows_processed(benchmark::State& state, std::size_t rows) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rows));
  state.counters["ns/row"] = benchmark::Counter(static_cast<double>(state.iterations() * rows),
                                                benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

template <class Engine>
pgm::em_result one_iteration(std::size_t rows) {
  const pgm::em_options options{.max_iterations = 1, .threads = 1};
  return pgm::expectation_maximization<Engine>(alarm().structure(), alarm_with_gaps(rows), {}, options);
}

template <class Engine>
void em_iteration(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  static_cast<void>(alarm_with_gaps(rows));
  double log_likelihood = 0.0;
  for (auto _ : state) {
    auto result = one_iteration<Engine>(rows);
    log_likelihood = result.log_likelihood;
    benchmark::DoNotOptimize(result);
  }
  // Both engines answer the same queries: their log-likelihoods agree.
  const double reference = one_iteration<pgm::junction_tree_engine<>>(rows).log_likelihood;
  if (std::abs(log_likelihood - reference) > 1e-6 * std::abs(reference)) {
    throw std::runtime_error("the engines disagree on the log-likelihood");
  }
  set_rows_processed(state, rows);
}

void em_iteration_jt(benchmark::State& state) { em_iteration<pgm::junction_tree_engine<>>(state); }
void em_iteration_ve_simple(benchmark::State& state) { em_iteration<pgm::variable_elimination<>>(state); }

void em_to_convergence(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = alarm_with_gaps(rows);
  const pgm::em_options options{.tolerance = 1e-6, .max_iterations = 200, .threads = 1};
  std::size_t iterations = 0;
  bool converged = false;
  for (auto _ : state) {
    auto result = pgm::expectation_maximization(alarm().structure(), data, {}, options);
    iterations = result.iterations;
    converged = result.converged && std::isfinite(result.log_likelihood);
    benchmark::DoNotOptimize(result);
  }
  pgm::bench::check(state, converged, "EM did not converge to a finite log-likelihood");
  state.counters["iterations"] = static_cast<double>(iterations);
  set_rows_processed(state, rows);
}

BENCHMARK(em_iteration_jt)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(em_iteration_ve_simple)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(em_to_convergence)->Arg(10000)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
