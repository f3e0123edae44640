#pragma once
// Internal: not part of pgm's API, may change without notice.
//
// The two loops of message passing, generic over a semiring: multiply a small table into a big
// one whose variables include its own (`multiply_into`), and fold a big table onto a small one
// (`fold_onto`). Both walk the big table in order with an odometer that carries the small
// table's index along, the last variable in a tight inner loop; no index is ever decoded.

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/inference/semiring.hpp"

namespace pgm::detail {

/// Calls visit(i, j) for every index i of a table over `cards` (last fastest), with j the index
/// the same joint state has in a table of `strides` (one per variable, 0 where it lacks one).
///
/// Neighbouring variables that step through both tables as one are walked as one (a run of
/// variables the small table lacks, or holds in the same order at the end), so the inner loop runs
/// over as many cells as it can, not over the last variable's few states; and it is written once
/// for each kind of step (0: a fold's sum or a broadcast, 1: contiguous in both) so that the
/// compiler can make each tight.
template <class Visit>
inline void walk_table(std::span<const std::size_t> cards, std::span<const std::size_t> strides, Visit&& visit) {
  PGM_ASSERT(cards.size() == strides.size(), "one stride per variable");
  // (cardinality, stride) of the fused variables, innermost first.
  std::vector<std::pair<std::size_t, std::size_t>> fused;
  fused.reserve(cards.size());
  for (std::size_t d = cards.size(); d-- > 0;) {
    if (cards[d] == 1) continue;
    if (!fused.empty() && strides[d] == fused.back().first * fused.back().second) {
      fused.back().first *= cards[d];
    } else {
      fused.emplace_back(cards[d], strides[d]);
    }
  }
  if (fused.empty()) {
    visit(std::size_t{0}, std::size_t{0});
    return;
  }
  // Plain variables, not a structured binding: clang 14 cannot capture one in the lambda.
  const std::size_t inner = fused.front().first;
  const std::size_t step = fused.front().second;
  const auto run = [&](std::size_t i, std::size_t j) {
    if (step == 0) {
      for (std::size_t k = 0; k < inner; ++k) visit(i + k, j);
    } else if (step == 1) {
      for (std::size_t k = 0; k < inner; ++k) visit(i + k, j + k);
    } else {
      for (std::size_t k = 0; k < inner; ++k) visit(i + k, j + k * step);
    }
  };
  const std::size_t dims = fused.size();
  std::size_t outer = 1;
  for (std::size_t d = 1; d < dims; ++d) outer *= fused[d].first;
  std::vector<std::size_t> digit(dims, 0);
  std::size_t i = 0;
  std::size_t j = 0;
  for (std::size_t o = 0; o < outer; ++o) {
    run(i, j);
    i += inner;
    for (std::size_t d = 1; d < dims; ++d) {
      const auto [card, stride] = fused[d];
      if (++digit[d] < card) {
        j += stride;
        break;
      }
      digit[d] = 0;
      j -= stride * (card - 1);
    }
  }
}

/// big[i] ⊗= small[j] over big's table.
template <class S, class V>
inline void multiply_into(std::span<V> big, std::span<const std::size_t> cards, std::span<const std::size_t> strides,
                          std::span<const V> small) {
  walk_table(cards, strides, [&](std::size_t i, std::size_t j) { big[i] = S::times(big[i], small[j]); });
}

/// A table to multiply into a bigger one: its values and its strides in the bigger table's order.
template <class V>
struct strided_table {
  std::span<const std::size_t> strides;
  std::span<const V> values;
};

/// How deep a table reaches into big's variables: one past its last variable there.
template <class V>
[[nodiscard]] inline std::size_t depth_of(const strided_table<V>& t) {
  std::size_t depth = t.strides.size();
  while (depth > 0 && t.strides[depth - 1] == 0) --depth;
  return depth;
}

/// The cells layered_product writes for tables reaching these depths, over `cards`.
[[nodiscard]] inline double layered_cost(std::span<const std::size_t> cards, std::vector<std::size_t> depths) {
  std::sort(depths.begin(), depths.end());
  std::vector<double> cells(cards.size() + 1, 1.0);
  for (std::size_t d = 0; d < cards.size(); ++d) cells[d + 1] = cells[d] * static_cast<double>(cards[d]);
  double cost = cells.back();
  for (std::size_t k = 0; k < depths.size(); ++k) {
    cost += cells[depths[k]];
    if (k == 0 || depths[k] != depths[k - 1]) cost += cells[depths[k]];
  }
  return cost;
}

/// The product of `tables` over the variables of `cards`, built up them in order: a table whose
/// last variable is d is multiplied into the product over the first d variables, which is then
/// repeated across the next ones. With pairwise factors in a clique of 21 variables that is a few
/// passes over the table, not one per factor.
template <class S, class V>
[[nodiscard]] inline std::vector<V> layered_product(std::span<const std::size_t> cards,
                                                    std::span<const strided_table<V>> tables) {
  std::vector<std::pair<std::size_t, std::size_t>> by_depth;  // (depth, table)
  by_depth.reserve(tables.size());
  for (std::size_t t = 0; t < tables.size(); ++t) by_depth.emplace_back(depth_of(tables[t]), t);
  std::stable_sort(by_depth.begin(), by_depth.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<V> product{S::one()};
  std::vector<V> wider;
  std::size_t depth = 0;
  const auto widen_to = [&](std::size_t target) {
    std::size_t block = 1;
    for (std::size_t d = depth; d < target; ++d) block *= cards[d];
    depth = target;
    if (block == 1) return;
    wider.resize(product.size() * block);
    for (std::size_t i = 0; i < product.size(); ++i) std::fill_n(wider.begin() + i * block, block, product[i]);
    product.swap(wider);
  };
  for (const auto& [level, t] : by_depth) {
    widen_to(level);
    multiply_into<S, V>(std::span<V>(product), cards.first(depth), tables[t].strides.first(depth), tables[t].values);
  }
  widen_to(cards.size());
  return product;
}

/// big[i] ⊗= the product of every table of `tables` at i, the cheapest of three ways in cells
/// written: each table into big in turn; the tables without big's last variable built up as
/// layered_product does, then the others into big; or those too, cut at each state of the last
/// variable into tables without it and built up the same way (bipartite pairwise factors, every
/// one ending at the last variable, then cost two passes rather than one each).
template <class S, class V>
inline void multiply_all_into(std::span<V> big, std::span<const std::size_t> cards,
                              std::span<const strided_table<V>> tables) {
  PGM_ASSERT(!cards.empty() || big.size() == 1, "the cardinalities describe big's table");
  if (cards.empty()) {
    for (const auto& t : tables) big[0] = S::times(big[0], t.values[0]);
    return;
  }
  // Nothing to share, or too little to pay for the bookkeeping (a small network's cliques).
  if (tables.size() < 2 || big.size() < 4096) {
    for (const auto& t : tables) multiply_into<S, V>(big, cards, t.strides, t.values);
    return;
  }
  const std::size_t last = cards.size() - 1;
  const auto prefix = cards.first(last);
  std::vector<strided_table<V>> before;
  std::vector<strided_table<V>> with_last;
  std::vector<std::size_t> before_depths;
  std::vector<std::size_t> cut_depths;
  for (const auto& t : tables) {
    if (t.strides[last] == 0) {
      before.push_back({t.strides.first(last), t.values});
      before_depths.push_back(depth_of(before.back()));
    } else {
      with_last.push_back(t);
      cut_depths.push_back(depth_of(strided_table<V>{t.strides.first(last), t.values}));
    }
  }
  const auto cells = static_cast<double>(big.size());
  const std::size_t states = cards[last];
  const double each_in_turn = cells * static_cast<double>(tables.size());
  const double head_cost = layered_cost(prefix, before_depths) + cells;
  const double layered = head_cost + cells * static_cast<double>(with_last.size());
  const double sliced =
      with_last.size() < 2 ? layered : head_cost + static_cast<double>(states) * layered_cost(prefix, cut_depths);
  if (each_in_turn <= std::min(layered, sliced)) {
    for (const auto& t : tables) multiply_into<S, V>(big, cards, t.strides, t.values);
    return;
  }
  const auto head = layered_product<S, V>(prefix, before);
  PGM_ASSERT(head.size() * states == big.size(), "the cardinalities describe big's table");
  if (layered <= sliced) {
    for (std::size_t i = 0; i < head.size(); ++i) {
      if (head[i] == S::one()) continue;
      for (std::size_t k = i * states; k < (i + 1) * states; ++k) big[k] = S::times(big[k], head[i]);
    }
    for (const auto& t : with_last) multiply_into<S, V>(big, cards, t.strides, t.values);
    return;
  }
  std::vector<strided_table<V>> cut(with_last.size());
  for (std::size_t s = 0; s < states; ++s) {
    for (std::size_t t = 0; t < with_last.size(); ++t) {
      cut[t] = {with_last[t].strides.first(last), with_last[t].values.subspan(s * with_last[t].strides[last])};
    }
    const auto slice = layered_product<S, V>(prefix, cut);
    for (std::size_t i = 0; i < head.size(); ++i) {
      big[i * states + s] = S::times(big[i * states + s], S::times(head[i], slice[i]));
    }
  }
}

/// small[j] ⊕= big[i] over big's table; `small` starts as it is given (S::zero() to marginalize).
/// In logarithms, log-sum-exp in two passes: each target's largest value first, then one exp per
/// value shifted by it, and one log per target (not an exp and a log1p per value).
template <class S, class V>
inline void fold_onto(std::span<const V> big, std::span<const std::size_t> cards, std::span<const std::size_t> strides,
                      std::span<V> small) {
  if constexpr (std::same_as<S, log_sum_product<V>>) {
    std::vector<V> top(small.begin(), small.end());
    walk_table(cards, strides, [&](std::size_t i, std::size_t j) { top[j] = std::max(top[j], big[i]); });
    std::vector<V> sum(small.size(), V{0});
    for (std::size_t j = 0; j < small.size(); ++j) {
      if (small[j] != S::zero()) sum[j] = std::exp(small[j] - top[j]);
    }
    walk_table(cards, strides, [&](std::size_t i, std::size_t j) {
      if (big[i] != S::zero()) sum[j] += std::exp(big[i] - top[j]);
    });
    for (std::size_t j = 0; j < small.size(); ++j)
      small[j] = top[j] == S::zero() ? S::zero() : top[j] + std::log(sum[j]);
  } else {
    walk_table(cards, strides, [&](std::size_t i, std::size_t j) { small[j] = S::plus(small[j], big[i]); });
  }
}

/// The fold of `table` onto each variable at `positions` (⊕ over every other variable), the
/// table summed down its variables from the last as the positions are met: about two passes over
/// the table for any number of variables, not one each.
template <class S, class V>
[[nodiscard]] inline std::vector<std::vector<V>> fold_onto_each(std::span<const V> table,
                                                                std::span<const std::size_t> cards,
                                                                std::span<const std::size_t> positions) {
  std::vector<std::vector<V>> folds(positions.size());
  std::vector<std::size_t> strides;
  if (positions.size() == 1) {  // one pass, nothing summed down first
    strides.assign(cards.size(), 0);
    strides[positions[0]] = 1;
    folds[0].assign(cards[positions[0]], S::zero());
    fold_onto<S, V>(table, cards, strides, std::span<V>(folds[0]));
    return folds;
  }
  std::vector<std::size_t> order(positions.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return positions[a] > positions[b]; });
  std::vector<V> reduced;
  std::vector<V> next;
  std::span<const V> current = table;
  std::size_t depth = cards.size();
  for (auto i : order) {
    const auto p = positions[i];
    PGM_ASSERT(p < cards.size(), "a position in the table");
    if (depth > p + 1) {
      // Sum out the variables past p: current becomes a table over the first p + 1.
      strides.assign(depth, 0);
      std::size_t cells = 1;
      for (std::size_t d = p + 1; d-- > 0;) {
        strides[d] = cells;
        cells *= cards[d];
      }
      next.assign(cells, S::zero());
      fold_onto<S, V>(current, cards.first(depth), strides, std::span<V>(next));
      reduced.swap(next);
      current = reduced;
      depth = p + 1;
    }
    strides.assign(depth, 0);
    strides[depth - 1] = 1;
    folds[i].assign(cards[p], S::zero());
    fold_onto<S, V>(current, cards.first(depth), strides, std::span<V>(folds[i]));
  }
  return folds;
}

/// For a table of logarithms: `plain` = exp(table − top), with top its largest value, so that
/// several folds of it cost one exp per cell and plain sums, not one exp per cell each. Returns
/// top, or nothing when a cell above −∞ would fall below the normal range there (its fold would
/// lose digits) or every cell is −∞.
template <class V>
[[nodiscard]] inline std::optional<V> shifted_exp(std::span<const V> logs, std::vector<V>& plain) {
  constexpr V lowest = -std::numeric_limits<V>::infinity();
  V top = lowest;
  for (const V v : logs) top = std::max(top, v);
  if (top == lowest) return std::nullopt;
  const V floor = std::log(std::numeric_limits<V>::min());
  plain.resize(logs.size());
  for (std::size_t i = 0; i < logs.size(); ++i) {
    const V shifted = logs[i] - top;
    if (shifted < floor && logs[i] != lowest) return std::nullopt;
    plain[i] = std::exp(shifted);
  }
  return top;
}

/// The logarithm of a plain fold of shifted_exp's table, back in the table's terms.
template <class V>
inline void unshift_log(std::span<V> folded, V top) {
  for (auto& v : folded) v = v == V{0} ? -std::numeric_limits<V>::infinity() : std::log(v) + top;
}

}  // namespace pgm::detail
