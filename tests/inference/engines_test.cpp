// Every inference engine against brute-force enumeration on random networks (hard and soft
// evidence, joint queries across cliques, the most probable explanation and marginal MAP), the
// sampling engines within their standard errors and repeatable for any thread count, log space
// where P(evidence) underflows, and the published networks engine against engine.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "pgm/inference/engine_registry.hpp"
#include "pgm/inference/inference_engine.hpp"
#include "pgm/inference/junction_tree_engine.hpp"
#include "pgm/inference/variable_elimination.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/testing/random_network.hpp"
#include "support/enumeration.hpp"

namespace pgm::engines_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// A random query on `net`: 1–3 query variables, 0–3 hard and 0–2 soft observations.
struct random_case {
  std::vector<variable_id> query;
  evidence_set observed;
};

random_case draw_case(const bayesian_network& net, std::mt19937_64& random) {
  std::vector<variable_id> nodes;
  for (std::size_t i = 0; i < net.size(); ++i) nodes.push_back(index_at<variable_id>(i));
  std::shuffle(nodes.begin(), nodes.end(), random);
  random_case item;
  const auto queried = 1 + random() % 3;
  const auto hard = random() % 4;
  const auto soft = random() % 3;
  std::size_t next = 0;
  for (std::size_t k = 0; k < queried; ++k) item.query.push_back(nodes[next++]);
  for (std::size_t k = 0; k < hard; ++k) {
    const auto id = nodes[next++];
    item.observed.hard.push_back({id, index_at<state_index>(random() % net.variables()[id.value()].cardinality())});
  }
  for (std::size_t k = 0; k < soft; ++k) {
    // Soft evidence may fall on a query variable too: its posterior is then reweighted.
    const auto id = k == 0 && random() % 2 ? item.query.front() : nodes[next++];
    std::vector<double> weights;
    for (std::size_t s = 0; s < net.variables()[id.value()].cardinality(); ++s) {
      weights.push_back(static_cast<double>(random() % 5));
    }
    weights[random() % weights.size()] += 0.5;  // not all zero
    item.observed.soft.push_back({id, weights});
  }
  return item;
}

/// The normalized enumeration answer and P(evidence).
std::pair<std::vector<double>, double> expected_posterior(const bayesian_network& net, const random_case& item) {
  auto joint = testing::enumerate_joint(net, item.query, item.observed);
  double total = 0.0;
  for (double v : joint) total += v;
  for (double& v : joint) v /= total;
  return {joint, total};
}

template <class Engine>
void expect_engine_matches(Engine& engine, const bayesian_network& net, const random_case& item) {
  const auto [expected, evidence] = expected_posterior(net, item);
  engine.set_evidence(item.observed);
  if (!(evidence > 0.0)) {
    EXPECT_THROW(static_cast<void>(engine.joint(item.query)), impossible_evidence);
    return;
  }
  const auto got = engine.joint(item.query);
  ASSERT_EQ(got.table.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(got.table.values()[i], expected[i], 1e-12) << i;
  EXPECT_NEAR(got.evidence_probability, evidence, 1e-12 * std::max(1.0, evidence));
  EXPECT_NEAR(engine.log_probability_of_evidence(), std::log(evidence), 1e-10);
}

TEST(engines_test, exact_engines_match_enumeration_on_random_networks) {
  std::mt19937_64 random(11);
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 8, .max_parents = 3, .min_states = 2, .max_states = 4});
    variable_elimination ve(net);
    junction_tree_engine jt(net);
    junction_tree_engine propagating(net, {.prune = false});
    junction_tree_engine by_weight(net, {.heuristic = elimination_heuristic::min_weight, .prune = false});
    for (int round = 0; round < 4; ++round) {
      const auto item = draw_case(net, random);
      SCOPED_TRACE("seed " + std::to_string(seed) + " round " + std::to_string(round));
      expect_engine_matches(ve, net, item);
      expect_engine_matches(jt, net, item);
      expect_engine_matches(propagating, net, item);
      expect_engine_matches(by_weight, net, item);
    }
  }
}

