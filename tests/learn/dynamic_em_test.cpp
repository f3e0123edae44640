// EM for a dynamic network's tied tables (pgm/learn/dynamic_em.hpp), against formulations of its
// own: complete episodes give the counted fit; the E-step's expected counts and log-likelihood
// equal the sums over every completion of each episode's missing values; for a hidden Markov
// model the iterations equal Baum–Welch written out by hand (forward–backward); the objective
// rises and the result does not depend on the threads.

#include "pgm/learn/dynamic_em.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "pgm/io/csv.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/learn/parameter_prior.hpp"
#include "support/long_form.hpp"
#include "support/program_test.hpp"
#include "support/random_dynamic_network.hpp"

namespace pgm {
namespace dynamic_em_test {

using ::testing::HasSubstr;

/// A table's family as (template variable, steps back), the child first.
std::vector<std::pair<std::size_t, std::size_t>> family_of(const cpt<double>& table, const dynamic_network& model) {
  const auto index_of = [&](const std::string& name) {
    for (std::size_t i = 0; i < model.size(); ++i) {
      if (model.variables()[i].name() == name) return i;
    }
    ADD_FAILURE() << "no template variable " << name;
    return std::size_t{0};
  };
  std::vector<std::pair<std::size_t, std::size_t>> family{{index_of(table.child().name()), 0}};
  for (const auto& p : table.parents()) {
    const auto at = p.name().find("@-1");
    family.emplace_back(index_of(p.name().substr(0, at)), at == std::string::npos ? 0 : 1);
  }
  return family;
}

const cpt<double>& table_at(const dynamic_network& model, std::size_t t, std::size_t i) {
  return t == 0 ? model.initial().tables()[i] : model.transition_tables()[i];
}

/// The cell (u·j + x) of table (t, i) for a completed episode.
std::size_t cell_at(const dynamic_network& model, std::size_t t, std::size_t i,
                    const std::vector<std::vector<std::uint32_t>>& episode) {
  const auto& table = table_at(model, t, i);
  const auto family = family_of(table, model);
  std::vector<std::size_t> parents;
  for (std::size_t k = 1; k < family.size(); ++k) parents.push_back(episode[t - family[k].second][family[k].first]);
  return table.configuration(parents).value() * table.child_cardinality() + episode[t][i];
}

/// E[M] of every table and ln P(observed values) by enumerating every completion of every
/// episode's missing values under `model`.
struct enumerated {
  std::vector<std::vector<double>> initial, transition;
  double log_likelihood = 0.0;
};

enumerated enumerate(const dynamic_network& model, const testing::long_form& data) {
  enumerated out;
  for (std::size_t i = 0; i < model.size(); ++i) {
    out.initial.emplace_back(model.initial().tables()[i].size());
    out.transition.emplace_back(model.transition_tables()[i].size());
  }
  for (const auto& observed : data.codes) {
    std::vector<std::pair<std::size_t, std::size_t>> gaps;
    for (std::size_t t = 0; t < observed.size(); ++t) {
      for (std::size_t i = 0; i < model.size(); ++i) {
        if (observed[t][i] == testing::long_form::missing) gaps.emplace_back(t, i);
      }
    }
    std::vector<std::pair<std::vector<std::vector<std::uint32_t>>, double>> completions;
    auto episode = observed;
    std::function<void(std::size_t)> complete = [&](std::size_t g) {
      if (g == gaps.size()) {
        double p = 1.0;
        for (std::size_t t = 0; t < episode.size(); ++t) {
          for (std::size_t i = 0; i < model.size(); ++i)
            p *= table_at(model, t, i).values()[cell_at(model, t, i, episode)];
        }
        completions.emplace_back(episode, p);
        return;
      }
      const auto [t, i] = gaps[g];
      for (std::uint32_t x = 0; x < model.variables()[i].cardinality(); ++x) {
        episode[t][i] = x;
        complete(g + 1);
      }
    };
    complete(0);
    double evidence = 0.0;
    for (const auto& [completed, p] : completions) evidence += p;
    out.log_likelihood += std::log(evidence);
    for (const auto& [completed, p] : completions) {
      for (std::size_t t = 0; t < completed.size(); ++t) {
        for (std::size_t i = 0; i < model.size(); ++i) {
          (t == 0 ? out.initial : out.transition)[i][cell_at(model, t, i, completed)] += p / evidence;
        }
      }
    }
  }
  return out;
}

void expect_tables_near(const dynamic_network& got, const dynamic_network& expected, double tolerance) {
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t t = 0; t < 2; ++t) {
    for (std::size_t i = 0; i < got.size(); ++i) {
      const auto a = table_at(got, t, i).values();
      const auto b = table_at(expected, t, i).values();
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t c = 0; c < a.size(); ++c) {
        EXPECT_NEAR(a[c], b[c], tolerance) << (t == 0 ? "first slice " : "transition ") << i << " cell " << c;
      }
    }
  }
}

