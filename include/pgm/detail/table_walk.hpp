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
#include <span>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/inference/semiring.hpp"

namespace pgm::detail {

/// Calls visit(i, j) for every index i of a table over `cards` (last fastest), with j the index
/// the same joint state has in a table of `strides` (one per variable, 0 where it lacks one).
template <class Visit>
inline void walk_table(std::span<const std::size_t> cards, std::span<const std::size_t> strides, Visit&& visit) {
  PGM_ASSERT(cards.size() == strides.size(), "one stride per variable");
  if (cards.empty()) {
    visit(std::size_t{0}, std::size_t{0});
    return;
  }
  const std::size_t dims = cards.size();
  const std::size_t inner = cards[dims - 1];
  const std::size_t step = strides[dims - 1];
  std::size_t outer = 1;
  for (std::size_t d = 0; d + 1 < dims; ++d) outer *= cards[d];
  std::vector<std::size_t> digit(dims, 0);
  std::size_t i = 0;
  std::size_t j = 0;
  for (std::size_t o = 0; o < outer; ++o) {
    for (std::size_t k = 0; k < inner; ++k) visit(i + k, j + k * step);
    i += inner;
    for (std::size_t d = dims - 1; d-- > 0;) {
      if (++digit[d] < cards[d]) {
        j += strides[d];
        break;
      }
      digit[d] = 0;
      j -= strides[d] * (cards[d] - 1);
    }
  }
}

/// big[i] ⊗= small[j] over big's table.
template <class S, class V>
inline void multiply_into(std::span<V> big, std::span<const std::size_t> cards, std::span<const std::size_t> strides,
                          std::span<const V> small) {
  walk_table(cards, strides, [&](std::size_t i, std::size_t j) { big[i] = S::times(big[i], small[j]); });
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

}  // namespace pgm::detail
