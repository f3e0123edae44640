#include "pgm/learn/count_values.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace pgm::count_values_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// Columns of random values drawn from `values[c]`, in a row-major matrix (so that each column is
/// strided) and column by column.
struct value_frame {
  std::vector<std::string> names;
  std::vector<std::vector<std::int64_t>> columns;
  std::vector<std::int64_t> matrix;  // rows × columns

  value_frame(const std::vector<std::vector<std::int64_t>>& values, std::size_t rows, std::uint64_t seed) {
    std::mt19937_64 random(seed);
    for (std::size_t c = 0; c < values.size(); ++c) {
      names.push_back("v" + std::to_string(c));
      std::uniform_int_distribution<std::size_t> pick(0, values[c].size() - 1);
      auto& column = columns.emplace_back(rows);
      for (auto& v : column) v = values[c][pick(random)];
    }
    for (std::size_t r = 0; r < rows; ++r) {
      for (const auto& column : columns) matrix.push_back(column[r]);
    }
  }

  [[nodiscard]] std::vector<named_value_column> contiguous() const {
    std::vector<named_value_column> result;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      result.push_back({names[c], value_span<std::int64_t>{columns[c].data(), columns[c].size(), 1}});
    }
    return result;
  }
  [[nodiscard]] std::vector<named_value_column> strided() const {
    std::vector<named_value_column> result;
    const auto width = static_cast<std::ptrdiff_t>(columns.size());
    for (std::size_t c = 0; c < columns.size(); ++c) {
      result.push_back({names[c], value_span<std::int64_t>{matrix.data() + c, columns[c].size(), width}});
    }
    return result;
  }
  /// The data set the CSV reader would make of the same values.
  [[nodiscard]] dataset data() const {
    dataset result;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      std::vector<std::int64_t> distinct = columns[c];
      std::sort(distinct.begin(), distinct.end());
      distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
      std::vector<std::string> states;
      for (const auto v : distinct) states.push_back(std::to_string(v));
      std::vector<std::size_t> codes;
      for (const auto v : columns[c]) {
        codes.push_back(
            static_cast<std::size_t>(std::lower_bound(distinct.begin(), distinct.end(), v) - distinct.begin()));
      }
      result.add(discrete_column(variable(names[c], states), codes));
    }
    return result;
  }
};

count_table expected(const dataset& data, const value_frame& frame, const value_family& family) {
  std::vector<std::string> parents;
  for (const auto p : family.parents) parents.push_back(frame.names[p]);
  return count_family(data, frame.names[family.child], parents, {.threads = 1});
}

// Families that share columns (summed out of one another: v1 | v0 out of v1 | v0, v2) and that do
// not (v3 | v2 beside v1 | v0, v2), a root, and a column no family names (v4).
const std::vector<value_family> families{{1, {0, 2}}, {1, {0}}, {3, {2}}, {0, {}}, {2, {1}}};

TEST(count_values_test, equal_the_counts_of_the_data_set_of_the_same_values) {
  // Gaps, a range not starting at 0, a single value, a wide range (10000).
  const value_frame frame({{0, 1}, {3, 7, 12}, {5, 4, 3, 2, 1, 0}, {9}, {0, 10000}}, 5000, 1);
  const auto data = frame.data();
  for (const auto& columns : {frame.contiguous(), frame.strided()}) {
    const auto counts = count_value_families(columns, families, {.threads = 1});
    ASSERT_TRUE(counts.has_value());
    ASSERT_EQ(counts->variables.size(), 5u);
    EXPECT_EQ(counts->variables[1], variable("v1", {"3", "7", "12"}));
    EXPECT_EQ(counts->variables[4], variable("v4", {"0", "10000"}));
    ASSERT_EQ(counts->tables.size(), families.size());
    for (std::size_t i = 0; i < families.size(); ++i) {
      EXPECT_EQ(counts->tables[i], expected(data, frame, families[i])) << "family " << i;
    }
  }
}