TEST(dynamic_em_test, complete_episodes_give_the_counted_fit) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto model = testing::random_dynamic(seed, 2 + seed % 3);
    const auto data = testing::sample_long_form(model, 80, 6, seed, seed % 2 == 0);
    dynamic_fit_options options;
    options.fit.prior = bdeu_prior(2.0);
    const auto em = dynamic_expectation_maximization(structure_of(model), data.data, options);
    expect_tables_near(em.model, fit_dynamic(structure_of(model), data.data, options), 1e-12);
    EXPECT_TRUE(em.converged);
    EXPECT_EQ(em.incomplete_patterns, 0u);
    EXPECT_EQ(em.episodes, 80u);
  }
}

TEST(dynamic_em_test, the_expected_counts_and_likelihood_equal_every_completion_summed) {
  for (std::uint64_t seed = 10; seed <= 15; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto model = testing::random_dynamic(seed, 2 + seed % 2);
    const auto data = testing::with_gaps(testing::sample_long_form(model, 25, 4, seed, seed % 2 == 1), model, seed, 3);
    dynamic_em_options em;
    em.start = &model;
    em.em.max_iterations = 0;  // the E-step under `model` only
    em.em.threads = 2;
    const auto result = dynamic_expectation_maximization(structure_of(model), data.data, {}, em);
    const auto expected = enumerate(model, data);
    EXPECT_NEAR(result.log_likelihood, expected.log_likelihood, 1e-9 * std::abs(expected.log_likelihood));
    EXPECT_GT(result.incomplete_patterns, 0u);
    for (std::size_t i = 0; i < model.size(); ++i) {
      const auto first = result.initial[i].counts();
      const auto later = result.transition[i].counts();
      for (std::size_t c = 0; c < first.size(); ++c) EXPECT_NEAR(first[c], expected.initial[i][c], 1e-9) << i;
      for (std::size_t c = 0; c < later.size(); ++c) EXPECT_NEAR(later[c], expected.transition[i][c], 1e-9) << i;
    }
  }
}

/// A hidden Markov model: H (2 states, latent) with H@-1 -> H, and H -> O (3 states); the first
/// slice's tables of its own.
struct hmm {
  std::vector<double> pi, a, b0, b;  // P(H@0), P(H | H@-1), P(O@0 | H@0), P(O | H)

  [[nodiscard]] dynamic_network model(const dynamic_structure& structure) const {
    const auto& h = structure.variables()[0];
    const auto& o = structure.variables()[1];
    const auto h_before = detail::renamed(h, "H@-1");
    bayesian_network first(structure.initial, {cpt<double>(h, {}, pi), cpt<double>(o, {h}, b0)});
    return {std::move(first), {cpt<double>(h, {h_before}, a), cpt<double>(o, {h}, b)}};
  }
};

dynamic_structure hmm_structure() {
  return dynamic_structure_of({variable("H", {"0", "1"}), variable("O", {"a", "b", "c"})},
                              parse_edge_list("H->O, H@-1->H"));
}

hmm hmm_truth() {
  return {{0.6, 0.4}, {0.9, 0.1, 0.2, 0.8}, {0.5, 0.3, 0.2, 0.2, 0.3, 0.5}, {0.7, 0.2, 0.1, 0.1, 0.3, 0.6}};
}

