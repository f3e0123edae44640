#pragma once
/// \file
/// `cpt<T>`: the conditional probability table P(X | Pa_X) of one node, as one contiguous
/// array. Values are stored parent-configuration major: the distribution of X given the
/// configuration u occupies values()[u*J, u*J + J), J = |Val(X)|; configurations are numbered
/// by `mixed_radix` over the parents in order (last parent fastest). Every column — the
/// distribution for one u — sums to one.

#include <cmath>
#include <concepts>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/variable.hpp"

namespace pgm {

template <std::floating_point T = double>
class cpt {
 public:
  using value_type = T;
  /// How far a column's sum may stray from one, for tables read from files that print a
  /// limited number of digits.
  static constexpr T default_tolerance = static_cast<T>(1e-6);

  /// The uniform table.
  cpt(variable child, std::vector<variable> parents)
      : child_(std::move(child)), parents_(std::move(parents)), radix_(radices(parents_)) {
    check_names();
    values_.assign(checked_table_cells(child_.name(), child_.cardinality(), radix_.size()),
                   T{1} / static_cast<T>(child_.cardinality()));
  }

  /// A table with the given values (configuration major). Throws model_error if the size is
  /// wrong, a value is not a probability, or a column does not sum to one within `tolerance`.
  cpt(variable child, std::vector<variable> parents, std::vector<T> values, T tolerance = default_tolerance)
      : child_(std::move(child)), parents_(std::move(parents)), radix_(radices(parents_)), values_(std::move(values)) {
    check_names();
    validate(tolerance);
  }

  [[nodiscard]] const variable& child() const noexcept { return child_; }
  [[nodiscard]] const std::vector<variable>& parents() const noexcept { return parents_; }
  [[nodiscard]] const mixed_radix& parent_radix() const noexcept { return radix_; }
  [[nodiscard]] std::size_t child_cardinality() const noexcept { return child_.cardinality(); }
  /// |Val(Pa_X)|, the number of columns.
  [[nodiscard]] std::size_t configurations() const noexcept { return radix_.size(); }
  /// J·|Val(Pa_X)|, the number of values.
  [[nodiscard]] std::size_t size() const noexcept { return values_.size(); }

  [[nodiscard]] T operator()(state_index x, config_index u) const {
    return values_[u.value() * child_cardinality() + x.value()];
  }

  /// P(child = child_state | parents = parent_states), by labels in parent order.
  [[nodiscard]] T probability(std::string_view child_state, std::span<const std::string> parent_states) const {
    return (*this)(child_.state(child_state), configuration(parent_states));
  }
  [[nodiscard]] T probability(std::string_view child_state, std::initializer_list<std::string> parent_states) const {
    return probability(child_state, std::span<const std::string>(parent_states.begin(), parent_states.size()));
  }

  /// The configuration index of parent state codes, in parent order.
  [[nodiscard]] config_index configuration(std::span<const std::size_t> parent_codes) const {
    if (parent_codes.size() != parents_.size()) throw_arity(parent_codes.size());
    for (std::size_t i = 0; i < parent_codes.size(); ++i) {
      if (parent_codes[i] >= parents_[i].cardinality()) {
        throw model_error("state code " + std::to_string(parent_codes[i]) + " of '" + parents_[i].name() +
                          "' is out of range");
      }
    }
    return config_index(radix_.encode(parent_codes));
  }
  /// The configuration index of parent state labels, in parent order.
  [[nodiscard]] config_index configuration(std::span<const std::string> parent_states) const {
    if (parent_states.size() != parents_.size()) throw_arity(parent_states.size());
    std::vector<std::size_t> codes(parent_states.size());
    for (std::size_t i = 0; i < codes.size(); ++i) {
      codes[i] = parents_[i].state(parent_states[i]).value();
    }
    return config_index(radix_.encode(codes));
  }
  /// The parent state codes of a configuration index.
  [[nodiscard]] std::vector<std::size_t> parent_codes(config_index u) const { return radix_.decode(u.value()); }

  /// The distribution of the child given configuration u.
  [[nodiscard]] std::span<const T> column(config_index u) const {
    return {values_.data() + u.value() * child_cardinality(), child_cardinality()};
  }
  [[nodiscard]] std::span<const T> values() const noexcept { return values_; }

  friend bool operator==(const cpt&, const cpt&) = default;

 private:
  static mixed_radix radices(const std::vector<variable>& parents) {
    std::vector<std::size_t> cards;
    cards.reserve(parents.size());
    for (const auto& parent : parents) cards.push_back(parent.cardinality());
    return mixed_radix(std::move(cards));
  }

  void check_names() const {
    for (std::size_t i = 0; i < parents_.size(); ++i) {
      if (parents_[i].name() == child_.name()) {
        throw model_error("'" + child_.name() + "' cannot be its own parent");
      }
      for (std::size_t j = 0; j < i; ++j) {
        if (parents_[i].name() == parents_[j].name()) {
          throw model_error("'" + parents_[i].name() + "' is a parent of '" + child_.name() + "' twice");
        }
      }
    }
  }

  void validate(T tolerance) const {
    const std::size_t j = child_cardinality();
    if (values_.size() != j * configurations()) {
      throw model_error("the table of '" + child_.name() + "' needs " + std::to_string(j * configurations()) +
                        " values (" + std::to_string(j) + " states × " + std::to_string(configurations()) +
                        " parent configurations), got " + std::to_string(values_.size()));
    }
    for (std::size_t u = 0; u < configurations(); ++u) {
      T sum = 0;
      for (std::size_t x = 0; x < j; ++x) {
        const T value = values_[u * j + x];
        if (!std::isfinite(value) || value < T{0} || value > T{1}) {
          throw model_error("the table of '" + child_.name() + "' has the value " +
                            detail::format_double(static_cast<double>(value)) + ", which is not a probability" +
                            where(u));
        }
        sum += value;
      }
      if (std::abs(sum - T{1}) > tolerance) {
        throw model_error("the distribution of '" + child_.name() + "'" + where(u) + " sums to " +
                          detail::format_double(static_cast<double>(sum)) + ", not 1");
      }
    }
  }

  std::string where(std::size_t u) const {
    if (parents_.empty()) return {};
    const auto codes = radix_.decode(u);
    std::string text = " given ";
    for (std::size_t i = 0; i < codes.size(); ++i) {
      text += (i ? ", " : "") + parents_[i].name() + "=" + parents_[i].states()[codes[i]];
    }
    return text;
  }

  [[noreturn]] void throw_arity(std::size_t given) const {
    throw model_error("'" + child_.name() + "' has " + std::to_string(parents_.size()) + " parents, got states for " +
                      std::to_string(given));
  }

  variable child_;
  std::vector<variable> parents_;
  mixed_radix radix_;
  std::vector<T> values_;
};

}  // namespace pgm
