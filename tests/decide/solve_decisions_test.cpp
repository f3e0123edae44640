// Influence diagrams: the published oil wildcatter, and on random small diagrams the MEU and
// policies against enumeration of the definition (sum over what is unknown, max over each
// decision in turn) and of every deterministic policy.

#include "pgm/decide/solve_decisions.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "pgm/core/mixed_radix.hpp"
#include "support/influence_diagrams.hpp"

namespace pgm::solve_decisions_tests {
namespace {

using testing::best_over_every_policy;
using ::testing::ElementsAre;
using testing::evidence_states;
using testing::expected_utility_by_enumeration;
using ::testing::HasSubstr;
using testing::oil_wildcatter;
using testing::term_at;
using ::testing::ThrowsMessage;

TEST(solve_decisions_test, the_oil_wildcatter_tests_and_drills_unless_the_sounding_is_diffuse) {
  const auto d = oil_wildcatter();
  for (const bool limited : {false, true}) {
    const auto solution = solve_decisions(d, {}, {.limited_memory = limited});
    EXPECT_NEAR(solution.meu, 22.5, 1e-12);
    ASSERT_EQ(solution.policies.size(), 2u);
    EXPECT_EQ(d.at(solution.policies[0].decision).name(), "Test");
    EXPECT_THAT(solution.policies[0].actions, ElementsAre(0));
    EXPECT_EQ(solution.policies[1].observed, (std::vector{d.id("Test"), d.id("Seismic")}));
    // Tested: closed, open -> drill, diffuse -> not; untested: drill (EU 20 > 0).
    EXPECT_THAT(solution.policies[1].actions, ElementsAre(0, 0, 1, 0, 0, 0));
    EXPECT_EQ(solution.local_optimum, limited);
  }
  // Drilling blind is worth 0.5·-70 + 0.3·50 + 0.2·200 = 20; the sounding, 2.5 more.
  EXPECT_NEAR(solve_decisions(d, {{"Oil", "wet"}}).meu, 50, 1e-12);
  EXPECT_NEAR(value_of_information(d, "Oil", "Drill"), 0.5 * 0 + 0.3 * 50 + 0.2 * 200 - 22.5, 1e-12);
}

TEST(solve_decisions_test, evidence_must_come_before_every_decision_and_be_possible) {
  const auto d = oil_wildcatter();
  EXPECT_THAT(
      [&] {
        (void)solve_decisions(d, {{"Seismic", "open"}});
      },
      ThrowsMessage<model_error>(HasSubstr("'Seismic' depends on the decision 'Test'")));
  EXPECT_THAT(
      [&] {
        (void)solve_decisions(d, {{"Drill", "yes"}});
      },
      ThrowsMessage<model_error>(HasSubstr("'Drill' is a decision")));
  EXPECT_THAT([&] { (void)value_of_information(d, "Seismic", "Test"); },
              ThrowsMessage<model_error>(HasSubstr("'Seismic' depends on the decision 'Test'")));
}

TEST(solve_decisions_test, a_malformed_diagram_is_refused_by_name) {
  influence_diagram d;
  const auto a = d.add_chance(variable("A", {"0", "1"}));
  const auto b = d.add_decision(variable("B", {"0", "1"}));
  EXPECT_THAT([&] { d.set_table(b, {}, {0.5, 0.5}); }, ThrowsMessage<model_error>(HasSubstr("'B' is a decision")));
  EXPECT_THAT([&] { d.set_table(a, {}, {0.5, 0.6}); }, ThrowsMessage<model_error>(HasSubstr("sums to 1.1")));
  d.set_table(a, {b}, {0.5, 0.5, 0.2, 0.8});
  EXPECT_THROW(d.set_observed(b, {a}), not_a_dag);
  EXPECT_THAT([&] { d.add_utility("A", {}, {1}); }, ThrowsMessage<model_error>(HasSubstr("'A' is declared twice")));
  EXPECT_THAT([&] { d.validate(); }, ThrowsMessage<model_error>(HasSubstr("no utility")));
  EXPECT_THAT([&] { d.add_utility("U", {a}, {1, std::nan("")}); }, ThrowsMessage<model_error>(HasSubstr("not finite")));
}

// ---- random diagrams against enumeration ----

struct random_diagram {
  influence_diagram diagram;
  evidence observed;
};

/// 3–5 chance variables and 2–3 decisions in a random order, each with up to two parents
/// among those before it; with `recall`, every decision also observes what the one before it
/// observed and chose. Evidence, sometimes, on a chance variable before the first decision.
random_diagram make_random(unsigned seed, bool recall) {
  std::mt19937 rng(seed);
  const auto below = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  std::vector<bool> is_decision(below(3) + 3, false);
  for (std::size_t k = 0, decisions = below(2) + 2; k < decisions; ++k) {
    is_decision.insert(is_decision.begin() + static_cast<std::ptrdiff_t>(below(is_decision.size()) + 1), true);
  }
  random_diagram r;
  auto& d = r.diagram;
  std::vector<variable_id> ids;
  for (std::size_t i = 0; i < is_decision.size(); ++i) {
    std::vector<std::string> states(below(2) + 2);
    for (std::size_t s = 0; s < states.size(); ++s) states[s] = std::to_string(s);
    const variable v((is_decision[i] ? "D" : "X") + std::to_string(i), states);
    ids.push_back(is_decision[i] ? d.add_decision(v) : d.add_chance(v));
  }
  std::vector<variable_id> previous_decision_family;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    std::vector<variable_id> parents;
    for (std::size_t tries = below(3); i > 0 && tries-- > 0;) {
      const auto p = ids[below(i)];
      if (std::find(parents.begin(), parents.end(), p) == parents.end()) parents.push_back(p);
    }
    if (is_decision[i]) {
      if (recall) {
        for (const auto p : previous_decision_family) {
          if (std::find(parents.begin(), parents.end(), p) == parents.end()) parents.push_back(p);
        }
        previous_decision_family = parents;
        previous_decision_family.push_back(ids[i]);
      }
      d.set_observed(ids[i], parents);
      continue;
    }
    std::size_t columns = 1;
    for (const auto p : parents) columns *= d.at(p).cardinality();
    std::vector<double> table;
    for (std::size_t c = 0; c < columns; ++c) {
      std::vector<double> column(d.at(ids[i]).cardinality());
      double total = 0;
      for (auto& x : column) total += x = std::uniform_real_distribution<double>(0.05, 1)(rng);
      for (auto x : column) table.push_back(x / total);
    }
    d.set_table(ids[i], parents, table);
  }
  for (std::size_t u = 0, count = below(2) + 1; u < count; ++u) {
    // Each utility sees a decision, so that few decisions are without consequence.
    std::vector<variable_id> decisions;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (is_decision[i]) decisions.push_back(ids[i]);
    }
    std::vector<variable_id> parents{decisions[below(decisions.size())]};
    for (std::size_t tries = below(3); tries-- > 0;) {
      const auto p = ids[below(ids.size())];
      if (std::find(parents.begin(), parents.end(), p) == parents.end()) parents.push_back(p);
    }
    std::size_t cells = 1;
    for (const auto p : parents) cells *= d.at(p).cardinality();
    std::vector<double> values(cells);
    for (auto& v : values) v = std::uniform_real_distribution<double>(-10, 10)(rng);
    d.add_utility("U" + std::to_string(u), parents, values);
  }
  if (below(2) == 0) {
    for (std::size_t i = 0; i < ids.size() && !is_decision[i]; ++i) {
      if (below(2) == 0) r.observed[d.at(ids[i]).name()] = std::to_string(below(d.at(ids[i]).cardinality()));
    }
  }
  return r;
}

