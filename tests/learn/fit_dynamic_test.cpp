// Fitting a dynamic network with tied parameters (pgm/learn/fit_dynamic.hpp): every table equals
// the one counted by hand over every step of every episode, under MLE and under priors; the row
// order does not matter; a large sample recovers the model; malformed structures are named.

#include "pgm/learn/fit_dynamic.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "pgm/io/csv.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/learn/dynamic_statistics.hpp"
#include "pgm/learn/parameter_prior.hpp"
#include "support/long_form.hpp"
#include "support/program_test.hpp"
#include "support/random_dynamic_network.hpp"

namespace pgm {
namespace fit_dynamic_test {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// Counts of one table by hand: M[u][x] over the episodes' steps `first_slice` (t = 0) or t ≥ 1,
/// each parent read at the step its name says ("y" this step, "y@-1" the one before), where none
/// of the family's values is missing.
std::vector<std::vector<double>> hand_counts(const cpt<double>& table, const dynamic_network& model,
                                             const testing::long_form& data, bool first_slice) {
  const auto index_of = [&](const std::string& name) {
    for (std::size_t i = 0; i < model.size(); ++i) {
      if (model.variables()[i].name() == name) return i;
    }
    ADD_FAILURE() << "no template variable " << name;
    return std::size_t{0};
  };
  const auto child = index_of(table.child().name());
  std::vector<std::pair<std::size_t, std::size_t>> parents;  // (template variable, steps back)
  for (const auto& p : table.parents()) {
    const auto at = p.name().find("@-1");
    parents.emplace_back(index_of(p.name().substr(0, at)), at == std::string::npos ? 0 : 1);
  }
  std::vector<std::vector<double>> counts(table.configurations(), std::vector<double>(table.child_cardinality()));
  for (const auto& episode : data.codes) {
    for (std::size_t t = first_slice ? 0 : 1; t < (first_slice ? 1 : episode.size()); ++t) {
      std::vector<std::size_t> codes;
      bool present = episode[t][child] != testing::long_form::missing;
      for (const auto& [i, back] : parents) {
        codes.push_back(episode[t - back][i]);
        present = present && codes.back() != testing::long_form::missing;
      }
      if (present) counts[table.configuration(codes).value()][episode[t][child]] += 1.0;
    }
  }
  return counts;
}

/// Eq. 6 by hand with the same pseudo-count α everywhere (0: MLE; an empty column: uniform).
void expect_dirichlet_estimate(const cpt<double>& table, const std::vector<std::vector<double>>& counts, double alpha) {
  const auto j = table.child_cardinality();
  for (std::size_t u = 0; u < counts.size(); ++u) {
    double total = 0.0;
    for (double m : counts[u]) total += m;
    const auto column = table.column(config_index(u));
    for (std::size_t x = 0; x < j; ++x) {
      const double expected = total + alpha * static_cast<double>(j) == 0.0
                                  ? 1.0 / static_cast<double>(j)
                                  : (counts[u][x] + alpha) / (total + alpha * static_cast<double>(j));
      EXPECT_DOUBLE_EQ(column[x], expected) << table.child().name() << " u " << u << " x " << x;
    }
  }
}

dynamic_structure structure_of_model(const dynamic_network& model) { return structure_of(model); }

TEST(fit_dynamic_test, tied_tables_count_every_step_of_every_episode) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const auto model = testing::random_dynamic(seed, 2 + seed % 4);
    const auto data = testing::sample_long_form(model, 40, 6, seed, seed % 2 == 0);
    for (const double alpha : {0.0, 1.0, 2.5}) {
      dynamic_fit_options options;
      if (alpha > 0.0) options.fit.prior = dirichlet_prior(alpha);
      const auto fitted = fit_dynamic(structure_of_model(model), data.data, options);
      ASSERT_EQ(fitted.size(), model.size());
      for (std::size_t i = 0; i < model.size(); ++i) {
        SCOPED_TRACE("seed " + std::to_string(seed) + " alpha " + std::to_string(alpha) + " variable " +
                     model.variables()[i].name());
        const auto& first = fitted.initial().table(index_at<variable_id>(i));
        expect_dirichlet_estimate(first, hand_counts(first, model, data, true), alpha);
        const auto& transition = fitted.transition_tables()[i];
        expect_dirichlet_estimate(transition, hand_counts(transition, model, data, false), alpha);
      }
    }
  }
}

