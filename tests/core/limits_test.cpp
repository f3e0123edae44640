// The limit of table cells (pgm/core/limits.hpp): refused before anything is allocated.

#include "pgm/core/limits.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "pgm/core/cpt.hpp"
#include "pgm/data/sufficient_statistics.hpp"

namespace pgm::core_limits_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

variable many(const std::string& name, std::size_t states) {
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < states; ++i) labels.push_back(std::to_string(i));
  return variable(name, std::move(labels));
}

TEST(limits_test, table_cells_up_to_the_limit_are_counted) {
  EXPECT_EQ(checked_table_cells("y", 2, max_table_cells / 2), max_table_cells);
  EXPECT_EQ(checked_table_cells("y", 3, 0), 0u);
}

TEST(limits_test, a_table_beyond_the_limit_names_it) {
  EXPECT_THAT([] { static_cast<void>(checked_table_cells("y", 2, max_table_cells / 2 + 1)); },
              ThrowsMessage<table_too_large>(HasSubstr(
                  "the table of 'y' would have 16777218 cells (2 states × 8388609 parent configurations), more than "
                  "pgm's limit of 16777216 cells per table (docs/limits.md)")));
  // A product beyond 2^64 is never formed.
  EXPECT_THAT([] { static_cast<void>(checked_table_cells("y", std::numeric_limits<std::size_t>::max(), 3)); },
              ThrowsMessage<table_too_large>(HasSubstr("more than 2^64 cells")));
}

TEST(limits_test, uniform_tables_are_refused_and_count_tables_kept_sparse_before_they_are_allocated) {
  // 1000 × 1000 × 1000 = 10^9 cells: 8 GB if it were allocated.
  const auto first = many("a", 1000), second = many("b", 1000), child = many("y", 1000);
  EXPECT_THAT(
      [&] {
        cpt<double> table(child, {first, second});
      },
      ThrowsMessage<table_too_large>(HasSubstr("'y' would have 1000000000 cells")));
  // Counts of so many configurations are kept sparse, holding what rows bring, within the limit.
  count_table counts(child, {first, second});
  EXPECT_TRUE(counts.is_sparse());
  std::vector<count_table::cell> cells;
  for (std::size_t u = 0; u <= max_table_cells / 1000; ++u)
    cells.push_back({.configuration = u, .state = 0, .count = 1});
  EXPECT_THAT([&] { counts.add(cells); }, ThrowsMessage<table_too_large>(HasSubstr("'y' would have 16778000 cells")));
  cells.pop_back();
  cells.pop_back();
  EXPECT_NO_THROW(counts.add(cells));
  EXPECT_FALSE(count_table(child, {first}).is_sparse());
}

}  // namespace
}  // namespace pgm::core_limits_tests
