#pragma once
/// \file
/// `cpt<T>`: the conditional probability table P(X | Pa_X) of one node, as one contiguous
/// array. Values are stored parent-configuration major: the distribution of X given the
/// configuration u occupies values()[u*J, u*J + J), J = |Val(X)|; configurations are numbered
/// by `mixed_radix` over the parents in order (last parent fastest). Every column — the
/// distribution for one u — sums to one.
///
/// A table fitted from fewer rows than it has parent configurations can be stored sparse
/// (`sparse_columns`): the columns of the configurations the data held, and one column for
/// all the others (the estimator's answer where there are no data). It answers every
/// configuration the same way; `values()` needs a dense table and `dense()` makes one.

#include <algorithm>
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

/// The columns of a sparse table: the parent configurations stored (ascending), their columns
/// one after another, and the column of every configuration not stored.
template <std::floating_point T = double>
struct sparse_columns {
  std::vector<std::size_t> configurations;
  std::vector<T> values;
  std::vector<T> rest;
  friend bool operator==(const sparse_columns&, const sparse_columns&) = default;
};

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

  /// A sparse table: `columns.configurations` ascending and in range, a valid column for each
  /// and for the rest. Throws model_error otherwise, or table_too_large when the stored values
  /// alone exceed max_table_cells.
  cpt(variable child, std::vector<variable> parents, sparse_columns<T> columns, T tolerance = default_tolerance)
      : child_(std::move(child)),
        parents_(std::move(parents)),
        radix_(radices(parents_)),
        values_(std::move(columns.values)),
        stored_(std::move(columns.configurations)),
        rest_(std::move(columns.rest)),
        sparse_(true) {
    check_names();
    static_cast<void>(checked_table_cells(child_.name(), child_.cardinality(), stored_.size()));
    validate_sparse(tolerance);
  }

  [[nodiscard]] const variable& child() const noexcept { return child_; }
  [[nodiscard]] const std::vector<variable>& parents() const noexcept { return parents_; }
  [[nodiscard]] const mixed_radix& parent_radix() const noexcept { return radix_; }
  [[nodiscard]] std::size_t child_cardinality() const noexcept { return child_.cardinality(); }
  /// |Val(Pa_X)|, the number of columns.
  [[nodiscard]] std::size_t configurations() const noexcept { return radix_.size(); }
  /// J·|Val(Pa_X)|, the number of values (as a dense table would hold them; saturating).
  [[nodiscard]] std::size_t size() const noexcept {
    return detail::saturating_multiply(child_cardinality(), configurations());
  }

  /// Whether the table is stored sparse.
  [[nodiscard]] bool is_sparse() const noexcept { return sparse_; }
  /// A sparse table's stored configurations, ascending (none for a dense table).
  [[nodiscard]] std::span<const std::size_t> stored_configurations() const noexcept { return stored_; }
  /// A sparse table's column for every configuration not stored (none for a dense table).
  [[nodiscard]] std::span<const T> rest() const noexcept { return rest_; }

  [[nodiscard]] T operator()(state_index x, config_index u) const { return column(u)[x.value()]; }

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
    if (!sparse_) return {values_.data() + u.value() * child_cardinality(), child_cardinality()};
    const auto at = std::lower_bound(stored_.begin(), stored_.end(), u.value());
    if (at == stored_.end() || *at != u.value()) return rest_;
    return {values_.data() + static_cast<std::size_t>(at - stored_.begin()) * child_cardinality(), child_cardinality()};
  }
  /// Every value, configuration major. A sparse table has no such array: throws
  /// table_too_large, naming the table, for one (`dense()` gives a dense copy).
  [[nodiscard]] std::span<const T> values() const {
    if (sparse_) {
      throw table_too_large("the table of '" + child_.name() + "' is stored sparse (" + std::to_string(stored_.size()) +
                            " of " + std::to_string(configurations()) +
                            " parent configurations), and this step needs every value of it");
    }
    return values_;
  }

  /// The same table stored dense; throws table_too_large when it would exceed max_table_cells.
  [[nodiscard]] cpt dense() const {
    if (!sparse_) return *this;
    const std::size_t j = child_cardinality();
    std::vector<T> values(checked_table_cells(child_.name(), j, configurations()));
    std::size_t next = 0;
    for (std::size_t u = 0; u < configurations(); ++u) {
      const T* from = next < stored_.size() && stored_[next] == u ? values_.data() + j * next++ : rest_.data();
      std::copy(from, from + j, values.begin() + static_cast<std::ptrdiff_t>(u * j));
    }
    return cpt(child_, parents_, std::move(values), T{1});
  }

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

  /// Checks one column; `u` is its configuration, or configurations() for a sparse table's rest.
  void validate_column(std::span<const T> column, T tolerance, std::size_t u) const {
    auto place = [&] { return u < configurations() ? where(u) : std::string(" given any configuration not stored"); };
    T sum = 0;
    for (const T value : column) {
      if (!std::isfinite(value) || value < T{0} || value > T{1}) {
        throw model_error("the table of '" + child_.name() + "' has the value " +
                          text::format_double(static_cast<double>(value)) + ", which is not a probability" + place());
      }
      sum += value;
    }
    if (std::abs(sum - T{1}) > tolerance) {
      throw model_error("the distribution of '" + child_.name() + "'" + place() + " sums to " +
                        text::format_double(static_cast<double>(sum)) + ", not 1");
    }
  }

  void validate_sparse(T tolerance) const {
    const std::size_t j = child_cardinality();
    if (values_.size() != j * stored_.size() || rest_.size() != j) {
      throw model_error("the sparse table of '" + child_.name() + "' needs " + std::to_string(j) +
                        " values for each of its " + std::to_string(stored_.size()) +
                        " stored configurations and for the rest, got " + std::to_string(values_.size()) + " and " +
                        std::to_string(rest_.size()));
    }
    for (std::size_t i = 0; i < stored_.size(); ++i) {
      if (stored_[i] >= configurations() || (i > 0 && stored_[i] <= stored_[i - 1])) {
        throw model_error("the sparse table of '" + child_.name() + "' stores the configuration " +
                          std::to_string(stored_[i]) +
                          (stored_[i] >= configurations() ? ", out of range" : " out of ascending order"));
      }
      validate_column(std::span<const T>(values_).subspan(i * j, j), tolerance, stored_[i]);
    }
    validate_column(rest_, tolerance, configurations());
  }

  void validate(T tolerance) const {
    const std::size_t j = child_cardinality();
    if (values_.size() != j * configurations()) {
      throw model_error("the table of '" + child_.name() + "' needs " + std::to_string(j * configurations()) +
                        " values (" + std::to_string(j) + " states × " + std::to_string(configurations()) +
                        " parent configurations), got " + std::to_string(values_.size()));
    }
    for (std::size_t u = 0; u < configurations(); ++u) {
      validate_column(std::span<const T>(values_).subspan(u * j, j), tolerance, u);
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
  std::vector<T> values_;            // dense: every column; sparse: the stored ones
  std::vector<std::size_t> stored_;  // sparse: the stored configurations, ascending
  std::vector<T> rest_;              // sparse: the column of the others
  bool sparse_ = false;
};

}  // namespace pgm
