// The three replacement strategies on the shapes of the paper's scenarios (Table II), Example 1,
// and the identities of eq. 8.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "pgm/inference/sampling.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/testing/random_network.hpp"
#include "pgm/transfer/network_transfer.hpp"
#include "pgm/transfer/replacement.hpp"

namespace transfer_tests {
namespace {

using namespace pgm;
using pgm::testing::random_network;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

const std::vector<double> stack_edges{-3.0, -1.4, -0.4, 0.4, 1.4, 3.0};
const std::vector<double> drop_edges{-6.0, -3.6, -1.2, 1.2, 3.6, 6.0};
const variable outcome_1("onTop1", {"0", "1"});
const variable outcome_2("onTop2", {"0", "1"});

variable offset(const std::string& name, const std::vector<double>& edges = stack_edges) {
  return variable::intervals(name, edges);
}

/// A binary child's table whose success probability differs in every configuration:
/// P(1 | u) = 0.05 + 0.9 · u / (n - 1), with `shuffle` permuting which u gets which.
cpt<double> distinct_table(const variable& child, std::vector<variable> parents, unsigned shuffle = 0) {
  std::size_t n = 1;
  for (const auto& p : parents) n *= p.cardinality();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(shuffle));
  std::vector<double> values;
  for (std::size_t u = 0; u < n; ++u) {
    const double p = 0.05 + 0.9 * static_cast<double>(order[u]) / static_cast<double>(std::max<std::size_t>(n - 1, 1));
    values.push_back(1 - p);
    values.push_back(p);
  }
  return cpt<double>(child, std::move(parents), std::move(values));
}

double success(const cpt<double>& table, std::vector<std::size_t> codes) {
  return table.column(table.configuration(codes))[1];
}

struct two_stack : ::testing::Test {
  cpt<double> prior = distinct_table(outcome_1, {offset("xOff1"), offset("yOff1")}, 3);
  std::vector<variable> target_parents{offset("xOff1"), offset("yOff1"), offset("xOff2"), offset("yOff2")};
  correspondence map = parse_correspondence("onTop2=onTop1, xOff2~xOff1, yOff2~yOff1");
  transfer_problem problem{prior, outcome_2, target_parents, map};
};

TEST_F(two_stack, direct_reads_the_first_cube_for_all_625_parameters) {
  const auto result = direct_replacement{}(problem);
  ASSERT_EQ(result.table().configurations(), 625U);
  for (std::size_t u = 0; u < 625; ++u) {
    const auto codes = result.table().parent_codes(index_at<config_index>(u));
    EXPECT_EQ(result.table().column(index_at<config_index>(u))[1], success(prior, {codes[0], codes[1]}));
  }
  EXPECT_EQ(result.describe_sources(result.table().configuration(std::vector<std::size_t>{2, 3, 4, 0})),
            "xOff1=2, yOff1=3");
}

TEST_F(two_stack, cross_reads_the_second_cube_as_the_first) {
  const auto result = cross_replacement{}(problem);
  for (std::size_t u = 0; u < 625; ++u) {
    const config_index c = index_at<config_index>(u);
    const auto codes = result.table().parent_codes(c);
    EXPECT_EQ(result.table().column(c)[1], success(prior, {codes[2], codes[3]}));
    EXPECT_EQ(result.via(c), replacement::cross);
  }
}

TEST_F(two_stack, minimal_takes_the_smaller_success_and_says_which) {
  const auto result = minimal_replacement{}(problem);
  std::size_t direct_wins = 0;
  for (std::size_t u = 0; u < 625; ++u) {
    const config_index c = index_at<config_index>(u);
    const auto codes = result.table().parent_codes(c);
    const double d = success(prior, {codes[0], codes[1]});
    const double x = success(prior, {codes[2], codes[3]});
    EXPECT_EQ(result.table().column(c)[1], std::min(d, x));
    EXPECT_EQ(result.via(c), d < x ? replacement::direct : replacement::cross);  // ties go to cross (eq. 9)
    direct_wins += d < x;
  }
  EXPECT_EQ(direct_wins, 300U);  // of the 625 pairs, 25 tie and the rest split evenly
}

// Example 1 of the paper: xOffset = 0.5, yOffset = 1, xOffset2 = 1.5, yOffset2 = 2 (cm).
TEST_F(two_stack, example_1_of_the_paper) {
  const auto u = [&](const variable& v, double value) { return v.bin(value).value(); };
  const std::vector<std::size_t> codes{u(target_parents[0], 0.5), u(target_parents[1], 1.0), u(target_parents[2], 1.5),
                                       u(target_parents[3], 2.0)};
  const double direct = success(prior, {codes[0], codes[1]});  // P(onTop=1 | 0.5, 1)
  const double cross = success(prior, {codes[2], codes[3]});   // P(onTop=1 | 1.5, 2)
  EXPECT_NE(direct, cross);
  EXPECT_EQ(success(direct_replacement{}(problem).table(), codes), direct);
  EXPECT_EQ(success(cross_replacement{}(problem).table(), codes), cross);
  EXPECT_EQ(success(minimal_replacement{}(problem).table(), codes), std::min(direct, cross));
}

TEST(transfer_test, reality_3_to_9_on_the_offset_grid) {
  const variable x1("xOff1", {"0", "0.9", "2.2"}), x2("xOff2", {"0", "0.9", "2.2"});
  const auto prior = distinct_table(outcome_1, {x1});
  const transfer_problem problem(prior, outcome_2, {x1, x2}, parse_correspondence("onTop2=onTop1,xOff2~xOff1"));
  const auto direct = direct_replacement{}(problem), cross = cross_replacement{}(problem),
             minimal = minimal_replacement{}(problem);
  ASSERT_EQ(direct.table().configurations(), 9U);
  for (std::size_t a = 0; a < 3; ++a) {
    for (std::size_t b = 0; b < 3; ++b) {
      EXPECT_EQ(success(direct.table(), {a, b}), success(prior, {a}));
      EXPECT_EQ(success(cross.table(), {a, b}), success(prior, {b}));
      EXPECT_EQ(success(minimal.table(), {a, b}), std::min(success(prior, {a}), success(prior, {b})));
    }
  }
}

TEST(transfer_test, sphere_dropping_125_to_125_is_the_identity) {
  const std::vector<variable> parents{offset("xOff", drop_edges), offset("yOff", drop_edges),
                                      variable::intervals("scalingFactor", {0.4, 0.52, 0.64, 0.76, 0.88, 1.0})};
  const variable inside("inside", {"0", "1"});
  const auto prior = distinct_table(inside, parents, 11);
  const transfer_problem problem(prior, inside, parents, parse_correspondence("inside=inside"));
  EXPECT_EQ(direct_replacement{}(problem).table(), prior);
}

TEST(transfer_test, stack_to_drop_25_to_125_by_cross_with_midpoints) {
  const auto prior = distinct_table(outcome_1, {offset("xOff1"), offset("yOff1")}, 5);
  const variable inside("inside", {"0", "1"});
  const std::vector<variable> parents{offset("xOff", drop_edges), offset("yOff", drop_edges),
                                      variable::intervals("scalingFactor", {0.4, 0.52, 0.64, 0.76, 0.88, 1.0})};
  const transfer_problem problem(prior, inside, parents, parse_correspondence("inside=onTop1,xOff~xOff1,yOff~yOff1"));
  const auto result = cross_replacement{}(problem);
  ASSERT_EQ(result.table().configurations(), 125U);
  // Drop bins' midpoints -4.8, -2.4, 0, 2.4, 4.8 fall in stack bins 0, 0, 2, 4, 4.
  const std::size_t stack_bin[] = {0, 0, 2, 4, 4};
  for (std::size_t x = 0; x < 5; ++x) {
    for (std::size_t y = 0; y < 5; ++y) {
      for (std::size_t s = 0; s < 5; ++s) {
        EXPECT_EQ(success(result.table(), {x, y, s}), success(prior, {stack_bin[x], stack_bin[y]}));
      }
    }
  }
  EXPECT_THAT([&] { static_cast<void>(direct_replacement{}(problem)); },
              ThrowsMessage<model_error>(
                  HasSubstr("Direct-Replacement leaves the prior's parent 'xOff1' of 'onTop1' unassigned")));
}

TEST(transfer_test, sim_to_real_maps_points_into_bins_and_pins_what_reality_holds_fixed) {
  const auto prior = distinct_table(outcome_2, {offset("xOff1"), offset("yOff1"), offset("xOff2"), offset("yOff2")}, 9);
  const variable x1("xOff1", {"0", "0.9", "2.2"}), x2("xOff2", {"0", "0.9", "2.2"});
  const std::size_t bin[] = {2, 3, 4};  // 0 ∈ [-0.4, 0.4), 0.9 ∈ [0.4, 1.4), 2.2 ∈ [1.4, 3]
  EXPECT_THAT(
      [&] {
        static_cast<void>(
            direct_replacement{}(transfer_problem(prior, outcome_2, {x1, x2}, parse_correspondence("onTop2=onTop2"))));
      },
      ThrowsMessage<model_error>(HasSubstr("pin it with 'yOff1@<value>' or marginalize it with 'yOff1@*'")));
  const transfer_problem problem(prior, outcome_2, {x1, x2}, parse_correspondence("onTop2=onTop2,yOff1@0,yOff2@0"));
  const auto result = direct_replacement{}(problem);
  for (std::size_t a = 0; a < 3; ++a) {
    for (std::size_t b = 0; b < 3; ++b)
      EXPECT_EQ(success(result.table(), {a, b}), success(prior, {bin[a], 2, bin[b], 2}));
  }
}

TEST(transfer_test, marginalizing_mixes_columns_by_the_prior_marginal) {
  const variable a("a", {"0", "1"}), b("b", {"0", "1"}), x("x", {"0", "1"});
  const auto net = bayesian_network::from_tables({cpt<double>(a, {}, {0.5, 0.5}), cpt<double>(b, {}, {0.25, 0.75}),
                                                  cpt<double>(x, {a, b}, {0.9, 0.1, 0.8, 0.2, 0.6, 0.4, 0.3, 0.7})});
  const transfer_problem problem(net, "x", x, {a}, parse_correspondence("x=x,b@*"));
  const auto result = direct_replacement{}(problem);
  EXPECT_DOUBLE_EQ(success(result.table(), {0}), 0.25 * 0.1 + 0.75 * 0.2);
  EXPECT_DOUBLE_EQ(success(result.table(), {1}), 0.25 * 0.4 + 0.75 * 0.7);
  EXPECT_EQ(result.sources(config_index(1)).size(), 2U);
  EXPECT_EQ(result.describe_sources(config_index(1)), "0.25·(a=1, b=0) + 0.75·(a=1, b=1)");
}

TEST(transfer_test, overlap_matching_weights_prior_intervals_by_length) {
  const auto prior = distinct_table(outcome_1, {offset("xOff1")});
  const variable coarse = variable::intervals("xOff1", {-3.0, 0.0, 3.0});
  transfer_options options;
  options.matching = state_matching::overlap;
  const transfer_problem problem(prior, outcome_1, {coarse}, parse_correspondence("onTop1=onTop1"), options);
  const auto result = direct_replacement{}(problem);
  // [-3, 0) covers [-3,-1.4) 1.6, [-1.4,-0.4) 1.0 and [-0.4, 0) 0.4 of 3 cm.
  const double expected = (1.6 * success(prior, {0}) + 1.0 * success(prior, {1}) + 0.4 * success(prior, {2})) / 3.0;
  EXPECT_NEAR(success(result.table(), {0}), expected, 1e-15);
}

TEST(transfer_test, mismatched_children_and_unmatched_states_are_errors) {
  const auto prior = distinct_table(outcome_1, {offset("xOff1")});
  const variable three("onTop2", {"0", "1", "2"});
  EXPECT_THAT(
      [&] {
        static_cast<void>(direct_replacement{}(
            transfer_problem(prior, three, {offset("xOff1")}, parse_correspondence("onTop2=onTop1"))));
      },
      ThrowsMessage<model_error>(HasSubstr("the prior has no state '2'")));
  const variable colour("xOff1", {"red", "blue"});
  EXPECT_THAT(
      [&] {
        static_cast<void>(
            direct_replacement{}(transfer_problem(prior, outcome_2, {colour}, parse_correspondence("onTop2=onTop1"))));
      },
      ThrowsMessage<model_error>(HasSubstr("state 'red' has no value on the prior's scale")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(minimal_replacement{}(transfer_problem(
            prior, variable("onTop2", {"no", "yes"}), {offset("xOff1")}, parse_correspondence("onTop2=onTop1"))));
      },
      ThrowsMessage<model_error>(HasSubstr("has no success state '1'")));
}

TEST(transfer_test, correspondence_syntax) {
  const auto map = parse_correspondence(" onTop2 = onTop1, xOff2~xOff1 ,xOffset==xOff1, yOff1@0, yOff2@*");
  EXPECT_EQ(map.transferred.at("onTop2"), "onTop1");
  EXPECT_EQ(map.related.at("xOff2"), "xOff1");
  EXPECT_EQ(map.identical_to("xOffset"), "xOff1");
  EXPECT_EQ(map.identical_to("yOff1"), "yOff1");
  EXPECT_EQ(map.pinned.at("yOff1").value, "0");
  EXPECT_TRUE(map.pinned.at("yOff2").marginalize());
  EXPECT_EQ(parse_correspondence(to_string(map)), map);
  // A dynamic network's previous slice in a pair is no pin.
  const auto slices = parse_correspondence("onTop=onTop1, xOff@-1==xOff1, yOff@-1~yOff1, xOff1@*");
  EXPECT_EQ(slices.identical_to("xOff@-1"), "xOff1");
  EXPECT_EQ(slices.related.at("yOff@-1"), "yOff1");
  EXPECT_EQ(slices.pinned.size(), 1u);
  EXPECT_THAT([] { static_cast<void>(parse_correspondence("onTop2=onTop1,xOff2")); },
              ThrowsMessage<model_error>(HasSubstr("map entry 2 ('xOff2') has no '=', '~', '==' or '@'")));
  EXPECT_THAT([] { static_cast<void>(parse_correspondence("xOff2~xOff1")); },
              ThrowsMessage<model_error>(HasSubstr("names no transferred node")));
  EXPECT_THAT([] { static_cast<void>(parse_correspondence("a=b,a=c")); },
              ThrowsMessage<model_error>(HasSubstr("gives 'a' a second transferred counterpart")));
}

// Eq. 8 through a whole fit: w = 0 is MLE, M[u] = 0 gives f(θ′), every column a distribution.
TEST(transfer_test, weighted_transfer_identities_on_random_networks) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto truth = random_network(seed, {.nodes = 6, .max_parents = 3, .max_states = 3});
    const auto data = sample(truth, seed % 4 == 0 ? 0 : 40 + seed, seed);
    const auto& structure = truth.structure();
    // The prior is the truth itself with its states, so direct replacement is the identity.
    correspondence map;
    for (const auto& v : structure.variables()) map.transferred.emplace(v.name(), v.name());
    const auto priors = transfer_priors(truth, structure, map, direct_replacement{});
    fit_options zero, weighted;
    use_transferred_priors(zero, priors, [&] {
      std::map<std::string, double, std::less<>> w;
      for (const auto& v : structure.variables()) w.emplace(v.name(), 0.0);
      return w;
    }());
    EXPECT_EQ(fit(structure, data, zero).tables(), fit(structure, data).tables()) << seed;
    std::map<std::string, double, std::less<>> five;
    for (const auto& v : structure.variables()) five.emplace(v.name(), 5.0);
    use_transferred_priors(weighted, priors, five);
    const auto fitted = fit(structure, data, weighted);
    for (std::size_t i = 0; i < structure.size(); ++i) {
      const variable_id id = index_at<variable_id>(i);
      const auto counts = count_node(structure, id, data);
      const auto& table = fitted.table(id);
      for (std::size_t u = 0; u < table.configurations(); ++u) {
        const config_index c = index_at<config_index>(u);
        double sum = 0;
        for (double p : table.column(c)) sum += p;
        EXPECT_NEAR(sum, 1.0, 1e-12);
        if (counts.total(c) == 0) {
          const auto expected = truth.table(id).column(c);
          EXPECT_TRUE(std::equal(expected.begin(), expected.end(), table.column(c).begin())) << seed;
        }
      }
    }
  }
}