/// The definition: Σ over what no decision sees, max over the last decision, Σ over what it
/// alone saw, …, max over the first, Σ over what it saw — by plain recursion over every
/// configuration, with every decision knowing everything before it.
double meu_by_definition(const influence_diagram& d, const evidence& e) {
  const auto order = d.decision_order();
  std::vector<bool> placed(d.size(), false);
  std::vector<std::size_t> sequence;  // variables in the order they are fixed
  const auto fixed = evidence_states(d, e);
  for (const auto& [id, state] : fixed) placed[id] = true;
  for (const auto decision : order) {
    for (const auto p : d.parents(decision)) {
      if (!placed[p.value()]) sequence.push_back(p.value()), placed[p.value()] = true;
    }
    sequence.push_back(decision.value());
    placed[decision.value()] = true;
  }
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (!placed[i]) sequence.push_back(i);
  }
  std::vector<std::size_t> x(d.size(), 0);
  for (const auto& [id, state] : fixed) x[id] = state;
  double evidence_probability = 0;
  std::function<double(std::size_t)> value = [&](std::size_t k) -> double {
    if (k == sequence.size()) {
      const auto t = term_at(d, x);
      return t.probability * t.utility;
    }
    const auto v = sequence[k];
    const bool decision = d.is_decision(index_at<variable_id>(v));
    double result = decision ? -std::numeric_limits<double>::infinity() : 0;
    for (std::size_t s = 0; s < d.at(index_at<variable_id>(v)).cardinality(); ++s) {
      x[v] = s;
      const double w = value(k + 1);
      result = decision ? std::max(result, w) : result + w;
    }
    return result;
  };
  // P(evidence) does not depend on the decisions: enumerate it with every decision at 0.
  std::function<void(std::size_t)> chance = [&](std::size_t v) {
    if (v == d.size()) {
      evidence_probability += term_at(d, x).probability;
      return;
    }
    const bool set = d.is_decision(index_at<variable_id>(v)) ||
                     std::any_of(fixed.begin(), fixed.end(), [&](const auto& f) { return f.first == v; });
    if (set) return chance(v + 1);
    for (std::size_t s = 0; s < d.at(index_at<variable_id>(v)).cardinality(); ++s) {
      x[v] = s;
      chance(v + 1);
    }
  };
  const double total = value(0);
  std::fill(x.begin(), x.end(), 0);
  for (const auto& [id, state] : fixed) x[id] = state;
  chance(0);
  return total / evidence_probability;
}

