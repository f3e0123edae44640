// Counterfactuals on structural models: the twin network against abduction, action and
// prediction over every noise value on random models; a hand-worked tower; the monotone
// structural model of a network implying the network, and giving PN where Tian & Pearl's
// bounds say monotonicity puts it.

#include "pgm/causal/counterfactual.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pgm/causal/probability_of_causation.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::counterfactual_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

std::vector<std::string> labels(std::size_t n) {
  std::vector<std::string> out;
  for (std::size_t s = 0; s < n; ++s) out.push_back(std::to_string(s));
  return out;
}

/// Variables v0 … v(n−1) in topological order, each with up to two earlier parents, a noise of
/// one to four states (some of them impossible) and a random function.
structural_model random_structural_model(unsigned seed) {
  std::mt19937 rng(seed);
  const auto below = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  const auto n = 3 + below(3);
  std::vector<variable> variables;
  std::vector<structural_equation> equations;
  for (std::size_t i = 0; i < n; ++i) {
    variables.emplace_back("v" + std::to_string(i), labels(2 + below(2)));
    structural_equation e;
    for (std::size_t p = 0; p < i; ++p) {
      if (e.parents.size() < 2 && below(2) == 0) e.parents.push_back(index_at<variable_id>(p));
    }
    e.noise.resize(1 + below(4));
    double total = 0;
    for (auto& p : e.noise) total += p = below(4) == 0 ? 0.0 : std::exponential_distribution<double>(1)(rng);
    if (total == 0) e.noise[0] = total = 1;
    for (auto& p : e.noise) p /= total;
    std::size_t configurations = 1;
    for (const auto p : e.parents) configurations *= variables[p.value()].cardinality();
    for (std::size_t c = 0; c < configurations * e.noise.size(); ++c)
      e.values.push_back(below(variables[i].cardinality()));
    equations.push_back(std::move(e));
  }
  return {std::move(variables), std::move(equations)};
}

/// The states of every variable given the noises and what is forced, in topological order.
std::vector<std::size_t> solve(const structural_model& m, const std::vector<std::size_t>& noise,
                               const std::vector<int>& forced) {
  std::vector<std::size_t> x(m.size());
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (forced[i] >= 0) {
      x[i] = static_cast<std::size_t>(forced[i]);
      continue;
    }
    std::size_t c = 0;
    for (const auto p : m.equation(index_at<variable_id>(i)).parents) c = c * m.at(p).cardinality() + x[p.value()];
    x[i] = m.value(index_at<variable_id>(i), c, noise[i]);
  }
  return x;
}

/// P(query in the intervened world | observed), and P(observed), by every joint noise value.
std::pair<std::vector<double>, double> enumerate(const structural_model& m, const std::vector<std::size_t>& query,
                                                 const std::vector<int>& observed, const std::vector<int>& forced) {
  std::size_t cells = 1;
  for (const auto q : query) cells *= m.variables()[q].cardinality();
  std::vector<double> joint(cells, 0.0);
  double evidence = 0;
  std::vector<std::size_t> noise(m.size(), 0);
  const std::vector<int> none(m.size(), -1);
  while (true) {
    double w = 1;
    for (std::size_t i = 0; i < m.size(); ++i) w *= m.equation(index_at<variable_id>(i)).noise[noise[i]];
    const auto factual = solve(m, noise, none);
    bool consistent = true;
    for (std::size_t i = 0; i < m.size(); ++i)
      consistent = consistent && (observed[i] < 0 || factual[i] == static_cast<std::size_t>(observed[i]));
    if (consistent) {
      evidence += w;
      const auto world = solve(m, noise, forced);
      std::size_t at = 0;
      for (const auto q : query) at = at * m.variables()[q].cardinality() + world[q];
      joint[at] += w;
    }
    std::size_t k = 0;
    for (; k < m.size(); ++k) {
      if (++noise[k] < m.equation(index_at<variable_id>(k)).noise.size()) break;
      noise[k] = 0;
    }
    if (k == m.size()) break;
  }
  for (auto& p : joint) p /= evidence;
  return {joint, evidence};
}

TEST(counterfactual_test, the_twin_network_equals_abduction_action_and_prediction_on_random_models) {
  std::size_t checked = 0;
  for (unsigned seed = 0; seed < 400; ++seed) {
    SCOPED_TRACE(seed);
    const auto m = random_structural_model(seed);
    std::mt19937 rng(seed + 1000);
    const auto below = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
    std::vector<int> observed(m.size(), -1);
    std::vector<int> forced(m.size(), -1);
    evidence e;
    intervention set;
    for (std::size_t i = 0; i < m.size(); ++i) {
      const auto& v = m.variables()[i];
      if (below(3) == 0) {
        observed[i] = static_cast<int>(below(v.cardinality()));
        e[v.name()] = v.states()[static_cast<std::size_t>(observed[i])];
      }
      if (below(4) == 0 || (i == 0 && set.empty())) {
        forced[i] = static_cast<int>(below(v.cardinality()));
        set[v.name()] = v.states()[static_cast<std::size_t>(forced[i])];
      }
    }
    std::vector<std::size_t> query{m.size() - 1};
    if (below(2) == 0) query.insert(query.begin(), below(m.size() - 1));
    std::vector<std::string> names;
    for (const auto q : query) names.push_back(m.variables()[q].name());
    const auto [truth, p_evidence] = enumerate(m, query, observed, forced);
    if (!(p_evidence > 0)) {
      EXPECT_THROW((void)counterfactual_query(m, names, e, set), impossible_evidence);
      continue;
    }
    const auto answer = counterfactual_query(m, names, e, set);
    ASSERT_EQ(answer.table.values().size(), truth.size());
    for (std::size_t k = 0; k < truth.size(); ++k) EXPECT_NEAR(answer.table.values()[k], truth[k], 1e-12) << k;
    EXPECT_NEAR(answer.evidence_probability, p_evidence, 1e-12);
    ++checked;
  }
  EXPECT_GT(checked, 200u);
}

