// The engines over a Markov network (variable elimination, the junction tree, loopy belief
// propagation, Gibbs on the factors), through the registry as `pgm query` uses them, against
// brute force; what they own; and what they refuse.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "pgm/core/graphical_model.hpp"
#include "pgm/inference/approximate_engines.hpp"
#include "pgm/inference/engine_registry.hpp"
#include "pgm/testing/random_markov_network.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm {
namespace markov_engines_test {

using ::testing::HasSubstr;

variable_id id_of(std::size_t i) { return index_at<variable_id>(i); }

std::vector<double> values_of(const posterior& p) { return {p.table.values().begin(), p.table.values().end()}; }

TEST(markov_engines_test, ve_and_jt_equal_brute_force_through_the_registry) {
  std::size_t checked = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    testing::random_markov_options shape;
    shape.variables = 3 + seed % 4;
    shape.factors = 2 + seed % 6;
    shape.zero_chance = 0.05;
    const auto model = testing::random_markov_network(seed, shape);
    std::vector<long> fixed;
    const auto observed = testing::random_hard_evidence(model, seed * 104729, fixed);
    const auto truth = testing::brute_force(model, fixed);
    if (truth.log_z == -INFINITY) continue;
    const double log_z = testing::brute_force(model, std::vector<long>(model.size(), -1)).log_z;
    for (const char* name : {"ve", "jt", "auto"}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", engine " + name);
      auto engine = make_engine(name, model);
      EXPECT_EQ(engine.model().kind(), "Markov network");
      engine.set_evidence(observed);
      // P(evidence) = Z(e) / Z.
      EXPECT_NEAR(engine.log_probability_of_evidence(), truth.log_z - log_z, 1e-12 * std::max(1.0, std::abs(log_z)));
      EXPECT_NEAR(engine.log_partition_function(), truth.log_z, 1e-12 * std::max(1.0, std::abs(log_z)));
      const auto all = marginals(engine);
      std::size_t k = 0;
      for (std::size_t i = 0; i < model.size(); ++i) {
        if (fixed[i] >= 0) continue;
        const auto& p = all.at(k++);
        for (std::size_t s = 0; s < p.table.values().size(); ++s)
          EXPECT_NEAR(p.table.values()[s], truth.marginals[i][s], 1e-12);
        EXPECT_NEAR(p.log_evidence_probability, truth.log_z - log_z, 1e-12 * std::max(1.0, std::abs(log_z)));
      }
      // A joint of the first two unobserved variables, against Σ over the others.
      std::vector<variable_id> pair;
      for (std::size_t i = 0; i < model.size() && pair.size() < 2; ++i) {
        if (fixed[i] < 0) pair.push_back(id_of(i));
      }
      if (pair.size() == 2) {
        const auto joint = engine.joint(pair);
        const auto a = model.variables()[pair[0].value()].cardinality();
        const auto b = model.variables()[pair[1].value()].cardinality();
        for (std::size_t x = 0; x < a; ++x) {
          for (std::size_t y = 0; y < b; ++y) {
            const double expected =
                std::exp(testing::brute_force_query_value(model, pair, {x, y}, fixed) - truth.log_z);
            EXPECT_NEAR(joint.table.values()[x * b + y], expected, 1e-12);
          }
        }
      }
      // The most probable explanation: its value, and P(x, e) = Π φ / Z.
      const auto best = engine.mpe({});
      std::vector<std::size_t> state(model.size());
      for (std::size_t i = 0; i < model.size(); ++i) state[i] = fixed[i] >= 0 ? static_cast<std::size_t>(fixed[i]) : 0;
      const auto unobserved = detail::unobserved(model, observed);
      for (std::size_t j = 0; j < unobserved.size(); ++j) state[unobserved[j].value()] = best.states[j].value();
      EXPECT_NEAR(testing::log_value(model, state), truth.log_max, 1e-12 * std::max(1.0, std::abs(truth.log_max)));
      EXPECT_NEAR(best.log_joint_probability, truth.log_max - log_z, 1e-11 * std::max(1.0, std::abs(log_z)));
      EXPECT_NEAR(best.log_probability, truth.log_max - truth.log_z, 1e-11 * std::max(1.0, std::abs(log_z)));
      ++checked;
    }
  }
  EXPECT_GT(checked, 90U);
}

