// Causal questions: do-queries against the truncated factorisation by enumeration on random
// networks (every engine), the mutilated network, d-separation against the exact joint's
// independences, back-door sets against their definition and against the do-query itself, the
// front-door criterion on the textbook graphs, the adjustment formula from sampled data, checking
// a DAG against data, and prevention following the intervention where conditioning differs.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "pgm/causal/adjustment.hpp"
#include "pgm/causal/d_separation.hpp"
#include "pgm/causal/dag_check.hpp"
#include "pgm/causal/intervention.hpp"
#include "pgm/decide/explain.hpp"
#include "pgm/inference/engine_registry.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/testing/random_network.hpp"
#include "support/enumeration.hpp"

namespace pgm::causal_tests {
namespace {

using ::testing::HasSubstr;

std::vector<double> normalized(std::vector<double> values) {
  double total = 0.0;
  for (double v : values) total += v;
  for (double& v : values) v /= total;
  return values;
}

TEST(intervention_test, every_engine_gives_the_truncated_factorisation) {
  std::mt19937_64 random(31);
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 8, .max_parents = 3, .min_states = 2, .max_states = 3});
    std::vector<variable_id> nodes;
    for (std::size_t i = 0; i < net.size(); ++i) nodes.push_back(index_at<variable_id>(i));
    std::shuffle(nodes.begin(), nodes.end(), random);
    evidence_set observed;
    const auto set = 1 + random() % 2;
    for (std::size_t k = 0; k < set; ++k) {
      observed.intervened.push_back(
          {nodes[k], index_at<state_index>(random() % net.variables()[nodes[k].value()].cardinality())});
    }
    if (random() % 2) {
      const auto v = nodes[set];
      observed.hard.push_back({v, index_at<state_index>(random() % net.variables()[v.value()].cardinality())});
    }
    const variable_id query[] = {nodes[set + 1]};
    const auto raw = testing::enumerate_joint(net, query, observed);
    double p_evidence = 0.0;
    for (double v : raw) p_evidence += v;
    const auto expected = normalized(raw);
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::vector<any_inference_engine> engines;
    engines.push_back(make_engine("ve", net));
    engines.push_back(make_engine("jt", net));
    engines.push_back(any_inference_engine(junction_tree_engine(net, {.prune = false})));
    for (auto& engine : engines) {
      engine.set_evidence(observed);
      for (int twice = 0; twice < 2; ++twice) {
        const auto p = engine.joint(query);
        for (std::size_t s = 0; s < expected.size(); ++s) EXPECT_NEAR(p.table.values()[s], expected[s], 1e-12);
        EXPECT_NEAR(p.evidence_probability, p_evidence, 1e-12);
      }
      // The most probable explanation under the intervention, against enumeration.
      std::vector<variable_id> free;
      for (auto v : nodes) {
        if (!observed.fixes(v)) free.push_back(v);
      }
      std::sort(free.begin(), free.end());
      EXPECT_NEAR(engine.mpe({}).joint_probability, testing::enumerate_maximum(net, free, observed), 1e-12);
    }
    // The mutilated network, queried with its interventions as observations, gives the same.
    intervention set_by_name;
    evidence hard_by_name;
    for (const auto& o : observed.intervened) {
      const auto& v = net.variables()[o.variable.value()];
      set_by_name.emplace(v.name(), v.states()[o.state.value()]);
    }
    for (const auto& o : observed.hard) {
      const auto& v = net.variables()[o.variable.value()];
      hard_by_name.emplace(v.name(), v.states()[o.state.value()]);
    }
    const auto mutilated = intervene(net, set_by_name);
    auto both = hard_by_name;
    both.insert(set_by_name.begin(), set_by_name.end());
    const auto p = pgm::query(mutilated, {net.variables()[query[0].value()].name()}, both);
    for (std::size_t s = 0; s < expected.size(); ++s) EXPECT_NEAR(p.table.values()[s], expected[s], 1e-12);
    for (const auto& [name, state] : set_by_name) EXPECT_TRUE(mutilated.graph().parents(mutilated.id(name)).empty());
  }
}

