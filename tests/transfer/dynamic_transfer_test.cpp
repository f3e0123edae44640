// Transferred priors for a dynamic network (pgm/transfer/dynamic_transfer.hpp): a static 1-Stack
// network's table as the prior of a tower's template variable in both slices. With a weight w
// that swamps the data each table is the prior (the previous cube's offset, which the 1-Stack has
// no counterpart of, changes nothing); with w = 0 it is MLE.

#include "pgm/transfer/dynamic_transfer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "pgm/inference/sampling.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/pipeline/dynamic_fit_pipeline.hpp"
#include "support/long_form.hpp"
#include "support/program_test.hpp"

namespace pgm {
namespace dynamic_transfer_test {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

const variable bins3(const std::string& name) { return variable(name, {"-1", "0", "1"}); }

/// The 1-Stack's onTop1 read directly as the tower's onTop, its cube as this cube.
transfer_settings direct_this_cube(std::optional<double> weight) {
  transfer_settings settings;
  settings.strategy = "direct";
  settings.map = "onTop=onTop1, xOff==xOff1, yOff==yOff1";
  settings.weight = weight;
  return settings;
}

/// onTop1 | xOff1, yOff1 with a success probability of its own in each configuration.
bayesian_network one_stack() {
  const variable x = bins3("xOff1");
  const variable y = bins3("yOff1");
  const variable on_top("onTop1", {"0", "1"});
  std::vector<double> values;
  for (std::size_t u = 0; u < 9; ++u) {
    const double p = 0.05 + 0.1 * static_cast<double>(u);
    values.insert(values.end(), {1 - p, p});
  }
  network_structure structure({x, y, on_top}, {{"xOff1", "onTop1"}, {"yOff1", "onTop1"}});
  return bayesian_network(structure, {cpt<double>(x, {}, {0.2, 0.5, 0.3}), cpt<double>(y, {}, {0.3, 0.4, 0.3}),
                                      cpt<double>(on_top, {x, y}, values)});
}

/// A tower's step: this cube's offsets and whether it stays on top, the outcome also read with
/// the previous cube's x offset.
struct tower_data {
  std::vector<variable> templates{bins3("xOff"), bins3("yOff"), variable("onTop", {"0", "1"})};
  dynamic_structure structure =
      dynamic_structure_of(templates, parse_edge_list("xOff->onTop, yOff->onTop, xOff@-1->onTop"));
  dataset data = sampled();

