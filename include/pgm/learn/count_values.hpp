#pragma once
/// \file
/// Counting families straight from columns of integer values held elsewhere (NumPy buffers, a
/// memory-mapped file), without building a data set first. A column's states are the values seen,
/// ordered as the CSV reader orders them (pgm/data/state_order.hpp), so the counts are those of
/// count_family on the data set the same values make. All the families are counted in one pass over
/// the rows, by value in the ranges a sample of rows suggests (a second pass when a value lies
/// beyond), and a family whose columns another family holds too (a parent that is a root, say) is
/// summed out of that one's counts instead of being counted again.
///
/// This way is for columns of small non-negative values (codes 0..k-1, the usual case): the rows
/// are counted by value and the values mapped to states afterwards. For other columns
/// count_value_families returns std::nullopt, and the caller builds a data set.

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/state_order.hpp"
#include "pgm/data/sufficient_statistics.hpp"

namespace pgm {

/// `size` integer values held elsewhere, `stride` elements apart (a column of a row-major matrix
/// has the row's length).
template <class Value>
struct value_span {
  const Value* data = nullptr;
  std::size_t size = 0;
  std::ptrdiff_t stride = 1;
};

using value_column = std::variant<value_span<std::int8_t>, value_span<std::int16_t>, value_span<std::int32_t>,
                                  value_span<std::int64_t>, value_span<std::uint8_t>, value_span<std::uint16_t>,
                                  value_span<std::uint32_t>, value_span<std::uint64_t>>;

struct named_value_column {
  std::string name;
  value_column values;
};

/// A family by column positions: the child and its parents, in the order of its table.
struct value_family {
  std::size_t child = 0;
  std::vector<std::size_t> parents;
};

struct value_counts {
  /// Each column's variable: its name and the values seen as states.
  std::vector<variable> variables;
  /// Each family's counts over those variables.
  std::vector<count_table> tables;
};

/// Columns with a value at or above this, or a negative one, are not counted by value.
inline constexpr std::uint64_t value_count_limit = std::uint64_t{1} << 16;
/// Nor are families whose table by value (each column's range of values rounded up to a power
/// of two) would have more cells than this: it is counted into, and must stay in the
/// second-level cache.
inline constexpr std::size_t value_cell_limit = std::size_t{1} << 18;

namespace detail {

template <class Value>
[[nodiscard]] const Value* value_at(const value_span<Value>& c, std::size_t row) {
  return c.data + static_cast<std::ptrdiff_t>(row) * c.stride;
}

/// Rows of each column looked at, evenly spaced, for a first guess of its values' range.
inline constexpr std::size_t value_sample_rows = 2048;

/// Every bit set in the values of some evenly spaced rows.
template <class Value>
[[nodiscard]] std::uint64_t sampled_value_bits(const value_span<Value>& c) {
  std::uint64_t bits = 0;
  const std::size_t step = std::max<std::size_t>(1, c.size / value_sample_rows);
  for (std::size_t r = 0; r < c.size; r += step) bits |= static_cast<std::uint64_t>(*value_at(c, r));
  return bits;
}

/// index[i] += (value of row `first + i` & mask) << shift, for i < n; returns every bit set in
/// those values (a negative value sets the top ones). Plain loops over contiguous values in 64
/// bits, which the compiler vectorizes; the mask keeps a value beyond the guessed range inside
/// the table, and the bits returned tell the caller to count again.
template <class Value>
[[nodiscard]] std::uint64_t add_values(const value_span<Value>& c, std::size_t first, std::size_t n, std::uint64_t mask,
                                       unsigned shift, std::uint64_t* index) {
  const Value* v = value_at(c, first);
  std::uint64_t bits = 0;
  if (c.stride == 1) {
    for (std::size_t i = 0; i < n; ++i) {
      const auto value = static_cast<std::uint64_t>(v[i]);
      bits |= value;
      index[i] += (value & mask) << shift;
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      const auto value = static_cast<std::uint64_t>(v[static_cast<std::ptrdiff_t>(i) * c.stride]);
      bits |= value;
      index[i] += (value & mask) << shift;
    }
  }
  return bits;
}

/// The same as add_values for two contiguous columns of one type in one pass: `index` is read
/// and written once for both.
template <class Value>
void add_value_pair(const value_span<Value>& a, const value_span<Value>& b, std::size_t first, std::size_t n,
                    const std::uint64_t (&mask)[2], const unsigned (&shift)[2], std::uint64_t (&bits)[2],
                    std::uint64_t* index) {
  const Value* va = a.data + first;
  const Value* vb = b.data + first;
  std::uint64_t bits_a = 0;
  std::uint64_t bits_b = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto x = static_cast<std::uint64_t>(va[i]);
    const auto y = static_cast<std::uint64_t>(vb[i]);
    bits_a |= x;
    bits_b |= y;
    index[i] += ((x & mask[0]) << shift[0]) + ((y & mask[1]) << shift[1]);
  }
  bits[0] |= bits_a;
  bits[1] |= bits_b;
}

/// A family counted by value: its columns (child first), each column's values taking `bits[k]`
/// bits of the cell index from bit `shifts[k]` on.
struct value_table_layout {
  std::vector<std::size_t> columns;
  std::vector<unsigned> shifts;
  std::vector<unsigned> bits;
  std::size_t cells = 1;
};

/// The counts by value of one thread: one table per layout, and every bit set in each column.
struct value_tally {
  std::vector<std::vector<std::uint64_t>> tables;
  std::vector<std::uint64_t> bits;
};

/// Adds the counts of rows [begin, end) into `tally`, a block of rows at a time so that the cell
/// indices stay in the first-level cache.
PGM_DECL void count_value_rows(std::span<const value_column> columns, std::span<const value_table_layout> layouts,
                               std::size_t begin, std::size_t end, value_tally& tally);

/// The counts by value of rows [0, rows) on the threads `options` asks for (as
/// count_rows_parallel): each thread counts its chunks into a private tally, and the tallies are
/// summed.
PGM_DECL value_tally count_by_value(std::span<const value_column> columns, std::span<const value_table_layout> layouts,
                                    std::size_t rows, const count_options& options);

/// The bits a column of these values takes in a cell index: its values lie in [0, 2^width).
[[nodiscard]] inline unsigned value_width(std::uint64_t bits) { return static_cast<unsigned>(std::bit_width(bits)); }

}  // namespace detail

/// The counts of each family of `families` over `columns`, each column's states being the values
/// it holds. std::nullopt when some column has a negative value or one of value_count_limit or
/// more, or no rows, or a family's table by value would exceed value_cell_limit cells: count
/// those from a data set. Throws data_error when columns differ in length, model_error for a
/// family naming no column.
[[nodiscard]] PGM_DECL std::optional<value_counts> count_value_families(std::span<const named_value_column> columns,
                                                                        std::span<const value_family> families,
                                                                        const count_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/count_values.ipp"
#endif
