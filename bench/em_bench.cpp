// EM (pgm/learn/expectation_maximization.hpp) on alarm (37 variables, 509 parameters) from
// rows sampled from it with a fifth of the values removed at random: one iteration (the start's
// E-step, one M-step, the next E-step) at 10^3–10^5 rows, with the junction tree answering the
// E-step's queries beside the simple approach, variable elimination afresh per query; and a run
// to convergence. Reported as ns/row (lower is better) and rows/s. The check after the loop
// compares the two engines' log-likelihoods.
//
// EM for a dynamic network (pgm/learn/dynamic_em.hpp) on a hidden Markov model (a latent state of
// 2 values, an observation of 3; episodes of 10 steps): one iteration per 10^3–10^4 episodes,
// beside Baum–Welch written out for this one model (scaled forward–backward), the floor a
// general engine is measured against. Reported per long-form row (ns/row); the check compares
// the two log-likelihoods.

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
#include "pgm/learn/dynamic_em.hpp"
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

// A hidden Markov model: H@-1 -> H, H -> O; rows / 10 episodes of 10 steps sampled from it.
constexpr std::size_t hmm_steps = 10;
const std::vector<double> hmm_pi{0.6, 0.4}, hmm_a{0.9, 0.1, 0.2, 0.8}, hmm_b{0.7, 0.2, 0.1, 0.1, 0.3, 0.6};

const pgm::dynamic_structure& hmm_structure() {
  static const auto structure = pgm::dynamic_structure_of(
      {pgm::variable("H", {"0", "1"}), pgm::variable("O", {"0", "1", "2"})}, pgm::parse_edge_list("H->O, H@-1->H"));
  return structure;
}

/// The observations, episode after episode.
const std::vector<std::uint8_t>& hmm_observations(std::size_t rows) {
  static std::map<std::size_t, std::vector<std::uint8_t>> cache;
  auto [it, fresh] = cache.try_emplace(rows);
  if (!fresh) return it->second;
  std::mt19937_64 random(rows);
  const auto draw = [&](const double* p, std::size_t n) {
    double u = pgm::uniform01(random);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      if ((u -= p[k]) < 0) return k;
    }
    return n - 1;
  };
  std::size_t h = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    h = r % hmm_steps == 0 ? draw(hmm_pi.data(), 2) : draw(&hmm_a[h * 2], 2);
    it->second.push_back(static_cast<std::uint8_t>(draw(&hmm_b[h * 3], 3)));
  }
  return it->second;
}

const pgm::dataset& hmm_episodes(std::size_t rows) {
  static std::map<std::size_t, pgm::dataset> cache;
  auto [it, fresh] = cache.try_emplace(rows, pgm::dataset("hmm.csv"));
  if (!fresh) return it->second;
  std::vector<double> episode(rows), t(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    episode[r] = static_cast<double>(r / hmm_steps);
    t[r] = static_cast<double>(r % hmm_steps);
  }
  it->second.add(pgm::continuous_column("episode", episode));
  it->second.add(pgm::continuous_column("t", t));
  const auto& o = hmm_observations(rows);
  it->second.add(pgm::discrete_column(hmm_structure().variables()[1], std::vector<unsigned>(o.begin(), o.end())));
  return it->second;
}

/// The start both EMs take: the truth, perturbed.
const pgm::dynamic_network& hmm_start() {
  static const auto model = [] {
    const auto& s = hmm_structure();
    const auto& h = s.variables()[0];
    const auto& o = s.variables()[1];
    const pgm::variable h_before("H@-1", h.states());
    const std::vector<double> b{0.5, 0.3, 0.2, 0.2, 0.3, 0.5};
    pgm::bayesian_network first(s.initial, {pgm::cpt<double>(h, {}, {0.5, 0.5}), pgm::cpt<double>(o, {h}, b)});
    return pgm::dynamic_network(std::move(first),
                                {pgm::cpt<double>(h, {h_before}, {0.7, 0.3, 0.4, 0.6}), pgm::cpt<double>(o, {h}, b)});
  }();
  return model;
}

void dynamic_em_iteration_hmm(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& data = hmm_episodes(rows);
  pgm::dynamic_em_options options;
  options.start = &hmm_start();
  options.em = {.max_iterations = 1, .threads = 1};
  double log_likelihood = 0.0;
  for (auto _ : state) {
    auto result = pgm::dynamic_expectation_maximization(hmm_structure(), data, {}, options);
    log_likelihood = result.log_likelihood;
    benchmark::DoNotOptimize(result);
  }
  pgm::bench::check(state, std::isfinite(log_likelihood), "the log-likelihood is not finite");
  state.counters["patterns"] = static_cast<double>(
      pgm::dynamic_expectation_maximization(hmm_structure(), data, {}, options).incomplete_patterns);
  set_rows_processed(state, rows);
}