TEST(counterfactual_test, a_fallen_tower_would_have_stood_as_worked_by_hand) {
  // xOff1 ∈ {0, 1, 2} uniform; the tower stands (1) or falls (0) by its offset and a noise of
  // three units: u0 (0.5) always stands, u1 (0.3) stands unless the offset is 2, u2 (0.2) never.
  const variable offset("xOff1", {"0", "1", "2"});
  const variable stands("onTop1", {"0", "1"});
  const structural_model m(
      {offset, stands},
      {{.parents = {}, .noise = {1.0 / 3, 1.0 / 3, 1.0 / 3}, .values = {0, 1, 2}},
       {.parents = {index_at<variable_id>(0)}, .noise = {0.5, 0.3, 0.2}, .values = {1, 1, 0, 1, 1, 0, 1, 0, 0}}});
  // It fell at offset 2: the unit was u1 or u2 (0.3 : 0.2); at offset 0, u1 stands.
  const std::string asked[] = {"onTop1"};
  const auto answer = counterfactual_query(m, asked, {{"xOff1", "2"}, {"onTop1", "0"}}, {{"xOff1", "0"}});
  EXPECT_NEAR(answer.probability({"1"}), 0.3 / 0.5, 1e-15);
  EXPECT_NEAR(answer.evidence_probability, 0.5 / 3, 1e-15);
  // The network alone says P(stands | do(xOff1 = 0)) = 0.8: the counterfactual is not that.
  EXPECT_NEAR(m.network().table("onTop1").probability("1", {"0"}), 0.8, 1e-15);
  // Only what the intervention reaches is copied, with only its noise.
  const auto twin = make_twin_network(m, {{"xOff1", "0"}});
  EXPECT_EQ(twin.network.size(), 5u);  // xOff1, onTop1, xOff1*, onTop1*, U_onTop1
  EXPECT_EQ(twin.network.variables()[twin.intervened[1].value()].name(), "onTop1*");
  const auto no_reach = make_twin_network(m, {{"onTop1", "1"}});
  EXPECT_EQ(no_reach.network.size(), 3u);
  EXPECT_EQ(no_reach.intervened[0], no_reach.network.id("xOff1"));
}

TEST(counterfactual_test, what_the_intervention_fixes_or_does_not_reach_keeps_its_state) {
  const auto m = random_structural_model(7);
  const auto& first = m.variables().front();
  const auto& last = m.variables().back();
  const std::string asked[] = {first.name(), last.name()};
  const auto answer = counterfactual_query(m, asked, {}, {{first.name(), first.states()[1]}});
  for (std::size_t s = 0; s < last.cardinality(); ++s) {
    EXPECT_EQ(answer.probability({first.states()[0], last.states()[s]}), 0.0);
  }
  // Observed and out of the intervention's reach: as observed.
  const std::string only_first[] = {first.name()};
  const auto seen =
      counterfactual_query(m, only_first, {{first.name(), first.states()[1]}}, {{last.name(), last.states()[0]}});
  EXPECT_EQ(seen.probability({first.states()[1]}), 1.0);
  EXPECT_NEAR(seen.evidence_probability, m.network().table(first.name()).column(index_at<config_index>(0))[1], 1e-15);
}

TEST(counterfactual_test, a_question_the_model_cannot_answer_is_refused) {
  const auto m = random_structural_model(3);
  const auto& v = m.variables().back().name();
  const std::string twice[] = {v, v};
  EXPECT_THAT([&] { (void)counterfactual_query(m, twice, {}, {}); },
              ThrowsMessage<model_error>(HasSubstr("names '" + v + "' twice")));
  const std::string unknown[] = {"nowhere"};
  EXPECT_THAT([&] { (void)counterfactual_query(m, unknown, {}, {}); },
              ThrowsMessage<model_error>(HasSubstr("nowhere")));
  const std::string asked[] = {v};
  EXPECT_THAT(
      [&] {
        (void)counterfactual_query(m, asked, {}, {{"v0", "7"}});
      },
      ThrowsMessage<model_error>(HasSubstr("'7'")));
  EXPECT_THAT(
      [&] {
        (void)counterfactual_query(m, asked, {{"v0", "9"}}, {});
      },
      ThrowsMessage<model_error>(HasSubstr("'9'")));
  EXPECT_THROW((void)counterfactual_query(m, {}, {}, {}), model_error);
}

