// The estimators by name, as `pgm fit --estimator --prior --alpha --ess` and pgm.fit name them.

#include "pgm/learn/estimator_choice.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace pgm::estimator_choice_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(estimator_choice_test, names_give_their_priors) {
  EXPECT_NE(prior_of({}).target<no_prior>(), nullptr);
  const auto bdeu = prior_of({.estimator = "bayes"});
  ASSERT_NE(bdeu.target<bdeu_prior>(), nullptr);
  EXPECT_EQ(bdeu.target<bdeu_prior>()->equivalent_sample_size, 1.0);
  EXPECT_EQ(bdeu.choice()->text(), "bdeu[ess=1]");
  const auto ess = prior_of({.estimator = "bayes", .settings = {{"--ess", "ess", "7.5"}}});
  EXPECT_EQ(ess.target<bdeu_prior>()->equivalent_sample_size, 7.5);
  const auto dirichlet =
      prior_of({.estimator = "bayes", .prior = "dirichlet", .settings = {{"--alpha", "alpha", "0.3"}}});
  EXPECT_EQ(dirichlet.target<dirichlet_prior>()->alpha, 0.3);
  EXPECT_EQ(prior_of({.estimator = "bayes", .prior = "dirichlet[alpha=0.3]"}).target<dirichlet_prior>()->alpha, 0.3);
  EXPECT_NE(prior_of({.estimator = "bayes", .prior = "k2"}).target<k2_prior>(), nullptr);
  // A setting not given is no setting.
  EXPECT_NE(
      prior_of({.estimator = "bayes", .prior = "k2", .settings = {{"--ess", "ess", std::nullopt}}}).target<k2_prior>(),
      nullptr);
}

TEST(estimator_choice_test, a_setting_the_estimator_or_the_prior_does_not_use_is_an_error) {
  EXPECT_THAT([] { (void)prior_of({.prior = "k2"}); }, ThrowsMessage<error>(HasSubstr("apply to the bayes estimator")));
  EXPECT_THAT(
      [] {
        (void)prior_of({.settings = {{"--alpha", "alpha", "2"}}});
      },
      ThrowsMessage<error>(HasSubstr("apply to the bayes estimator")));
  EXPECT_THAT(
      [] {
        (void)prior_of({.estimator = "bayes", .prior = "k2", .settings = {{"--ess", "ess", "2"}}});
      },
      ThrowsMessage<error>(HasSubstr("--ess: sets the option ess, which the prior k2 has not")));
  EXPECT_THAT(
      [] {
        (void)prior_of({.estimator = "bayes", .settings = {{"--alpha", "alpha", "2"}}});
      },
      ThrowsMessage<error>(HasSubstr("--alpha: sets the option alpha, which the prior bdeu has not")));
  EXPECT_THAT(
      [] {
        (void)prior_of({.estimator = "bayes", .prior = "bdeu[ess=2]", .settings = {{"--ess", "ess", "3"}}});
      },
      ThrowsMessage<error>(HasSubstr("--ess: sets ess, which 'bdeu[ess=2]' sets already; give it once")));
  EXPECT_THAT([] { (void)prior_of({.estimator = "map"}); }, ThrowsMessage<error>(HasSubstr("unknown estimator 'map'")));
  EXPECT_THAT([] { (void)prior_of({.estimator = "bayes", .prior = "flat"}); },
              ThrowsMessage<error>(HasSubstr("unknown prior 'flat'")));
  EXPECT_THAT(
      [] {
        (void)prior_of({.estimator = "bayes", .settings = {{"--ess", "ess", "-1"}}});
      },
      ThrowsMessage<error>(HasSubstr("--ess: option ess of the prior 'bdeu' must be a number >= 0, got '-1'")));
}

}  // namespace
}  // namespace pgm::estimator_choice_tests
