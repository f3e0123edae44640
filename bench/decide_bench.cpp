// Failure prevention over every configuration of a 625-configuration table (onTop2 of
// 2-Stack: 4 parents × 5 bins, binary), beside a plain breadth-first search from each
// configuration; exact inference by variable elimination beside brute-force enumeration; and
// influence diagrams solved beside enumeration of every policy (the oil wildcatter) and beside
// single policy updating that evaluates every candidate action by a pass of its own (a robot's
// 20-decision LIMID); and prevention during a task of several steps by one junction tree beside
// variable elimination for each setting.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "check.hpp"
#include "pgm/causal/counterfactual.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/decide/prevent.hpp"
#include "pgm/decide/prevent_by_utility.hpp"
#include "pgm/decide/prevent_over_time.hpp"
#include "pgm/decide/solve_decisions.hpp"
#include "pgm/inference/variable_elimination.hpp"
#include "pgm/testing/random_network.hpp"
#include "support/enumeration.hpp"
#include "support/influence_diagrams.hpp"
#include "support/random_dynamic_network.hpp"

namespace {

/// P(success | offsets) high near the centre, as in stacking, with noise; `scale` < 1 makes
/// fewer configurations exceed ε (longer searches).
pgm::cpt<double> stacking_table(double scale) {
  std::vector<pgm::variable> parents;
  for (const char* name : {"xOff1", "yOff1", "xOff2", "yOff2"}) {
    parents.push_back(pgm::variable::intervals(name, {-3, -1.4, -0.4, 0.4, 1.4, 3}));
  }
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  std::vector<double> values;
  for (std::size_t u = 0; u < 625; ++u) {
    std::size_t rest = u;
    double off = 0;
    for (int d = 0; d < 4; ++d) {
      const auto digit = static_cast<double>(rest % 5);
      rest /= 5;
      off += std::abs(digit - 2.0);
    }
    const double p = std::clamp(scale * (1.0 - 0.16 * off) + noise(random), 0.0, 1.0);
    values.push_back(1 - p);
    values.push_back(p);
  }
  return pgm::cpt<double>(pgm::variable("onTop2", {"0", "1"}), parents, values);
}

const bool all_controllable[] = {true, true, true, true};

void set_configurations(benchmark::State& state) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * 625));
  state.counters["ns/config"] = benchmark::Counter(static_cast<double>(state.iterations() * 625),
                                                   benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// range(0): scale in percent (100: many above ε; 70: none above ε).
void prevent_625_steps(benchmark::State& state) {
  const auto table = stacking_table(static_cast<double>(state.range(0)) / 100.0);
  for (auto _ : state) benchmark::DoNotOptimize(pgm::prevention_targets(table, 1, all_controllable));
  set_configurations(state);
  if (pgm::prevention_targets(table, 1, all_controllable) !=
      pgm::testing::naive_prevention_targets(table, 1, all_controllable, 0.8)) {
    state.SkipWithError("prevention disagrees with the plain search");
  }
}
BENCHMARK(prevent_625_steps)->Arg(100)->Arg(85)->Arg(70)->Unit(benchmark::kMicrosecond);

void prevent_625_units(benchmark::State& state) {
  const auto table = stacking_table(static_cast<double>(state.range(0)) / 100.0);
  const pgm::prevention_options units{.epsilon = 0.8, .metric = pgm::prevention_options::distance::units};
  std::vector<std::size_t> targets;
  for (auto _ : state) {
    targets = pgm::prevention_targets(table, 1, all_controllable, units);
    benchmark::DoNotOptimize(targets);
  }
  // A target per configuration, each no worse than where it starts.
  bool no_worse = targets.size() == 625;
  for (std::size_t u = 0; u < targets.size(); ++u) {
    no_worse = no_worse && table.column(pgm::config_index(targets[u]))[1] >= table.column(pgm::config_index(u))[1];
  }
  pgm::bench::check(state, no_worse, "a prevention target is worse than its configuration");
  set_configurations(state);
}
BENCHMARK(prevent_625_units)->Arg(100)->Arg(85)->Arg(70)->Unit(benchmark::kMicrosecond);

// The obvious approach: a fresh breadth-first search from each configuration below ε.
void prevent_625_naive(benchmark::State& state) {
  const auto table = stacking_table(static_cast<double>(state.range(0)) / 100.0);
  std::vector<std::size_t> targets;
  for (auto _ : state) {
    targets = pgm::testing::naive_prevention_targets(table, 1, all_controllable, 0.8);
    benchmark::DoNotOptimize(targets);
  }
  pgm::bench::check(state, targets == pgm::prevention_targets(table, 1, all_controllable),
                    "the plain search disagrees with prevention");
  set_configurations(state);
}
BENCHMARK(prevent_625_naive)->Arg(100)->Arg(85)->Arg(70)->Unit(benchmark::kMicrosecond);

// Metric 3 with the table as its own truth (the oracle), uniform weights.
void prevention_rate_625(benchmark::State& state) {
  const auto table = stacking_table(1.0);
  const std::vector<double> weights(625, 1.0);
  double rate = -1.0;
  for (auto _ : state) {
    const double one = pgm::failure_prevention_rate(table, table, 1, all_controllable, weights);
    benchmark::DoNotOptimize(one);  // a const value: a double lvalue may come back garbled (score_search_bench)
    rate = one;
  }
  pgm::bench::check(state, rate >= 0.0 && rate <= 1.0, "the prevention rate is not a probability");
  set_configurations(state);
}
BENCHMARK(prevention_rate_625)->Unit(benchmark::kMicrosecond);

// range(0): nodes. Sachs-like: 3 states, up to 3 parents; query one node given two.
pgm::bayesian_network inference_network(std::int64_t nodes) {
  return pgm::testing::random_network(
      17, {.nodes = static_cast<std::size_t>(nodes), .max_parents = 3, .min_states = 3, .max_states = 3});
}

void variable_elimination(benchmark::State& state) {
  const auto net = inference_network(state.range(0));
  const auto n = static_cast<pgm::variable_id::rep>(net.size());
  const pgm::variable_id query[] = {pgm::variable_id(n - 1)};
  const pgm::observation observed[] = {{pgm::variable_id(0), pgm::state_index(1)},
                                       {pgm::variable_id(n / 2), pgm::state_index(2)}};
  for (auto _ : state) benchmark::DoNotOptimize(pgm::joint_with_evidence(net, query, observed));
  if (state.range(0) <= 11) {
    const auto expected = pgm::testing::enumerate_joint(net, query, observed);
    const auto got = pgm::joint_with_evidence(net, query, observed);
    for (std::size_t i = 0; i < expected.size(); ++i) {
      if (std::abs(expected[i] - got.values()[i]) > 1e-12) state.SkipWithError("VE disagrees with enumeration");
    }
  }
}
BENCHMARK(variable_elimination)->Arg(11)->Arg(30)->Arg(60)->Unit(benchmark::kMicrosecond);

void enumeration(benchmark::State& state) {
  const auto net = inference_network(state.range(0));
  const auto n = static_cast<pgm::variable_id::rep>(net.size());
  const pgm::variable_id query[] = {pgm::variable_id(n - 1)};
  const pgm::observation observed[] = {{pgm::variable_id(0), pgm::state_index(1)},
                                       {pgm::variable_id(n / 2), pgm::state_index(2)}};
  std::vector<double> joint;
  for (auto _ : state) {
    joint = pgm::testing::enumerate_joint(net, query, observed);
    benchmark::DoNotOptimize(joint);
  }
  const auto eliminated = pgm::joint_with_evidence(net, query, observed);
  bool same = joint.size() == eliminated.values().size();
  for (std::size_t i = 0; same && i < joint.size(); ++i) same = std::abs(joint[i] - eliminated.values()[i]) <= 1e-12;
  pgm::bench::check(state, same, "enumeration disagrees with VE");
}
BENCHMARK(enumeration)->Arg(11)->Unit(benchmark::kMillisecond);

void oil_wildcatter_solve(benchmark::State& state) {
  const auto diagram = pgm::testing::oil_wildcatter();
  double meu = 0;
  for (auto _ : state) {
    meu = pgm::solve_decisions(diagram).meu;
    benchmark::DoNotOptimize(meu);
  }
  pgm::bench::check(state, std::abs(meu - 22.5) < 1e-12, "the oil wildcatter's MEU is not 22.5");
}
BENCHMARK(oil_wildcatter_solve)->Unit(benchmark::kMicrosecond);

void oil_wildcatter_every_policy(benchmark::State& state) {
  const auto diagram = pgm::testing::oil_wildcatter();
  double meu = 0;
  for (auto _ : state) {
    meu = pgm::testing::best_over_every_policy(diagram, {});
    benchmark::DoNotOptimize(meu);
  }
  pgm::bench::check(state, std::abs(meu - 22.5) < 1e-12, "the oil wildcatter's MEU is not 22.5");
}
BENCHMARK(oil_wildcatter_every_policy)->Unit(benchmark::kMicrosecond);

// range(0): decisions.
void limid_single_policy_updating(benchmark::State& state) {
  const auto diagram = pgm::testing::robot_limid(static_cast<std::size_t>(state.range(0)));
  pgm::decision_solution solution;
  for (auto _ : state) solution = pgm::solve_decisions(diagram, {}, {.limited_memory = true});
  state.counters["rounds"] = static_cast<double>(solution.rounds);
  state.counters["eu"] = solution.meu;
  pgm::bench::check(state, solution.meu >= solution.start_expected_utility, "single policy updating lost utility");
}
BENCHMARK(limid_single_policy_updating)->Arg(20)->Unit(benchmark::kMillisecond);

/// Single policy updating done plainly: every candidate action of every configuration of every
/// decision is scored by evaluating the whole policy with it, until no change improves.
void limid_one_pass_per_candidate(benchmark::State& state) {
  const auto diagram = pgm::testing::robot_limid(static_cast<std::size_t>(state.range(0)));
  double eu = 0;
  std::size_t passes = 0;
  for (auto _ : state) {
    std::vector<pgm::decision_policy> policies;
    for (const auto d : diagram.decision_order())
      policies.push_back({d, diagram.parents(d), std::vector<std::size_t>(3, 0)});
    eu = pgm::expected_utility(diagram, policies);
    for (bool changed = true; changed;) {
      changed = false;
      for (auto& policy : policies) {
        for (auto& action : policy.actions) {
          for (std::size_t candidate = 0; candidate < 3; ++candidate) {
            const auto kept = action;
            action = candidate;
            const double tried = pgm::expected_utility(diagram, policies);
            ++passes;
            if (tried > eu + 1e-12 * std::max(1.0, std::abs(eu))) {
              eu = tried;
              changed = true;
            } else {
              action = kept;
            }
          }
        }
      }
    }
  }
  state.counters["passes"] = static_cast<double>(passes) / static_cast<double>(state.iterations());
  state.counters["eu"] = eu;
}
BENCHMARK(limid_one_pass_per_candidate)->Arg(20)->Unit(benchmark::kMillisecond);

// One plan, as `pgm prevent` decides it: the move of highest expected utility (an influence
// diagram of four decisions solved) beside the nearest move above ε (one breadth-first search).
void prevent_one_plan_by_utility(benchmark::State& state) {
  const auto table = stacking_table(0.85);
  const pgm::move_costs costs{.reward = 100, .cost = {{"xOff1", 2}, {"yOff1", 2}, {"xOff2", 2}, {"yOff2", 2}}};
  pgm::utility_move move;
  for (auto _ : state) {
    move = pgm::best_move(table, 1, 0, all_controllable, costs);
    benchmark::DoNotOptimize(move);
  }
  pgm::bench::check(state, move.success_probability > table(pgm::state_index(1), pgm::config_index(0)),
                    "the best move does not raise success");
}
BENCHMARK(prevent_one_plan_by_utility)->Unit(benchmark::kMicrosecond);

// The same plan through its influence diagram, built and solved as any diagram: the general
// route best_move's scan of the slice stands in for.
void prevent_one_plan_by_its_diagram(benchmark::State& state) {
  const auto table = stacking_table(0.85);
  const pgm::move_costs costs{.reward = 100, .cost = {{"xOff1", 2}, {"yOff1", 2}, {"xOff2", 2}, {"yOff2", 2}}};
  double meu = 0;
  for (auto _ : state) {
    meu = pgm::solve_decisions(pgm::prevention_diagram(table, 1, 0, all_controllable, costs)).meu;
    benchmark::DoNotOptimize(meu);
  }
  pgm::bench::check(state,
                    std::abs(meu - pgm::best_move(table, 1, 0, all_controllable, costs).expected_utility) <= 1e-9,
                    "the diagram and the scan disagree");
}
BENCHMARK(prevent_one_plan_by_its_diagram)->Unit(benchmark::kMicrosecond);

// Every configuration of the 625-parameter table by expected utility, as the experiment scores
// an estimate (best_moves: each slice's members found once), beside best_move one plan at a time.
const pgm::move_costs stacking_costs{.reward = 1,
                                     .cost = {{"xOff1", 0.01}, {"yOff1", 0.01}, {"xOff2", 0.01}, {"yOff2", 0.01}}};

void prevent_whole_table_by_utility(benchmark::State& state) {
  const auto table = stacking_table(0.85);
  std::vector<pgm::utility_move> moves;
  for (auto _ : state) {
    moves = pgm::best_moves(table, 1, all_controllable, stacking_costs);
    benchmark::DoNotOptimize(moves.data());
  }
  pgm::bench::check(state, moves.size() == table.configurations(), "a move per configuration");
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(table.configurations()));
}
BENCHMARK(prevent_whole_table_by_utility)->Unit(benchmark::kMillisecond);

