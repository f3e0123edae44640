#pragma once
/// \file
/// `dataset`: a columnar table of observations. A discrete column stores each row's state
/// as a small unsigned code — 8 bits when the variable has at most 256 states, 16 or 32 bits
/// otherwise — so that counting streams through as few bytes as possible. A continuous column
/// stores doubles until it is discretized.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/missing.hpp"
#include "pgm/detail/text.hpp"

namespace pgm {

using code_vector = std::variant<std::vector<std::uint8_t>, std::vector<std::uint16_t>, std::vector<std::uint32_t>>;

/// The narrowest code width for a variable with `cardinality` states (pass one more when the
/// column holds missing values, whose code is the width's largest value).
[[nodiscard]] inline code_vector make_code_vector(std::size_t cardinality, std::size_t rows = 0) {
  if (cardinality <= 256) return std::vector<std::uint8_t>(rows);
  if (cardinality <= 65536) return std::vector<std::uint16_t>(rows);
  return std::vector<std::uint32_t>(rows);
}

class discrete_column {
 public:
  /// Codes index the variable's states; throws data_error on a code out of range.
  template <class Code>
  requires std::unsigned_integral<Code> discrete_column(variable var, const std::vector<Code>& codes)
      : variable_(std::move(var)), codes_(make_code_vector(variable_.cardinality(), codes.size())) {
    std::visit(
        [&](auto& stored) {
          using stored_code = typename std::decay_t<decltype(stored)>::value_type;
          const auto card = variable_.cardinality();
          for (std::size_t row = 0; row < codes.size(); ++row) {
            if (codes[row] >= card) {
              throw data_error("column '" + variable_.name() + "' row " + std::to_string(row + 1) + ": state code " +
                               std::to_string(codes[row]) + " is out of range (" + std::to_string(card) + " states)");
            }
            stored[row] = static_cast<stored_code>(codes[row]);
          }
        },
        codes_);
  }

  /// Takes codes already stored at the right width, unchecked: for pgm's own producers.
  /// `missing` rows hold missing_code (the width then leaves that code free of states).
  discrete_column(variable var, code_vector codes, std::in_place_t, std::size_t missing = 0)
      : variable_(std::move(var)), codes_(std::move(codes)), missing_(missing) {}

  [[nodiscard]] const variable& var() const noexcept { return variable_; }
  [[nodiscard]] const std::string& name() const noexcept { return variable_.name(); }
  [[nodiscard]] std::size_t size() const noexcept {
    return std::visit([](const auto& c) { return c.size(); }, codes_);
  }
  [[nodiscard]] std::uint32_t code(std::size_t row) const {
    return std::visit([row](const auto& c) { return static_cast<std::uint32_t>(c[row]); }, codes_);
  }
  /// The state label of a row; throws data_error for a missing value.
  [[nodiscard]] const std::string& label(std::size_t row) const {
    const auto c = code(row);
    if (c >= variable_.cardinality()) {
      throw data_error("column '" + name() + "' row " + std::to_string(row + 1) + ": the value is missing");
    }
    return variable_.states()[c];
  }
  /// Rows whose value is missing (their code is missing_code of the code type).
  [[nodiscard]] std::size_t missing() const noexcept { return missing_; }
  [[nodiscard]] bool is_missing(std::size_t row) const {
    return missing_ != 0 && std::visit(
                                [row](const auto& c) {
                                  using code_type = typename std::decay_t<decltype(c)>::value_type;
                                  return c[row] == missing_code<code_type>;
                                },
                                codes_);
  }
  [[nodiscard]] const code_vector& codes() const noexcept { return codes_; }
  /// Bytes per stored code: 1, 2 or 4.
  [[nodiscard]] std::size_t code_width() const noexcept {
    return std::visit([](const auto& c) { return sizeof(c[0]); }, codes_);
  }

