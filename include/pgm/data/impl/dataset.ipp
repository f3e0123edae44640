#pragma once
// The definitions of pgm/data/dataset.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/data/dataset.hpp"

namespace pgm {

PGM_DECL code_vector make_code_vector(std::size_t cardinality, std::size_t rows) {
  if (cardinality <= 256) return std::vector<std::uint8_t>(rows);
  if (cardinality <= 65536) return std::vector<std::uint16_t>(rows);
  return std::vector<std::uint32_t>(rows);
}

PGM_DECL const std::string& discrete_column::label(std::size_t row) const {
  const auto c = code(row);
  if (c >= variable_.cardinality()) {
    throw data_error("column '" + name() + "' row " + std::to_string(row + 1) + ": the value is missing");
  }
  return variable_.states()[c];
}

PGM_DECL bool discrete_column::is_missing(std::size_t row) const {
  return missing_ != 0 && std::visit(
                              [row](const auto& c) {
                                using code_type = typename std::decay_t<decltype(c)>::value_type;
                                return c[row] == missing_code<code_type>;
                              },
                              codes_);
}

PGM_DECL discrete_column discrete_column::with_variable(variable replacement) const& {
  return discrete_column(*this).with_variable(std::move(replacement));
}

PGM_DECL discrete_column discrete_column::with_variable(variable replacement) && {
  if (replacement.cardinality() != variable_.cardinality()) {
    throw model_error("column '" + name() + "' has " + std::to_string(variable_.cardinality()) +
                      " states, the replacement variable " + std::to_string(replacement.cardinality()));
  }
  return discrete_column(std::move(replacement), std::move(codes_), std::in_place, missing_);
}

PGM_DECL discrete_column discrete_column::select(std::span<const std::size_t> rows) const {
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

PGM_DECL discrete_column discrete_column::select_runs(std::span<const std::pair<std::size_t, std::size_t>> runs) const {
  std::size_t rows = 0;
  for (const auto& [begin, end] : runs) {
    if (begin > end || end > size()) throw std::out_of_range("discrete_column::select_runs: a run past the rows");
    rows += end - begin;
  }
  std::size_t missing = 0;
  auto picked = std::visit(
      [&](const auto& c) -> code_vector {
        using code_type = typename std::decay_t<decltype(c)>::value_type;
        std::decay_t<decltype(c)> chosen(rows);
        auto out = chosen.begin();
        for (const auto& [begin, end] : runs) {
          out = std::copy(c.begin() + static_cast<std::ptrdiff_t>(begin), c.begin() + static_cast<std::ptrdiff_t>(end),
                          out);
        }
        if (missing_ != 0)
          missing = static_cast<std::size_t>(std::count(chosen.begin(), chosen.end(), missing_code<code_type>));
        return chosen;
      },
      codes_);
  return discrete_column(variable_, std::move(picked), std::in_place, missing);
}

PGM_DECL continuous_column continuous_column::select(std::span<const std::size_t> rows) const {
  std::vector<double> picked(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) picked[i] = values_.at(rows[i]);
  return continuous_column(name_, std::move(picked), tags_);
}

PGM_DECL void dataset::add(data_column c) {
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

PGM_DECL void dataset::replace(data_column c) {
  const auto i = position(column_name(c));
  if (column_size(c) != rows_) {
    throw data_error(prefix() + "replacement column '" + column_name(c) + "' has " + std::to_string(column_size(c)) +
                     " rows, the data " + std::to_string(rows_));
  }
  columns_[i] = std::move(c);
}

PGM_DECL std::vector<std::string> dataset::names() const {
  std::vector<std::string> result;
  for (const auto& c : columns_) result.push_back(column_name(c));
  return result;
}

PGM_DECL const discrete_column& dataset::discrete(std::string_view name) const {
  const auto& c = at(name);
  if (const auto* d = std::get_if<discrete_column>(&c)) return *d;
  throw data_error(prefix() + "column '" + std::string(name) + "' holds continuous values; discretize it first");
}

PGM_DECL const continuous_column& dataset::continuous(std::string_view name) const {
  const auto& c = at(name);
  if (const auto* d = std::get_if<continuous_column>(&c)) return *d;
  throw data_error(prefix() + "column '" + std::string(name) + "' is discrete, not numeric");
}

PGM_DECL dataset dataset::select_rows(std::span<const std::size_t> rows) const {
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

PGM_DECL dataset dataset::slice(std::size_t begin, std::size_t end) const {
  end = std::min(end, rows_);
  std::vector<std::size_t> rows;
  for (std::size_t r = begin; r < end; ++r) rows.push_back(r);
  return select_rows(rows);
}

PGM_DECL dataset dataset::select_columns(std::span<const std::string> names) const {
  dataset result(source_);
  for (const auto& name : names) result.add(at(name));
  if (names.empty()) result.rows_ = rows_;
  return result;
}

PGM_DECL std::size_t dataset::position(std::string_view name) const {
  const auto it = index_.find(name);
  if (it == index_.end()) {
    throw data_error(prefix() + "there is no column '" + std::string(name) +
                     "' (columns: " + text::list_for_message(names()) + ")");
  }
  return it->second;
}

}  // namespace pgm
