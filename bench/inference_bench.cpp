// The inference engines on the published networks (tests/data/networks), model loaded and
// engine compiled outside the timed loop: one query under 0–3 observed variables (a fixed,
// seeded mix drawn once), do-queries beside the same queries on the mutilated network, every
// marginal under ten observations, the most probable explanation, and likelihood weighting;
// each beside the simple approach — variable elimination afresh per query, or per variable for
// all marginals. Each check after the loop compares the answers with variable elimination.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "check.hpp"
#include "pgm/causal/intervention.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/inference/dynamic_inference.hpp"
#include "pgm/inference/engine_registry.hpp"
#include "pgm/io/bif.hpp"

namespace {

const std::vector<std::string> networks = {"asia", "child", "insurance", "alarm", "hailfinder", "pathfinder"};

const pgm::bayesian_network& network(std::size_t index) {
  static std::map<std::size_t, pgm::bayesian_network> loaded;
  auto it = loaded.find(index);
  if (it == loaded.end()) {
    const auto path = std::filesystem::path(PGM_NETWORKS_DIR) / (networks[index] + ".bif");
    it = loaded.emplace(index, pgm::read_bif(path)).first;
  }
  return it->second;
}

struct single_query {
  pgm::variable_id query;
  pgm::evidence_set observed;
};

/// 256 queries of one variable, a quarter each under 0, 1, 2 and 3 observed variables, drawn
/// by a fixed seed and kept only where the evidence is possible.
const std::vector<single_query>& query_mix(std::size_t index) {
  static std::map<std::size_t, std::vector<single_query>> mixes;
  auto it = mixes.find(index);
  if (it != mixes.end()) return it->second;
  const auto& net = network(index);
  std::mt19937_64 random(7);
  pgm::variable_elimination ve(net);
  std::vector<single_query> mix;
  while (mix.size() < 256) {
    single_query q;
    q.query = pgm::index_at<pgm::variable_id>(random() % net.size());
    const auto observed = mix.size() % 4;
    while (q.observed.hard.size() < observed) {
      const auto v = pgm::index_at<pgm::variable_id>(random() % net.size());
      if (v == q.query || q.observed.fixes(v)) continue;
      const auto states = net.variables()[v.value()].cardinality();
      q.observed.hard.push_back({v, pgm::index_at<pgm::state_index>(random() % states)});
    }
    ve.set_evidence(q.observed);
    try {
      const pgm::variable_id one[] = {q.query};
      static_cast<void>(ve.joint(one));
      mix.push_back(std::move(q));
    } catch (const pgm::impossible_evidence&) {
    }
  }
  return mixes.emplace(index, std::move(mix)).first->second;
}

void check_against_elimination(benchmark::State& state, pgm::any_inference_engine& engine, std::size_t index) {
  pgm::variable_elimination ve(network(index));
  for (const auto& q : query_mix(index)) {
    const pgm::variable_id one[] = {q.query};
    engine.set_evidence(q.observed);
    ve.set_evidence(q.observed);
    const auto a = engine.joint(one);
    const auto b = ve.joint(one);
    for (std::size_t k = 0; k < a.table.size(); ++k) {
      if (std::abs(a.table.values()[k] - b.table.values()[k]) > 1e-12) {
        state.SkipWithError("an answer differs from variable elimination's");
        return;
      }
    }
  }
}

// range(0): the network; the engine by name in the benchmark's name.
void single_queries(benchmark::State& state, const char* engine_name) {
  const auto index = static_cast<std::size_t>(state.range(0));
  auto engine = pgm::make_engine(engine_name, network(index));
  const auto& mix = query_mix(index);
  std::size_t next = 0;
  for (auto _ : state) {
    const auto& q = mix[next++ % mix.size()];
    engine.set_evidence(q.observed);
    const pgm::variable_id one[] = {q.query};
    benchmark::DoNotOptimize(engine.joint(one));
  }
  state.SetLabel(networks[index]);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  check_against_elimination(state, engine, index);
}
BENCHMARK_CAPTURE(single_queries, jt, "jt")->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(single_queries, ve, "ve")->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);

/// do(X = first state) for the variable with the most parents (the first such), and the
/// query mix without X, kept where its evidence stays possible under the intervention.
struct do_mix {
  pgm::observation set;
  std::vector<single_query> queries;
};

