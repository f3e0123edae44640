// The table walks of message passing (pgm/inference/table_walk.hpp): the layered product and the
// folds onto each variable agree with one multiplication or one fold at a time, in probabilities
// and in logarithms, on random tables whichever of their ways the walks choose.

#include "pgm/inference/table_walk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <utility>
#include <vector>

#include "pgm/inference/semiring.hpp"

namespace pgm {
namespace table_walk_test {

// A table over some of a big table's variables, with its strides in the big table's order.
struct small_table {
  std::vector<std::size_t> strides;
  std::vector<double> values;
};

small_table random_small(std::mt19937_64& engine, const std::vector<std::size_t>& cards, double chance) {
  std::bernoulli_distribution in(chance);
  std::uniform_real_distribution<double> value(0.0, 2.0);
  small_table t;
  t.strides.assign(cards.size(), 0);
  std::size_t cells = 1;
  for (std::size_t d = cards.size(); d-- > 0;) {
    if (!in(engine)) continue;
    t.strides[d] = cells;
    cells *= cards[d];
  }
  for (std::size_t i = 0; i < cells; ++i) t.values.push_back(value(engine) < 0.2 ? 0.0 : value(engine));
  return t;
}

std::vector<std::size_t> random_cards(std::mt19937_64& engine, std::size_t dims, std::size_t least = 1) {
  std::vector<std::size_t> cards;
  for (std::size_t d = 0; d < dims; ++d) cards.push_back(least + engine() % (4 - least));
  return cards;
}

std::size_t cells_of(const std::vector<std::size_t>& cards) {
  std::size_t cells = 1;
  for (auto c : cards) cells *= c;
  return cells;
}

// The walk fuses neighbouring variables that step through both tables as one; every cell is
// still visited in order with the index its joint state has in the small table, whatever order
// the small table holds its variables in and with variables of one state among them.
TEST(table_walk_test, every_cell_is_visited_in_order_with_its_index_in_the_small_table) {
  std::mt19937_64 engine(5);
  for (int trial = 0; trial < 300; ++trial) {
    const auto cards = random_cards(engine, engine() % 7);
    std::vector<std::size_t> kept;  // the small table's variables, in its own order
    for (std::size_t d = 0; d < cards.size(); ++d) {
      if (engine() % 3 != 0) kept.push_back(d);
    }
    if (trial % 2 == 1) std::shuffle(kept.begin(), kept.end(), engine);
    std::vector<std::size_t> strides(cards.size(), 0);
    std::size_t small_cells = 1;
    for (std::size_t k = kept.size(); k-- > 0;) {
      strides[kept[k]] = small_cells;
      small_cells *= cards[kept[k]];
    }
    std::vector<std::pair<std::size_t, std::size_t>> visited;
    detail::walk_table(cards, strides, [&](std::size_t i, std::size_t j) { visited.emplace_back(i, j); });
    ASSERT_EQ(visited.size(), cells_of(cards)) << "trial " << trial;
    for (std::size_t i = 0; i < visited.size(); ++i) {
      std::size_t rest = i;
      std::size_t j = 0;
      for (std::size_t d = cards.size(); d-- > 0;) {
        j += (rest % cards[d]) * strides[d];
        rest /= cards[d];
      }
      ASSERT_EQ(visited[i], std::make_pair(i, j)) << "trial " << trial;
      ASSERT_LT(j, small_cells);
    }
  }
}

TEST(table_walk_test, the_product_of_many_tables_equals_multiplying_them_in_turn) {
  std::mt19937_64 engine(5);
  for (int trial = 0; trial < 300; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    // Small tables, multiplied in turn, and tables of 2^8 to 3^10 cells, past where the product
    // is built up or cut at the last variable's states.
    const auto cards = trial % 2 == 0 ? random_cards(engine, trial % 7) : random_cards(engine, 8 + trial % 3, 2);
    std::vector<small_table> smalls;
    // Bipartite-like trials: every table holds the last variable, so the cut at its states runs.
    const bool all_hold_last = trial % 3 == 0 && !cards.empty();
    for (std::size_t t = 0; t < static_cast<std::size_t>(trial % 9); ++t) {
      auto s = random_small(engine, cards, 0.4);
      if (all_hold_last && s.strides.back() == 0) {
        std::size_t cells = s.values.size();
        for (auto& stride : s.strides) stride *= cards.back();
        s.strides.back() = 1;
        std::vector<double> wider;
        for (std::size_t i = 0; i < cells; ++i) {
          for (std::size_t k = 0; k < cards.back(); ++k) wider.push_back(s.values[i] * static_cast<double>(k + 1));
        }
        s.values = wider;
      }
      smalls.push_back(std::move(s));
    }
    std::vector<double> start(cells_of(cards));
    for (auto& v : start) v = std::uniform_real_distribution<double>(0.5, 1.5)(engine);
    auto expected = start;
    for (const auto& s : smalls) {
      detail::multiply_into<sum_product<double>, double>(std::span<double>(expected), cards, s.strides, s.values);
    }
    std::vector<detail::strided_table<double>> tables;
    for (const auto& s : smalls) tables.push_back({s.strides, s.values});
    auto actual = start;
    detail::multiply_all_into<sum_product<double>, double>(std::span<double>(actual), cards, tables);
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) EXPECT_NEAR(actual[i], expected[i], 1e-12 * expected[i]);
  }
}

TEST(table_walk_test, folds_onto_each_variable_equal_one_fold_each) {
  std::mt19937_64 engine(11);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const auto cards = random_cards(engine, 1 + trial % 6);
    std::vector<double> table(cells_of(cards));
    for (auto& v : table) v = std::uniform_real_distribution<double>(0.0, 1.0)(engine);
    std::vector<std::size_t> positions;
    for (std::size_t k = 0; k < 1 + static_cast<std::size_t>(trial % 4); ++k)
      positions.push_back(engine() % cards.size());
    const auto folds = detail::fold_onto_each<sum_product<double>, double>(table, cards, positions);
    std::vector<double> logs;
    for (auto v : table) logs.push_back(std::log(v));
    const auto log_folds = detail::fold_onto_each<log_sum_product<double>, double>(logs, cards, positions);
    ASSERT_EQ(folds.size(), positions.size());
    for (std::size_t k = 0; k < positions.size(); ++k) {
      std::vector<std::size_t> strides(cards.size(), 0);
      strides[positions[k]] = 1;
      std::vector<double> expected(cards[positions[k]], 0.0);
      detail::fold_onto<sum_product<double>, double>(table, cards, strides, std::span<double>(expected));
      ASSERT_EQ(folds[k].size(), expected.size());
      for (std::size_t s = 0; s < expected.size(); ++s) {
        EXPECT_NEAR(folds[k][s], expected[s], 1e-12 * expected[s]);
        EXPECT_NEAR(log_folds[k][s], std::log(expected[s]), 1e-12);
      }
    }
  }
}

TEST(table_walk_test, shifted_exps_refuse_a_cell_that_would_lose_its_digits) {
  std::vector<double> plain;
  const std::vector<double> fine{-1.0, 0.0, -INFINITY, -700.0};
  const auto top = detail::shifted_exp<double>(fine, plain);
  ASSERT_TRUE(top.has_value());
  EXPECT_EQ(*top, 0.0);
  EXPECT_EQ(plain, (std::vector<double>{std::exp(-1.0), 1.0, 0.0, std::exp(-700.0)}));
  std::vector<double> folded{plain[0] + plain[1], 0.0};
  detail::unshift_log<double>(folded, 2.0);
  EXPECT_NEAR(folded[0], std::log(std::exp(-1.0) + 1.0) + 2.0, 1e-15);
  EXPECT_EQ(folded[1], -INFINITY);
  EXPECT_FALSE(detail::shifted_exp<double>(std::vector<double>{0.0, -800.0}, plain).has_value());
  EXPECT_FALSE(detail::shifted_exp<double>(std::vector<double>{-INFINITY, -INFINITY}, plain).has_value());
}

}  // namespace table_walk_test
}  // namespace pgm
