// The built-in estimators by name, as `pgm fit --estimator --prior --alpha --ess` and pgm.fit
// name them.

#include "pgm/learn/estimator_choice.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace pgm::estimator_choice_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(estimator_choice_test, names_give_their_priors) {
  EXPECT_TRUE(std::holds_alternative<no_prior>(prior_of({})));
  const auto bdeu = prior_of({.estimator = "bayes"});
  ASSERT_TRUE(std::holds_alternative<bdeu_prior>(bdeu));
  EXPECT_EQ(std::get<bdeu_prior>(bdeu).equivalent_sample_size, 1.0);
  EXPECT_EQ(std::get<bdeu_prior>(prior_of({.estimator = "bayes", .ess = 7.5})).equivalent_sample_size, 7.5);
  EXPECT_EQ(std::get<dirichlet_prior>(prior_of({.estimator = "bayes", .prior = "dirichlet", .alpha = 0.3})).alpha, 0.3);
  EXPECT_TRUE(std::holds_alternative<k2_prior>(prior_of({.estimator = "bayes", .prior = "k2"})));
}

TEST(estimator_choice_test, a_setting_the_estimator_does_not_use_is_an_error) {
  EXPECT_THAT([] { (void)prior_of({.prior = "k2"}); }, ThrowsMessage<error>(HasSubstr("apply to the bayes estimator")));
  EXPECT_THAT([] { (void)prior_of({.estimator = "bayes", .prior = "k2", .ess = 2.0}); },
              ThrowsMessage<error>(HasSubstr("ess applies to the bdeu prior")));
  EXPECT_THAT([] { (void)prior_of({.estimator = "bayes", .alpha = 2.0}); },
              ThrowsMessage<error>(HasSubstr("alpha applies to the dirichlet prior")));
  EXPECT_THAT([] { (void)prior_of({.estimator = "map"}); }, ThrowsMessage<error>(HasSubstr("unknown estimator 'map'")));
  EXPECT_THAT([] { (void)prior_of({.estimator = "bayes", .prior = "flat"}); },
              ThrowsMessage<error>(HasSubstr("unknown prior 'flat'")));
  EXPECT_THAT([] { (void)prior_of({.estimator = "bayes", .ess = -1.0}); }, ThrowsMessage<error>(HasSubstr("ess")));
}

}  // namespace
}  // namespace pgm::estimator_choice_tests
