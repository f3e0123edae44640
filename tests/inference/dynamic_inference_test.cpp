// Inference over time (pgm/inference/dynamic_inference.hpp): filtering, prediction, smoothing,
// P(evidence) and do() at a step, by the interface algorithm, against the junction tree on the
// network unrolled over every step, on random 2-TBNs and horizons up to 20.

#include "pgm/inference/dynamic_inference.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "pgm/core/dynamic_network.hpp"
#include "pgm/core/text.hpp"
#include "pgm/inference/junction_tree_engine.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/testing/random_network.hpp"
#include "support/program_test.hpp"
#include "support/random_dynamic_network.hpp"

namespace pgm {
namespace dynamic_inference_test {

using ::testing::HasSubstr;

// Random evidence at each of `horizon` steps: hard on about a third of the variables, soft on
// some, do() on a few when `interventions`.
std::vector<evidence_set> random_steps(const dynamic_network& model, std::size_t horizon, std::uint64_t seed,
                                       bool interventions) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> weight(0.1, 2.0);
  std::vector<evidence_set> steps(horizon);
  for (auto& e : steps) {
    for (std::size_t i = 0; i < model.size(); ++i) {
      const variable_id id = index_at<variable_id>(i);
      const auto states = model.variables()[i].cardinality();
      const auto roll = engine() % 12;
      if (roll < 4) {
        e.hard.push_back({id, index_at<state_index>(engine() % states)});
      } else if (roll == 4) {
        std::vector<double> weights;
        for (std::size_t s = 0; s < states; ++s) weights.push_back(weight(engine));
        e.soft.push_back({id, weights});
      } else if (roll == 5 && interventions) {
        e.intervened.push_back({id, index_at<state_index>(engine() % states)});
      }
    }
  }
  return steps;
}

// The evidence of steps [0, upto) on the unrolled network: template id i at step t is X@t.
evidence_set unrolled_evidence(const dynamic_network& model, const bayesian_network& unrolled,
                               const std::vector<evidence_set>& steps, std::size_t upto) {
  evidence_set all;
  const auto at = [&](variable_id id, std::size_t t) {
    return unrolled.id(slice_name(model.variables()[id.value()].name(), static_cast<long>(t)));
  };
  for (std::size_t t = 0; t < upto; ++t) {
    for (const auto& o : steps[t].hard) all.hard.push_back({at(o.variable, t), o.state});
    for (const auto& l : steps[t].soft) all.soft.push_back({at(l.variable, t), l.weights});
    for (const auto& o : steps[t].intervened) all.intervened.push_back({at(o.variable, t), o.state});
  }
  return all;
}

// Every template variable's marginal at step t, from the engine on the unrolled network.
std::vector<std::vector<double>> unrolled_marginals(const dynamic_network& model, junction_tree_engine<>& engine,
                                                    std::size_t t) {
  std::vector<std::vector<double>> result;
  for (const auto& v : model.variables()) {
    const variable_id one[] = {engine.model().id(slice_name(v.name(), static_cast<long>(t)))};
    const auto answer = engine.joint(one);
    result.emplace_back(answer.table.values().begin(), answer.table.values().end());
  }
  return result;
}

// An observed or intervened variable is the point it is set to (the engines are not asked about
// one: they answer with no distribution of it).
void expect_near(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b,
                 const evidence_set& step = {}) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const variable_id id = index_at<variable_id>(i);
    if (step.fixes(id)) {
      for (const auto* fixed : {&step.hard, &step.intervened}) {
        for (const auto& o : *fixed) {
          if (o.variable != id) continue;
          for (std::size_t s = 0; s < a[i].size(); ++s) EXPECT_NEAR(a[i][s], s == o.state.value() ? 1.0 : 0.0, 1e-15);
        }
      }
      continue;
    }
    ASSERT_EQ(a[i].size(), b[i].size());
    for (std::size_t s = 0; s < a[i].size(); ++s) EXPECT_NEAR(a[i][s], b[i][s], 1e-9) << "variable " << i;
  }
}