const do_mix& intervention_mix(std::size_t index) {
  static std::map<std::size_t, do_mix> mixes;
  auto it = mixes.find(index);
  if (it != mixes.end()) return it->second;
  const auto& net = network(index);
  do_mix mix;
  std::size_t most = 0;
  for (std::size_t v = 0; v < net.size(); ++v) {
    const auto id = pgm::index_at<pgm::variable_id>(v);
    if (net.graph().parents(id).size() > most) {
      most = net.graph().parents(id).size();
      mix.set = {id, pgm::state_index(0)};
    }
  }
  pgm::variable_elimination ve(net);
  for (auto q : query_mix(index)) {
    if (q.query == mix.set.variable || q.observed.fixes(mix.set.variable)) continue;
    q.observed.intervened = {mix.set};
    ve.set_evidence(q.observed);
    if (std::isfinite(ve.log_probability_of_evidence())) mix.queries.push_back(std::move(q));
  }
  return mixes.emplace(index, std::move(mix)).first->second;
}

// A do-query against the same query on the mutilated network, compiled once
// (pgm::intervene): the surgery is a view, so the first should cost no more than the second.
void do_queries(benchmark::State& state, const char* engine_name, bool on_mutilated) {
  const auto index = static_cast<std::size_t>(state.range(0));
  const auto& mix = intervention_mix(index);
  const auto& net = network(index);
  const auto& x = net.variables()[mix.set.variable.value()];
  const auto mutilated = pgm::intervene(net, {{x.name(), x.states()[mix.set.state.value()]}});
  auto engine = pgm::make_engine(engine_name, on_mutilated ? mutilated : net);
  auto plain = [&](pgm::evidence_set e) {
    if (on_mutilated) e.intervened.clear();
    return e;
  };
  std::size_t next = 0;
  for (auto _ : state) {
    const auto& q = mix.queries[next++ % mix.queries.size()];
    engine.set_evidence(plain(q.observed));
    const pgm::variable_id one[] = {q.query};
    benchmark::DoNotOptimize(engine.joint(one));
  }
  state.SetLabel(networks[index] + ", do(" + x.name() + ")");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  pgm::variable_elimination check(mutilated);
  for (const auto& q : mix.queries) {
    const pgm::variable_id one[] = {q.query};
    engine.set_evidence(plain(q.observed));
    auto e = q.observed;
    e.intervened.clear();
    check.set_evidence(e);
    const auto a = engine.joint(one);
    const auto b = check.joint(one);
    for (std::size_t k = 0; k < a.table.size(); ++k) {
      if (std::abs(a.table.values()[k] - b.table.values()[k]) > 1e-12) {
        state.SkipWithError("a do-query differs from the query on the mutilated network");
        return;
      }
    }
  }
}
BENCHMARK_CAPTURE(do_queries, jt, "jt", false)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(do_queries, jt_on_mutilated, "jt", true)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(do_queries, ve, "ve", false)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(do_queries, ve_on_mutilated, "ve", true)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);

/// Ten observations spread over the network (the first state of every tenth variable; a
/// quarter of the variables for a small network), each kept only where the evidence stays possible.
pgm::evidence_set ten_observations(std::size_t index) {
  const auto& net = network(index);
  pgm::variable_elimination ve(net);
  pgm::evidence_set observed;
  const auto wanted = std::min<std::size_t>(10, net.size() / 4);
  for (std::size_t v = 0; v < net.size() && observed.hard.size() < wanted; v += 1 + net.size() / 10) {
    auto trial = observed;
    trial.hard.push_back({pgm::index_at<pgm::variable_id>(v), pgm::state_index(0)});
    ve.set_evidence(trial);
    if (std::isfinite(ve.log_probability_of_evidence())) observed = std::move(trial);
  }
  return observed;
}

std::vector<pgm::variable_id> unobserved(std::size_t index, const pgm::evidence_set& observed) {
  std::vector<pgm::variable_id> ids;
  for (std::size_t v = 0; v < network(index).size(); ++v) {
    const auto id = pgm::index_at<pgm::variable_id>(v);
    if (!observed.fixes(id)) ids.push_back(id);
  }
  return ids;
}

// Fails the run unless `marginals` (of the unobserved variables, in order) are within `tolerance`
// of the junction tree's, compiled afresh.
void check_marginals(benchmark::State& state, const std::vector<pgm::posterior>& marginals, std::size_t index,
                     const pgm::evidence_set& observed, double tolerance) {
  pgm::junction_tree_engine exact(network(index));
  exact.set_evidence(observed);
  const auto free = unobserved(index, observed);
  const auto expected = exact.marginals(free);
  bool close = marginals.size() == expected.size();
  for (std::size_t k = 0; close && k < expected.size(); ++k) {
    const auto a = marginals[k].table.values();
    const auto b = expected[k].table.values();
    close = a.size() == b.size();
    for (std::size_t s = 0; close && s < a.size(); ++s) close = std::abs(a[s] - b[s]) <= tolerance;
  }
  pgm::bench::check(state, close, "a marginal differs from the junction tree's");
}