void prevent_whole_table_one_plan_at_a_time(benchmark::State& state) {
  const auto table = stacking_table(0.85);
  double total = 0;
  for (auto _ : state) {
    total = 0;
    for (std::size_t u = 0; u < table.configurations(); ++u) {
      total += pgm::best_move(table, 1, u, all_controllable, stacking_costs).expected_utility;
    }
    benchmark::DoNotOptimize(total);
  }
  double expected = 0;
  for (const auto& move : pgm::best_moves(table, 1, all_controllable, stacking_costs)) {
    expected += move.expected_utility;
  }
  pgm::bench::check(state, std::abs(total - expected) <= 1e-9 * std::abs(expected), "the two disagree");
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(table.configurations()));
}
BENCHMARK(prevent_whole_table_one_plan_at_a_time)->Unit(benchmark::kMillisecond);

void prevent_one_plan_by_epsilon(benchmark::State& state) {
  const auto table = stacking_table(0.85);
  std::size_t target = 0;
  for (auto _ : state) {
    target = pgm::prevention_target(table, 1, 0, all_controllable, {.epsilon = 0.8});
    benchmark::DoNotOptimize(target);
  }
  pgm::bench::check(state, target != 0, "prevention stayed");
}
BENCHMARK(prevent_one_plan_by_epsilon)->Unit(benchmark::kMicrosecond);