TEST(dynamic_inference_test, filtering_prediction_and_smoothing_equal_the_unrolled_junction_tree) {
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto model = testing::random_dynamic(seed, 2 + seed % 4);
    const std::size_t horizon = seed % 3 == 0 ? 20 : 1 + seed % 7;
    const std::size_t predict = seed % 4;
    const auto steps = random_steps(model, horizon, seed * 13, seed % 2 == 0);
    interface_filter filter(model);
    const auto filtered = filter.filter(steps, predict);
    const auto smoothed = filter.smooth(steps);
    ASSERT_EQ(filtered.steps.size(), horizon + predict);
    ASSERT_EQ(smoothed.steps.size(), horizon);

    const auto unrolled = model.unroll(horizon + predict);
    junction_tree_engine<> engine(unrolled);
    for (std::size_t t = 0; t < horizon + predict; ++t) {
      SCOPED_TRACE("filtering, step " + std::to_string(t));
      engine.set_evidence(unrolled_evidence(model, unrolled, steps, std::min(t + 1, horizon)));
      expect_near(filtered.steps[t], unrolled_marginals(model, engine, t), t < horizon ? steps[t] : evidence_set{});
    }
    engine.set_evidence(unrolled_evidence(model, unrolled, steps, horizon));
    EXPECT_NEAR(filtered.log_evidence_probability, engine.log_probability_of_evidence(), 1e-9);
    EXPECT_NEAR(smoothed.log_evidence_probability, engine.log_probability_of_evidence(), 1e-9);
    for (std::size_t t = 0; t < horizon; ++t) {
      SCOPED_TRACE("smoothing, step " + std::to_string(t));
      expect_near(smoothed.steps[t], unrolled_marginals(model, engine, t), steps[t]);
    }
  }
}

// The most probable sequence: its ln P(x*, e) is the unrolled tree's most probable explanation's,
// and so is every state (random tables leave no ties), observed and set ones as given.
TEST(dynamic_inference_test, the_most_probable_sequence_is_the_unrolled_trees_most_probable_explanation) {
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto model = testing::random_dynamic(seed + 50, 2 + seed % 4);
    const std::size_t horizon = seed % 3 == 0 ? 20 : 1 + seed % 7;
    const auto steps = random_steps(model, horizon, seed * 17, seed % 2 == 0);
    interface_filter filter(model);
    const auto best = filter.most_probable(steps);
    ASSERT_EQ(best.states.size(), horizon);
    const auto unrolled = model.unroll(horizon);
    junction_tree_engine<> engine(unrolled);
    engine.set_evidence(unrolled_evidence(model, unrolled, steps, horizon));
    const auto expected = engine.mpe();
    EXPECT_NEAR(best.log_probability, expected.log_joint_probability, 1e-9);
    for (std::size_t k = 0; k < expected.variables.size(); ++k) {
      const auto& name = expected.variables[k].name();
      const auto at = name.rfind('@');
      const auto t = std::stoul(name.substr(at + 1));
      const auto i = model.initial().id(name.substr(0, at)).value();
      EXPECT_EQ(best.states[t][i], expected.states[k].value()) << name;
    }
    for (std::size_t t = 0; t < horizon; ++t) {
      for (const auto& o : steps[t].hard) EXPECT_EQ(best.states[t][o.variable.value()], o.state.value());
      for (const auto& o : steps[t].intervened) EXPECT_EQ(best.states[t][o.variable.value()], o.state.value());
    }
  }
}

TEST(dynamic_inference_test, zeros_in_the_tables_and_kept_messages_between_episodes) {
  // One filter over several episodes: what a step leaves in the trees must not leak into the next.
  std::size_t impossible = 0;
  std::size_t checked = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto model = testing::random_dynamic(seed + 100, 3 + seed % 3, true);
    interface_filter filter(model);
    for (std::uint64_t episode = 0; episode < 3; ++episode) {
      const std::size_t horizon = 3 + (seed + episode) % 5;
      const auto steps = random_steps(model, horizon, seed * 101 + episode, false);
      const auto unrolled = model.unroll(horizon);
      junction_tree_engine<> engine(unrolled);
      engine.set_evidence(unrolled_evidence(model, unrolled, steps, horizon));
      if (!std::isfinite(engine.log_probability_of_evidence())) {
        EXPECT_THROW(static_cast<void>(filter.smooth(steps)), impossible_evidence);
        ++impossible;
        continue;
      }
      ++checked;
      const auto smoothed = filter.smooth(steps);
      for (std::size_t t = 0; t < horizon; ++t) {
        expect_near(smoothed.steps[t], unrolled_marginals(model, engine, t), steps[t]);
      }
    }
  }
  EXPECT_GT(impossible, 0U);
  EXPECT_GT(checked, 10U);
}