std::size_t policy_count(const influence_diagram& d) {
  double count = 1;
  for (const auto decision : d.decision_order()) {
    std::size_t cells = 1;
    for (const auto o : d.parents(decision)) cells *= d.at(o).cardinality();
    count *= std::pow(static_cast<double>(d.at(decision).cardinality()), static_cast<double>(cells));
  }
  return count > 4096 ? 0 : static_cast<std::size_t>(count);
}

TEST(solve_decisions_test, perfect_recall_equals_the_definition_on_random_diagrams) {
  for (unsigned seed = 0; seed < 60; ++seed) {
    SCOPED_TRACE(seed);
    for (const bool recall : {false, true}) {
      const auto r = make_random(seed, recall);
      const auto solution = solve_decisions(r.diagram, r.observed);
      const double expected = meu_by_definition(r.diagram, r.observed);
      EXPECT_NEAR(solution.meu, expected, 1e-12 * std::max(1.0, std::abs(expected)));
      // The policies reach it, by pgm's evaluation and by enumeration.
      EXPECT_NEAR(expected_utility(r.diagram, solution.policies, r.observed), expected,
                  1e-12 * std::max(1.0, std::abs(expected)));
      EXPECT_NEAR(expected_utility_by_enumeration(r.diagram, solution.policies, r.observed), expected,
                  1e-12 * std::max(1.0, std::abs(expected)));
      EXPECT_FALSE(solution.local_optimum);
    }
  }
}

TEST(solve_decisions_test, single_policy_updating_climbs_and_reaches_the_optimum_with_perfect_recall) {
  std::size_t enumerated = 0;
  for (unsigned seed = 0; seed < 50; ++seed) {
    SCOPED_TRACE(seed);
    for (const bool recall : {false, true}) {
      const auto r = make_random(seed, recall);
      if (policy_count(r.diagram) == 0) continue;
      ++enumerated;
      const auto solution = solve_decisions(r.diagram, r.observed, {.limited_memory = true});
      const double best = best_over_every_policy(r.diagram, r.observed);
      const double tolerance = 1e-12 * std::max(1.0, std::abs(best));
      EXPECT_TRUE(solution.local_optimum);
      EXPECT_GE(solution.meu, solution.start_expected_utility - tolerance);
      EXPECT_LE(solution.meu, best + tolerance);
      EXPECT_NEAR(expected_utility_by_enumeration(r.diagram, solution.policies, r.observed), solution.meu, tolerance);
      if (recall) {
        EXPECT_NEAR(solution.meu, best, tolerance);
        EXPECT_NEAR(solve_decisions(r.diagram, r.observed).meu, best, tolerance);
      }
    }
  }
  EXPECT_GT(enumerated, 50u);  // most diagrams are small enough to enumerate
}

TEST(solve_decisions_test, information_is_never_worth_less_than_nothing_with_perfect_recall) {
  for (unsigned seed = 0; seed < 30; ++seed) {
    SCOPED_TRACE(seed);
    const auto r = make_random(seed, true);
    const auto first = r.diagram.decision_order().front();
    for (std::size_t i = 0; i < r.diagram.size(); ++i) {
      const auto x = index_at<variable_id>(i);
      if (r.diagram.is_decision(x) || r.observed.contains(r.diagram.at(x).name()) ||
          !r.diagram.graph().path_between(first, x).empty()) {
        continue;
      }
      const double voi =
          value_of_information(r.diagram, r.diagram.at(x).name(), r.diagram.at(first).name(), r.observed);
      EXPECT_GE(voi, -1e-12);
      const auto informed = observing(r.diagram, x, first);
      EXPECT_NEAR(voi, meu_by_definition(informed, r.observed) - meu_by_definition(r.diagram, r.observed), 1e-10);
    }
  }
}

}  // namespace
}  // namespace pgm::solve_decisions_tests