TEST(fit_dynamic_test, missing_values_leave_out_only_the_families_they_are_in) {
  // Available-case counting, rows in order (neighbouring pairs less the crossings) and shuffled
  // (the exact pairs).
  for (std::uint64_t seed = 20; seed <= 23; ++seed) {
    const auto model = testing::random_dynamic(seed, 2 + seed % 3);
    const auto data = testing::with_gaps(testing::sample_long_form(model, 50, 6, seed, seed % 2 == 0), model, seed, 5);
    const auto fitted = fit_dynamic(structure_of_model(model), data.data);
    for (std::size_t i = 0; i < model.size(); ++i) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " variable " + model.variables()[i].name());
      const auto& first = fitted.initial().table(index_at<variable_id>(i));
      expect_dirichlet_estimate(first, hand_counts(first, model, data, true), 0.0);
      const auto& transition = fitted.transition_tables()[i];
      expect_dirichlet_estimate(transition, hand_counts(transition, model, data, false), 0.0);
    }
  }
}

TEST(fit_dynamic_test, the_order_of_the_rows_does_not_matter_and_counts_fit_alike) {
  const auto model = testing::random_dynamic(11, 4);
  const auto ordered = testing::sample_long_form(model, 60, 7, 11, false);
  const auto shuffled = testing::sample_long_form(model, 60, 7, 11, true);
  const auto structure = structure_of_model(model);
  const auto fitted = fit_dynamic(structure, ordered.data);
  EXPECT_EQ(fit_dynamic(structure, shuffled.data), fitted);
  const auto counts = count_dynamic(structure, shuffled.data);
  EXPECT_EQ(counts.episodes, 60u);
  EXPECT_EQ(counts.steps, shuffled.data.rows());
  EXPECT_EQ(fit_dynamic(structure, counts), fitted);
}

TEST(fit_dynamic_test, a_large_sample_recovers_the_model) {
  const auto model = testing::random_dynamic(5, 3);
  const auto data = testing::sample_long_form(model, 4000, 10, 5);
  const auto fitted = fit_dynamic(structure_of_model(model), data.data);
  double worst = 0.0;
  for (std::size_t i = 0; i < model.size(); ++i) {
    const auto& truth = model.transition_tables()[i];
    const auto& estimate = fitted.transition_tables()[i];
    const auto counts = hand_counts(estimate, model, data, false);
    for (std::size_t u = 0; u < truth.configurations(); ++u) {
      double rows = 0.0;
      for (double m : counts[u]) rows += m;
      if (rows < 1000) continue;  // a column seen this often is within a few hundredths
      for (std::size_t x = 0; x < truth.child_cardinality(); ++x) {
        worst = std::max(worst, std::abs(truth.column(config_index(u))[x] - estimate.column(config_index(u))[x]));
      }
    }
  }
  EXPECT_LT(worst, 0.06);
}

TEST(fit_dynamic_test, a_prior_of_its_own_for_a_table_of_either_slice) {
  const auto model = testing::random_dynamic(3, 3);
  const auto data = testing::sample_long_form(model, 30, 5, 3);
  const auto structure = structure_of_model(model);
  const auto mle = fit_dynamic(structure, data.data);
  const auto& name = model.variables()[1].name();
  // Eq. 8 with w = 0 is MLE; with no data (a large w against few rows) it tends to the prior f.
  dynamic_fit_options zero;
  zero.fit.node_priors.emplace(name, weighted_prior{model.transition_tables()[1], 0.0});
  zero.initial_priors.emplace(name, weighted_prior{model.initial().table(variable_id(1)), 0.0});
  EXPECT_EQ(fit_dynamic(structure, data.data, zero), mle);
  dynamic_fit_options heavy;
  heavy.fit.node_priors.emplace(name, weighted_prior{model.transition_tables()[1], 1e12});
  const auto fitted = fit_dynamic(structure, data.data, heavy);
  const auto truth = model.transition_tables()[1].values();
  const auto got = fitted.transition_tables()[1].values();
  for (std::size_t c = 0; c < truth.size(); ++c) EXPECT_NEAR(got[c], truth[c], 1e-9);
  EXPECT_EQ(fitted.initial(), mle.initial());  // the first slice's table kept its MLE
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (i != 1) {
      EXPECT_EQ(fitted.transition_tables()[i], mle.transition_tables()[i]);
    }
  }
  dynamic_fit_options unknown;
  unknown.fit.node_priors.emplace("ghost", no_prior{});
  EXPECT_THAT([&] { static_cast<void>(fit_dynamic(structure, data.data, unknown)); },
              ThrowsMessage<model_error>(HasSubstr("a prior is given for 'ghost', which is not a template variable")));
}