TEST(dynamic_inference_test, the_interface_is_what_the_next_slice_depends_on) {
  const auto model = testing::random_dynamic(5, 4);
  interface_filter filter(model);
  std::vector<variable_id> expected;
  for (std::size_t i = 0; i < model.size(); ++i) {
    const auto name = slice_name(model.variables()[i].name(), -1);
    for (const auto& table : model.transition_tables()) {
      const auto& parents = table.parents();
      if (std::any_of(parents.begin(), parents.end(), [&](const variable& p) { return p.name() == name; })) {
        expected.push_back(index_at<variable_id>(i));
        break;
      }
    }
  }
  EXPECT_EQ(filter.interface(), expected);
}

TEST(dynamic_inference_test, evidence_of_probability_zero_names_its_step) {
  // a stays as it was: a@-1 → a with the identity; seeing a = on after a = off is impossible.
  const variable a("a", {"off", "on"});
  const variable a_before("a@-1", {"off", "on"});
  const dynamic_network model(bayesian_network::from_tables({cpt<double>(a, {}, {0.5, 0.5})}),
                              {cpt<double>(a, {a_before}, {1.0, 0.0, 0.0, 1.0})});
  interface_filter filter(model);
  std::vector<evidence_set> steps(4);
  steps[1].hard.push_back({variable_id(0), state_index(0)});
  steps[3].hard.push_back({variable_id(0), state_index(1)});
  EXPECT_THAT([&] { static_cast<void>(filter.filter(steps)); },
              ::testing::ThrowsMessage<impossible_evidence>(HasSubstr("the evidence at step 3 (a=on)")));
  steps[3].hard.clear();
  const auto filtered = filter.filter(steps);
  EXPECT_NEAR(filtered.steps[3][0][0], 1.0, 1e-15);
  EXPECT_NEAR(filtered.log_evidence_probability, std::log(0.5), 1e-15);
}

using filter_cli_test = pgm::testing::program_test;