/// The episodes with the observations only: H latent.
dataset without_the_state(const testing::long_form& sampled) {
  dataset observed(sampled.data.source());
  for (const auto* name : {"episode", "t", "O"}) observed.add(sampled.data.at(name));
  return observed;
}

/// One Baum–Welch iteration by scaled forward–backward, the emissions at t = 0 counted apart
/// (the first slice's table); returns ln P(observations) under `m`.
double baum_welch_step(hmm& m, const std::vector<std::vector<std::size_t>>& episodes) {
  std::vector<double> pi(2), a(4), b0(6), b(6);
  double log_likelihood = 0.0;
  for (const auto& o : episodes) {
    const auto n = o.size();
    std::vector<std::vector<double>> alpha(n, std::vector<double>(2)), beta(n, std::vector<double>(2, 1.0));
    std::vector<double> scale(n);
    for (std::size_t t = 0; t < n; ++t) {
      for (std::size_t h = 0; h < 2; ++h) {
        double prior = 0.0;
        if (t == 0) {
          prior = m.pi[h];
        } else {
          for (std::size_t g = 0; g < 2; ++g) prior += alpha[t - 1][g] * m.a[g * 2 + h];
        }
        alpha[t][h] = prior * (t == 0 ? m.b0 : m.b)[h * 3 + o[t]];
      }
      scale[t] = alpha[t][0] + alpha[t][1];
      for (auto& x : alpha[t]) x /= scale[t];
      log_likelihood += std::log(scale[t]);
    }
    for (std::size_t t = n - 1; t-- > 0;) {
      for (std::size_t g = 0; g < 2; ++g) {
        beta[t][g] = 0.0;
        for (std::size_t h = 0; h < 2; ++h) beta[t][g] += m.a[g * 2 + h] * m.b[h * 3 + o[t + 1]] * beta[t + 1][h];
        beta[t][g] /= scale[t + 1];
      }
    }
    for (std::size_t t = 0; t < n; ++t) {
      for (std::size_t h = 0; h < 2; ++h) {
        const double gamma = alpha[t][h] * beta[t][h];
        if (t == 0) {
          pi[h] += gamma;
          b0[h * 3 + o[t]] += gamma;
        } else {
          b[h * 3 + o[t]] += gamma;
          for (std::size_t g = 0; g < 2; ++g) {
            a[g * 2 + h] += alpha[t - 1][g] * m.a[g * 2 + h] * m.b[h * 3 + o[t]] * beta[t][h] / scale[t];
          }
        }
      }
    }
  }
  const auto normalize = [](std::vector<double>& v, std::size_t j) {
    for (std::size_t u = 0; u < v.size() / j; ++u) {
      double sum = 0.0;
      for (std::size_t x = 0; x < j; ++x) sum += v[u * j + x];
      for (std::size_t x = 0; x < j; ++x) v[u * j + x] /= sum;
    }
  };
  normalize(pi, 2);
  normalize(a, 2);
  normalize(b0, 3);
  normalize(b, 3);
  m = {pi, a, b0, b};
  return log_likelihood;
}

TEST(dynamic_em_test, a_hidden_markov_model_is_fitted_as_baum_welch_by_hand) {
  const auto structure = hmm_structure();
  const auto truth = hmm_truth();
  const auto sampled = testing::sample_long_form(truth.model(structure), 120, 9, 7);
  const auto observed = without_the_state(sampled);
  std::vector<std::vector<std::size_t>> episodes;
  for (const auto& episode : sampled.codes) {
    auto& o = episodes.emplace_back();
    for (const auto& step : episode) o.push_back(step[1]);
  }
  hmm by_hand{{0.5, 0.5}, {0.7, 0.3, 0.4, 0.6}, {0.3, 0.3, 0.4, 0.4, 0.3, 0.3}, {0.4, 0.35, 0.25, 0.2, 0.3, 0.5}};
  const auto start = by_hand.model(structure);
  dynamic_em_options em;
  em.start = &start;
  em.em.max_iterations = 6;
  em.em.tolerance = 0.0;
  std::vector<double> log_likelihoods;
  em.em.on_step = [&](const em_step& step) { log_likelihoods.push_back(step.log_likelihood); };
  const auto result = dynamic_expectation_maximization(structure, observed, {}, em);
  ASSERT_EQ(log_likelihoods.size(), 7u);
  for (std::size_t k = 0; k < 7; ++k) {
    if (k == 6) expect_tables_near(result.model, by_hand.model(structure), 1e-9);  // after six M-steps each
    const double expected = baum_welch_step(by_hand, episodes);
    EXPECT_NEAR(log_likelihoods[k], expected, 1e-9 * std::abs(expected)) << "iteration " << k;
    if (k > 0) {
      EXPECT_GE(log_likelihoods[k], log_likelihoods[k - 1] - 1e-9);
    }
  }
  EXPECT_EQ(result.iterations, 6u);
  EXPECT_FALSE(result.converged);
}