/// One E-step of Baum–Welch for this model: expected counts of the first slice's and the tied
/// tables; returns ln P(observations). `m` holds pi (2), a (4), b0 (6), b (6).
double forward_backward(const std::vector<double>& m, const std::vector<std::uint8_t>& o, std::vector<double>& counts) {
  const double* pi = m.data();
  const double* a = pi + 2;
  const double* b0 = a + 4;
  const double* b = b0 + 6;
  std::fill(counts.begin(), counts.end(), 0.0);
  double log_likelihood = 0.0;
  double alpha[hmm_steps][2], beta[hmm_steps][2], scale[hmm_steps];
  for (std::size_t e = 0; e < o.size() / hmm_steps; ++e) {
    const auto* x = &o[e * hmm_steps];
    for (std::size_t t = 0; t < hmm_steps; ++t) {
      for (std::size_t h = 0; h < 2; ++h) {
        const double prior = t == 0 ? pi[h] : alpha[t - 1][0] * a[h] + alpha[t - 1][1] * a[2 + h];
        alpha[t][h] = prior * (t == 0 ? b0 : b)[h * 3 + x[t]];
      }
      scale[t] = alpha[t][0] + alpha[t][1];
      alpha[t][0] /= scale[t];
      alpha[t][1] /= scale[t];
      log_likelihood += std::log(scale[t]);
    }
    beta[hmm_steps - 1][0] = beta[hmm_steps - 1][1] = 1.0;
    for (std::size_t t = hmm_steps - 1; t-- > 0;) {
      for (std::size_t g = 0; g < 2; ++g) {
        beta[t][g] =
            (a[g * 2] * b[x[t + 1]] * beta[t + 1][0] + a[g * 2 + 1] * b[3 + x[t + 1]] * beta[t + 1][1]) / scale[t + 1];
      }
    }
    for (std::size_t t = 0; t < hmm_steps; ++t) {
      for (std::size_t h = 0; h < 2; ++h) {
        const double gamma = alpha[t][h] * beta[t][h];
        if (t == 0) {
          counts[h] += gamma;
          counts[6 + h * 3 + x[t]] += gamma;
          continue;
        }
        counts[12 + h * 3 + x[t]] += gamma;
        for (std::size_t g = 0; g < 2; ++g) {
          counts[2 + g * 2 + h] += alpha[t - 1][g] * a[g * 2 + h] * b[h * 3 + x[t]] * beta[t][h] / scale[t];
        }
      }
    }
  }
  return log_likelihood;
}

void baum_welch_iteration_by_hand(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const auto& o = hmm_observations(rows);
  const std::vector<double> start{0.5, 0.5, 0.7, 0.3, 0.4, 0.6, 0.5, 0.3, 0.2,
                                  0.2, 0.3, 0.5, 0.5, 0.3, 0.2, 0.2, 0.3, 0.5};
  std::vector<double> counts(18);
  double log_likelihood = 0.0;
  for (auto _ : state) {
    // As dynamic_em_iteration_hmm: the start's E-step, an M-step, the next E-step.
    auto m = start;
    static_cast<void>(forward_backward(m, o, counts));
    for (std::size_t begin : {0, 2, 4, 6, 9, 12, 15}) {
      const std::size_t width = begin < 6 ? 2 : 3;
      double sum = 0.0;
      for (std::size_t k = 0; k < width; ++k) sum += counts[begin + k];
      for (std::size_t k = 0; k < width; ++k) m[begin + k] = counts[begin + k] / sum;
    }
    log_likelihood = forward_backward(m, o, counts);
    benchmark::DoNotOptimize(log_likelihood);
  }
  pgm::dynamic_em_options options;
  options.start = &hmm_start();
  options.em = {.max_iterations = 1, .threads = 1};
  const double reference =
      pgm::dynamic_expectation_maximization(hmm_structure(), hmm_episodes(rows), {}, options).log_likelihood;
  pgm::bench::check(state, std::abs(log_likelihood - reference) <= 1e-9 * std::abs(reference),
                    "Baum-Welch by hand and pgm's EM disagree on the log-likelihood");
  set_rows_processed(state, rows);
}

BENCHMARK(em_iteration_jt)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(em_iteration_ve_simple)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(em_to_convergence)->Arg(10000)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK(dynamic_em_iteration_hmm)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(baum_welch_iteration_by_hand)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