  dataset sampled() const {
    // Any 2-TBN of this structure: the 1-Stack's tables, the transition's onTop the same for
    // every previous offset.
    const auto prior = one_stack();
    std::vector<cpt<double>> transition;
    transition.emplace_back(templates[0], std::vector<variable>{}, std::vector<double>{0.3, 0.4, 0.3});
    transition.emplace_back(templates[1], std::vector<variable>{}, std::vector<double>{0.3, 0.4, 0.3});
    std::vector<double> on_top;
    for (std::size_t u = 0; u < 27; ++u) on_top.insert(on_top.end(), {0.6, 0.4});
    const auto parents = structure.transition.parent_variables(structure.transition.id("onTop"));
    transition.emplace_back(templates[2], parents, on_top);
    std::vector<cpt<double>> first{cpt<double>(templates[0], {}, {0.2, 0.5, 0.3}),
                                   cpt<double>(templates[1], {}, {0.3, 0.4, 0.3})};
    std::vector<double> first_on_top(18, 0.5);
    first.emplace_back(templates[2], std::vector<variable>{templates[0], templates[1]}, first_on_top);
    const dynamic_network model(bayesian_network(structure.initial, first), transition);
    return testing::sample_long_form(model, 30, 4, 9).data;
  }
};

struct tower : ::testing::Test, tower_data {};

TEST_F(tower, a_swamping_weight_gives_the_prior_in_both_slices) {
  const auto prior = one_stack();
  const auto& source = prior.table(prior.id("onTop1"));
  const auto counts = count_dynamic(structure, data);
  dynamic_fit_options options;
  const auto settings = direct_this_cube(1e12);
  const auto report = add_transferred_priors(options, structure, counts, prior, settings);
  EXPECT_EQ(report.nodes.at("onTop").prior_node, "onTop1");
  EXPECT_TRUE(options.initial_priors.contains("onTop"));
  EXPECT_TRUE(options.fit.node_priors.contains("onTop"));
  const auto fitted = fit_dynamic(structure, counts, options);
  const auto& first = fitted.initial().table(fitted.initial().id("onTop"));
  const auto& transition = fitted.transition_tables()[2];
  for (std::size_t x = 0; x < 3; ++x) {
    for (std::size_t y = 0; y < 3; ++y) {
      const double expected = source.column(source.configuration(std::vector<std::size_t>{x, y}))[1];
      EXPECT_NEAR(first.column(first.configuration(std::vector<std::size_t>{x, y}))[1], expected, 1e-9);
      for (std::size_t before = 0; before < 3; ++before) {
        const auto u = transition.configuration(std::vector<std::size_t>{x, y, before});
        EXPECT_NEAR(transition.column(u)[1], expected, 1e-9) << x << y << before;
      }
    }
  }
  // Not in the map: fitted from the data alone.
  const auto mle = fit_dynamic(structure, counts);
  EXPECT_EQ(fitted.transition_tables()[0], mle.transition_tables()[0]);
  EXPECT_EQ(fitted.initial().table(fitted.initial().id("xOff")), mle.initial().table(mle.initial().id("xOff")));
}

// EM takes the transferred priors as the counted fit does: on complete episodes the two agree;
// with outcomes missing, a swamping weight still gives the prior.
TEST_F(tower, em_fits_under_the_transferred_prior) {
  const auto prior = one_stack();
  dynamic_fit_request counted;
  counted.prior_network = &prior;
  counted.transfer = direct_this_cube(5.0);
  auto by_em = counted;
  by_em.em = dynamic_em_options{};
  const auto a = fit_from_episodes(structure, data, counted);
  const auto b = fit_from_episodes(structure, data, by_em);
  ASSERT_TRUE(b.em && b.transfer);
  EXPECT_EQ(b.transfer->nodes.at("onTop").weight, 5.0);
  ASSERT_EQ(b.model.transition_tables().size(), templates.size());
  for (std::size_t i = 0; i < templates.size(); ++i) {
    const auto x = a.model.transition_tables()[i].values();
    const auto y = b.model.transition_tables()[i].values();
    for (std::size_t c = 0; c < x.size(); ++c) EXPECT_NEAR(x[c], y[c], 1e-12) << i << " cell " << c;
  }

  auto gaps = data;
  const auto& on_top = gaps.discrete("onTop");
  auto codes = make_code_vector(3, gaps.rows());
  std::size_t missing = 0;
  std::visit(
      [&](auto& out) {
        using code = typename std::decay_t<decltype(out)>::value_type;
        for (std::size_t r = 0; r < gaps.rows(); ++r) {
          const bool gap = r % 3 == 1;
          missing += gap;
          out[r] = gap ? missing_code<code> : static_cast<code>(on_top.code(r));
        }
      },
      codes);
  gaps.replace(discrete_column(on_top.var(), std::move(codes), std::in_place, missing));
  by_em.transfer = direct_this_cube(1e12);
  const auto swamped = fit_from_episodes(structure, gaps, by_em);
  const auto& source = prior.table(prior.id("onTop1"));
  const auto& transition = swamped.model.transition_tables()[2];
  for (std::size_t u = 0; u < 27; ++u) {
    const auto expected = source.column(source.configuration(std::vector<std::size_t>{u / 9, u / 3 % 3}))[1];
    EXPECT_NEAR(transition.column(transition.configuration(std::vector<std::size_t>{u / 9, u / 3 % 3, u % 3}))[1],
                expected, 1e-9);
  }
  by_em.keep_statistics = true;
  EXPECT_THROW(static_cast<void>(fit_from_episodes(structure, gaps, by_em)), model_error);
}

TEST_F(tower, a_weight_of_zero_is_mle_and_a_weight_chosen_per_slice_from_its_counts) {
  const auto prior = one_stack();
  const auto counts = count_dynamic(structure, data);
  auto settings = direct_this_cube(0.0);
  dynamic_fit_options zero;
  static_cast<void>(add_transferred_priors(zero, structure, counts, prior, settings));
  EXPECT_EQ(fit_dynamic(structure, counts, zero), fit_dynamic(structure, counts));
  settings.weight.reset();
  dynamic_fit_options chosen;
  const auto report = add_transferred_priors(chosen, structure, counts, prior, settings);
  ASSERT_TRUE(report.nodes.at("onTop").reason.has_value());
  EXPECT_GE(report.nodes.at("onTop").weight, 0.0);
}

TEST_F(tower, minimal_replacement_with_the_previous_cube_as_the_first) {
  // The 1-Stack's cube read as this cube (related: Cross) or as the one below (identical:
  // Direct); Minimal takes, per configuration, the smaller success. The first slice has no cube
  // below: there the 1-Stack is the same step, transferred directly.
  const auto prior = one_stack();
  const auto& source = prior.table(prior.id("onTop1"));
  const auto counts = count_dynamic(structure, data);
  transfer_settings settings;
  settings.strategy = "minimal";
  settings.map = "onTop=onTop1, xOff~xOff1, yOff~yOff1, xOff@-1==xOff1, yOff1@0";
  settings.weight = 1e12;
  dynamic_fit_options options;
  EXPECT_THAT([&] { static_cast<void>(add_transferred_priors(options, structure, counts, prior, settings)); },
              ThrowsMessage<model_error>(HasSubstr("the first slice: Direct-Replacement")));
  const auto first_step = direct_this_cube(1e12);
  options = {};
  static_cast<void>(add_transferred_priors(options, structure, counts, prior, settings, &first_step));
  const auto fitted = fit_dynamic(structure, counts, options);
  const auto success = [&](std::size_t x, std::size_t y) {
    return source.column(source.configuration(std::vector<std::size_t>{x, y}))[1];
  };
  const auto& first = fitted.initial().table(fitted.initial().id("onTop"));
  const auto& transition = fitted.transition_tables()[2];
  for (std::size_t x = 0; x < 3; ++x) {
    for (std::size_t y = 0; y < 3; ++y) {
      const auto v = first.configuration(std::vector<std::size_t>{x, y});
      EXPECT_NEAR(first.column(v)[1], success(x, y), 1e-9) << x << y;
      for (std::size_t before = 0; before < 3; ++before) {
        // Direct: xOff1 is the cube below, yOff1 pinned at 0 (state 1); Cross: this cube.
        const double expected = std::min(success(before, 1), success(x, y));
        const auto u = transition.configuration(std::vector<std::size_t>{x, y, before});
        EXPECT_NEAR(transition.column(u)[1], expected, 1e-9) << x << y << before;
      }
    }
  }
}

TEST_F(tower, the_first_slice_may_be_left_out) {
  const auto prior = one_stack();
  const auto counts = count_dynamic(structure, data);
  const auto settings = direct_this_cube(5.0);
  transfer_settings none;
  none.map = "none";
  dynamic_fit_options options;
  static_cast<void>(add_transferred_priors(options, structure, counts, prior, settings, &none));
  EXPECT_TRUE(options.initial_priors.empty());
  EXPECT_TRUE(options.fit.node_priors.contains("onTop"));
}

TEST_F(tower, a_map_to_no_template_variable_is_refused) {
  const auto prior = one_stack();
  const auto counts = count_dynamic(structure, data);
  transfer_settings settings;
  settings.map = "ghost=onTop1";
  dynamic_fit_options options;
  EXPECT_THAT([&] { static_cast<void>(add_transferred_priors(options, structure, counts, prior, settings)); },
              ThrowsMessage<model_error>(HasSubstr("the map transfers 'onTop1' to 'ghost', which is not a template "
                                                   "variable (xOff, yOff, onTop)")));
}

struct tower_cli : pgm::testing::program_test {};

// pgm fit --dynamic --prior-model writes what the library gives with the same settings, the first
// slice by its own map and strategy; the options of a first slice's transfer need --dynamic.
TEST_F(tower_cli, transfers_into_both_slices) {
  const auto prior_file = file("one.json", to_json(one_stack()).dump(2));
  const tower_data shape;
  std::ostringstream csv;
  write_csv(shape.data, csv);
  const auto data = file("tower.csv", csv.str());
  const std::string map = "onTop=onTop1, xOff~xOff1, yOff~yOff1, xOff@-1==xOff1, yOff1@0";
  const auto first_map = direct_this_cube(3.0).map;
  const auto fit = "fit --dynamic --data " + data.string() +
                   " --edges 'xOff->onTop, yOff->onTop, xOff@-1->onTop' --estimator bayes --prior-model " +
                   prior_file.string() + " --w-prior 3 --map '" + map + "' ";
  const auto r =
      run(fit + "--initial-map '" + first_map + "' --initial-strategy direct --out " + path("t.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("'onTop' gets the minimal prior from 'onTop1' with w = 3"));
  auto reading = long_form_options();
  const auto read = read_csv(data, reading);
  const auto structure = dynamic_structure_from_data(read, parse_edge_list("xOff->onTop, yOff->onTop, xOff@-1->onTop"));
  const auto counts = count_dynamic(structure, read);
  transfer_settings settings;
  settings.map = map;
  settings.weight = 3.0;
  const auto first_step = direct_this_cube(3.0);
  dynamic_fit_options options;
  options.fit.prior = bdeu_prior();
  static_cast<void>(add_transferred_priors(options, structure, counts, one_stack(), settings, &first_step));
  EXPECT_EQ(parse_dynamic_json(slurp(path("t.json")), "t.json"), fit_dynamic(structure, counts, options));

  expect_failure(fit + "--out " + path("u.json").string(), "the first slice: Direct-Replacement", path("u.json"));
  expect_failure(
      "fit --data " + data.string() + " --edges 'xOff->onTop' --initial-map none --out " + path("v.json").string(),
      "--initial-map and --initial-strategy apply with --dynamic", path("v.json"));
}

}  // namespace dynamic_transfer_test
}  // namespace pgm