// Had a failed run of the plan been moved to the centre, would it have stood? The counterfactual
// on the twin network of the 625-configuration table read as monotone (626 noise states), beside
// abduction, action and prediction over the noise by hand.
pgm::bayesian_network stacking_network() {
  auto table = stacking_table(0.85);
  std::vector<pgm::cpt<double>> tables;
  for (const auto& parent : table.parents()) tables.emplace_back(parent, std::vector<pgm::variable>{});
  tables.push_back(std::move(table));
  return pgm::bayesian_network::from_tables(std::move(tables));
}

const pgm::evidence failed_plan{{"xOff1", "0"}, {"yOff1", "0"}, {"xOff2", "0"}, {"yOff2", "0"}, {"onTop2", "0"}};
const pgm::intervention centred{{"xOff1", "2"}, {"yOff1", "2"}, {"xOff2", "2"}, {"yOff2", "2"}};

void counterfactual_twin_625(benchmark::State& state) {
  const auto network = stacking_network();
  const std::string asked[] = {"onTop2"};
  double stood = 0;
  for (auto _ : state) {
    stood = pgm::monotone_counterfactual_query(network, asked, failed_plan, centred).probability({"1"});
    benchmark::DoNotOptimize(stood);
  }
  pgm::bench::check(state, stood > 0.5, "the centre would not have saved it");
}
BENCHMARK(counterfactual_twin_625)->Unit(benchmark::kMicrosecond);