TEST(counterfactual_test, a_structural_model_refuses_what_is_not_one) {
  const variable x("X", {"0", "1"});
  const auto x_id = index_at<variable_id>(0);
  EXPECT_THAT(
      [&] {
        structural_model({x}, {{.noise = {0.5, 0.6}, .values = {0, 1}}});
      },
      ThrowsMessage<model_error>(HasSubstr("sums to 1.1")));
  EXPECT_THAT([&] { structural_model({x}, {{.noise = {1.0}, .values = {2}}}); },
              ThrowsMessage<model_error>(HasSubstr("gives state 2")));
  EXPECT_THAT(
      [&] {
        structural_model({x}, {{.noise = {1.0}, .values = {0, 1}}});
      },
      ThrowsMessage<model_error>(HasSubstr("has 2 values")));
  EXPECT_THROW(structural_model({x}, {{.parents = {x_id}, .noise = {1.0}, .values = {0, 1}}}), not_a_dag);
  EXPECT_THAT([&] { structural_model({x}, {}); }, ThrowsMessage<model_error>(HasSubstr("one equation per variable")));
}

TEST(counterfactual_test, the_monotone_model_of_a_network_implies_the_network) {
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    SCOPED_TRACE(seed);
    const auto network = testing::random_network(seed, {.nodes = 6, .max_parents = 3, .max_states = 4});
    const auto m = monotone_structural_model(network);
    const auto implied = m.network();
    for (std::size_t i = 0; i < network.size(); ++i) {
      const auto& name = network.variables()[i].name();
      const auto& table = network.table(name);
      const auto& back = implied.table(name);
      ASSERT_EQ(back.parents(), table.parents());
      for (std::size_t k = 0; k < table.values().size(); ++k) EXPECT_NEAR(back.values()[k], table.values()[k], 1e-15);
      std::size_t bound = table.configurations() * (table.child_cardinality() - 1) + 1;
      EXPECT_LE(m.equation(index_at<variable_id>(i)).noise.size(), bound);
    }
  }
}

TEST(counterfactual_test, the_monotone_twin_of_a_network_equals_the_twin_of_its_monotone_model) {
  std::size_t checked = 0;
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    SCOPED_TRACE(seed);
    const auto network = testing::random_network(seed, {.nodes = 6, .max_parents = 2, .max_states = 3});
    const auto m = monotone_structural_model(network);
    std::mt19937 rng(static_cast<unsigned>(seed));
    const auto pick = [&](std::size_t i) {
      const auto& v = network.variables()[i];
      return std::pair{v.name(), v.states()[rng() % v.cardinality()]};
    };
    evidence e{pick(5), pick(rng() % 5)};
    const intervention set{pick(rng() % 3)};
    const std::string asked[] = {network.variables()[4].name(), network.variables()[5].name()};
    try {
      const auto expected = counterfactual_query(m, asked, e, set);
      const auto answer = monotone_counterfactual_query(network, asked, e, set);
      for (std::size_t k = 0; k < expected.table.values().size(); ++k) {
        EXPECT_NEAR(answer.table.values()[k], expected.table.values()[k], 1e-12);
      }
      ++checked;
    } catch (const impossible_evidence&) {
      EXPECT_THROW((void)monotone_counterfactual_query(network, asked, e, set), impossible_evidence);
    }
  }
  EXPECT_GT(checked, 50u);
}

TEST(counterfactual_test, the_monotone_model_puts_pn_at_the_lower_bound_for_an_exogenous_cause) {
  // Pearl, Causality (2009), Theorem 9.2.14: under exogeneity and monotonicity PN is the excess
  // risk ratio, the lower end of Tian & Pearl's bounds.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  const variable x("X", {"0", "1"});
  const variable y("Y", {"0", "1"});
  for (int trial = 0; trial < 200; ++trial) {
    const double px = unit(rng);
    const double y_if_0 = unit(rng);
    const double y_if_1 = unit(rng);
    const auto network = bayesian_network::from_tables(
        {cpt<double>(x, {}, {1 - px, px}), cpt<double>(y, {x}, {1 - y_if_0, y_if_0, 1 - y_if_1, y_if_1})});
    const auto m = monotone_structural_model(network);
    for (const std::string effect : {"0", "1"}) {
      const std::string asked[] = {"Y"};
      const auto answer = counterfactual_query(m, asked, {{"X", "1"}, {"Y", effect}}, {{"X", "0"}});
      const double pn = 1 - answer.probability({effect});
      const auto bounds = bound_causation(causation_terms_of(network, "X", "1", "0", "Y", effect));
      EXPECT_NEAR(pn, bounds.pn_lower, 1e-12);
      const double p1 = effect == "1" ? y_if_1 : 1 - y_if_1;
      const double p0 = effect == "1" ? y_if_0 : 1 - y_if_0;
      EXPECT_NEAR(pn, std::max(0.0, (p1 - p0) / p1), 1e-12);
    }
  }
}

}  // namespace
}  // namespace pgm::counterfactual_tests