TEST(transfer_test, map_names_are_checked_against_both_networks) {
  const auto prior = bayesian_network::from_tables(
      {cpt<double>(offset("xOff1"), {}, std::vector<double>(5, 0.2)), distinct_table(outcome_1, {offset("xOff1")})});
  const network_structure target({offset("xOff1"), offset("xOff2"), outcome_2},
                                 {{"xOff1", "onTop2"}, {"xOff2", "onTop2"}});
  EXPECT_THAT(
      [&] {
        static_cast<void>(transfer_priors(prior, target, parse_correspondence("onTop2=onTop9"), direct_replacement{}));
      },
      ThrowsMessage<model_error>(
          HasSubstr("the map's transferred node 'onTop9' is not a variable of the prior network")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(
            transfer_priors(prior, target, parse_correspondence("onTop2=onTop1,xOff3~xOff1"), cross_replacement{}));
      },
      ThrowsMessage<model_error>(
          HasSubstr("the map's related variable 'xOff3' is not a variable of the target network")));
  const auto priors =
      transfer_priors(prior, target, parse_correspondence("onTop2=onTop1,xOff2~xOff1"), cross_replacement{});
  EXPECT_EQ(priors.at("onTop2").table().configurations(), 25U);
}

TEST(transfer_test, a_transferred_node_cannot_take_the_table_of_its_parents_counterpart) {
  const auto prior = bayesian_network::from_tables(
      {cpt<double>(offset("xOff1"), {}, std::vector<double>(5, 0.2)), distinct_table(outcome_1, {offset("xOff1")})});
  const network_structure target({offset("xOff1"), offset("xOff2"), outcome_2},
                                 {{"xOff1", "onTop2"}, {"xOff2", "onTop2"}});
  // The prior's xOff1 is already the target's xOff1 (same name), a parent of onTop2.
  EXPECT_THAT([&] { check_correspondence(parse_correspondence("onTop2=xOff1"), prior, target); },
              ThrowsMessage<model_error>(HasSubstr("map entry 'onTop2=xOff1': the prior's 'xOff1' already stands for "
                                                   "'xOff1', a parent of 'onTop2'")));
  // ... and so is it through `~`.
  EXPECT_THAT([&] { check_correspondence(parse_correspondence("onTop2=xOff1,xOff2~xOff1"), prior, target); },
              ThrowsMessage<model_error>(HasSubstr("already stands for 'xOff1'")));
  EXPECT_NO_THROW(check_correspondence(parse_correspondence("onTop2=onTop1,xOff2~xOff1"), prior, target));
}

}  // namespace
}  // namespace transfer_tests