// pgm filter on a random 2-TBN and one episode with gaps: every row it writes is the unrolled
// junction tree's marginal, for filtering, smoothing and prediction; bad input is refused with
// nothing written.
TEST_F(filter_cli_test, writes_the_unrolled_trees_marginals_and_refuses_bad_input) {
  const auto model = testing::random_dynamic(7, 3);
  const auto model_file = file("m.json", to_json(model).dump(2));
  std::mt19937_64 engine(3);
  std::string data = "episode,t";
  for (const auto& v : model.variables()) data += "," + v.name();
  data += "\n";
  std::vector<evidence_set> steps(6);
  for (std::size_t t = 0; t < steps.size(); ++t) {
    data += "e7," + std::to_string(t);
    for (std::size_t i = 0; i < model.size(); ++i) {
      data += ",";
      if (engine() % 2 == 0) continue;  // unobserved: an empty cell
      const auto s = engine() % model.variables()[i].cardinality();
      data += model.variables()[i].states()[s];
      steps[t].hard.push_back({index_at<variable_id>(i), index_at<state_index>(s)});
    }
    data += "\n";
  }
  const auto episode = file("episode.csv", data);
  for (const std::string mode : {"", " --smooth", " --predict 3"}) {
    SCOPED_TRACE(mode);
    const auto r = run("filter --model " + model_file.string() + " --data " + episode.string() + mode +
                       " --digits 17 --out " + path("out.csv").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("ln P(evidence) = "));
    const std::size_t horizon = steps.size() + (mode == " --predict 3" ? 3 : 0);
    const auto unrolled = model.unroll(horizon);
    junction_tree_engine<> exact(unrolled);
    const auto rows = read_csv(path("out.csv"));
    ASSERT_GT(rows.rows(), 0U);
    const auto t = rows.continuous("t").values();
    std::size_t expected_rows = 0;
    for (std::size_t step = 0; step < horizon; ++step) {
      const auto upto = mode == " --smooth" ? steps.size() : std::min(step + 1, steps.size());
      exact.set_evidence(unrolled_evidence(model, unrolled, steps, upto));
      const auto marginals = unrolled_marginals(model, exact, step);
      for (std::size_t i = 0; i < model.size(); ++i) {
        if (step < steps.size() && steps[step].fixes(index_at<variable_id>(i))) continue;
        for (std::size_t s = 0; s < marginals[i].size(); ++s, ++expected_rows) {
          ASSERT_LT(expected_rows, rows.rows());
          EXPECT_EQ(t[expected_rows], static_cast<double>(step));
          EXPECT_EQ(rows.discrete("variable").label(expected_rows), model.variables()[i].name());
          EXPECT_EQ(rows.discrete("state").label(expected_rows), model.variables()[i].states()[s]);
          EXPECT_NEAR(rows.continuous("probability").values()[expected_rows], marginals[i][s], 1e-12);
        }
      }
    }
    EXPECT_EQ(rows.rows(), expected_rows);
  }
  {
    // The most probable sequence: the unrolled tree's most probable explanation, row by row.
    const auto r = run("filter --model " + model_file.string() + " --data " + episode.string() +
                       " --most-probable --out " + path("best.csv").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("ln P(x*, e) = "));
    const auto unrolled = model.unroll(steps.size());
    junction_tree_engine<> exact(unrolled);
    exact.set_evidence(unrolled_evidence(model, unrolled, steps, steps.size()));
    const auto expected = exact.mpe();
    const auto rows = read_csv(path("best.csv"));
    ASSERT_EQ(rows.rows(), expected.variables.size());
    for (std::size_t k = 0; k < rows.rows(); ++k) {
      const auto name =
          rows.discrete("variable").label(k) + "@" + text::format_double(rows.continuous("t").values()[k]);
      const auto at = std::find(expected.variables.begin(), expected.variables.end(),
                                unrolled.variables()[unrolled.id(name).value()]);
      ASSERT_NE(at, expected.variables.end()) << name;
      EXPECT_EQ(rows.discrete("state").label(k),
                at->states()[expected.states[static_cast<std::size_t>(at - expected.variables.begin())].value()])
          << name;
    }
  }
  EXPECT_EQ(run("filter --help").code, 0);
  const auto refused = [&](const std::string& csv, const std::string& extra, const std::string& message) {
    const auto bad = file("bad.csv", csv);
    expect_failure("filter --model " + model_file.string() + " --data " + bad.string() + extra + " --out " +
                       path("refused.csv").string(),
                   message, path("refused.csv"));
  };
  const auto& v0 = model.variables()[0];
  refused("episode,t," + v0.name() + "\ne,0,\ne,2,\n", "", "row 2 has t = 2 where 1 was expected");
  refused("episode,t," + v0.name() + "\ne,0,\nf,1,\n", "", "one episode is answered at a time");
  refused("episode,t,nope\ne,0,\n", "", "'nope' is not a variable of the model");
  refused("episode," + v0.name() + "\ne,\n", "", "the data have no column t");
  refused("episode,t," + v0.name() + "\ne,0,\n", " --do " + v0.name() + "@5=" + v0.states()[0], "the step must be");
  refused("episode,t," + v0.name() + "\ne,0,\n", " --smooth --predict 2", "--smooth excludes --predict");
  const auto static_model = file("s.json", to_json(model.initial()).dump(2));
  expect_failure("filter --model " + static_model.string() + " --data " + episode.string() + " --out " +
                     path("refused.csv").string(),
                 "not a dynamic one", path("refused.csv"));
}

}  // namespace dynamic_inference_test
}  // namespace pgm
