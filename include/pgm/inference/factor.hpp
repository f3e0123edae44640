#pragma once
/// \file
/// `factor`: a non-negative function over the joint states of a few discrete variables, the
/// currency of exact inference. Variables are network ids with their cardinalities; values are
/// numbered mixed-radix over the scope in order, last variable fastest, as `cpt` numbers its
/// configurations — so a table P(X | U1..Uk) is the factor over (U1, …, Uk, X) with the same
/// array, no reshuffling.

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/strong_index.hpp"

namespace pgm {

class factor {
 public:
  /// The constant factor 1 over no variables.
  factor() : values_{1.0} {}

  /// A factor over `scope` (distinct ids) with these cardinalities and values (product of the
  /// cardinalities of them, last variable fastest). Throws model_error on a size mismatch.
  factor(std::vector<variable_id> scope, std::vector<std::size_t> cardinalities, std::vector<double> values)
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

  /// The table of `child` given `parents` as a factor over (parents…, child).
  [[nodiscard]] static factor from_cpt(const cpt<double>& table, variable_id child,
                                       std::span<const variable_id> parents) {
    PGM_ASSERT(parents.size() == table.parents().size(), "one id per parent");
    std::vector<variable_id> scope(parents.begin(), parents.end());
    scope.push_back(child);
    std::vector<std::size_t> cards = table.parent_radix().radices();
    cards.push_back(table.child_cardinality());
    return factor(std::move(scope), std::move(cards), {table.values().begin(), table.values().end()});
  }

  [[nodiscard]] const std::vector<variable_id>& scope() const noexcept { return scope_; }
  [[nodiscard]] const std::vector<std::size_t>& cardinalities() const noexcept { return cardinalities_; }
  [[nodiscard]] std::span<const double> values() const noexcept { return values_; }
  [[nodiscard]] std::size_t size() const noexcept { return values_.size(); }

  /// Where `id` sits in the scope, or scope().size() if absent.
  [[nodiscard]] std::size_t position(variable_id id) const noexcept {
    return static_cast<std::size_t>(std::find(scope_.begin(), scope_.end(), id) - scope_.begin());
  }
  [[nodiscard]] bool contains(variable_id id) const noexcept { return position(id) < scope_.size(); }

  /// The value at these states, one per scope variable in scope order.
  [[nodiscard]] double at(std::span<const std::size_t> states) const {
    PGM_ASSERT(states.size() == scope_.size(), "one state per scope variable");
    std::size_t index = 0;
    for (std::size_t i = 0; i < states.size(); ++i) {
      PGM_ASSERT(states[i] < cardinalities_[i], "state out of range");
      index = index * cardinalities_[i] + states[i];
    }
    return values_[index];
  }

  [[nodiscard]] double sum() const noexcept {
    double total = 0.0;
    for (double v : values_) total += v;
    return total;
  }

  /// Divides by the sum so that the values add up to one; returns the sum it divided by.
  /// A factor summing to zero is left as it is (the caller reports why).
  double normalize() noexcept {
    const double total = sum();
    if (total > 0.0) {
      for (double& v : values_) v /= total;
    }
    return total;
  }

  /// The product; its scope is this factor's followed by the other's new variables.
  [[nodiscard]] friend factor operator*(const factor& a, const factor& b) {
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
    std::vector<double> values(size);
    std::vector<std::size_t> digit(scope.size(), 0);
    std::size_t ia = 0;
    std::size_t ib = 0;
    for (std::size_t r = 0; r < size; ++r) {
      values[r] = a.values_[ia] * b.values_[ib];
      for (std::size_t k = scope.size(); k-- > 0;) {
        if (++digit[k] < cards[k]) {
          ia += stride_a[k];
          ib += stride_b[k];
          break;
        }
        digit[k] = 0;
        ia -= stride_a[k] * (cards[k] - 1);
        ib -= stride_b[k] * (cards[k] - 1);
      }
    }
    factor result;
    result.scope_ = std::move(scope);
    result.cardinalities_ = std::move(cards);
    result.values_ = std::move(values);
    return result;
  }

  /// The factor with `id` summed out (unchanged if `id` is not in the scope).
  [[nodiscard]] factor sum_out(variable_id id) const {
    const auto p = position(id);
    if (p == scope_.size()) return *this;
    const auto [outer, card, inner] = split_at(p);
    std::vector<double> values(outer * inner, 0.0);
    for (std::size_t o = 0; o < outer; ++o) {
      for (std::size_t s = 0; s < card; ++s) {
        const double* from = values_.data() + (o * card + s) * inner;
        double* to = values.data() + o * inner;
        for (std::size_t i = 0; i < inner; ++i) to[i] += from[i];
      }
    }
    return without(p, std::move(values));
  }

  /// The factor with every variable of `ids` summed out.
  [[nodiscard]] factor marginalize(std::span<const variable_id> ids) const {
    factor result = *this;
    for (auto id : ids) result = result.sum_out(id);
    return result;
  }

  /// The slice where `id` is in `state`, over the remaining variables (unchanged if `id` is
  /// not in the scope).
  [[nodiscard]] factor reduce(variable_id id, std::size_t state) const {
    const auto p = position(id);
    if (p == scope_.size()) return *this;
    if (state >= cardinalities_[p]) throw model_error("a reduced state is out of range");
    const auto [outer, card, inner] = split_at(p);
    std::vector<double> values(outer * inner);
    for (std::size_t o = 0; o < outer; ++o) {
      std::copy_n(values_.data() + (o * card + state) * inner, inner, values.data() + o * inner);
    }
    return without(p, std::move(values));
  }

  /// The same function with the scope in `order` (a permutation of scope()).
  [[nodiscard]] factor permuted(std::span<const variable_id> order) const {
    if (order.size() != scope_.size()) throw model_error("a permutation must list every scope variable");
    std::vector<std::size_t> cards;
    for (auto id : order) {
      const auto p = position(id);
      if (p == scope_.size()) throw model_error("a permutation lists a variable outside the scope");
      cards.push_back(cardinalities_[p]);
    }
    // Multiplying the one-valued factor over the new order by this one reorders without new code.
    const factor ones(std::vector<variable_id>(order.begin(), order.end()), std::move(cards),
                      std::vector<double>(values_.size(), 1.0));
    return ones * *this;
  }

  friend bool operator==(const factor&, const factor&) = default;

 private:
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

  factor without(std::size_t p, std::vector<double> values) const {
    factor result;
    result.scope_ = scope_;
    result.cardinalities_ = cardinalities_;
    result.scope_.erase(result.scope_.begin() + static_cast<std::ptrdiff_t>(p));
    result.cardinalities_.erase(result.cardinalities_.begin() + static_cast<std::ptrdiff_t>(p));
    result.values_ = std::move(values);
    return result;
  }

  /// This factor's stride along each variable of `scope` (0 for variables it lacks).
  std::vector<std::size_t> strides_in(const std::vector<variable_id>& scope) const {
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

  std::vector<variable_id> scope_;
  std::vector<std::size_t> cardinalities_;
  std::vector<double> values_;
};

}  // namespace pgm