void counterfactual_by_hand_625(benchmark::State& state) {
  const auto network = stacking_network();
  double stood = 0;
  for (auto _ : state) {
    const auto model = pgm::monotone_structural_model(network);
    const auto on_top = model.id("onTop2");
    const auto& noise = model.equation(on_top).noise;
    const std::size_t planned = 0;
    const std::size_t centre = 2 * (125 + 25 + 5 + 1);
    double failed = 0;
    double saved = 0;
    for (std::size_t k = 0; k < noise.size(); ++k) {
      if (model.value(on_top, planned, k) != 0) continue;
      failed += noise[k];
      if (model.value(on_top, centre, k) == 1) saved += noise[k];
    }
    stood = saved / failed;
    benchmark::DoNotOptimize(stood);
  }
  pgm::bench::check(state, stood > 0.5, "the centre would not have saved it");
}
BENCHMARK(counterfactual_by_hand_625)->Unit(benchmark::kMicrosecond);

}  // namespace

namespace {

/// A 6-variable random 2-TBN, two steps seen, the next of `horizon` steps decided over v0 … v3.
pgm::prevention_over_time_request tower_request(const pgm::dynamic_network& model, std::size_t horizon) {
  pgm::prevention_over_time_request request;
  request.success = {model.variables()[5].name(), model.variables()[5].states()[0]};
  request.controllable = {pgm::variable_id(0), pgm::variable_id(1), pgm::variable_id(2), pgm::variable_id(3)};
  request.horizon = horizon;
  request.steps.resize(2);
  for (auto& step : request.steps) step.hard = {{pgm::variable_id(5), pgm::state_index(0)}};
  return request;
}

}  // namespace

