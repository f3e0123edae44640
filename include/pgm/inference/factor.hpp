#pragma once
/// \file
/// `basic_factor<T>`: a function over the joint states of a few discrete variables, the
/// currency of exact inference. Variables are network ids with their cardinalities; values are
/// numbered mixed-radix over the scope in order, last variable fastest, as `cpt` numbers its
/// configurations — so a table P(X | U1..Uk) is the factor over (U1, …, Uk, X) with the same
/// array, no reshuffling.
///
/// The operations are generic over a `Semiring` (semiring.hpp): `combine<S>` is its ⊗ entry by
/// entry, `eliminate<S>` folds a variable away with its ⊕, so one elimination serves sums,
/// maxima and logarithms. `factor` (double) keeps the sum-product shorthands `*` and `sum_out`.

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/inference/semiring.hpp"

namespace pgm {

namespace detail {

/// A sparse table made dense for a factor, which holds every cell; throws table_too_large,
/// pointing to the sampling engines (which read it sparse), when it would exceed the limit.
template <std::floating_point U>
[[nodiscard]] cpt<U> dense_for_factor(const cpt<U>& table) {
  if (table.size() > max_table_cells) {
    throw table_too_large("the table of '" + table.child().name() +
                          "' is stored sparse, and as a factor it would have " + std::to_string(table.size()) +
                          " cells, more than pgm's limit of " + std::to_string(max_table_cells) +
                          " (docs/limits.md): exact inference cannot hold it; the sampling engines (lw, gibbs) can");
  }
  return table.dense();
}

}  // namespace detail

template <std::floating_point T>
class basic_factor;

template <Semiring S>
using factor_of = basic_factor<typename S::value_type>;

template <Semiring S>
[[nodiscard]] factor_of<S> combine(const factor_of<S>& a, const factor_of<S>& b);

template <std::floating_point T>
class basic_factor {
 public:
  using value_type = T;

  /// The constant factor 1 over no variables (the sum-product identity; `unit<S>()` for others).
  basic_factor() : values_{T{1}} {}

  /// A factor over `scope` (distinct ids) with these cardinalities and values (product of the
  /// cardinalities of them, last variable fastest). Throws model_error on a size mismatch.
  basic_factor(std::vector<variable_id> scope, std::vector<std::size_t> cardinalities, std::vector<T> values)
      : scope_(std::move(scope)), cardinalities_(std::move(cardinalities)), values_(std::move(values)) {
    if (scope_.size() != cardinalities_.size()) throw model_error("a factor needs one cardinality per variable");
    std::size_t size = 1;
    for (std::size_t i = 0; i < scope_.size(); ++i) {
      if (cardinalities_[i] == 0) throw model_error("a factor variable has no states");
      size *= cardinalities_[i];
      for (std::size_t j = 0; j < i; ++j) {
        if (scope_[i] == scope_[j]) throw model_error("a factor lists a variable twice");
      }
    }
    if (values_.size() != size) {
      throw model_error("a factor over " + std::to_string(scope_.size()) + " variables needs " + std::to_string(size) +
                        " values, got " + std::to_string(values_.size()));
    }
  }

  /// The constant `value` over no variables, e.g. `S::one()`.
  [[nodiscard]] static basic_factor constant(T value) {
    basic_factor result;
    result.values_[0] = value;
    return result;
  }

  /// The table of `child` given `parents` as a factor over (parents…, child), its probabilities
  /// converted by `convert` (a semiring's `from_probability`, by default the value itself).
  template <std::floating_point U, class Convert = T (*)(double)>
  [[nodiscard]] static basic_factor from_cpt(
      const cpt<U>& table, variable_id child, std::span<const variable_id> parents,
      Convert convert = [](double p) { return static_cast<T>(p); }) {
    PGM_ASSERT(parents.size() == table.parents().size(), "one id per parent");
    if (table.is_sparse()) return from_cpt(detail::dense_for_factor(table), child, parents, convert);
    std::vector<variable_id> scope(parents.begin(), parents.end());
    scope.push_back(child);
    std::vector<std::size_t> cards = table.parent_radix().radices();
    cards.push_back(table.child_cardinality());
    std::vector<T> values;
    values.reserve(table.size());
    for (const U p : table.values()) values.push_back(convert(static_cast<double>(p)));
    return basic_factor(std::move(scope), std::move(cards), std::move(values));
  }

  [[nodiscard]] const std::vector<variable_id>& scope() const noexcept { return scope_; }
  [[nodiscard]] const std::vector<std::size_t>& cardinalities() const noexcept { return cardinalities_; }
  [[nodiscard]] std::span<const T> values() const noexcept { return values_; }
  [[nodiscard]] std::span<T> mutable_values() noexcept { return values_; }
  [[nodiscard]] std::size_t size() const noexcept { return values_.size(); }

