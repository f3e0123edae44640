#include "pgm/data/dataset.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace pgm::dataset_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(dataset_test, code_width_follows_cardinality) {
  auto labels = [](std::size_t n) {
    std::vector<std::string> l;
    for (std::size_t i = 0; i < n; ++i) l.push_back(std::to_string(i));
    return l;
  };
  EXPECT_EQ(discrete_column(variable("a", labels(256)), std::vector<unsigned>{255}).code_width(), 1u);
  EXPECT_EQ(discrete_column(variable("a", labels(257)), std::vector<unsigned>{256}).code_width(), 2u);
  EXPECT_EQ(discrete_column(variable("a", labels(70000)), std::vector<unsigned>{69999}).code_width(), 4u);
}

TEST(dataset_test, codes_must_index_states) {
  EXPECT_THAT(
      [] {
        discrete_column(variable("a", {"x", "y"}), std::vector<unsigned>{0, 2});
      },
      ThrowsMessage<data_error>(HasSubstr("column 'a' row 2: state code 2 is out of range (2 states)")));
}

TEST(dataset_test, columns_must_agree) {
  dataset data("runs.csv");
  data.add(continuous_column("x", {1, 2, 3}));
  EXPECT_THAT(
      [&] {
        data.add(continuous_column("y", {1, 2}));
      },
      ThrowsMessage<data_error>(HasSubstr("runs.csv: column 'y' has 2 rows, the others 3")));
  EXPECT_THAT([&] { data.add(continuous_column("x", {1, 2, 3})); }, ThrowsMessage<data_error>(HasSubstr("twice")));
  EXPECT_THAT([&] { static_cast<void>(data.discrete("x")); },
              ThrowsMessage<data_error>(HasSubstr("discretize it first")));
  EXPECT_THAT([&] { static_cast<void>(data.at("z")); },
              ThrowsMessage<data_error>(HasSubstr("runs.csv: there is no column 'z' (columns: x)")));
}

TEST(dataset_test, select_and_slice_rows) {
  dataset data;
  data.add(continuous_column("x", {10, 11, 12, 13}));
  data.add(discrete_column(variable("c", {"a", "b"}), std::vector<unsigned>{0, 1, 0, 1}));
  const std::vector<std::size_t> rows{3, 0};
  const auto picked = data.select_rows(rows);
  EXPECT_THAT(picked.continuous("x").values(), ElementsAre(13, 10));
  EXPECT_EQ(picked.discrete("c").code(0), 1u);
  EXPECT_THAT(data.slice(1, 3).continuous("x").values(), ElementsAre(11, 12));
  EXPECT_EQ(data.slice(2, 100).rows(), 2u);
  const std::vector<std::size_t> bad{9};
  EXPECT_THROW(static_cast<void>(data.select_rows(bad)), data_error);
}

}  // namespace
}  // namespace pgm::dataset_tests
