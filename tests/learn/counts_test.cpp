#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "pgm/data/sufficient_statistics.hpp"

namespace pgm::counts_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// child c in {0,1}, parent p in {a,b,c}: rows (a,0) (a,1) (a,1) (b,0) (b,0) (b,0) (b,1).
dataset small() {
  dataset data;
  data.add(discrete_column(variable("p", {"a", "b", "c"}), std::vector<unsigned>{0, 0, 0, 1, 1, 1, 1}));
  data.add(discrete_column(variable("c", {"0", "1"}), std::vector<unsigned>{0, 1, 1, 0, 0, 0, 1}));
  return data;
}

TEST(count_table_test, hand_counted_family) {
  const std::vector<std::string> parents{"p"};
  const auto counts = count_family(small(), "c", parents);
  EXPECT_THAT(counts.counts(), ElementsAre(1, 2, 3, 1, 0, 0));
  EXPECT_EQ(counts(state_index(1), config_index(0)), 2u);
  EXPECT_EQ(counts.total(config_index(1)), 4u);
  EXPECT_EQ(counts.total(config_index(2)), 0u);
  EXPECT_EQ(counts.total(), 7u);
}

TEST(count_table_test, no_parents_and_row_ranges) {
  const auto data = small();
  const auto all = count_family(data, "c", {});
  EXPECT_THAT(all.counts(), ElementsAre(4, 3));
  auto head = count_family(data, "c", {}, {}, {0, 3});
  const auto tail = count_family(data, "c", {}, {}, {3, 100});
  EXPECT_THAT(head.counts(), ElementsAre(1, 2));
  head += tail;
  EXPECT_EQ(head, all);  // counts of disjoint ranges add up
  EXPECT_EQ(count_family(data, "c", {}, {}, {5, 2}).total(), 0u);
}

TEST(count_table_test, adding_other_families_is_an_error) {
  auto a = count_family(small(), "c", {});
  const std::vector<std::string> parents{"c"};
  const auto b = count_family(small(), "p", parents);
  EXPECT_THAT([&] { a += b; }, ThrowsMessage<model_error>(HasSubstr("the families differ")));
}

TEST(count_table_test, continuous_or_missing_columns_are_errors) {
  auto data = small();
  data.add(continuous_column("x", {1, 2, 3, 4, 5, 6, 7}));
  const std::vector<std::string> parents{"x"};
  EXPECT_THAT([&] { static_cast<void>(count_family(data, "c", parents)); },
              ThrowsMessage<data_error>(HasSubstr("'x' holds continuous values")));
  const std::vector<std::string> missing{"nope"};
  EXPECT_THAT([&] { static_cast<void>(count_family(data, "c", missing)); },
              ThrowsMessage<data_error>(HasSubstr("no column 'nope'")));
}

// Random data of mixed code widths, counted naively through a std::map.
struct random_family {
  dataset data;
  std::vector<std::string> parents;
  std::map<std::vector<std::uint32_t>, std::uint64_t> naive;  // key: parent codes then child
};

random_family make_random_family(std::size_t rows, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  const std::vector<std::size_t> cards{5, 300, 3, 7};  // the 300-state parent uses 16-bit codes
  random_family f;
  std::vector<std::vector<std::uint32_t>> columns(cards.size() + 1, std::vector<std::uint32_t>(rows));
  for (std::size_t r = 0; r < rows; ++r) {
    std::vector<std::uint32_t> key;
    for (std::size_t k = 0; k < cards.size(); ++k)
      key.push_back(columns[k][r] = static_cast<std::uint32_t>(engine() % cards[k]));
    key.push_back(columns.back()[r] = static_cast<std::uint32_t>(engine() % 2));
    ++f.naive[key];
  }
  for (std::size_t k = 0; k < cards.size(); ++k) {
    std::vector<std::string> labels;
    for (std::size_t s = 0; s < cards[k]; ++s) labels.push_back(std::to_string(s));
    f.parents.push_back("p" + std::to_string(k));
    f.data.add(discrete_column(variable(f.parents.back(), labels), columns[k]));
  }
  f.data.add(discrete_column(variable("child", {"0", "1"}), columns.back()));
  return f;
}

TEST(count_table_test, matches_naive_counting_for_every_thread_count) {
  const auto f = make_random_family(100003, 5);
  count_table reference(f.data.discrete("child").var(), {});
  for (unsigned threads : {1u, 2u, 3u, 7u}) {
    count_options options;
    options.threads = threads;
    options.min_rows_per_thread = 1;
    const auto counts = count_family(f.data, "child", f.parents, options);
    if (threads == 1) {
      for (const auto& [key, n] : f.naive) {
        const std::vector<std::size_t> parent_codes(key.begin(), key.end() - 1);
        const auto u = counts.parent_radix().encode(parent_codes);
        EXPECT_EQ(counts(state_index(key.back()), config_index(u)), n);
      }
      EXPECT_EQ(counts.total(), 100003u);
      reference = counts;
    } else {
      EXPECT_EQ(counts, reference) << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace pgm::counts_tests