TEST(dynamic_em_test, the_objective_rises_and_the_threads_do_not_change_the_result) {
  const auto model = testing::random_dynamic(31, 4);
  const auto data = testing::with_gaps(testing::sample_long_form(model, 200, 7, 31), model, 31, 4);
  dynamic_fit_options options;
  options.fit.prior = bdeu_prior(4.0);
  const auto variable_name = model.variables()[1].name();
  options.initial_priors.emplace(variable_name, dirichlet_prior(3.0));
  std::vector<double> objectives;
  dynamic_em_options em;
  em.em.threads = 1;
  em.em.on_step = [&](const em_step& step) { objectives.push_back(step.objective); };
  const auto one = dynamic_expectation_maximization(structure_of(model), data.data, options, em);
  ASSERT_GT(objectives.size(), 2u);
  for (std::size_t k = 1; k < objectives.size(); ++k) {
    EXPECT_GE(objectives[k], objectives[k - 1] - 1e-9 * std::abs(objectives[k - 1])) << "iteration " << k;
  }
  EXPECT_TRUE(one.converged);
  em.em.on_step = nullptr;
  em.em.threads = 2;
  const auto two = dynamic_expectation_maximization(structure_of(model), data.data, options, em);
  EXPECT_EQ(one.model, two.model);
  EXPECT_EQ(one.log_likelihood, two.log_likelihood);
}

TEST(dynamic_em_test, latent_variables_start_at_random_and_the_best_start_is_kept) {
  const auto structure = hmm_structure();
  const auto truth = hmm_truth();
  const auto sampled = testing::sample_long_form(truth.model(structure), 200, 10, 3);
  const auto observed = without_the_state(sampled);
  dynamic_em_options em;
  em.em.restarts = 3;
  em.em.seed = 9;
  std::vector<double> final_objectives(3, -INFINITY);
  em.em.on_step = [&](const em_step& step) { final_objectives[step.restart] = step.objective; };
  const auto best = dynamic_expectation_maximization(structure, observed, {}, em);
  for (double objective : final_objectives) EXPECT_GE(best.objective, objective);
  em.em.on_step = nullptr;
  EXPECT_EQ(dynamic_expectation_maximization(structure, observed, {}, em).model, best.model);
  // At least as likely as the truth, and near it up to the naming of H's states.
  const auto true_model = truth.model(structure);
  dynamic_em_options at_truth;
  at_truth.start = &true_model;
  at_truth.em.max_iterations = 0;
  EXPECT_GT(best.log_likelihood, dynamic_expectation_maximization(structure, observed, {}, at_truth).log_likelihood);
  const auto a = best.model.transition_tables()[0].values();
  const bool swapped = best.model.transition_tables()[1].values()[0] < 0.4;  // P(O = a | H = 0), 0.7 in truth
  EXPECT_NEAR(a[swapped ? 3 : 0], 0.9, 0.15);
  EXPECT_NEAR(a[swapped ? 0 : 3], 0.8, 0.15);
}