/// The rows of the first `episodes` episodes, and the rest.
std::pair<dataset, dataset> split_episodes(const testing::long_form& sampled, std::size_t episodes) {
  std::vector<std::size_t> first, later;
  for (std::size_t r = 0; r < sampled.rows.size(); ++r) (sampled.rows[r].first < episodes ? first : later).push_back(r);
  return {sampled.data.select_rows(first), sampled.data.select_rows(later)};
}

// Counts add up: the statistics kept from some episodes, updated with the rest, estimate the
// network fitted on all of them to the last bit, under any prior; a decay weighs the old less.
TEST(fit_dynamic_test, kept_statistics_updated_with_more_episodes_equal_the_fit_on_all) {
  const auto model = testing::random_dynamic(13, 4);
  const auto sampled = testing::sample_long_form(model, 70, 6, 13, true);
  const auto [first, later] = split_episodes(sampled, 40);
  const auto structure = structure_of_model(model);
  dynamic_fit_options options;
  options.fit.prior = bdeu_prior(3.0);
  options.fit.node_priors.emplace(model.variables()[2].name(), weighted_prior{model.transition_tables()[2], 4.0});
  options.initial_priors.emplace(model.variables()[0].name(), dirichlet_prior(0.5));
  const auto kept = dynamic_statistics_of(structure, count_dynamic(structure, first), options);
  EXPECT_EQ(kept.initial.rows, 40.0);
  EXPECT_EQ(estimate_dynamic(structure, kept), fit_dynamic(structure, first, options));
  const auto more = count_dynamic(structure, later);
  const auto all = updated(kept, more);
  EXPECT_EQ(all.initial.rows, 70.0);
  EXPECT_EQ(all.transition.rows, static_cast<double>(sampled.data.rows() - 70));
  EXPECT_EQ(estimate_dynamic(structure, all), fit_dynamic(structure, sampled.data, options));
  // A decay of ½: half of each old count, the new ones whole.
  const auto decayed = updated(kept, more, 0.5);
  for (std::size_t i = 0; i < model.size(); ++i) {
    const auto old_cells = kept.transition.counts[i].counts();
    const auto new_cells = more.transition[i].counts();
    const auto cells = decayed.transition.counts[i].counts();
    for (std::size_t c = 0; c < cells.size(); ++c) {
      EXPECT_EQ(cells[c], 0.5 * old_cells[c] + static_cast<double>(new_cells[c]));
    }
  }
  EXPECT_EQ(decayed.initial.rows, 0.5 * 40 + 30);
  // Statistics of another network are refused.
  const auto other_model = testing::random_dynamic(14, 4);
  const auto other = structure_of_model(other_model);
  const auto other_counts = count_dynamic(other, testing::sample_long_form(other_model, 5, 3, 1).data);
  EXPECT_THROW(static_cast<void>(estimate_dynamic(other, all)), model_error);
  EXPECT_THROW(static_cast<void>(updated(kept, other_counts)), model_error);
}

TEST(fit_dynamic_test, episodes_of_one_step_leave_the_transition_to_the_empty_rule) {
  const auto model = testing::random_dynamic(2, 2);
  const auto data = testing::sample_long_form(model, 20, 1, 2);
  const auto fitted = fit_dynamic(structure_of_model(model), data.data);
  for (const auto& table : fitted.transition_tables()) {
    for (double p : table.values()) EXPECT_DOUBLE_EQ(p, 1.0 / static_cast<double>(table.child_cardinality()));
  }
  dynamic_fit_options strict;
  strict.fit.estimation.empty = empty_configuration::fail;
  EXPECT_THAT([&] { static_cast<void>(fit_dynamic(structure_of_model(model), data.data, strict)); },
              ThrowsMessage<data_error>(HasSubstr("no data for")));
  EXPECT_THAT([&] { static_cast<void>(fit_dynamic(structure_of_model(model), data.data.select_rows({}))); },
              ThrowsMessage<data_error>(HasSubstr("episodes.csv: there are no data rows")));
}

