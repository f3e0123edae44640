// Episodes in long form (pgm/data/episodes.hpp): each episode's rows in step order, whatever the
// order of the rows, and every malformed step named.

#include "pgm/data/episodes.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace pgm {
namespace episodes_test {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

dataset long_form(const std::vector<std::string>& episode, const std::vector<double>& t) {
  dataset data("runs.csv");
  std::vector<std::string> names;
  std::vector<std::uint32_t> codes;
  for (const auto& e : episode) {
    const auto it = std::find(names.begin(), names.end(), e);
    codes.push_back(static_cast<std::uint32_t>(it - names.begin()));
    if (it == names.end()) names.push_back(e);
  }
  data.add(discrete_column(variable("episode", names), codes));
  data.add(continuous_column("t", t));
  return data;
}

TEST(episodes_test, rows_in_any_order_are_indexed_by_episode_then_step) {
  const auto data = long_form({"b", "a", "b", "a", "a", "c"}, {1, 2, 0, 0, 1, 0});
  const auto index = index_episodes(data);
  EXPECT_EQ(index.episodes(), 3u);
  EXPECT_EQ(episode_name(data, index, 0), "b");
  EXPECT_EQ(episode_name(data, index, 2), "c");
  EXPECT_THAT(index.starts, ElementsAre(0u, 2u, 5u, 6u));
  EXPECT_THAT(index.rows, ElementsAre(2u, 0u, 3u, 4u, 1u, 5u));
  EXPECT_EQ(index.length(1), 3u);
}

TEST(episodes_test, rows_in_order_are_found_so_in_one_pass) {
  const auto data = long_form({"a", "a", "b", "c", "c", "c"}, {0, 1, 0, 0, 1, 2});
  const auto index = index_episodes(data);
  EXPECT_TRUE(index.in_order());
  EXPECT_THAT(index.starts, ElementsAre(0u, 2u, 3u, 6u));
  EXPECT_EQ(index.row(4), 4u);
  EXPECT_EQ(episode_name(data, index, 1), "b");
  // An episode that comes back later is not in order; its rows are still found.
  const auto back = index_episodes(long_form({"a", "a", "b", "a"}, {0, 1, 0, 2}));
  EXPECT_FALSE(back.in_order());
  EXPECT_THAT(back.rows, ElementsAre(0u, 1u, 3u, 2u));
  EXPECT_THAT(
      [] {
        static_cast<void>(index_episodes(long_form({"a", "b", "a"}, {0, 0, 0})));
      },
      ThrowsMessage<data_error>(HasSubstr("episode 'a' has two rows with t = 0 (data rows 1 and 3)")));
}

TEST(episodes_test, numbered_episodes_and_no_episode_column) {
  dataset data("runs.csv");
  data.add(continuous_column("run", {7, 7, 3}));
  data.add(continuous_column("step", {1, 0, 0}));
  const auto index = index_episodes(data, {.episode = "run", .step = "step"});
  EXPECT_EQ(index.episodes(), 2u);
  EXPECT_EQ(episode_name(data, index, 0, {.episode = "run"}), "7");
  EXPECT_EQ(episode_name(data, index, 1, {.episode = "run"}), "3");
  EXPECT_THAT(index.rows, ElementsAre(1u, 0u, 2u));
  // Without the episode column the data are one episode.
  const auto one = index_episodes(data.select_rows(std::vector<std::size_t>{0, 1}), {.step = "step"});
  EXPECT_EQ(one.episodes(), 1u);
  EXPECT_THAT(one.rows, ElementsAre(1u, 0u));
  EXPECT_THAT(
      [&] { static_cast<void>(index_episodes(data, {.step = "step"})); },
      ThrowsMessage<data_error>(HasSubstr("episode '(the only one)' has two rows with t = 0 (data rows 2 and 3)")));
}

TEST(episodes_test, every_malformed_step_is_named) {
  const auto refused = [](const dataset& data, const std::string& message) {
    EXPECT_THAT([&] { static_cast<void>(index_episodes(data)); }, ThrowsMessage<data_error>(HasSubstr(message)))
        << message;
  };
  refused(long_form({"a", "a", "a"}, {0, 1, 1}), "runs.csv: episode 'a' has two rows with t = 1 (data rows 2 and 3)");
  refused(long_form({"a", "b", "a"}, {0, 0, 2}),
          "runs.csv: episode 'a' has no row with t = 1, but one with t = 2 (data row 3): the steps of an episode run "
          "t = 0, 1, 2, … without a gap");
  refused(long_form({"a", "a"}, {1, 2}), "episode 'a' has no row with t = 0, but one with t = 1 (data row 1)");
  refused(long_form({"a", "a"}, {0, 1.5}), "runs.csv: data row 2: the step 't' is 1.5, not a whole number ≥ 0");
  refused(long_form({"a"}, {-1}), "data row 1: the step 't' is -1, not a whole number ≥ 0");
  refused(long_form({"a", "a"}, {0, std::nan("")}), "data row 2: the step 't' is missing");
  refused(long_form({"a"}, {1e300}), "episode 'a' has no row with t = 0, but one with t = 1e+300");
  dataset no_step("runs.csv");
  no_step.add(continuous_column("x", {1.0}));
  refused(no_step, "runs.csv: the data have no column 't' numbering the steps (long form: episode,t,<variables>");
  // A step read as labels is read as the number it writes.
  dataset labelled("runs.csv");
  labelled.add(discrete_column(variable("t", {"0", "1", "one"}), std::vector<std::uint32_t>{1, 0, 2}));
  refused(labelled, "data row 3: the step 't' is 'one', not a number");
  EXPECT_THAT(index_episodes(labelled.select_rows(std::vector<std::size_t>{0, 1})).rows, ElementsAre(1u, 0u));
}

}  // namespace episodes_test
}  // namespace pgm