// Every marginal under ten observations: one propagation (set_evidence retracts and enters
// the evidence anew each time, so nothing is kept from the last iteration).
void all_marginals_jt(benchmark::State& state) {
  const auto index = static_cast<std::size_t>(state.range(0));
  pgm::junction_tree_engine jt(network(index));
  const auto observed = ten_observations(index);
  const auto free = unobserved(index, observed);
  std::vector<pgm::posterior> marginals;
  for (auto _ : state) {
    jt.set_evidence({});
    benchmark::DoNotOptimize(jt.log_probability_of_evidence());
    jt.set_evidence(observed);
    marginals = jt.marginals(free);
    benchmark::DoNotOptimize(marginals);
  }
  state.SetLabel(networks[index] + ", " + std::to_string(free.size()) + " marginals");
  check_marginals(state, marginals, index, observed, 1e-9);
}
BENCHMARK(all_marginals_jt)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);

// The simple approach: variable elimination once per variable.
void all_marginals_ve(benchmark::State& state) {
  const auto index = static_cast<std::size_t>(state.range(0));
  pgm::variable_elimination ve(network(index));
  const auto observed = ten_observations(index);
  const auto free = unobserved(index, observed);
  ve.set_evidence(observed);
  std::vector<pgm::posterior> marginals;
  for (auto _ : state) {
    marginals.clear();
    for (auto id : free) {
      const pgm::variable_id one[] = {id};
      marginals.push_back(ve.joint(one));
    }
    benchmark::DoNotOptimize(marginals);
  }
  state.SetLabel(networks[index] + ", " + std::to_string(free.size()) + " marginals");
  check_marginals(state, marginals, index, observed, 1e-9);
}
BENCHMARK(all_marginals_ve)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);

// The most probable explanation with no evidence, by max-product on the tree and by variable
// elimination with traceback.
void mpe(benchmark::State& state, const char* engine_name) {
  const auto index = static_cast<std::size_t>(state.range(0));
  auto engine = pgm::make_engine(engine_name, network(index));
  for (auto _ : state) {
    engine.set_evidence({});
    benchmark::DoNotOptimize(engine.mpe({}));
  }
  state.SetLabel(networks[index]);
  pgm::variable_elimination ve(network(index));
  const auto a = engine.mpe({});
  const auto b = ve.mpe({});
  if (std::abs(a.log_joint_probability - b.log_joint_probability) > 1e-9) {
    state.SkipWithError("the most probable explanation differs from variable elimination's");
  }
}
BENCHMARK_CAPTURE(mpe, jt, "jt")->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(mpe, ve, "ve")->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);