  /// Where `id` sits in the scope, or scope().size() if absent.
  [[nodiscard]] std::size_t position(variable_id id) const noexcept {
    return static_cast<std::size_t>(std::find(scope_.begin(), scope_.end(), id) - scope_.begin());
  }
  [[nodiscard]] bool contains(variable_id id) const noexcept { return position(id) < scope_.size(); }

  /// The value at these states, one per scope variable in scope order.
  [[nodiscard]] T at(std::span<const std::size_t> states) const {
    PGM_ASSERT(states.size() == scope_.size(), "one state per scope variable");
    std::size_t index = 0;
    for (std::size_t i = 0; i < states.size(); ++i) {
      PGM_ASSERT(states[i] < cardinalities_[i], "state out of range");
      index = index * cardinalities_[i] + states[i];
    }
    return values_[index];
  }

  /// The sum of the values (sum-product's total; `total_of<S>` for others).
  [[nodiscard]] T sum() const noexcept {
    T result = 0;
    for (T v : values_) result += v;
    return result;
  }

  /// Divides by the sum so that the values add up to one; returns the sum it divided by.
  /// A factor summing to zero is left as it is (the caller reports why).
  T normalize() noexcept {
    const T total = sum();
    if (total > T{0}) {
      for (T& v : values_) v /= total;
    }
    return total;
  }

  /// Sum-product shorthands: the product, and a variable summed out.
  [[nodiscard]] friend basic_factor operator*(const basic_factor& a, const basic_factor& b) {
    return combine<sum_product<T>>(a, b);
  }
  [[nodiscard]] basic_factor sum_out(variable_id id) const;

  /// The factor with every variable of `ids` summed out.
  [[nodiscard]] basic_factor marginalize(std::span<const variable_id> ids) const {
    basic_factor result = *this;
    for (auto id : ids) result = result.sum_out(id);
    return result;
  }

  /// The slice where `id` is in `state`, over the remaining variables (unchanged if `id` is
  /// not in the scope).
  [[nodiscard]] basic_factor reduce(variable_id id, std::size_t state) const {
    const auto p = position(id);
    if (p == scope_.size()) return *this;
    if (state >= cardinalities_[p]) throw model_error("a reduced state is out of range");
    const auto [outer, card, inner] = split_at(p);
    std::vector<T> values(outer * inner);
    for (std::size_t o = 0; o < outer; ++o) {
      std::copy_n(values_.data() + (o * card + state) * inner, inner, values.data() + o * inner);
    }
    return without(p, std::move(values));
  }

  /// The same function with the scope in `order` (a permutation of scope()).
  [[nodiscard]] basic_factor permuted(std::span<const variable_id> order) const {
    if (order.size() != scope_.size()) throw model_error("a permutation must list every scope variable");
    std::vector<std::size_t> cards;
    for (auto id : order) {
      const auto p = position(id);
      if (p == scope_.size()) throw model_error("a permutation lists a variable outside the scope");
      cards.push_back(cardinalities_[p]);
    }
    basic_factor result;
    result.scope_.assign(order.begin(), order.end());
    result.cardinalities_ = std::move(cards);
    result.values_.resize(values_.size());
    const auto from = strides_in(result.scope_);
    std::size_t i = 0;
    for_each_index(result.cardinalities_, from, [&](std::size_t source) { result.values_[i++] = values_[source]; });
    return result;
  }

  /// This factor's stride along each variable of `scope` (0 for variables it lacks): the step
  /// of its index when that variable's state goes up by one.
  [[nodiscard]] std::vector<std::size_t> strides_in(std::span<const variable_id> scope) const {
    std::vector<std::size_t> own(scope_.size());
    std::size_t stride = 1;
    for (std::size_t i = scope_.size(); i-- > 0;) {
      own[i] = stride;
      stride *= cardinalities_[i];
    }
    std::vector<std::size_t> result(scope.size(), 0);
    for (std::size_t k = 0; k < scope.size(); ++k) {
      const auto p = position(scope[k]);
      if (p < scope_.size()) result[k] = own[p];
    }
    return result;
  }

  /// Calls `visit(index)` for every joint state of `cards` in order (last fastest), with the
  /// index that state has in a factor of these `strides` (one per dimension): an odometer that
  /// never decodes an index.
  template <class Visit>
  static void for_each_index(std::span<const std::size_t> cards, std::span<const std::size_t> strides, Visit&& visit) {
    std::size_t size = 1;
    for (auto c : cards) size *= c;
    std::vector<std::size_t> digit(cards.size(), 0);
    std::size_t index = 0;
    for (std::size_t r = 0; r < size; ++r) {
      visit(index);
      for (std::size_t k = cards.size(); k-- > 0;) {
        if (++digit[k] < cards[k]) {
          index += strides[k];
          break;
        }
        digit[k] = 0;
        index -= strides[k] * (cards[k] - 1);
      }
    }
  }

  friend bool operator==(const basic_factor&, const basic_factor&) = default;