TEST(intervention_test, sampling_engines_sample_the_mutilated_network) {
  const auto net = testing::random_network(12, {.nodes = 8, .max_parents = 2, .min_states = 2, .max_states = 3});
  const evidence_set observed{{{variable_id(7), state_index(0)}}, {}, {{variable_id(3), state_index(1)}}};
  for (const char* name : {"lw", "gibbs"}) {
    inference_options options;
    options.sampling = {.samples = 200'000, .seed = 5, .threads = 1};
    auto engine = make_engine(name, net, options);
    engine.set_evidence(observed);
    for (std::size_t v : {0U, 4U, 5U}) {
      const variable_id q[] = {index_at<variable_id>(v)};
      const auto expected = normalized(testing::enumerate_joint(net, q, observed));
      const auto p = engine.joint(q);
      for (std::size_t s = 0; s < expected.size(); ++s) {
        EXPECT_LE(std::abs(p.table.values()[s] - expected[s]), 4.0 * p.standard_errors[s] + 1e-9) << name << v;
      }
    }
  }
}

TEST(intervention_test, errors_name_what_is_wrong) {
  const auto net = testing::random_network(3, {.nodes = 4, .max_parents = 2});
  auto engine = make_engine("jt", net);
  EXPECT_THAT(
      [&] {
        set_evidence(engine, {{"v1", "s0"}}, {}, {{"v1", "s1"}});
      },
      ::testing::ThrowsMessage<model_error>(HasSubstr("'v1' is both intervened on and observed")));
  set_evidence(engine, {}, {}, {{"v1", "s1"}});
  EXPECT_THAT([&] { static_cast<void>(marginal(engine, "v1")); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("'v1' is intervened on")));
  EXPECT_THAT(
      [&] {
        set_evidence(engine, {}, {}, {{"v9", "s0"}});
      },
      ::testing::ThrowsMessage<model_error>(HasSubstr("no variable 'v9'")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(intervene(net, {{"v2", "s7"}}));
      },
      ::testing::ThrowsMessage<model_error>(HasSubstr("no state 's7'")));
}

/// An engine that does not declare handles_interventions: variable elimination seen through
/// the concept's required members only.
class unaware_engine {
 public:
  explicit unaware_engine(const bayesian_network& network) : inner_(network) {}
  [[nodiscard]] std::string_view name() const { return "unaware"; }
  [[nodiscard]] const bayesian_network& network() const { return inner_.network(); }
  [[nodiscard]] const evidence_set& evidence() const { return inner_.evidence(); }
  void set_evidence(evidence_set observed) { inner_.set_evidence(std::move(observed)); }
  [[nodiscard]] posterior joint(std::span<const variable_id> query) { return inner_.joint(query); }
  [[nodiscard]] double log_probability_of_evidence() { return inner_.log_probability_of_evidence(); }

 private:
  variable_elimination<> inner_;
};
static_assert(InferenceEngine<unaware_engine> && !detail::HandlesInterventions<unaware_engine>);

TEST(intervention_test, an_engine_that_does_not_read_interventions_refuses_them) {
  const auto net = testing::random_network(3, {.nodes = 4, .max_parents = 2});
  unaware_engine direct(net);
  EXPECT_THAT(
      [&] {
        set_evidence(direct, {}, {}, {{"v1", "s1"}});
      },
      ::testing::ThrowsMessage<model_error>(HasSubstr("'unaware' does not handle interventions")));
  any_inference_engine erased(unaware_engine{net});
  EXPECT_FALSE(erased.reads_interventions());
  EXPECT_THAT(
      [&] {
        set_evidence(erased, {}, {}, {{"v1", "s1"}});
      },
      ::testing::ThrowsMessage<model_error>(HasSubstr("'unaware' does not handle interventions")));
  set_evidence(erased, {{"v1", "s1"}});  // evidence alone is fine
  EXPECT_NO_THROW(static_cast<void>(marginal(erased, "v2")));
}

TEST(d_separation_test, agrees_with_the_independences_of_the_exact_joint) {
  std::mt19937_64 random(8);
  int separated = 0;
  int connected = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 7, .max_parents = 2, .min_states = 2, .max_states = 2});
    std::vector<variable_id> nodes;
    for (std::size_t i = 0; i < net.size(); ++i) nodes.push_back(index_at<variable_id>(i));
    for (int round = 0; round < 4; ++round) {
      std::shuffle(nodes.begin(), nodes.end(), random);
      const variable_id x[] = {nodes[0]};
      const variable_id y[] = {nodes[1]};
      const std::vector<variable_id> z(nodes.begin() + 2, nodes.begin() + 2 + static_cast<long>(random() % 3));
      const bool d_sep = d_separated(net.graph(), x, y, z);
      // Independence of the exact joint: P(x, y | z) = P(x | z) P(y | z) in every stratum z.
      std::vector<variable_id> scope(z.begin(), z.end());
      scope.push_back(x[0]);
      scope.push_back(y[0]);
      const auto joint = testing::enumerate_joint(net, scope, evidence_set{});
      double largest = 0.0;
      for (std::size_t s = 0; s < joint.size(); s += 4) {
        const double total = joint[s] + joint[s + 1] + joint[s + 2] + joint[s + 3];
        const double px = (joint[s + 2] + joint[s + 3]) / total;
        const double py = (joint[s + 1] + joint[s + 3]) / total;
        largest = std::max(largest, std::abs(joint[s + 3] / total - px * py));
      }
      if (d_sep) {
        ++separated;
        EXPECT_LT(largest, 1e-12) << "seed " << seed;
      } else {
        ++connected;
        EXPECT_GT(largest, 1e-9) << "seed " << seed << ": random tables are faithful";
      }
    }
  }
  EXPECT_GT(separated, 20);
  EXPECT_GT(connected, 20);
}