  /// The same codes under a variable of equal cardinality (new labels, edges or tags).
  [[nodiscard]] discrete_column with_variable(variable replacement) const {
    if (replacement.cardinality() != variable_.cardinality()) {
      throw model_error("column '" + name() + "' has " + std::to_string(variable_.cardinality()) +
                        " states, the replacement variable " + std::to_string(replacement.cardinality()));
    }
    return discrete_column(std::move(replacement), codes_, std::in_place, missing_);
  }

  [[nodiscard]] discrete_column select(std::span<const std::size_t> rows) const {
    std::size_t missing = 0;
    auto picked = std::visit(
        [&](const auto& c) -> code_vector {
          using code_type = typename std::decay_t<decltype(c)>::value_type;
          std::decay_t<decltype(c)> chosen(rows.size());
          for (std::size_t i = 0; i < rows.size(); ++i) {
            chosen[i] = c.at(rows[i]);
            missing += chosen[i] == missing_code<code_type> && missing_ != 0;
          }
          return chosen;
        },
        codes_);
    return discrete_column(variable_, std::move(picked), std::in_place, missing);
  }

  friend bool operator==(const discrete_column&, const discrete_column&) = default;

 private:
  variable variable_;
  code_vector codes_;
  std::size_t missing_ = 0;
};

class continuous_column {
 public:
  continuous_column(std::string name, std::vector<double> values, semantic_tags tags = {})
      : name_(std::move(name)), values_(std::move(values)), tags_(std::move(tags)) {
    if (name_.empty()) throw data_error("a column needs a name");
  }

  [[nodiscard]] const std::string& name() const noexcept { return name_; }
  [[nodiscard]] std::size_t size() const noexcept { return values_.size(); }
  /// The values; a missing one is NaN.
  [[nodiscard]] std::span<const double> values() const noexcept { return values_; }
  [[nodiscard]] const semantic_tags& tags() const noexcept { return tags_; }
  /// Rows whose value is missing (NaN).
  [[nodiscard]] std::size_t missing() const noexcept {
    return static_cast<std::size_t>(std::count_if(values_.begin(), values_.end(), [](double v) { return v != v; }));
  }

  [[nodiscard]] continuous_column select(std::span<const std::size_t> rows) const {
    std::vector<double> picked(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) picked[i] = values_.at(rows[i]);
    return continuous_column(name_, std::move(picked), tags_);
  }

  /// Equal names, tags and values, a missing value (NaN) equal to a missing one.
  friend bool operator==(const continuous_column& a, const continuous_column& b) {
    return a.name_ == b.name_ && a.tags_ == b.tags_ &&
           std::equal(a.values_.begin(), a.values_.end(), b.values_.begin(), b.values_.end(),
                      [](double x, double y) { return x == y || (x != x && y != y); });
  }

 private:
  std::string name_;
  std::vector<double> values_;
  semantic_tags tags_;
};

using data_column = std::variant<discrete_column, continuous_column>;

[[nodiscard]] inline const std::string& column_name(const data_column& c) {
  return std::visit([](const auto& typed) -> const std::string& { return typed.name(); }, c);
}
[[nodiscard]] inline std::size_t column_size(const data_column& c) {
  return std::visit([](const auto& typed) { return typed.size(); }, c);
}

class dataset {
 public:
  dataset() = default;
  /// `source` names where the data came from, for error messages ("runs.csv").
  explicit dataset(std::string source) : source_(std::move(source)) {}

  [[nodiscard]] std::size_t rows() const noexcept { return rows_; }
  [[nodiscard]] std::size_t size() const noexcept { return columns_.size(); }
  [[nodiscard]] bool empty() const noexcept { return rows_ == 0; }
  [[nodiscard]] const std::string& source() const noexcept { return source_; }