TEST(markov_engines_test, impossible_evidence_is_named) {
  // φ(a, b) allows only a = b.
  const variable a("a", {"0", "1"});
  const variable b("b", {"0", "1"});
  const markov_network model({a, b}, {factor_table({id_of(0), id_of(1)}, {2, 2}, {1.0, 0.0, 0.0, 1.0})});
  for (const char* name : {"ve", "jt"}) {
    auto engine = make_engine(name, model);
    set_evidence(engine, {{"a", "0"}, {"b", "1"}});
    EXPECT_EQ(engine.log_probability_of_evidence(), -INFINITY) << name;
    EXPECT_THAT([&] { static_cast<void>(engine.mpe({})); },
                ::testing::ThrowsMessage<impossible_evidence>(HasSubstr("a=0, b=1 has probability 0 under the model")));
  }
}

TEST(markov_engines_test, belief_propagation_is_exact_on_a_chain) {
  // A chain of pairwise factors: its factor graph is a tree, where loopy BP is exact.
  std::mt19937_64 draw(11);
  std::uniform_real_distribution<double> value(0.1, 2.0);
  std::vector<variable> variables;
  std::vector<factor_table> factors;
  for (std::size_t i = 0; i < 6; ++i)
    variables.emplace_back("v" + std::to_string(i), std::vector<std::string>{"a", "b", "c"});
  for (std::size_t i = 0; i + 1 < 6; ++i) {
    std::vector<double> values(9);
    for (auto& v : values) v = value(draw);
    factors.emplace_back(std::vector<variable_id>{id_of(i), id_of(i + 1)}, std::vector<std::size_t>{3, 3}, values);
  }
  const markov_network model(variables, factors);
  std::vector<long> fixed(model.size(), -1);
  fixed[3] = 2;
  const auto truth = testing::brute_force(model, fixed);
  const double log_z = testing::brute_force(model, std::vector<long>(model.size(), -1)).log_z;
  auto engine = make_engine("bp", model);
  set_evidence(engine, {{"v3", "c"}});
  EXPECT_NEAR(engine.log_probability_of_evidence(), truth.log_z - log_z, 1e-9);
  EXPECT_NEAR(engine.log_partition_function(), truth.log_z, 1e-9);
  const auto all = marginals(engine);
  ASSERT_EQ(all.size(), 5U);
  for (const auto& p : all) {
    const auto i = p.table.scope().front().value();
    for (std::size_t s = 0; s < 3; ++s) EXPECT_NEAR(p.table.values()[s], truth.marginals[i][s], 1e-9);
  }
  EXPECT_THAT(
      [&] {
        static_cast<void>(engine.joint(std::vector{id_of(0), id_of(1)}));
      },
      ::testing::ThrowsMessage<model_error>(HasSubstr("one variable's marginal at a time")));
}

TEST(markov_engines_test, gibbs_on_the_factors_estimates_marginals_and_says_it_has_no_evidence_probability) {
  const auto model = testing::random_markov_network(5, {.variables = 5, .factors = 6, .zero_chance = 0.0});
  std::vector<long> fixed(model.size(), -1);
  fixed[0] = 1;
  const auto truth = testing::brute_force(model, fixed);
  inference_options options;
  options.sampling.samples = 40'000;
  options.sampling.seed = 3;
  auto engine = make_engine("gibbs", model, options);
  EXPECT_EQ(engine.name(), "gibbs");
  evidence_set observed;
  observed.hard.push_back({id_of(0), state_index(1)});
  engine.set_evidence(observed);
  for (std::size_t i = 1; i < model.size(); ++i) {
    const auto p = engine.joint(std::vector{id_of(i)});
    for (std::size_t s = 0; s < p.table.values().size(); ++s)
      EXPECT_NEAR(p.table.values()[s], truth.marginals[i][s], 0.02);
    EXPECT_TRUE(std::isnan(p.evidence_probability));
  }
  EXPECT_THAT([&] { static_cast<void>(engine.log_probability_of_evidence()); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("does not estimate P(evidence)")));
  EXPECT_THAT([&] { static_cast<void>(engine.log_partition_function()); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("does not estimate the partition function")));
  // The same seed, the same numbers.
  auto again = make_engine("gibbs", model, options);
  again.set_evidence(observed);
  EXPECT_EQ(again.joint(std::vector{id_of(2)}).table.values()[0],
            engine.joint(std::vector{id_of(2)}).table.values()[0]);
}

