#pragma once
/// \file
/// The sizes pgm refuses rather than trying (docs/limits.md): beyond them an input is an error
/// that names the limit, reported before memory or time is spent on it, instead of an
/// out-of-memory kill, a stack overflow or an hour of work.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"

namespace pgm {

/// Cells of one table (child states × parent configurations): 2^24, 128 MiB of doubles or
/// counts. The published networks need at most 8,064 (pathfinder); a larger table is almost
/// always a raw continuous column taken for a variable with a state per distinct value.
inline constexpr std::size_t max_table_cells = std::size_t{1} << 24;

/// The most variables a dynamic network unrolls into (slices × template variables).
inline constexpr std::size_t max_unrolled_variables = std::size_t{1} << 20;

/// Columns of a CSV file (fields of its header or any record).
inline constexpr std::size_t csv_max_columns = std::size_t{1} << 16;

/// Bytes of one CSV record (one line, or several when a quoted field holds line ends): 64 MiB.
inline constexpr std::size_t csv_max_record_bytes = std::size_t{64} << 20;

/// Nesting of arrays and objects in a JSON file (models, discretizations, tasks, scenarios).
inline constexpr std::size_t json_max_depth = 256;

/// Bytes of a file pgm reads whole into memory — a model (BIF, XMLBIF, NET, JSON), a
/// discretization, a task or scenario file, a report template or summary: 256 MiB, some 50
/// times the largest published network (diabetes, 5.5 MB of BIF). Checked before reading a
/// regular file, and while reading a device or pipe (/dev/zero never ends).
inline constexpr std::uint64_t max_file_bytes = std::uint64_t{256} << 20;

/// States of a latent variable fitted by EM: 1,000. Every row's posterior spreads over all of
/// them, and each of its children's tables grows with them; latent classes number a handful.
inline constexpr std::size_t max_latent_states = 1000;

/// Values (numbers, strings, arrays, objects) of one JSON file: 2^25. Read into a document they
/// take some 16 bytes each, 8 times the text of "0," at worst; a model written by pgm holds a
/// value in 20 bytes or so, so that a file within max_file_bytes stays well below the limit.
inline constexpr std::size_t json_max_values = std::size_t{1} << 25;

/// Text that entities of an XMLBIF file's DTD may expand to, in all: 1 MiB (a name or a state
/// needs a few bytes; a "billion laughs" file asks for gigabytes).
inline constexpr std::size_t xml_max_entity_bytes = std::size_t{1} << 20;

/// Rows a scenario may ask to simulate for one data set, as `pgm simulate --rows` allows.
inline constexpr std::uint64_t max_simulated_rows = 1'000'000'000;

/// Repetitions and subsets of an experiment (a scenario's `repetitions` and `subsets`,
/// `pgm experiment --reps`): 1,000 and 100, 50 and 5 times the paper's 20. Every point is kept
/// until the tables are written, about 4,600 of them a repetition for the shipped scenarios.
inline constexpr std::size_t max_repetitions = 1000;
inline constexpr std::size_t max_subsets = 100;

namespace detail {

/// a·b, or the largest size_t where it would overflow: sizes compared with a limit.
[[nodiscard]] constexpr std::size_t saturating_multiply(std::size_t a, std::size_t b) noexcept {
  if (a != 0 && b > std::numeric_limits<std::size_t>::max() / a) return std::numeric_limits<std::size_t>::max();
  return a * b;
}
[[nodiscard]] constexpr std::size_t saturating_add(std::size_t a, std::size_t b) noexcept {
  return b > std::numeric_limits<std::size_t>::max() - a ? std::numeric_limits<std::size_t>::max() : a + b;
}

}  // namespace detail

/// The cells of a table whose child has `child_states` states and whose parents have
/// `configurations` configurations; throws model_error naming `child` and the limit when
/// they exceed max_table_cells (the product is never formed when it would overflow).
[[nodiscard]] PGM_DECL std::size_t checked_table_cells(const std::string& child, std::size_t child_states,
                                                       std::size_t configurations);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/limits.ipp"
#endif