  /// Appends a column. Throws data_error on a repeated name or a different row count.
  void add(data_column c) {
    const auto& name = column_name(c);
    if (index_.contains(name)) throw data_error(prefix() + "the column '" + name + "' appears twice");
    const auto n = column_size(c);
    if (!columns_.empty() && n != rows_) {
      throw data_error(prefix() + "column '" + name + "' has " + std::to_string(n) + " rows, the others " +
                       std::to_string(rows_));
    }
    rows_ = n;
    index_.emplace(name, columns_.size());
    columns_.push_back(std::move(c));
  }

  /// Replaces the column of the same name (e.g. by its discretized form), keeping its place.
  void replace(data_column c) {
    const auto i = position(column_name(c));
    if (column_size(c) != rows_) {
      throw data_error(prefix() + "replacement column '" + column_name(c) + "' has " + std::to_string(column_size(c)) +
                       " rows, the data " + std::to_string(rows_));
    }
    columns_[i] = std::move(c);
  }

  [[nodiscard]] bool contains(std::string_view name) const { return index_.find(name) != index_.end(); }
  [[nodiscard]] std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (const auto& c : columns_) result.push_back(column_name(c));
    return result;
  }
  [[nodiscard]] const std::vector<data_column>& columns() const noexcept { return columns_; }
  [[nodiscard]] const data_column& at(std::string_view name) const { return columns_[position(name)]; }
  [[nodiscard]] bool is_discrete(std::string_view name) const {
    return std::holds_alternative<discrete_column>(at(name));
  }

  /// The discrete column of this name; throws data_error if it is missing or continuous.
  [[nodiscard]] const discrete_column& discrete(std::string_view name) const {
    const auto& c = at(name);
    if (const auto* d = std::get_if<discrete_column>(&c)) return *d;
    throw data_error(prefix() + "column '" + std::string(name) + "' holds continuous values; discretize it first");
  }
  /// The continuous column of this name; throws data_error if it is missing or discrete.
  [[nodiscard]] const continuous_column& continuous(std::string_view name) const {
    const auto& c = at(name);
    if (const auto* d = std::get_if<continuous_column>(&c)) return *d;
    throw data_error(prefix() + "column '" + std::string(name) + "' is discrete, not numeric");
  }

  /// The rows at the given positions, in that order.
  [[nodiscard]] dataset select_rows(std::span<const std::size_t> rows) const {
    for (auto row : rows) {
      if (row >= rows_) throw data_error(prefix() + "row " + std::to_string(row) + " is out of range");
    }
    dataset result(source_);
    for (const auto& c : columns_) {
      result.add(std::visit([&](const auto& typed) -> data_column { return typed.select(rows); }, c));
    }
    if (columns_.empty()) result.rows_ = rows.size();
    return result;
  }
  /// Rows [begin, end).
  [[nodiscard]] dataset slice(std::size_t begin, std::size_t end) const {
    end = std::min(end, rows_);
    std::vector<std::size_t> rows;
    for (std::size_t r = begin; r < end; ++r) rows.push_back(r);
    return select_rows(rows);
  }
  /// Only the named columns, in the given order.
  [[nodiscard]] dataset select_columns(std::span<const std::string> names) const {
    dataset result(source_);
    for (const auto& name : names) result.add(at(name));
    if (names.empty()) result.rows_ = rows_;
    return result;
  }

  friend bool operator==(const dataset& a, const dataset& b) { return a.rows_ == b.rows_ && a.columns_ == b.columns_; }

 private:
  std::size_t position(std::string_view name) const {
    const auto it = index_.find(name);
    if (it == index_.end()) {
      throw data_error(prefix() + "there is no column '" + std::string(name) +
                       "' (columns: " + detail::list_for_message(names()) + ")");
    }
    return it->second;
  }
  std::string prefix() const { return source_.empty() ? std::string() : source_ + ": "; }

  std::string source_;
  std::vector<data_column> columns_;
  std::map<std::string, std::size_t, std::less<>> index_;
  std::size_t rows_ = 0;
};

}  // namespace pgm
