#pragma once
/// \file
/// The conformance kit of inference engines: a GoogleTest suite that holds an engine, chosen by
/// name from the registry as a user chooses it, to brute-force enumeration on random Bayesian
/// and Markov networks (hard and soft evidence, every marginal, P(evidence), evidence replaced),
/// and that checks a Markov network is refused by name where the engine does not serve one.
/// Instantiate it in one test source of a program that links GoogleTest:
///
///     #include <pgm/testing/engine_conformance.hpp>
///     using pgm::testing::engine_conformance;  // the macro takes the suite's name unqualified
///     INSTANTIATE_TEST_SUITE_P(mine, engine_conformance,
///                              ::testing::Values(pgm::testing::engine_case{"mine"}),
///                              pgm::testing::engine_case_name);
///
/// or over every engine registered when the tests are set up, with `registered_engine_cases`.
/// Everything is seeded: an engine passes or fails the same way every run.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/graphical_model.hpp"
#include "pgm/core/markov_network.hpp"
#include "pgm/inference/engine_registry.hpp"
#include "pgm/inference/exact.hpp"
#include "pgm/testing/case_names.hpp"
#include "pgm/testing/random_markov_network.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::testing {

/// One engine as the kit checks it.
struct engine_case {
  /// A choice the registry makes, options included: "bp[damping=0.5]".
  std::string engine;
  /// The largest difference from enumeration allowed in a probability (a sampler's is its error).
  double tolerance = 1e-12;
  /// False for an engine exact only on trees (loopy belief propagation): its models are trees.
  bool exact_on_loops = true;
  /// False for an engine that estimates no P(evidence) (Gibbs sampling) and may say so by
  /// throwing model_error.
  bool estimates_evidence_probability = true;
};

/// What GoogleTest prints of a case: its engine.
inline void PrintTo(const engine_case& c, std::ostream* out) { *out << c.engine; }

/// Every engine the registry holds, each checked as the case of `cases` with its name (the part
/// before any '['), or exactly with the defaults where none has it.
[[nodiscard]] inline std::vector<engine_case> registered_engine_cases(const std::vector<engine_case>& cases) {
  return cases_of(engine_registry::instance().names(), cases, [](const engine_case& c) { return c.engine; });
}

/// The case's engine as a test name ("bp_damping_0_5_").
[[nodiscard]] inline std::string engine_case_name(const ::testing::TestParamInfo<engine_case>& info) {
  return test_name(info.param.engine);
}

/// The unnormalized joint of `query` (ids in that order) with the evidence, hard and soft, by
/// summing the product of every factor over every joint state: small models only.
template <GraphicalModel M>
[[nodiscard]] std::vector<double> brute_force_joint(const M& model, std::span<const variable_id> query,
                                                    const evidence_set& observed) {
  const auto& variables = model.variables();
  std::vector<std::size_t> cells_of_query(query.size());
  std::size_t cells = 1;
  for (std::size_t k = query.size(); k-- > 0;) {
    cells_of_query[k] = cells;
    cells *= variables[query[k].value()].cardinality();
  }
  std::vector<double> joint(cells, 0.0);
  std::vector<std::size_t> state(variables.size(), 0);
  while (true) {
    double weight = 1.0;
    for (const auto& o : observed.hard) weight *= state[o.variable.value()] == o.state.value() ? 1.0 : 0.0;
    for (const auto& l : observed.soft) weight *= l.weights[state[l.variable.value()]];
    for (std::size_t f = 0; f < model.factor_count() && weight > 0.0; ++f) {
      const auto& table = model.factor(f);
      std::size_t cell = 0;
      const auto scope = table.scope();
      const auto cards = table.cardinalities();
      for (std::size_t k = 0; k < scope.size(); ++k) cell = cell * cards[k] + state[scope[k].value()];
      weight *= table.values()[cell];
    }
    std::size_t at = 0;
    for (std::size_t k = 0; k < query.size(); ++k) at += state[query[k].value()] * cells_of_query[k];
    joint[at] += weight;
    std::size_t v = variables.size();
    while (v-- > 0) {
      if (++state[v] < variables[v].cardinality()) break;
      state[v] = 0;
    }
    if (v == static_cast<std::size_t>(-1)) break;
  }
  return joint;
}

/// A Markov network with the factors of `network` (a tree when the network is one).
[[nodiscard]] inline markov_network as_markov_network(const bayesian_network& network) {
  std::vector<factor_table> factors;
  for (std::size_t f = 0; f < network.factor_count(); ++f) factors.push_back(network.factor(f));
  return markov_network(network.variables(), std::move(factors));
}

class engine_conformance : public ::testing::TestWithParam<engine_case> {
 protected:
  static constexpr std::uint64_t models = 12;
  static constexpr int rounds = 3;

  [[nodiscard]] bool exact() const { return GetParam().tolerance < 1e-6; }

  /// A random network for `seed`: a polytree for an engine exact on trees only, and without
  /// zeros for an estimate (where a state of probability 0 would leave a sampler nothing).
  [[nodiscard]] bayesian_network network(std::uint64_t seed) const {
    return random_network(seed, {.nodes = 6, .max_parents = GetParam().exact_on_loops ? 2U : 1U, .max_states = 3});
  }

  [[nodiscard]] markov_network markov(std::uint64_t seed) const {
    if (!GetParam().exact_on_loops) return as_markov_network(network(seed));
    return random_markov_network(
        seed, {.variables = 5, .factors = 6, .max_states = 3, .max_arity = 3, .zero_chance = exact() ? 0.1 : 0.0});
  }