TEST(d_separation_test, textbook_cases_by_name) {
  // rain -> grass <- sprinkler, grass -> shoes
  const network_structure s({variable("rain", {"0", "1"}), variable("sprinkler", {"0", "1"}),
                             variable("grass", {"0", "1"}), variable("shoes", {"0", "1"})},
                            {{"rain", "grass"}, {"sprinkler", "grass"}, {"grass", "shoes"}});
  const std::vector<std::string> rain{"rain"}, sprinkler{"sprinkler"}, grass{"grass"}, shoes{"shoes"};
  EXPECT_TRUE(d_separated(s, rain, sprinkler));
  EXPECT_FALSE(d_separated(s, rain, sprinkler, grass));  // a collider observed
  EXPECT_FALSE(d_separated(s, rain, sprinkler, shoes));  // a descendant of the collider observed
  EXPECT_TRUE(d_separated(s, rain, shoes, grass));
  EXPECT_THAT([&] { static_cast<void>(d_separated(s, rain, rain)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("disjoint")));
}

TEST(adjustment_test, minimal_backdoor_sets_meet_the_definition_and_identify_the_effect) {
  std::mt19937_64 random(4);
  int sets_checked = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 7, .max_parents = 3, .min_states = 2, .max_states = 2});
    const variable_id x[] = {index_at<variable_id>(1 + random() % 3)};
    const variable_id y[] = {variable_id(6)};
    const auto found = minimal_backdoor_sets(net.graph(), x, y);
    ASSERT_TRUE(found.complete);
    // The do-query, exactly.
    evidence_set set{{}, {}, {{x[0], state_index(1)}}};
    const auto truth = normalized(testing::enumerate_joint(net, y, set));
    for (const auto& z : found.sets) {
      EXPECT_TRUE(satisfies_backdoor(net.graph(), x, y, z));
      for (std::size_t drop = 0; drop < z.size(); ++drop) {
        auto smaller = z;
        smaller.erase(smaller.begin() + static_cast<long>(drop));
        EXPECT_FALSE(satisfies_backdoor(net.graph(), x, y, smaller)) << "not minimal";
      }
      // Σ_z P(y | x, z) P(z) from the exact joint equals P(y | do(x)).
      std::vector<variable_id> scope(z.begin(), z.end());
      scope.push_back(x[0]);
      scope.push_back(y[0]);
      const auto joint = testing::enumerate_joint(net, scope, evidence_set{});
      double adjusted = 0.0;
      for (std::size_t s = 0; s < joint.size(); s += 4) {
        const double pz = joint[s] + joint[s + 1] + joint[s + 2] + joint[s + 3];
        const double px = joint[s + 2] + joint[s + 3];
        if (px > 0) adjusted += pz * joint[s + 3] / px;
      }
      EXPECT_NEAR(adjusted, truth[1], 1e-12) << "seed " << seed;
      ++sets_checked;
    }
  }
  EXPECT_GT(sets_checked, 20);
}