/// pgm::prevent_over_time: one junction tree of the unrolled network, two propagations a setting.
void prevent_over_time_jt(benchmark::State& state) {
  const auto model = pgm::testing::random_dynamic(7, 6);
  const auto request = tower_request(model, static_cast<std::size_t>(state.range(0)));
  pgm::prevention_over_time answer;
  for (auto _ : state) answer = pgm::prevent_over_time(model, request);
  state.counters["after"] = answer.after;
  pgm::bench::check(state, answer.after >= answer.before - 1e-15, "the best setting lost probability");
}
BENCHMARK(prevent_over_time_jt)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);

/// The same answer done plainly: variable elimination of the unrolled network for each setting's
/// two probabilities, nothing kept between them.
void prevent_over_time_elimination(benchmark::State& state) {
  const auto model = pgm::testing::random_dynamic(7, 6);
  const auto request = tower_request(model, static_cast<std::size_t>(state.range(0)));
  const auto horizon = request.horizon;
  const auto unrolled = model.unroll(horizon);
  const auto at = [&](std::size_t v, std::size_t t) {
    return unrolled.id(model.variables()[v].name() + "@" + std::to_string(t));
  };
  pgm::variable_elimination<> engine(unrolled);
  double best = 0.0;
  for (auto _ : state) {
    best = 0.0;
    std::vector<std::size_t> cards;
    for (std::size_t v = 0; v < 4; ++v) cards.push_back(model.variables()[v].cardinality());
    const pgm::mixed_radix settings(cards);
    for (std::size_t c = 0; c < settings.size(); ++c) {
      const auto states = settings.decode(c);
      pgm::evidence_set given;
      for (std::size_t t = 0; t < 2; ++t) given.hard.push_back({at(5, t), pgm::state_index(0)});
      for (std::size_t v = 0; v < 4; ++v) {
        given.intervened.push_back({at(v, 2), pgm::index_at<pgm::state_index>(states[v])});
      }
      engine.set_evidence(given);
      const double episode = engine.log_probability_of_evidence();
      for (std::size_t t = 2; t < horizon; ++t) given.hard.push_back({at(5, t), pgm::state_index(0)});
      engine.set_evidence(given);
      best = std::max(best, std::exp(engine.log_probability_of_evidence() - episode));
    }
  }
  const auto answer = pgm::prevent_over_time(model, request);
  pgm::bench::check(state, std::abs(best - answer.after) < 1e-12, "elimination and the junction tree disagree");
}
BENCHMARK(prevent_over_time_elimination)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