  /// Up to two hard observations and one soft, on distinct variables.
  template <GraphicalModel M>
  [[nodiscard]] static evidence_set draw_evidence(const M& model, std::mt19937_64& random) {
    const auto all = ids(model.size());
    std::vector<variable_id> order(all.begin(), all.end());
    std::shuffle(order.begin(), order.end(), random);
    evidence_set observed;
    std::size_t next = 0;
    const auto cardinality = [&](variable_id v) { return model.variables()[v.value()].cardinality(); };
    for (auto k = random() % 3; k > 0; --k, ++next) {
      const auto v = order[next];
      observed.hard.push_back({v, index_at<state_index>(random() % cardinality(v))});
    }
    if (random() % 2 == 0) {
      const auto v = order[next];
      std::vector<double> weights;
      for (std::size_t s = 0; s < cardinality(v); ++s) weights.push_back(0.25 + static_cast<double>(random() % 4));
      observed.soft.push_back({v, std::move(weights)});
    }
    return observed;
  }

  /// The engine's marginals of every unobserved variable and its P(evidence) against
  /// enumeration (ln Z of no evidence is `log_z`: 0 for a Bayesian network).
  template <GraphicalModel M>
  void expect_enumeration(any_inference_engine& engine, const M& model, const evidence_set& observed,
                          double log_z) const {
    const auto free = detail::unobserved(model, observed);
    const auto evidence_total = brute_force_joint(model, std::span<const variable_id>(), observed).front();
    engine.set_evidence(observed);
    if (evidence_total == 0.0) {
      EXPECT_THROW(static_cast<void>(engine.marginals(free)), impossible_evidence);
      return;
    }
    const auto marginals = engine.marginals(free);
    ASSERT_EQ(marginals.size(), free.size());
    for (std::size_t k = 0; k < free.size(); ++k) {
      const variable_id one[] = {free[k]};
      const auto truth = brute_force_joint(model, one, observed);
      ASSERT_EQ(marginals[k].table.size(), truth.size()) << model.variables()[free[k].value()].name();
      for (std::size_t s = 0; s < truth.size(); ++s) {
        EXPECT_NEAR(marginals[k].table.values()[s], truth[s] / evidence_total, GetParam().tolerance)
            << model.variables()[free[k].value()].name() << " state " << s;
      }
    }
    if (GetParam().estimates_evidence_probability) {
      const double log_p = std::log(evidence_total) - log_z;
      // A sampler's relative error in P(evidence) is about its error in a probability.
      EXPECT_NEAR(engine.log_probability_of_evidence(), log_p, exact() ? 1e-10 : 4 * GetParam().tolerance);
    }
  }
};

TEST_P(engine_conformance, marginals_and_evidence_probability_equal_enumeration_on_bayesian_networks) {
  std::mt19937_64 random(17);
  for (std::uint64_t seed = 1; seed <= models; ++seed) {
    const auto net = network(seed);
    auto engine = make_engine(GetParam().engine, net);
    for (int round = 0; round < rounds; ++round) {
      SCOPED_TRACE("network " + std::to_string(seed) + ", round " + std::to_string(round));
      expect_enumeration(engine, net, draw_evidence(net, random), 0.0);
    }
  }
}

TEST_P(engine_conformance, marginals_and_evidence_probability_equal_enumeration_on_markov_networks) {
  const auto serves = engine_registry::instance().names_for<markov_network>();
  if (std::find(serves.begin(), serves.end(), component_of(GetParam().engine)) == serves.end()) {
    // An engine that needs a DAG refuses a Markov network, saying so.
    EXPECT_THROW(static_cast<void>(make_engine(GetParam().engine, markov(1))), model_error);
    return;
  }
  std::mt19937_64 random(29);
  for (std::uint64_t seed = 1; seed <= models; ++seed) {
    const auto model = markov(seed);
    const double log_z = std::log(brute_force_joint(model, std::span<const variable_id>(), {}).front());
    auto engine = make_engine(GetParam().engine, model);
    for (int round = 0; round < rounds; ++round) {
      SCOPED_TRACE("model " + std::to_string(seed) + ", round " + std::to_string(round));
      expect_enumeration(engine, model, draw_evidence(model, random), log_z);
    }
  }
}

TEST_P(engine_conformance, evidence_replaced_gives_the_answers_of_a_fresh_engine) {
  std::mt19937_64 random(43);
  for (std::uint64_t seed = 1; seed <= models; ++seed) {
    const auto net = network(seed);
    auto kept = make_engine(GetParam().engine, net);
    for (int round = 0; round < rounds; ++round) {
      SCOPED_TRACE("network " + std::to_string(seed) + ", round " + std::to_string(round));
      const auto observed = draw_evidence(net, random);
      kept.set_evidence(draw_evidence(net, random));
      const variable_id first[] = {variable_id(0)};
      static_cast<void>(kept.marginals(first));
      kept.set_evidence(observed);
      auto fresh = make_engine(GetParam().engine, net);
      fresh.set_evidence(observed);
      const auto free = detail::unobserved(net, observed);
      const auto a = kept.marginals(free);
      const auto b = fresh.marginals(free);
      for (std::size_t k = 0; k < free.size(); ++k) {
        for (std::size_t s = 0; s < a[k].table.size(); ++s) {
          EXPECT_NEAR(a[k].table.values()[s], b[k].table.values()[s], exact() ? 1e-12 : 2 * GetParam().tolerance);
        }
      }
    }
  }
}

}  // namespace pgm::testing