TEST(count_values_test, the_same_counts_on_any_number_of_threads) {
  const value_frame frame({{0, 1, 2}, {0, 1, 2, 3, 4}, {1, 2}, {0, 1}, {4}}, 50'000, 2);
  const auto one = count_value_families(frame.contiguous(), families, {.threads = 1});
  const auto four = count_value_families(frame.contiguous(), families, {.threads = 4, .min_rows_per_thread = 1});
  ASSERT_TRUE(one && four);
  EXPECT_EQ(one->tables, four->tables);
  EXPECT_EQ(one->tables[0], expected(frame.data(), frame, families[0]));
}

TEST(count_values_test, a_value_the_sample_misses_is_counted_in_a_second_pass) {
  // Sorted values, one large value at a row the first guess never looks at.
  std::vector<std::uint16_t> child(100'000, 0);
  std::vector<std::uint8_t> parent(100'000, 1);
  std::fill(child.begin() + 50'000, child.end(), 1);
  child[1] = 300;
  parent[3] = 0;
  const std::vector<named_value_column> columns{{"c", value_span<std::uint16_t>{child.data(), child.size(), 1}},
                                                {"p", value_span<std::uint8_t>{parent.data(), parent.size(), 1}}};
  const auto counts = count_value_families(columns, std::vector<value_family>{{0, {1}}}, {.threads = 1});
  ASSERT_TRUE(counts.has_value());
  EXPECT_EQ(counts->variables[0], variable("c", {"0", "1", "300"}));
  EXPECT_EQ(counts->variables[1], variable("p", {"0", "1"}));
  // Configuration p=0: the row with 0; p=1: 49'998 zeros, 50'000 ones, the 300.
  EXPECT_THAT(counts->tables[0].counts(), ElementsAre(1, 0, 0, 49'998, 50'000, 1));
}

TEST(count_values_test, values_of_every_integer_type) {
  const std::vector<std::int8_t> a{2, 0, 2, 2};
  const std::vector<std::uint64_t> b{1, 1, 0, 1};
  const std::vector<std::int32_t> c{7, 7, 7, 7};
  const std::vector<named_value_column> columns{{"a", value_span<std::int8_t>{a.data(), a.size(), 1}},
                                                {"b", value_span<std::uint64_t>{b.data(), b.size(), 1}},
                                                {"c", value_span<std::int32_t>{c.data(), c.size(), 1}}};
  const auto counts = count_value_families(columns, std::vector<value_family>{{0, {1, 2}}, {2, {}}}, {.threads = 1});
  ASSERT_TRUE(counts.has_value());
  EXPECT_EQ(counts->variables[0], variable("a", {"0", "2"}));
  // (a | b, c): b=0 → a=2; b=1 → a=2, 0, 2.
  EXPECT_THAT(counts->tables[0].counts(), ElementsAre(0, 1, 1, 2));
  EXPECT_THAT(counts->tables[1].counts(), ElementsAre(4));
}

TEST(count_values_test, says_no_where_a_data_set_must_count) {
  const auto no = [](std::vector<std::int64_t> values, std::vector<value_family> of = {{0, {}}}) {
    const std::vector<named_value_column> columns{{"a", value_span<std::int64_t>{values.data(), values.size(), 1}}};
    return !count_value_families(columns, of).has_value();
  };
  EXPECT_TRUE(no({0, -1, 2}));
  EXPECT_TRUE(no({0, static_cast<std::int64_t>(value_count_limit)}));
  EXPECT_TRUE(no({}));
  EXPECT_FALSE(no({0, static_cast<std::int64_t>(value_count_limit) - 1}));
  // A table by value of 2^16 × 2^16 cells (a column its own parent, as a family may name it).
  EXPECT_TRUE(no({0, 40000}, {{0, {0}}}));
}

TEST(count_values_test, bad_columns_and_families_are_errors) {
  const std::vector<std::int64_t> three{0, 1, 0};
  const std::vector<std::int64_t> two{0, 1};
  const std::vector<named_value_column> columns{{"a", value_span<std::int64_t>{three.data(), three.size(), 1}},
                                                {"b", value_span<std::int64_t>{two.data(), two.size(), 1}}};
  EXPECT_THAT(
      [&] {
        static_cast<void>(count_value_families(columns, std::vector<value_family>{{0, {1}}}));
      },
      ThrowsMessage<data_error>(HasSubstr("column 'b' has 2 rows, 'a' 3")));
  const std::span<const named_value_column> first(columns.data(), 1);
  EXPECT_THAT(
      [&] {
        static_cast<void>(count_value_families(first, std::vector<value_family>{{0, {1}}}));
      },
      ThrowsMessage<model_error>(HasSubstr("a family names column 1 of 1")));
}

}  // namespace
}  // namespace pgm::count_values_tests