TEST(dynamic_em_test, bad_input_is_named) {
  const auto model = testing::random_dynamic(5, 3);
  const auto data = testing::sample_long_form(model, 10, 3, 5);
  const auto structure = structure_of(model);
  dynamic_em_options hard;
  hard.em.kind = em_kind::hard;
  EXPECT_THAT([&] { static_cast<void>(dynamic_expectation_maximization(structure, data.data, {}, hard)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("hard EM is not available for dynamic networks")));
  const auto other = testing::random_dynamic(6, 3);
  dynamic_em_options elsewhere;
  elsewhere.start = &other;
  EXPECT_THAT([&] { static_cast<void>(dynamic_expectation_maximization(structure, data.data, {}, elsewhere)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("another structure")));
  dynamic_fit_options ghost;
  ghost.fit.node_priors.emplace("ghost", bdeu_prior(1.0));
  EXPECT_THAT([&] { static_cast<void>(dynamic_expectation_maximization(structure, data.data, ghost)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("'ghost', which is not a template variable")));
  EXPECT_THROW(static_cast<void>(dynamic_expectation_maximization(structure, data.data.slice(0, 0))), data_error);
  dynamic_em_options bad_tolerance;
  bad_tolerance.em.tolerance = -1.0;
  EXPECT_THROW(static_cast<void>(dynamic_expectation_maximization(structure, data.data, {}, bad_tolerance)),
               model_error);
}

using dynamic_em_cli_test = pgm::testing::program_test;

// pgm fit --dynamic --missing em writes what the library's EM gives on the same data, latent
// variables with --latent; what does not apply is refused with nothing written.
TEST_F(dynamic_em_cli_test, fits_missing_values_and_latent_variables) {
  const auto model = testing::random_dynamic(8, 3);
  const auto sampled = testing::with_gaps(testing::sample_long_form(model, 60, 5, 8, true), model, 8, 5);
  std::ostringstream csv;
  write_csv(sampled.data, csv);
  const auto data = file("episodes.csv", csv.str());
  const auto& v = model.variables();
  const std::string edges = v[0].name() + "->" + v[1].name() + "," + v[1].name() + "@-1->" + v[1].name() + "," +
                            v[2].name() + "@-1->" + v[0].name();
  const auto r = run("fit --dynamic --missing em --na NA --data " + data.string() + " --edges '" + edges +
                     "' --estimator bayes --prior dirichlet --alpha 2 --out " + path("fitted.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("EM: "));
  EXPECT_THAT(r.err, HasSubstr("(converged)"));
  auto reading = long_form_options();
  reading.missing.policy = missing_policy::available;
  const auto read = read_csv(data, reading);
  dynamic_fit_options options;
  options.fit.prior = dirichlet_prior(2.0);
  const auto expected =
      dynamic_expectation_maximization(dynamic_structure_from_data(read, parse_edge_list(edges)), read, options);
  EXPECT_EQ(parse_dynamic_json(slurp(path("fitted.json")), "fitted.json"), expected.model);

  // A hidden Markov model: H in no column.
  const auto hmm_data = file("hmm.csv", "episode,t,O\ne1,0,a\ne1,1,a\ne1,2,b\ne2,0,b\ne2,1,b\ne2,2,b\ne2,3,a\n");
  const auto h = run("fit --dynamic --missing em --latent H:2 --restarts 3 --seed 4 --data " + hmm_data.string() +
                     " --edges 'H->O, H@-1->H' --out " + path("hmm.json").string());
  ASSERT_EQ(h.code, 0) << h.err;
  const auto hmm_model = parse_dynamic_json(slurp(path("hmm.json")), "hmm.json");
  ASSERT_EQ(hmm_model.size(), 2u);
  EXPECT_EQ(hmm_model.variables()[1].name(), "H");
  EXPECT_EQ(hmm_model.variables()[1].cardinality(), 2u);

  const auto out = path("never.json");
  const auto fit = "fit --dynamic --data " + data.string() + " --edges '" + edges + "' ";
  expect_failure(fit + "--missing em --keep-counts --out " + out.string(), "--keep-counts does not apply", out);
  expect_failure(fit + "--missing em --hard --out " + out.string(), "--hard is not available for dynamic", out);
  expect_failure(fit + "--latent H:2 --out " + out.string(), "--latent applies with --missing em", out);
  expect_failure(fit + "--missing em --latent " + v[0].name() + ":2 --out " + out.string(),
                 "a latent variable is one the data do not hold", out);
  expect_failure(fit + "--missing em --latent Z:2 --out " + out.string(), "the latent variable 'Z' is in no edge", out);
}

}  // namespace dynamic_em_test
}  // namespace pgm
