// The one error for an unknown name: the same message shape, a suggestion only when a known
// name is close, and the parsers of user choices all throwing it.

#include "pgm/core/unknown_name.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pgm/data/discretizer.hpp"
#include "pgm/decide/prevent.hpp"
#include "pgm/eval/metrics.hpp"
#include "pgm/inference/posterior_table.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/learn/independence_test.hpp"
#include "pgm/learn/independence_test_registry.hpp"
#include "pgm/learn/learn_structure.hpp"
#include "pgm/learn/score_registry.hpp"
#include "pgm/learn/structure_learner_registry.hpp"
#include "pgm/transfer/registry.hpp"
#include "pgm/transfer/state_map.hpp"

namespace pgm::unknown_name_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(unknown_name_test, names_the_kind_suggests_the_closest_and_lists_the_known) {
  const unknown_name near("independence test", "chi", {"chi2", "g2"});
  EXPECT_STREQ(near.what(), "unknown independence test 'chi'; did you mean 'chi2'? (known: chi2, g2)");
  EXPECT_EQ(near.kind(), "independence test");
  EXPECT_EQ(near.name(), "chi");
  EXPECT_THAT(near.known(), ElementsAre("chi2", "g2"));
  EXPECT_EQ(near.suggestion(), "chi2");

  const unknown_name far("score", "mdl", {"bic", "aic"});
  EXPECT_STREQ(far.what(), "unknown score 'mdl' (known: bic, aic)");
  EXPECT_FALSE(far.suggestion());

  const unknown_name located("task", "3-stak", {"1-stack", "3-stack"}, "looked in tasks");
  EXPECT_STREQ(located.what(),
               "unknown task '3-stak'; did you mean '3-stack'? (known: 1-stack, 3-stack; looked in tasks)");
}

TEST(unknown_name_test, every_parser_of_a_choice_throws_it) {
  EXPECT_THAT([] { static_cast<void>(make_independence_test("chi3")); },
              ThrowsMessage<unknown_name>(HasSubstr("did you mean 'chi2'?")));
  EXPECT_THAT([] { static_cast<void>(make_score("bicc")); },
              ThrowsMessage<unknown_name>(HasSubstr("did you mean 'bic'?")));
  EXPECT_THAT([] { static_cast<void>(make_structure_learner("tabo")); },
              ThrowsMessage<unknown_name>(HasSubstr("did you mean 'tabu'?")));
  EXPECT_THAT([] { static_cast<void>(parse_posterior_format("jsn")); },
              ThrowsMessage<unknown_name>(HasSubstr("did you mean 'json'?")));
  EXPECT_THAT([] { static_cast<void>(network_format_named("xmlbf")); },
              ThrowsMessage<unknown_name>(HasSubstr("did you mean 'xmlbif'?")));
  EXPECT_THAT([] { static_cast<void>(parse_experiment_metric("max_diff")); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown metric 'max_diff' (known:")));
  EXPECT_THAT([] { static_cast<void>(parse_distance("unit")); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown distance 'unit'; did you mean 'units'?")));
  EXPECT_EQ(parse_distance(to_string(prevention_options::distance::units)), prevention_options::distance::units);
  EXPECT_THAT([] { static_cast<void>(parse_empty_configuration("fails")); },
              ThrowsMessage<unknown_name>(HasSubstr("did you mean 'fail'?")));
  EXPECT_THAT([] { static_cast<void>(parse_state_matching("overlaps")); },
              ThrowsMessage<unknown_name>(HasSubstr("did you mean 'overlap'?")));
  EXPECT_THAT([] { static_cast<void>(parse_binning("widht")); },
              ThrowsMessage<unknown_name>(HasSubstr("did you mean 'width'?")));
  for (auto method : {binning::quantile, binning::equal_width}) EXPECT_EQ(parse_binning(to_string(method)), method);
  EXPECT_THAT([] { static_cast<void>(transfer_registry::instance().at("minimall")); },
              ThrowsMessage<unknown_name>(HasSubstr("did you mean 'minimal'?")));
}

}  // namespace
}  // namespace pgm::unknown_name_tests