TEST(engines_test, junction_tree_propagation_matches_enumeration_when_it_keeps_messages) {
  // Repeated queries under one evidence propagate (the engine prunes only one-off queries); all
  // marginals come from one two-pass propagation.
  std::mt19937_64 random(5);
  for (std::uint64_t seed = 100; seed < 130; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 9, .max_parents = 3, .min_states = 2, .max_states = 3});
    junction_tree_engine jt(net, {.prune = false});
    const auto item = draw_case(net, random);
    const auto [unused, evidence] = expected_posterior(net, {item.query, item.observed});
    if (!(evidence > 0.0)) continue;
    jt.set_evidence(item.observed);
    for (std::size_t i = 0; i < net.size(); ++i) {
      const variable_id one[] = {index_at<variable_id>(i)};
      if (item.observed.fixes(one[0])) continue;
      const auto expected = expected_posterior(net, {{one[0]}, item.observed}).first;
      for (int twice = 0; twice < 2; ++twice) {
        const auto got = jt.joint(one);
        for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(got.table.values()[k], expected[k], 1e-12);
      }
    }
    std::vector<variable_id> free;
    for (std::size_t i = 0; i < net.size(); ++i) {
      if (!item.observed.fixes(index_at<variable_id>(i))) free.emplace_back(i);
    }
    const auto all = jt.marginals(free);
    ASSERT_EQ(all.size(), free.size());
    for (std::size_t i = 0; i < free.size(); ++i) {
      const auto expected = expected_posterior(net, {{free[i]}, item.observed}).first;
      for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(all[i].table.values()[k], expected[k], 1e-12);
      EXPECT_NEAR(all[i].evidence_probability, evidence, 1e-12);
    }
  }
}

TEST(engines_test, junction_tree_joints_of_many_scopes_match_enumeration) {
  // Every family's unobserved members (within one clique) and a pair that may span cliques, in
  // one call, under evidence that changes from call to call; a fresh() engine answers with the
  // bits of a newly compiled one, whatever its origin was asked before.
  std::mt19937_64 random(8);
  for (std::uint64_t seed = 200; seed < 220; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 9, .max_parents = 3, .min_states = 2, .max_states = 3});
    junction_tree_engine jt(net);
    std::vector<random_case> cases;
    for (int k = 0; k < 3; ++k) cases.push_back(draw_case(net, random));
    for (int pass = 0; pass < 2; ++pass) {
      for (std::size_t k = 0; k < cases.size(); ++k) {
        const auto& observed = cases[k].observed;
        if (!(expected_posterior(net, {cases[k].query, observed}).second > 0.0)) continue;
        jt.set_evidence(observed);
        std::vector<std::vector<variable_id>> scopes;
        for (std::size_t i = 0; i < net.size(); ++i) {
          auto& scope = scopes.emplace_back();
          const auto node = index_at<variable_id>(i);
          for (auto member : net.structure().parents(node)) {
            if (!observed.fixes(member)) scope.push_back(member);
          }
          if (!observed.fixes(node)) scope.push_back(node);
          if (scope.empty()) scopes.pop_back();
        }
        scopes.push_back({index_at<variable_id>(0), index_at<variable_id>(net.size() - 1)});
        std::erase_if(scopes.back(), [&](variable_id v) { return observed.fixes(v); });
        if (scopes.back().empty()) scopes.pop_back();
        const auto got = jt.joints(scopes);
        ASSERT_EQ(got.size(), scopes.size());
        for (std::size_t q = 0; q < scopes.size(); ++q) {
          const auto expected = expected_posterior(net, {scopes[q], observed}).first;
          ASSERT_EQ(got[q].size(), expected.size());
          for (std::size_t c = 0; c < expected.size(); ++c) EXPECT_NEAR(got[q][c], expected[c], 1e-12);
        }
        auto fresh = jt.fresh();
        fresh.set_evidence(observed);
        junction_tree_engine compiled(net);
        compiled.set_evidence(observed);
        EXPECT_EQ(fresh.joints(scopes), compiled.joints(scopes));
      }
    }
  }
}