TEST(markov_engines_test, what_needs_a_dag_is_refused_by_name) {
  const auto model = testing::random_markov_network(2);
  EXPECT_THAT([&] { static_cast<void>(make_engine("lw", model)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr(
                  "the engine 'lw' does not serve a Markov network (it samples along a DAG); engines for it: auto, "
                  "bp, gibbs, jt, ve")));
  for (const char* name : {"ve", "jt", "bp", "gibbs"}) {
    auto engine = make_engine(name, model);
    EXPECT_THAT(
        [&] {
          set_evidence(engine, {}, {}, {{"x0", model.variables()[0].states()[0]}});
        },
        ::testing::ThrowsMessage<model_error>(HasSubstr("does not handle interventions")))
        << name;
    EXPECT_THAT([&] { static_cast<void>(engine.network()); },
                ::testing::ThrowsMessage<model_error>(HasSubstr("holds a Markov network, not a Bayesian network")))
        << name;
  }
  variable_elimination direct(model);
  evidence_set surgery;
  surgery.intervened.push_back({id_of(0), state_index(0)});
  EXPECT_THAT([&] { direct.set_evidence(surgery); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("cannot intervene (do) on a Markov network")));
}

TEST(markov_engines_test, an_engine_owns_or_shares_its_model) {
  const auto net = testing::random_network(4, {.nodes = 6, .max_parents = 2});
  std::vector<double> expected;
  {
    variable_elimination reference(net);
    expected = values_of(reference.joint(std::vector{id_of(5)}));
  }
  // Built from a model that is gone before the first query: the engines hold their own copies.
  auto copy = std::make_unique<bayesian_network>(net);
  variable_elimination ve(*copy);
  junction_tree_engine jt(*copy);
  auto erased = make_engine("jt", *copy);
  auto weighting = make_engine("lw", *copy);
  copy.reset();
  EXPECT_EQ(values_of(ve.joint(std::vector{id_of(5)})), expected);
  EXPECT_EQ(values_of(jt.joint(std::vector{id_of(5)})), expected);
  EXPECT_EQ(values_of(erased.joint(std::vector{id_of(5)})), expected);
  EXPECT_EQ(weighting.model().size(), net.size());
  // Shared: the engines see the one model; borrowed: no copy at all.
  const auto shared = std::make_shared<const bayesian_network>(net);
  const variable_elimination sharing(shared);
  EXPECT_EQ(&sharing.model(), shared.get());
  const variable_elimination lent(borrowed(net));
  EXPECT_EQ(&lent.network(), &net);
}

/// An engine that can be built from a Bayesian network only: the registry serves no Markov
/// network with it.
class network_only_engine {
 public:
  network_only_engine(const bayesian_network& network, const inference_options&) : inner_(borrowed(network)) {}
  [[nodiscard]] std::string_view name() const { return "network-only"; }
  [[nodiscard]] const bayesian_network& network() const { return inner_.network(); }
  [[nodiscard]] const evidence_set& evidence() const { return inner_.evidence(); }
  void set_evidence(evidence_set observed) { inner_.set_evidence(std::move(observed)); }
  [[nodiscard]] posterior joint(std::span<const variable_id> query) { return inner_.joint(query); }
  [[nodiscard]] double log_probability_of_evidence() { return inner_.log_probability_of_evidence(); }

 private:
  variable_elimination<> inner_;
};

TEST(markov_engines_test, a_users_engine_serves_the_models_it_can_be_built_from) {
  static const register_engine<network_only_engine> registered("network-only");
  const auto net = testing::random_network(6, {.nodes = 5, .max_parents = 2});
  // Built through the registry from a reference, the engine's model is kept alive by it.
  auto engine = make_engine("network-only", net);
  const auto p = engine.joint(std::vector{id_of(4)});
  EXPECT_EQ(values_of(p), values_of(variable_elimination(net).joint(std::vector{id_of(4)})));
  const auto names = engine_registry::instance().names_for<markov_network>();
  EXPECT_EQ(std::count(names.begin(), names.end(), "network-only"), 0);
  EXPECT_THAT([&] { static_cast<void>(make_engine("network-only", testing::random_markov_network(1))); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("'network-only' does not serve a Markov network")));
}

}  // namespace markov_engines_test
}  // namespace pgm
