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

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/missing.hpp"

namespace pgm {

using code_vector = std::variant<std::vector<std::uint8_t>, std::vector<std::uint16_t>, std::vector<std::uint32_t>>;

/// The narrowest code width for a variable with `cardinality` states (pass one more when the
/// column holds missing values, whose code is the width's largest value).
[[nodiscard]] PGM_DECL code_vector make_code_vector(std::size_t cardinality, std::size_t rows = 0);

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
  [[nodiscard]] PGM_DECL const std::string& label(std::size_t row) const;
  /// Rows whose value is missing (their code is missing_code of the code type).
  [[nodiscard]] std::size_t missing() const noexcept { return missing_; }
  [[nodiscard]] PGM_DECL bool is_missing(std::size_t row) const;
  [[nodiscard]] const code_vector& codes() const noexcept { return codes_; }
  /// Bytes per stored code: 1, 2 or 4.
  [[nodiscard]] std::size_t code_width() const noexcept {
    return std::visit([](const auto& c) { return sizeof(c[0]); }, codes_);
  }

  /// The same codes under a variable of equal cardinality (new labels, edges or tags).
  [[nodiscard]] PGM_DECL discrete_column with_variable(variable replacement) const&;
  /// The same, its codes moved rather than copied.
  [[nodiscard]] PGM_DECL discrete_column with_variable(variable replacement) &&;

  [[nodiscard]] PGM_DECL discrete_column select(std::span<const std::size_t> rows) const;
  /// The rows of each run [begin, end), the runs one after another: a copy per run where
  /// select() looks up every row.
  [[nodiscard]] PGM_DECL discrete_column select_runs(std::span<const std::pair<std::size_t, std::size_t>> runs) const;

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

  [[nodiscard]] PGM_DECL continuous_column select(std::span<const std::size_t> rows) const;

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
  PGM_DECL void add(data_column c);

  /// Replaces the column of the same name (e.g. by its discretized form), keeping its place.
  PGM_DECL void replace(data_column c);

  [[nodiscard]] bool contains(std::string_view name) const { return index_.find(name) != index_.end(); }
  [[nodiscard]] PGM_DECL std::vector<std::string> names() const;
  [[nodiscard]] const std::vector<data_column>& columns() const noexcept { return columns_; }
  [[nodiscard]] const data_column& at(std::string_view name) const { return columns_[position(name)]; }
  [[nodiscard]] bool is_discrete(std::string_view name) const {
    return std::holds_alternative<discrete_column>(at(name));
  }

  /// The discrete column of this name; throws data_error if it is missing or continuous.
  [[nodiscard]] PGM_DECL const discrete_column& discrete(std::string_view name) const;
  /// The continuous column of this name; throws data_error if it is missing or discrete.
  [[nodiscard]] PGM_DECL const continuous_column& continuous(std::string_view name) const;

  /// The rows at the given positions, in that order.
  [[nodiscard]] PGM_DECL dataset select_rows(std::span<const std::size_t> rows) const;
  /// Rows [begin, end).
  [[nodiscard]] PGM_DECL dataset slice(std::size_t begin, std::size_t end) const;
  /// Only the named columns, in the given order.
  [[nodiscard]] PGM_DECL dataset select_columns(std::span<const std::string> names) const;

  friend bool operator==(const dataset& a, const dataset& b) { return a.rows_ == b.rows_ && a.columns_ == b.columns_; }

 private:
  PGM_DECL std::size_t position(std::string_view name) const;
  std::string prefix() const { return source_.empty() ? std::string() : source_ + ": "; }

  std::string source_;
  std::vector<data_column> columns_;
  std::map<std::string, std::size_t, std::less<>> index_;
  std::size_t rows_ = 0;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/data/impl/dataset.ipp"
#endif