TEST(engines_test, evidence_entered_and_retracted_gives_the_answers_of_a_fresh_engine) {
  const auto net = testing::random_network(42, {.nodes = 10, .max_parents = 3, .min_states = 2, .max_states = 3});
  junction_tree_engine kept(net, {.prune = false});
  std::mt19937_64 random(3);
  std::vector<random_case> cases;
  for (int k = 0; k < 12; ++k) cases.push_back(draw_case(net, random));
  for (int pass = 0; pass < 3; ++pass) {
    for (const auto& item : cases) {
      const auto [expected, evidence] = expected_posterior(net, item);
      if (!(evidence > 0.0)) continue;
      kept.set_evidence(item.observed);
      // Ask everything twice so that both the pruned and the propagated paths answer.
      for (int twice = 0; twice < 2; ++twice) {
        const auto got = kept.joint(item.query);
        for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(got.table.values()[i], expected[i], 1e-12);
      }
    }
  }
}

TEST(engines_test, most_probable_explanation_matches_enumeration) {
  std::mt19937_64 random(17);
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 8, .max_parents = 3, .min_states = 2, .max_states = 4});
    const auto item = draw_case(net, random);
    const auto evidence = expected_posterior(net, item).second;
    if (!(evidence > 0.0)) continue;
    std::vector<variable_id> unobserved;
    for (std::size_t i = 0; i < net.size(); ++i) {
      if (!item.observed.fixes(index_at<variable_id>(i))) unobserved.emplace_back(i);
    }
    const double best = testing::enumerate_maximum(net, unobserved, item.observed);
    SCOPED_TRACE("seed " + std::to_string(seed));
    variable_elimination ve(net);
    junction_tree_engine jt(net, {.prune = false});
    ve.set_evidence(item.observed);
    jt.set_evidence(item.observed);
    for (const auto& result : {ve.mpe(), jt.mpe()}) {
      EXPECT_NEAR(result.joint_probability, best, 1e-12 * best) << result.engine;
      EXPECT_NEAR(result.probability, best / evidence, 1e-10) << result.engine;
      // The states found have that probability (ties may be settled either way).
      evidence_set at_states = item.observed;
      for (std::size_t k = 0; k < result.variables.size(); ++k)
        at_states.hard.push_back({unobserved[k], result.states[k]});
      EXPECT_NEAR(testing::enumerate_joint(net, {}, at_states).front(), best, 1e-12 * best) << result.engine;
    }
    // Marginal MAP over the query variables: the others summed out.
    const double subset = testing::enumerate_maximum(net, item.query, item.observed);
    EXPECT_NEAR(ve.mpe(item.query).joint_probability, subset, 1e-12 * subset);
    EXPECT_NEAR(jt.mpe(item.query).joint_probability, subset, 1e-12 * subset);
  }
}

TEST(engines_test, log_space_answers_where_the_evidence_underflows_a_double) {
  // Q uniform; 400 children with P(C = 1 | Q = 0) = 0.01 and P(C = 1 | Q = 1) = 0.0101, all
  // observed 1: P(e) ≈ 1e-798, P(Q = 1 | e) = r / (1 + r) with r = 1.01^400.
  const variable q("Q", {"0", "1"});
  std::vector<cpt<double>> tables{cpt<double>(q, {}, {0.5, 0.5})};
  evidence observed;
  for (int i = 0; i < 400; ++i) {
    const variable item("C" + std::to_string(i), {"0", "1"});
    tables.emplace_back(item, std::vector<variable>{q}, std::vector<double>{0.99, 0.01, 0.9899, 0.0101});
    observed.emplace(item.name(), "1");
  }
  const auto net = bayesian_network::from_tables(tables);
  const double r = std::exp(400.0 * std::log(1.01));
  const double expected_log = std::log(0.5) + 400.0 * std::log(0.01) + std::log1p(r);
  for (const char* name : {"ve", "jt"}) {
    auto engine = make_engine(name, net);
    set_evidence(engine, observed);
    const auto p = marginal(engine, "Q");
    EXPECT_NEAR(p.probability({"1"}), r / (1.0 + r), 1e-12) << name;
    EXPECT_EQ(p.evidence_probability, 0.0) << name;  // beyond a double; the logarithm holds it
    EXPECT_NEAR(p.log_evidence_probability, expected_log, 1e-9) << name;
    EXPECT_NEAR(engine.log_probability_of_evidence(), expected_log, 1e-9) << name;
    // A Bayesian network's Z is 1: ln Z(e) is ln P(e).
    EXPECT_EQ(engine.log_partition_function(), engine.log_probability_of_evidence()) << name;
    const auto best = engine.mpe({});
    EXPECT_EQ(best.states.front().value(), 1U) << name;
    if (std::string_view(name) == "jt") {  // the batch of joints falls back on logarithms too
      junction_tree_engine jt(net);
      jt.set_evidence(engine.evidence());
      const std::vector<std::vector<variable_id>> scopes{{net.id("Q")}};
      EXPECT_NEAR(jt.joints(scopes)[0][1], r / (1.0 + r), 1e-12);
    }
    EXPECT_NEAR(best.log_joint_probability, std::log(0.5) + 400.0 * std::log(0.0101), 1e-9) << name;
  }
}