 private:
  template <Semiring S>
  friend factor_of<S> combine(const factor_of<S>& a, const factor_of<S>& b);
  template <Semiring S>
  friend factor_of<S> eliminate(const factor_of<S>& f, variable_id id);

  struct split {
    std::size_t outer, card, inner;
  };
  split split_at(std::size_t p) const {
    std::size_t outer = 1;
    std::size_t inner = 1;
    for (std::size_t i = 0; i < p; ++i) outer *= cardinalities_[i];
    for (std::size_t i = p + 1; i < scope_.size(); ++i) inner *= cardinalities_[i];
    return {outer, cardinalities_[p], inner};
  }

  basic_factor without(std::size_t p, std::vector<T> values) const {
    basic_factor result;
    result.scope_ = scope_;
    result.cardinalities_ = cardinalities_;
    result.scope_.erase(result.scope_.begin() + static_cast<std::ptrdiff_t>(p));
    result.cardinalities_.erase(result.cardinalities_.begin() + static_cast<std::ptrdiff_t>(p));
    result.values_ = std::move(values);
    return result;
  }

  std::vector<variable_id> scope_;
  std::vector<std::size_t> cardinalities_;
  std::vector<T> values_;
};

/// Probabilities as doubles, the factor most code uses.
using factor = basic_factor<double>;

/// The identity of S's ⊗ over no variables.
template <Semiring S>
[[nodiscard]] factor_of<S> unit() {
  return factor_of<S>::constant(S::one());
}

/// a ⊗ b entry by entry; the scope is a's followed by b's new variables.
template <Semiring S>
[[nodiscard]] factor_of<S> combine(const factor_of<S>& a, const factor_of<S>& b) {
  using T = typename S::value_type;
  std::vector<variable_id> scope = a.scope_;
  std::vector<std::size_t> cards = a.cardinalities_;
  for (std::size_t i = 0; i < b.scope_.size(); ++i) {
    if (!a.contains(b.scope_[i])) {
      scope.push_back(b.scope_[i]);
      cards.push_back(b.cardinalities_[i]);
    }
  }
  // Strides of a and b along each result variable (0 where a factor lacks it), so that one
  // odometer over the result walks both operands without decoding indices.
  const auto stride_a = a.strides_in(scope);
  const auto stride_b = b.strides_in(scope);
  std::size_t size = 1;
  for (auto c : cards) size *= c;
  std::vector<T> values(size);
  if (scope.empty()) {
    values[0] = S::times(a.values_[0], b.values_[0]);
  } else {
    // The last variable runs in a tight inner loop; the others advance by odometer.
    const std::size_t dims = scope.size();
    const std::size_t inner = cards[dims - 1];
    const std::size_t step_a = stride_a[dims - 1];
    const std::size_t step_b = stride_b[dims - 1];
    std::vector<std::size_t> digit(dims, 0);
    std::size_t ia = 0;
    std::size_t ib = 0;
    for (std::size_t r = 0; r < size; r += inner) {
      for (std::size_t k = 0; k < inner; ++k)
        values[r + k] = S::times(a.values_[ia + k * step_a], b.values_[ib + k * step_b]);
      for (std::size_t d = dims - 1; d-- > 0;) {
        if (++digit[d] < cards[d]) {
          ia += stride_a[d];
          ib += stride_b[d];
          break;
        }
        digit[d] = 0;
        ia -= stride_a[d] * (cards[d] - 1);
        ib -= stride_b[d] * (cards[d] - 1);
      }
    }
  }
  factor_of<S> result;
  result.scope_ = std::move(scope);
  result.cardinalities_ = std::move(cards);
  result.values_ = std::move(values);
  return result;
}

/// `id` folded away with S's ⊕ (unchanged if `id` is not in the scope).
template <Semiring S>
[[nodiscard]] factor_of<S> eliminate(const factor_of<S>& f, variable_id id) {
  using T = typename S::value_type;
  const auto p = f.position(id);
  if (p == f.scope_.size()) return f;
  const auto [outer, card, inner] = f.split_at(p);
  std::vector<T> values(outer * inner, S::zero());
  for (std::size_t o = 0; o < outer; ++o) {
    for (std::size_t s = 0; s < card; ++s) {
      const T* from = f.values_.data() + (o * card + s) * inner;
      T* to = values.data() + o * inner;
      for (std::size_t i = 0; i < inner; ++i) to[i] = S::plus(to[i], from[i]);
    }
  }
  return f.without(p, std::move(values));
}

/// ⊕ over every value: P(evidence) for sum-product, the maximum for max-product.
template <Semiring S>
[[nodiscard]] typename S::value_type total_of(const factor_of<S>& f) {
  auto result = S::zero();
  for (const auto v : f.values()) result = S::plus(result, v);
  return result;
}

template <std::floating_point T>
basic_factor<T> basic_factor<T>::sum_out(variable_id id) const {
  return eliminate<sum_product<T>>(*this, id);
}

}  // namespace pgm