TEST(fit_dynamic_test, structures_from_edges) {
  const std::vector<variable> templates{variable("a", {"0", "1"}), variable("b", {"lo", "hi"})};
  const auto structure = dynamic_structure_of(templates, parse_edge_list("a->b, a@-1->a, b@-1->b, a@-1->b"));
  EXPECT_EQ(structure.initial.edges(), (std::vector<named_edge>{{"a", "b"}}));
  EXPECT_EQ(structure.transition.size(), 4u);
  EXPECT_EQ(structure.transition.parent_variables(structure.transition.id("b")).size(), 3u);
  const auto refused = [&](const std::string& edges, const std::string& message) {
    EXPECT_THAT([&] { static_cast<void>(dynamic_structure_of(templates, parse_edge_list(edges))); },
                ThrowsMessage<pgm::error>(HasSubstr(message)))
        << edges;
  };
  refused("a->b@-1",
          "the edge 'a->b@-1' ends in another slice: an edge's child lies in this slice ('b'), its parent "
          "in this slice or the one before ('a@-1')");
  refused("a@+1->b", "the parent 'a@+1' of 'b' lies in a later slice");
  refused("a@-2->b", "lies 2 slices back: pgm's dynamic networks are of order 1");
  refused("c@-1->b", "the edge 'c@-1->b' names 'c', which is not a template variable (a, b)");
  refused("a->c", "the edge 'a->c' names 'c', which is not a template variable");
  refused("a->b, b->a", "cycle");
  EXPECT_NO_THROW(static_cast<void>(dynamic_structure_of(templates, parse_edge_list("a@-1->a"))));
  EXPECT_THAT(
      [&] {
        static_cast<void>(dynamic_structure_of({variable("a@1", {"0", "1"})}, {}));
      },
      ThrowsMessage<model_error>(HasSubstr("the template variable 'a@1' holds '@'")));
}

TEST(fit_dynamic_test, the_template_variables_from_the_data) {
  const auto model = testing::random_dynamic(4, 3);
  const auto data = testing::sample_long_form(model, 10, 3, 4);
  const auto& names = model.variables();
  const auto structure = dynamic_structure_from_data(
      data.data,
      parse_edge_list(names[2].name() + "@-1->" + names[2].name() + ", " + names[0].name() + "->" + names[2].name()));
  ASSERT_EQ(structure.variables().size(), 2u);
  EXPECT_EQ(structure.variables()[0], names[0]);
  EXPECT_EQ(structure.variables()[1], names[2]);
  EXPECT_THROW(static_cast<void>(dynamic_structure_from_data(data.data, parse_edge_list("ghost->" + names[0].name()))),
               data_error);
  EXPECT_THROW(static_cast<void>(dynamic_structure_from_data(data.data, parse_edge_list("t->" + names[0].name()))),
               data_error);  // continuous
}

using fit_dynamic_cli_test = pgm::testing::program_test;