TEST(adjustment_test, front_door_on_the_textbook_graph) {
  // U -> X -> M -> Y, U -> Y: {M} is a front-door set, {} and {U}'s roles differ.
  dag g({"U", "X", "M", "Y"});
  g.add_edge("U", "X");
  g.add_edge("X", "M");
  g.add_edge("M", "Y");
  g.add_edge("U", "Y");
  const variable_id x[] = {g.id("X")}, y[] = {g.id("Y")}, m[] = {g.id("M")}, u[] = {g.id("U")};
  EXPECT_TRUE(satisfies_frontdoor(g, x, y, m));
  EXPECT_FALSE(satisfies_frontdoor(g, x, y, u));
  EXPECT_TRUE(satisfies_backdoor(g, x, y, u));
  EXPECT_FALSE(satisfies_backdoor(g, x, y, m));  // a descendant of X
  // X -> Y directly as well: M no longer intercepts every directed path.
  g.add_edge("X", "Y");
  EXPECT_FALSE(satisfies_frontdoor(g, x, y, m));
}

TEST(adjustment_test, the_formula_on_sampled_data_converges_to_the_do_query) {
  // A confounded effect: C -> X, C -> Y, X -> Y; conditioning on X differs from setting it.
  const variable c("C", {"0", "1"}), xv("X", {"0", "1"}), yv("Y", {"0", "1"});
  const auto net =
      bayesian_network::from_tables({cpt<double>(c, {}, {0.3, 0.7}), cpt<double>(xv, {c}, {0.8, 0.2, 0.1, 0.9}),
                                     cpt<double>(yv, {c, xv}, {0.9, 0.1, 0.6, 0.4, 0.5, 0.5, 0.2, 0.8})});
  auto engine = make_engine("ve", net);
  set_evidence(engine, {}, {}, {{"X", "1"}});
  const double truth = marginal(engine, "Y").probability({"1"});
  set_evidence(engine, {{"X", "1"}});
  const double conditioned = marginal(engine, "Y").probability({"1"});
  EXPECT_GT(std::abs(truth - conditioned), 0.05) << "the example must tell the two apart";
  const auto data = sample(net, 400'000, 11);
  const std::vector<std::string> z{"C"};
  const auto estimate = adjust(data, "X", "Y", z);
  EXPECT_NEAR(estimate.values[1 * 2 + 1], truth, 0.005);
  EXPECT_EQ(estimate.unsupported[1], 0.0);
  const auto naive = adjust(data, "X", "Y", {});
  EXPECT_NEAR(naive.values[1 * 2 + 1], conditioned, 0.005);
}

TEST(dag_check_test, data_from_the_dag_pass_and_a_missing_edge_is_found) {
  const auto net = testing::random_network(17, {.nodes = 7, .max_parents = 2, .min_states = 2, .max_states = 3});
  const auto data = sample(net, 20'000, 3);
  const auto good = check_dag(net.structure(), data, {.alpha = 0.001});
  EXPECT_GT(good.tests.size(), 5U);
  EXPECT_LE(good.rejected(), 1U);
  for (std::size_t k = 1; k < good.tests.size(); ++k) {
    EXPECT_LE(good.tests[k - 1].result.p_value, good.tests[k].result.p_value);
  }
  // Drop a strong edge from the structure: the independence it implies is rejected first.
  auto wrong = net.structure();
  const auto [from, to] = net.graph().edges().front();
  wrong.remove_edge(net.variables()[from.value()].name(), net.variables()[to.value()].name());
  const auto bad = check_dag(wrong, data, {.alpha = 0.001});
  ASSERT_GE(bad.rejected(), 1U);
  const auto& worst = bad.tests.front();
  const std::set<std::string> pair{worst.x, worst.y};
  EXPECT_EQ(pair, (std::set<std::string>{net.variables()[from.value()].name(), net.variables()[to.value()].name()}));
  EXPECT_LT(worst.result.p_value, 1e-6);
  // The same result on any number of threads.
  const auto one = check_dag(wrong, data, {.alpha = 0.001, .threads = 1});
  ASSERT_EQ(one.tests.size(), bad.tests.size());
  for (std::size_t k = 0; k < one.tests.size(); ++k) EXPECT_EQ(one.tests[k].result, bad.tests[k].result);
}

TEST(prevention_test, a_controllable_variable_with_a_parent_is_set_not_observed) {
  // xOff1 -> xOff2 (the recorded plans put the second block where the first went), both ->
  // onTop2. With xOff1 unknown, observing xOff2 tells of xOff1; setting it does not.
  const variable x1("xOff1", {"left", "centre"}), x2("xOff2", {"left", "centre"}), top("onTop2", {"0", "1"});
  const auto net = bayesian_network::from_tables({
      cpt<double>(x1, {}, {0.5, 0.5}),
      cpt<double>(x2, {x1}, {0.9, 0.1, 0.1, 0.9}),
      cpt<double>(top, {x1, x2}, {0.9, 0.1, 0.6, 0.4, 0.5, 0.5, 0.05, 0.95}),
  });
  // do(xOff2 = centre): Σ_x1 P(x1) P(top | x1, centre) = 0.5·0.4 + 0.5·0.95 = 0.675;
  // conditioning: P(x1 | centre) = (0.05, 0.45)/0.5 → 0.1·0.4 + 0.9·0.95 = 0.895.
  auto engine = make_engine("jt", net);
  const std::string given[] = {"xOff2"};
  const auto seen = success_table(engine, "onTop2", given);
  const auto set = intervened_success_table(engine, "onTop2", given, given);
  EXPECT_NEAR(seen.probability("1", {"centre"}), 0.895, 1e-12);
  EXPECT_NEAR(set.probability("1", {"centre"}), 0.675, 1e-12);
  EXPECT_NEAR(set.probability("1", {"left"}), 0.5 * 0.1 + 0.5 * 0.5, 1e-12);
  // Prevention with ε = 0.7 from xOff2 = left: conditioning would call centre a success (0.895),
  // setting it does not (0.675 < 0.7): the best move, short of ε.
  const std::string controllable[] = {"xOff2"};
  const auto plan = plan_prevention(engine, {"onTop2", "1"}, {{"xOff2", std::string("left")}}, controllable,
                                    {.epsilon = 0.7}, {.marginalize_missing = true});
  EXPECT_NEAR(plan.why.target_predicted, 0.675, 1e-12);
  EXPECT_FALSE(plan.why.target_succeeds());
  // Roots as in the paper: setting is observing, the table is the same to the bit.
  const std::string root[] = {"xOff1"};
  const std::string both[] = {"xOff1", "xOff2"};
  EXPECT_EQ(intervened_success_table(engine, "onTop2", root, root), success_table(engine, "onTop2", root));
  EXPECT_EQ(intervened_success_table(engine, "onTop2", both, both), net.table("onTop2"));
}

}  // namespace
}  // namespace pgm::causal_tests
