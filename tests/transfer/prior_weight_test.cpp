// Choosing w from the target data, and proposing correspondences.

#include "pgm/transfer/prior_weight.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <boost/math/special_functions/beta.hpp>

#include "pgm/transfer/propose.hpp"

namespace prior_weight_tests {
namespace {

using namespace pgm;
using ::testing::HasSubstr;

count_table counts_of(const variable& child, const variable& parent, std::vector<std::uint64_t> cells) {
  count_table table(child, {parent});
  std::copy(cells.begin(), cells.end(), table.counts().begin());
  return table;
}

const variable child("ok", {"0", "1"});
const variable parent("x", {"a", "b"});

TEST(prior_weight_test, evidence_is_the_beta_binomial_by_hand) {
  // One configuration with 2 failures and 3 successes under Beta(w·0.4, w·0.6), w = 5, and
  // floor 0: log B(2 + 3, 3 + 2) − log B(2, 3) (the sequence, not the count).
  const auto counts = counts_of(child, parent, {2, 3, 0, 0});
  const cpt<double> prior(child, {parent}, {0.4, 0.6, 0.5, 0.5});
  const double expected = std::log(boost::math::beta(2.0 + 2, 3.0 + 3) / boost::math::beta(2.0, 3.0));
  EXPECT_NEAR(log_evidence(counts, prior, 5.0, 0.0), expected, 1e-12);
}

TEST(prior_weight_test, a_right_prior_earns_a_large_weight_a_wrong_one_a_small_one) {
  const cpt<double> prior(child, {parent}, {0.2, 0.8, 0.7, 0.3});
  const auto agreeing = counts_of(child, parent, {200, 800, 700, 300});
  const auto disagreeing = counts_of(child, parent, {800, 200, 300, 700});
  const auto right = choose_prior_weight(agreeing, prior);
  const auto wrong = choose_prior_weight(disagreeing, prior);
  EXPECT_EQ(right.weight, 10'000);
  EXPECT_THAT(right.reason, HasSubstr("high end"));
  // Evidence favours neither extreme for mixed data (a tiny w expects all-same outcomes), but a
  // prior that contradicts the data gets a weight below the paper's smallest, 5.
  EXPECT_LT(wrong.weight, 5);
  // A prior near the data's proportions, but not equal, lands inside the grid.
  const auto near = choose_prior_weight(counts_of(child, parent, {25, 75, 65, 35}), prior);
  EXPECT_GT(near.weight, 0.1);
  EXPECT_LT(near.weight, 10'000);
  EXPECT_THAT(near.reason, HasSubstr("neighbours"));
}

TEST(prior_weight_test, without_data_the_documented_default) {
  const cpt<double> prior(child, {parent}, {0.2, 0.8, 0.7, 0.3});
  const auto choice = choose_prior_weight(counts_of(child, parent, {0, 0, 0, 0}), prior);
  EXPECT_EQ(choice.weight, 5);
  EXPECT_THAT(choice.reason, HasSubstr("no target data"));
}

TEST(prior_weight_test, a_zero_prior_against_observed_data_is_finite_and_small) {
  const cpt<double> prior(child, {parent}, {0.0, 1.0, 0.0, 1.0});
  const auto choice = choose_prior_weight(counts_of(child, parent, {10, 10, 10, 10}), prior);
  EXPECT_TRUE(std::isfinite(choice.log_evidence));
  EXPECT_LT(choice.weight, 5);
}

TEST(propose_test, stacking_proposes_the_second_cube_as_related_to_the_first) {
  const semantic_tags x{"x-offset", "cm", ""}, y{"y-offset", "cm", ""};
  auto offset = [](const std::string& name, semantic_tags tags) {
    return variable::intervals(name, {-3, -1.4, -0.4, 0.4, 1.4, 3}, std::move(tags));
  };
  const variable on1("onTop1", {"0", "1"}), on2("onTop2", {"0", "1"});
  const network_structure prior({offset("xOff1", x), offset("yOff1", y), on1},
                                {{"xOff1", "onTop1"}, {"yOff1", "onTop1"}});
  const network_structure target({offset("xOff1", x), offset("yOff1", y), offset("xOff2", x), offset("yOff2", y), on2},
                                 {{"xOff1", "onTop2"}, {"yOff1", "onTop2"}, {"xOff2", "onTop2"}, {"yOff2", "onTop2"}});
  const auto map = propose_correspondence({&target}, {&prior});
  EXPECT_EQ(to_string(map), "onTop2=onTop1,xOff2~xOff1,yOff2~yOff1");
  const auto ranking = rank_correspondences({&target}, {&prior});
  ASSERT_FALSE(ranking.empty());
  EXPECT_THAT(ranking.front().reasons, ::testing::Contains(HasSubstr("same name stem")));
  // A y-offset is never proposed for an x-offset.
  for (const auto& c : ranking) {
    if (c.target == "yOff2" && c.prior == "xOff1") {
      EXPECT_LT(c.score, 0.5);
    }
  }
}

TEST(propose_test, stack_to_drop_pairs_the_sphere_offsets_with_the_cube_offsets) {
  const semantic_tags x{"x-offset", "cm", ""}, y{"y-offset", "cm", ""};
  const auto x1 = variable::intervals("xOff1", {-3, -1.4, -0.4, 0.4, 1.4, 3}, x);
  const auto y1 = variable::intervals("yOff1", {-3, -1.4, -0.4, 0.4, 1.4, 3}, y);
  const auto xs = variable::intervals("xOff", {-6, -3.6, -1.2, 1.2, 3.6, 6}, x);
  const auto ys = variable::intervals("yOff", {-6, -3.6, -1.2, 1.2, 3.6, 6}, y);
  const auto scale = variable::intervals("scalingFactor", {0.4, 0.52, 0.64, 0.76, 0.88, 1}, {"scale", "", ""});
  const network_structure prior({x1, y1, variable("onTop1", {"0", "1"})}, {{"xOff1", "onTop1"}, {"yOff1", "onTop1"}});
  const network_structure target({xs, ys, scale, variable("inside", {"0", "1"})},
                                 {{"xOff", "inside"}, {"yOff", "inside"}, {"scalingFactor", "inside"}});
  EXPECT_EQ(to_string(propose_correspondence({&target}, {&prior})), "inside=onTop1,xOff~xOff1,yOff~yOff1");
}

}  // namespace
}  // namespace prior_weight_tests