// pgm fit --dynamic writes what fit_dynamic gives on the same data, from edges (states from the
// data) or from a dynamic model (its states); what it does not take is refused, nothing written.
TEST_F(fit_dynamic_cli_test, fits_from_edges_or_a_model_and_refuses_bad_input) {
  const auto model = testing::random_dynamic(8, 3);
  const auto sampled = testing::sample_long_form(model, 50, 5, 8, true);
  std::ostringstream csv;
  write_csv(sampled.data, csv);
  const auto data = file("episodes.csv", csv.str());
  const auto& v = model.variables();
  const std::string edges = v[0].name() + "->" + v[1].name() + "," + v[1].name() + "@-1->" + v[1].name() + "," +
                            v[2].name() + "@-1->" + v[0].name();
  const auto r = run("fit --dynamic --data " + data.string() + " --edges '" + edges +
                     "' --estimator bayes --prior dirichlet --alpha 2 --out " + path("fitted.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("from 50 episodes"));
  auto reading = long_form_options();
  const auto read = read_csv(data, reading);
  dynamic_fit_options options;
  options.fit.prior = dirichlet_prior(2.0);
  const auto expected = fit_dynamic(dynamic_structure_from_data(read, parse_edge_list(edges)), read, options);
  EXPECT_EQ(parse_dynamic_json(slurp(path("fitted.json")), "fitted.json"), expected);

  // From a model: its structure and states (here the states of the model sampled from).
  const auto model_file = file("model.json", to_json(model).dump(2));
  ASSERT_EQ(run("fit --dynamic --data " + data.string() + " --model " + model_file.string() + " --out " +
                path("refit.json").string())
                .code,
            0);
  for (const auto& variable : v) reading.variables.emplace(variable.name(), variable);
  EXPECT_EQ(parse_dynamic_json(slurp(path("refit.json")), "refit.json"),
            fit_dynamic(structure_of(model), read_csv(data, reading)));

  const auto out = path("never.json");
  const auto fit = "fit --dynamic --data " + data.string() + " --edges '" + edges + "' ";
  expect_failure(fit + "--out " + path("never.bif").string(),
                 "a dynamic network is written as pgm's JSON model (.json)", path("never.bif"));
  expect_failure("fit --dynamic --data " + data.string() + " --edges '" + v[0].name() + "->" + v[1].name() +
                     "@-1' --out " + out.string(),
                 "ends in another slice", out);
  expect_failure(fit + "--missing drop --out " + out.string(), "--dynamic: --missing drop leaves gaps", out);
  const auto twice = file(
      "twice.csv", "episode,t," + v[0].name() + "\ne1,0," + v[0].states()[0] + "\ne1,0," + v[0].states()[0] + "\n");
  expect_failure("fit --dynamic --data " + twice.string() + " --edges '" + v[0].name() + "@-1->" + v[0].name() +
                     "' --out " + out.string(),
                 "twice.csv: episode 'e1' has two rows with t = 0 (data rows 1 and 2)", out);
}

// pgm fit --dynamic --keep-counts keeps the counts in the model; pgm update adds new episodes to
// them and writes the model fitted on all the episodes, to the last bit.
TEST_F(fit_dynamic_cli_test, update_adds_episodes_to_a_model_that_kept_its_counts) {
  const auto model = testing::random_dynamic(8, 3);
  const auto sampled = testing::sample_long_form(model, 60, 5, 21, true);
  const auto [first_data, later_data] = split_episodes(sampled, 35);
  const auto csv_of = [](const dataset& data) {
    std::ostringstream out;
    write_csv(data, out);
    return out.str();
  };
  const auto first = file("first.csv", csv_of(first_data));
  const auto later = file("later.csv", csv_of(later_data));
  const auto all = file("all.csv", csv_of(sampled.data));
  const auto model_file = file("model.json", to_json(model).dump(2));
  const auto fit = "fit --dynamic --model " + model_file.string() + " --estimator bayes --prior bdeu --ess 2 ";
  auto r = run(fit + "--data " + first.string() + " --keep-counts --out " + path("kept.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(slurp(path("kept.json")), HasSubstr("\"statistics\""));
  r = run("update --model " + path("kept.json").string() + " --data " + later.string() + " --out " +
          path("kept.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("updated a dynamic network of 3 template variables with 25 episodes"));
  EXPECT_THAT(r.out, HasSubstr("60 episodes in all"));
  r = run(fit + "--data " + all.string() + " --out " + path("all.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(parse_dynamic_json(slurp(path("kept.json")), "kept.json"),
            parse_dynamic_json(slurp(path("all.json")), "all.json"));
  // The statistics read back as written: a second update from the file adds to them again.
  const auto file_read = parse_dynamic_model_json(slurp(path("kept.json")), "kept.json");
  ASSERT_TRUE(file_read.statistics);
  EXPECT_EQ(file_read.statistics->initial.rows, 60.0);

  const auto out = path("never.json");
  expect_failure("update --model " + path("all.json").string() + " --data " + later.string() + " --out " + out.string(),
                 "carries no counts to add the new episodes to: fit it with pgm fit --dynamic --keep-counts", out);
  expect_failure("update --model " + path("kept.json").string() + " --data " + later.string() +
                     " --missing drop --out " + out.string(),
                 "a dynamic network is updated with --missing available", out);
  expect_failure("update --model " + path("kept.json").string() + " --data " + later.string() + " --out " +
                     path("never.bif").string(),
                 "a dynamic network is written as pgm's JSON model (.json)", path("never.bif"));
  // A file whose statistics do not fit its network names the JSON path.
  auto text = slurp(path("kept.json"));
  const auto at = text.find("\"rows\": 60");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 11, "\"rows\": -1");
  const auto broken = file("broken.json", text);
  expect_failure("update --model " + broken.string() + " --data " + later.string() + " --out " + out.string(),
                 "broken.json: /statistics/initial/rows: expected a finite number >= 0", out);
}

}  // namespace fit_dynamic_test
}  // namespace pgm