TEST(engines_test, sampling_engines_are_within_their_standard_errors_and_repeatable) {
  const auto net = testing::random_network(9, {.nodes = 9, .max_parents = 2, .min_states = 2, .max_states = 3});
  std::vector<double> likelihood{1.0, 3.0, 0.5, 2.0};
  likelihood.resize(net.variables()[5].cardinality());
  const evidence_set observed{{{variable_id(8), state_index(0)}}, {{variable_id(5), likelihood}}};
  std::vector<variable_id> free;
  for (std::size_t i = 0; i < 8; ++i) free.emplace_back(i);
  for (const char* name : {"lw", "gibbs"}) {
    inference_options options;
    options.sampling = {.samples = 200'000, .seed = 7, .threads = 1};
    auto one = make_engine(name, net, options);
    options.sampling.threads = 2;
    auto two = make_engine(name, net, options);
    one.set_evidence(observed);
    two.set_evidence(observed);
    const auto by_one = one.marginals(free);
    const auto by_two = two.marginals(free);
    for (std::size_t i = 0; i < free.size(); ++i) {
      const auto expected = expected_posterior(net, {{free[i]}, observed}).first;
      for (std::size_t k = 0; k < expected.size(); ++k) {
        const double se = by_one[i].standard_errors[k];
        EXPECT_GT(se, 0.0) << name;
        EXPECT_LE(std::abs(by_one[i].table.values()[k] - expected[k]), 4.0 * se + 1e-9)
            << name << " v" << i << " s" << k;
        EXPECT_EQ(by_one[i].table.values()[k], by_two[i].table.values()[k])
            << name << ": the thread count changed a number";
      }
    }
  }
}

TEST(engines_test, likelihood_weighting_estimates_the_probability_of_evidence) {
  const auto net = testing::random_network(21, {.nodes = 7, .max_parents = 2});
  const evidence_set observed{{{variable_id(6), state_index(1)}, {variable_id(3), state_index(0)}}, {}};
  const auto exact = expected_posterior(net, {{variable_id(0)}, observed}).second;
  likelihood_weighting lw(net, {.samples = 100'000, .seed = 3});
  lw.set_evidence(observed);
  const variable_id q[] = {variable_id(0)};
  const auto p = lw.joint(q);
  EXPECT_NEAR(p.evidence_probability, exact, 0.02 * exact);
  EXPECT_NEAR(std::exp(lw.log_probability_of_evidence()), exact, 0.02 * exact);
}

TEST(engines_test, the_samplers_take_soft_evidence_on_any_scale) {
  // Issue #49: a likelihood of 1e308 made the weights overflow (NaN), one of 1e-320 underflow.
  const auto net = testing::random_network(22, {.nodes = 6, .max_parents = 2});
  const variable_id q[] = {variable_id(0)};
  auto with_scale = [&](double scale) {
    evidence_set observed;
    observed.soft.push_back({variable_id(2), {0.25 * scale, 1.0 * scale}});
    observed.soft.push_back({variable_id(4), {1.0 * scale, 0.5 * scale}});
    return observed;
  };
  ASSERT_EQ(net.variables()[2].cardinality(), 2U);
  ASSERT_EQ(net.variables()[4].cardinality(), 2U);
  variable_elimination exact(net);
  exact.set_evidence(with_scale(1.0));
  const auto truth = exact.joint(q);
  for (const double scale : {1.0, 1e308, 1e-160, 1e-320}) {
    SCOPED_TRACE(scale);
    likelihood_weighting lw(net, {.samples = 20'000, .seed = 3});
    lw.set_evidence(with_scale(scale));
    const auto p = lw.joint(q);
    for (std::size_t s = 0; s < p.table.values().size(); ++s) {
      EXPECT_NEAR(p.table.values()[s], truth.table.values()[s], 0.03);
      EXPECT_TRUE(std::isfinite(p.standard_errors[s]) && p.standard_errors[s] > 0.0);
    }
    // ln P(evidence) on the user's scale: two likelihoods, each scaled.
    EXPECT_NEAR(p.log_evidence_probability, truth.log_evidence_probability + 2 * std::log(scale), 0.05);
    EXPECT_NEAR(lw.log_probability_of_evidence(), truth.log_evidence_probability + 2 * std::log(scale), 0.05);
    gibbs_sampling gibbs(net, {.samples = 20'000, .seed = 3});
    gibbs.set_evidence(with_scale(scale));
    const auto g = gibbs.joint(q);
    for (std::size_t s = 0; s < g.table.values().size(); ++s)
      EXPECT_NEAR(g.table.values()[s], truth.table.values()[s], 0.03);
  }
}

TEST(engines_test, junction_trees_have_the_running_intersection_property) {
  auto check = [](const bayesian_network& net, const std::string& what) {
    const junction_tree tree(net);
    const auto& cliques = tree.cliques();
    ASSERT_EQ(tree.edges().size() + 1, cliques.size()) << what << ": a tree";
    for (std::size_t v = 0; v < net.size(); ++v) {
      const variable_id id = index_at<variable_id>(v);
      std::size_t holding = 0;
      for (std::size_t item = 0; item < cliques.size(); ++item)
        holding += tree.position(item, id) < cliques[item].variables.size();
      std::size_t joined = 0;
      for (const auto& e : tree.edges()) {
        joined += std::find(e.separator.begin(), e.separator.end(), id) != e.separator.end();
      }
      // The cliques holding v are connected by edges whose separators hold v: a subtree.
      EXPECT_EQ(joined + 1, holding) << what << ": " << net.variables()[v].name();
      const auto family = tree.family_clique(id);
      for (auto parent : net.graph().parents(id)) {
        EXPECT_LT(tree.position(family, parent), cliques[family].variables.size()) << what;
      }
    }
  };
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    check(testing::random_network(seed, {.nodes = 14, .max_parents = 4}), "random " + std::to_string(seed));
  }
  for (const char* name : {"asia", "child", "insurance", "alarm", "hailfinder", "water", "pathfinder"}) {
    check(read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / (std::string(name) + ".bif")), name);
  }
}

TEST(engines_test, published_networks_agree_engine_with_engine) {
  std::mt19937_64 random(2024);
  for (const char* name : {"asia", "child", "insurance", "alarm", "hailfinder", "sachs", "pathfinder"}) {
    const auto net = read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / (std::string(name) + ".bif"));
    variable_elimination ve(net);
    junction_tree_engine jt(net, {.prune = false});
    double largest = 0.0;
    int answered = 0;
    for (int k = 0; k < 40; ++k) {
      auto item = draw_case(net, random);
      item.query.resize(1);
      ve.set_evidence(item.observed);
      jt.set_evidence(item.observed);
      try {
        const auto by_ve = ve.joint(item.query);
        const auto by_jt = jt.joint(item.query);
        for (std::size_t i = 0; i < by_ve.table.size(); ++i) {
          largest = std::max(largest, std::abs(by_ve.table.values()[i] - by_jt.table.values()[i]));
        }
        EXPECT_NEAR(by_ve.log_evidence_probability, by_jt.log_evidence_probability, 1e-12);
        ++answered;
      } catch (const impossible_evidence&) {
        EXPECT_THROW(static_cast<void>(jt.joint(item.query)), impossible_evidence) << name;
      }
    }
    EXPECT_GT(answered, 20) << name;
    EXPECT_LT(largest, 1e-14) << name;
    // Every marginal at once under ten observations equals variable elimination's.
    evidence_set observed;
    for (std::size_t v = 0; v < net.size() && observed.hard.size() < 10; v += 1 + net.size() / 10) {
      observed.hard.push_back({index_at<variable_id>(v), state_index(0)});
    }
    jt.set_evidence(observed);
    ve.set_evidence(observed);
    std::vector<variable_id> free;
    for (std::size_t v = 0; v < net.size(); ++v) {
      if (!observed.fixes(index_at<variable_id>(v))) free.emplace_back(v);
    }
    try {
      const auto all = jt.marginals(free);
      for (std::size_t i = 0; i < free.size(); i += 3) {
        const variable_id one[] = {free[i]};
        const auto expected = ve.joint(one);
        for (std::size_t s = 0; s < expected.table.size(); ++s) {
          EXPECT_NEAR(all[i].table.values()[s], expected.table.values()[s], 1e-13) << name;
        }
      }
    } catch (const impossible_evidence&) {
      const variable_id one[] = {free.front()};
      EXPECT_THROW(static_cast<void>(ve.joint(one)), impossible_evidence) << name;
    }
  }
}

TEST(engines_test, errors_name_what_is_wrong) {
  const variable coin("coin", {"heads", "tails"});
  const variable lamp("lamp", {"off", "on"});
  const auto net = bayesian_network::from_tables(
      {cpt<double>(coin, {}, {1.0, 0.0}), cpt<double>(lamp, {coin}, {0.3, 0.7, 0.5, 0.5})});
  for (const char* name : {"ve", "jt", "lw", "gibbs"}) {
    auto engine = make_engine(name, net);
    EXPECT_THAT(
        [&] {
          set_evidence(engine, {{"lamb", "on"}});
        },
        ::testing::ThrowsMessage<model_error>(HasSubstr("no variable 'lamb' (variables: coin, lamp)")));
    EXPECT_THAT(
        [&] {
          set_evidence(engine, {{"lamp", "bright"}});
        },
        ::testing::ThrowsMessage<model_error>(HasSubstr("no state 'bright'")));
    EXPECT_THAT(
        [&] {
          set_evidence(engine, {}, {{"lamp", {0.5}}});
        },
        ::testing::ThrowsMessage<model_error>(HasSubstr("has 1 weights, but 'lamp' has 2 states (off, on)")));
    EXPECT_THAT(
        [&] {
          set_evidence(engine, {}, {{"lamp", {0.0, 0.0}}});
        },
        ::testing::ThrowsMessage<model_error>(HasSubstr("every state weight 0")));
    EXPECT_THAT(
        [&] {
          set_evidence(engine, {}, {{"lamp", {-1.0, 2.0}}});
        },
        ::testing::ThrowsMessage<model_error>(HasSubstr("the weight -1")));
    EXPECT_THAT(
        [&] {
          set_evidence(engine, {{"lamp", "on"}}, {{"lamp", {1.0, 2.0}}});
        },
        ::testing::ThrowsMessage<model_error>(HasSubstr("both hard and soft evidence")));
    set_evidence(engine, {{"coin", "tails"}});
    EXPECT_THAT([&] { static_cast<void>(marginal(engine, "lamp")); },
                ::testing::ThrowsMessage<impossible_evidence>(HasSubstr("coin=tails")))
        << name;
    set_evidence(engine, {{"lamp", "on"}});
    EXPECT_THAT([&] { static_cast<void>(marginal(engine, "lamp")); },
                ::testing::ThrowsMessage<model_error>(HasSubstr("both queried and observed")));
    EXPECT_NEAR(marginal(engine, "coin").probability({"heads"}), 1.0, 1e-15) << name;
  }
  EXPECT_THAT(
      [&] { static_cast<void>(make_engine("magic", net)); },
      ::testing::ThrowsMessage<unknown_name>(HasSubstr("unknown inference engine 'magic' (known: auto, bp, gibbs")));
  auto lw = make_engine("lw", net);
  EXPECT_THAT([&] { static_cast<void>(lw.mpe({})); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("'lw' does not find the most probable explanation")));
}

TEST(engines_test, auto_is_exact_unless_the_tree_is_too_large) {
  const auto net = testing::random_network(4, {.nodes = 10});
  auto exact = make_engine("auto", net);
  EXPECT_EQ(exact.name(), "jt");
  EXPECT_THAT(exact.note(), HasSubstr("auto chose jt"));
  inference_options small;
  small.max_junction_tree_cells = 4;
  auto sampled = make_engine("auto", net, small);
  EXPECT_EQ(sampled.name(), "lw");
  EXPECT_THAT(sampled.note(), HasSubstr("auto chose lw"));
  EXPECT_THAT(sampled.note(), HasSubstr("more than the limit of 4"));
  EXPECT_THROW(static_cast<void>(make_engine("jt", net, small)), table_too_large);
}

/// A user's engine: enumeration, with nothing but the concept's members.
class enumerating_engine {
 public:
  enumerating_engine(const bayesian_network& network, const inference_options&) : network_(&network) {}
  [[nodiscard]] std::string_view name() const { return "enumerate"; }
  [[nodiscard]] const bayesian_network& network() const { return *network_; }
  [[nodiscard]] const evidence_set& evidence() const { return evidence_; }
  void set_evidence(evidence_set observed) { evidence_ = std::move(observed); }
  [[nodiscard]] posterior joint(std::span<const variable_id> query) {
    auto values = testing::enumerate_joint(*network_, query, evidence_);
    posterior p;
    std::vector<std::size_t> cards;
    for (auto id : query) {
      p.variables.push_back(network_->variables()[id.value()]);
      cards.push_back(p.variables.back().cardinality());
    }
    p.table = factor(std::vector<variable_id>(query.begin(), query.end()), cards, values);
    p.evidence_probability = p.table.normalize();
    p.log_evidence_probability = std::log(p.evidence_probability);
    p.engine = "enumerate";
    return p;
  }
  [[nodiscard]] double log_probability_of_evidence() { return std::log(joint({}).evidence_probability); }

 private:
  const bayesian_network* network_;
  evidence_set evidence_;
};

static_assert(InferenceEngine<enumerating_engine> && !MpeEngine<enumerating_engine>);
static_assert(!InferenceEngine<bayesian_network> && !InferenceEngine<factor>);

TEST(engines_test, a_users_engine_needs_only_the_concept) {
  static const register_engine<enumerating_engine> registered("enumerate");
  const auto net = testing::random_network(6, {.nodes = 6});
  auto engine = make_engine("enumerate", net);
  set_evidence(engine, {{"v5", "s0"}});
  const auto all = marginals(engine);
  EXPECT_EQ(all.size(), 5U);
  junction_tree_engine jt(net);
  set_evidence(jt, {{"v5", "s0"}});
  const auto expected = marginals(jt);
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (std::size_t k = 0; k < all[i].table.size(); ++k) {
      EXPECT_NEAR(all[i].table.values()[k], expected[i].table.values()[k], 1e-12);
    }
  }
  EXPECT_FALSE(engine.finds_mpe());
}

/// A user's engine with an option of its own, read from inference_options::engine.
class deep_engine : public enumerating_engine {
 public:
  static std::vector<option_declaration> options() {
    return {count_option("depth", 2, "how deep it looks").at_least(1)};
  }
  deep_engine(const bayesian_network& network, const inference_options& options)
      : enumerating_engine(network, options), name_("deep" + std::to_string(options.engine.count("depth"))) {}
  [[nodiscard]] std::string_view name() const { return name_; }

 private:
  std::string name_;
};

TEST(engines_test, an_engine_takes_its_declared_options_in_brackets) {
  const auto net = testing::random_network(4, {.nodes = 10});
  // A choice's options override the settings given beside it.
  EXPECT_EQ(make_engine("auto[max_cells=4]", net).name(), "lw");
  EXPECT_THROW(static_cast<void>(make_engine("jt[max_cells=4]", net)), table_too_large);
  const std::vector<variable_id> first{variable_id(0)};
  const auto answer = [&](any_inference_engine engine) {
    const auto answered = engine.joint(first);
    const auto values = answered.table.values();
    return std::vector<double>(values.begin(), values.end());
  };
  inference_options sampled;
  sampled.sampling = {.samples = 3000, .seed = 7, .threads = 1};
  EXPECT_EQ(answer(make_engine("lw[samples=3000,seed=7]", net, {.sampling = {.threads = 1}})),
            answer(make_engine("lw", net, sampled)));
  inference_options damped;
  damped.bp.damping = 0.5;
  damped.bp.schedule = bp_schedule::parallel;
  EXPECT_EQ(answer(make_engine("bp[damping=0.5,schedule=parallel]", net)), answer(make_engine("bp", net, damped)));
  EXPECT_NE(answer(make_engine("lw[seed=8]", net)), answer(make_engine("lw", net)));
  EXPECT_EQ(answer(make_engine("ve[heuristic=min-degree]", net)), answer(make_engine("ve", net)));
  EXPECT_THAT([&] { static_cast<void>(make_engine("jt[samples=5]", net)); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown jt option 'samples'")));
  EXPECT_THAT([&] { static_cast<void>(make_engine("bp[damping=1]", net)); },
              ThrowsMessage<model_error>(
                  HasSubstr("option damping of the inference engine 'bp' must be a number >= 0 and < 1, got '1'")));
  EXPECT_THAT([&] { static_cast<void>(make_engine("bp[damping=0.5", net)); },
              ThrowsMessage<model_error>(HasSubstr("expected ']' at column 15")));
  const auto listing = engine_registry::instance().listing();
  EXPECT_NE(std::find(listing.begin(), listing.end(), "jt[heuristic=min-fill,max_cells=134217728]"), listing.end());

  static const register_engine<deep_engine> registered("deep");
  EXPECT_EQ(make_engine("deep", net).name(), "deep2");
  EXPECT_EQ(make_engine("deep[depth=5]", net).name(), "deep5");
  EXPECT_THAT([&] { static_cast<void>(make_engine("deep[depth=0]", net)); },
              ThrowsMessage<model_error>(HasSubstr("option depth of the inference engine 'deep' must be")));
}

TEST(engines_test, semiring_operations_on_factors) {
  const variable_id x(0), y(1);
  const factor f({x, y}, {2, 2}, {0.1, 0.2, 0.3, 0.4});
  EXPECT_EQ(eliminate<max_product<>>(f, y), factor({x}, {2}, {0.2, 0.4}));
  EXPECT_EQ(eliminate<max_product<>>(f, x), factor({y}, {2}, {0.3, 0.4}));
  EXPECT_EQ(total_of<max_product<>>(f), 0.4);
  const factor logs({x, y}, {2, 2}, {std::log(0.1), std::log(0.2), std::log(0.3), std::log(0.4)});
  const auto summed = eliminate<log_sum_product<>>(logs, y);
  EXPECT_NEAR(std::exp(summed.values()[0]), 0.3, 1e-15);
  EXPECT_NEAR(std::exp(summed.values()[1]), 0.7, 1e-15);
  const auto product = combine<log_sum_product<>>(logs, logs);
  EXPECT_NEAR(std::exp(product.values()[3]), 0.16, 1e-15);
  EXPECT_EQ(log_sum_product<>::plus(log_sum_product<>::zero(), std::log(0.5)), std::log(0.5));
  const basic_factor<float> small({x}, {2}, {0.25F, 0.75F});
  EXPECT_EQ(total_of<sum_product<float>>(small), 1.0F);
  const cpt<float> table(variable("x", {"0", "1"}), {}, {0.25F, 0.75F});
  const variable_id no_parents[1] = {};
  EXPECT_EQ(basic_factor<float>::from_cpt(table, x, std::span<const variable_id>(no_parents, 0)), small);
}

}  // namespace
}  // namespace pgm::engines_tests