// Likelihood weighting: every marginal under two observations, 10^5 samples, in samples/s.
void likelihood_weighting_samples(benchmark::State& state) {
  const auto index = static_cast<std::size_t>(state.range(0));
  const auto threads = static_cast<unsigned>(state.range(1));
  pgm::likelihood_weighting lw(network(index), {.samples = 100'000, .seed = 1, .threads = threads});
  auto observed = ten_observations(index);
  observed.hard.resize(std::min<std::size_t>(2, observed.hard.size()));
  lw.set_evidence(observed);
  const auto free = unobserved(index, observed);
  std::vector<pgm::posterior> marginals;
  for (auto _ : state) {
    marginals = lw.marginals(free);
    benchmark::DoNotOptimize(marginals);
  }
  state.SetLabel(networks[index] + ", " + std::to_string(threads) + " thread(s)");
  check_marginals(state, marginals, index, observed, 0.05);  // 10^5 samples: within 0.05 of exact
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * 100'000));
}
BENCHMARK(likelihood_weighting_samples)
    ->Args({3, 1})
    ->Args({3, 2})
    ->Args({5, 1})
    ->Args({5, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

namespace {

// A 2-TBN of a chain tied across slices: x_k depends on x_k and x_(k−1) one slice back, and on
// x_(k−1) in its slice; 5 variables of 3 states, all of them in the interface.
pgm::dynamic_network chain_network() {
  const std::size_t n = 5;
  std::vector<pgm::variable> now;
  std::vector<pgm::variable> before;
  for (std::size_t k = 0; k < n; ++k) {
    now.emplace_back("x" + std::to_string(k), std::vector<std::string>{"lo", "mid", "hi"});
    before.push_back(pgm::detail::renamed(now.back(), pgm::slice_name(now.back().name(), -1)));
  }
  std::mt19937_64 engine(3);
  std::exponential_distribution<double> gamma1(1.0);
  const auto table = [&](const pgm::variable& child, std::vector<pgm::variable> parents) {
    pgm::cpt<double> shape(child, parents);
    std::vector<double> values(shape.size());
    for (std::size_t u = 0; u < shape.configurations(); ++u) {
      double sum = 0.0;
      for (std::size_t x = 0; x < 3; ++x) sum += values[3 * u + x] = gamma1(engine);
      for (std::size_t x = 0; x < 3; ++x) values[3 * u + x] /= sum;
    }
    return pgm::cpt<double>(child, std::move(parents), values);
  };
  std::vector<pgm::cpt<double>> first;
  std::vector<pgm::cpt<double>> transition;
  for (std::size_t k = 0; k < n; ++k) {
    first.push_back(k == 0 ? table(now[k], {}) : table(now[k], {now[k - 1]}));
    transition.push_back(k == 0 ? table(now[k], {before[k]}) : table(now[k], {now[k - 1], before[k], before[k - 1]}));
  }
  return pgm::dynamic_network(pgm::bayesian_network::from_tables(std::move(first)), std::move(transition));
}

// Filtering an episode of `steps` steps, x0 and x4 observed at every step: the time per step,
// flat in the horizon (the interface algorithm), beside the simple approach of the junction
// tree on the unrolled network (compiled once, outside the loop), for the horizons it reaches.
void filter_steps(benchmark::State& state) {
  const auto steps = static_cast<std::size_t>(state.range(0));
  const auto model = chain_network();
  std::vector<pgm::evidence_set> episode(steps);
  std::mt19937_64 engine(5);
  for (auto& e : episode) {
    for (pgm::variable_id::rep k : {0U, 4U}) {
      e.hard.push_back({pgm::variable_id(k), pgm::index_at<pgm::state_index>(engine() % 3)});
    }
  }
  pgm::interface_filter filter(model);
  pgm::dynamic_marginals answer;
  for (auto _ : state) {
    answer = filter.filter(episode);
    benchmark::DoNotOptimize(answer);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * steps));
  state.counters["per_step"] = benchmark::Counter(
      static_cast<double>(steps), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  // The last step's marginal of x3 against the unrolled network's (small horizons only).
  if (steps <= 50) {
    const auto unrolled = model.unroll(steps);
    pgm::junction_tree_engine exact(unrolled);
    pgm::evidence_set all;
    for (std::size_t t = 0; t < steps; ++t) {
      for (const auto& o : episode[t].hard) {
        all.hard.push_back(
            {unrolled.id(pgm::slice_name(model.variables()[o.variable.value()].name(), static_cast<long>(t))),
             o.state});
      }
    }
    exact.set_evidence(all);
    const pgm::variable_id x3[] = {unrolled.id(pgm::slice_name("x3", static_cast<long>(steps - 1)))};
    const auto expected = exact.joint(x3);
    bool close = true;
    for (std::size_t s = 0; s < 3; ++s)
      close = close && std::abs(expected.table.values()[s] - answer.steps.back()[3][s]) < 1e-9;
    pgm::bench::check(state, close, "the filtered marginal differs from the unrolled junction tree's");
  }
}
BENCHMARK(filter_steps)->Arg(10)->Arg(50)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

// The simple approach: the junction tree on the unrolled network (compiled once, outside the
// loop), every marginal under the whole episode's evidence in one propagation (filtering would
// take one per step). Its tree outgrows pgm's limit between 50 and 10,000 steps.
void filter_by_unrolling(benchmark::State& state) {
  const auto steps = static_cast<std::size_t>(state.range(0));
  const auto model = chain_network();
  const auto unrolled = model.unroll(steps);
  std::unique_ptr<pgm::junction_tree_engine<>> compiled;
  try {
    compiled = std::make_unique<pgm::junction_tree_engine<>>(unrolled);
  } catch (const pgm::table_too_large& e) {
    state.SkipWithError(e.what());  // the simple approach does not reach this horizon
    return;
  }
  auto& exact = *compiled;
  std::mt19937_64 engine(5);
  pgm::evidence_set all;
  for (std::size_t t = 0; t < steps; ++t) {
    for (pgm::variable_id::rep k : {0U, 4U}) {
      all.hard.push_back({unrolled.id(pgm::slice_name(model.variables()[k].name(), static_cast<long>(t))),
                          pgm::index_at<pgm::state_index>(engine() % 3)});
    }
  }
  const auto free = [&] {
    std::vector<pgm::variable_id> ids;
    for (std::size_t v = 0; v < unrolled.size(); ++v) {
      const auto id = pgm::index_at<pgm::variable_id>(v);
      if (!all.fixes(id)) ids.push_back(id);
    }
    return ids;
  }();
  std::vector<pgm::posterior> marginals;
  for (auto _ : state) {
    exact.set_evidence({});
    exact.set_evidence(all);
    marginals = exact.marginals(free);
    benchmark::DoNotOptimize(marginals);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * steps));
  pgm::bench::check(state, marginals.size() == free.size(), "a marginal is missing");
}
BENCHMARK(filter_by_unrolling)->Arg(10)->Arg(50)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
