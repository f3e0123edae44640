#pragma once
/// \file
/// The exceptions pgm throws for bad input. Programmer mistakes are PGM_ASSERTs instead
/// (pgm/core/assert.hpp); everything here is something a user can cause and should read.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"

namespace pgm {

/// Base of every error pgm reports about its input.
class error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Data that cannot be used: missing columns, values of the wrong kind, empty data.
class data_error : public error {
 public:
  using error::error;
};

/// A problem at a known place in a text file (CSV, BIF, JSON): "file:line:column: what".
class parse_error : public data_error {
 public:
  PGM_DECL parse_error(std::string file, std::size_t line, std::size_t column, const std::string& what);

  [[nodiscard]] const std::string& file() const noexcept { return file_; }
  [[nodiscard]] std::size_t line() const noexcept { return line_; }
  [[nodiscard]] std::size_t column() const noexcept { return column_; }

 private:
  std::string file_;
  std::size_t line_;
  std::size_t column_;
};

/// A missing value (or an empty field) in a CSV file where the reader's missing-value policy
/// refuses it (pgm/data/missing.hpp): the program adds how to read such data.
class missing_value_error : public parse_error {
 public:
  using parse_error::parse_error;
};

/// A model that is inconsistent: unknown variables or states, mismatched cardinalities, tables
/// that are not distributions.
class model_error : public error {
 public:
  using error::error;
};

/// An edge that would close a directed cycle. `cycle()` lists the nodes along it, first == last.
class not_a_dag : public model_error {
 public:
  explicit not_a_dag(std::vector<std::string> cycle)
      : model_error("adding this edge closes the cycle " + join(cycle)), cycle_(std::move(cycle)) {}

  [[nodiscard]] const std::vector<std::string>& cycle() const noexcept { return cycle_; }

 private:
  PGM_DECL static std::string join(const std::vector<std::string>& nodes);
  std::vector<std::string> cycle_;
};

/// A table beyond pgm's limit of cells (pgm/core/limits.hpp), refused before it is allocated.
class table_too_large : public model_error {
 public:
  using model_error::model_error;
};

/// Exact inference whose tables would take more memory than the limit it was given, refused
/// before any is allocated; the message names both and what answers such models.
class memory_limit_exceeded : public table_too_large {
 public:
  using table_too_large::table_too_large;
};

/// A file that cannot be opened, read or written.
class io_error : public error {
 public:
  using error::error;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/error.ipp"
#endif
