#pragma once
/// \file
/// Sufficient statistics: the counts M[x, u] of a node X and its parents U in a data set, in
/// one pass over the columns. This is the hot loop everything that learns from data calls
/// (MLE, Bayesian estimation, independence tests, experiments). Count tables are values and
/// add up (`+=`), so counts of data shards or subsets can be merged exactly.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/dataset.hpp"

namespace pgm {

/// Counts M[x, u], laid out like a cpt: configuration major, the child's states contiguous.
class count_table {
 public:
  using count_type = std::uint64_t;

  count_table(variable child, std::vector<variable> parents)
      : child_(std::move(child)), parents_(std::move(parents)) {
    std::vector<std::size_t> cards;
    for (const auto& p : parents_) cards.push_back(p.cardinality());
    radix_ = mixed_radix(std::move(cards));
    if (radix_.size() > std::numeric_limits<std::size_t>::max() / child_.cardinality()) {
      throw model_error("the table of '" + child_.name() + "' has too many cells");
    }
    counts_.assign(radix_.size() * child_.cardinality(), 0);
  }

  [[nodiscard]] const variable& child() const noexcept { return child_; }
  [[nodiscard]] const std::vector<variable>& parents() const noexcept { return parents_; }
  [[nodiscard]] const mixed_radix& parent_radix() const noexcept { return radix_; }
  [[nodiscard]] std::size_t child_cardinality() const noexcept { return child_.cardinality(); }
  [[nodiscard]] std::size_t configurations() const noexcept { return radix_.size(); }

  /// M[x, u].
  [[nodiscard]] count_type operator()(state_index x, config_index u) const {
    return counts_[u.value() * child_cardinality() + x.value()];
  }
  /// M[u] = sum over x of M[x, u].
  [[nodiscard]] count_type total(config_index u) const {
    const auto column = this->column(u);
    count_type sum = 0;
    for (auto c : column) sum += c;
    return sum;
  }
  /// The number of rows counted.
  [[nodiscard]] count_type total() const {
    count_type sum = 0;
    for (auto c : counts_) sum += c;
    return sum;
  }
  [[nodiscard]] std::span<const count_type> column(config_index u) const {
    return {counts_.data() + u.value() * child_cardinality(), child_cardinality()};
  }
  [[nodiscard]] std::span<const count_type> counts() const noexcept { return counts_; }
  [[nodiscard]] std::span<count_type> counts() noexcept { return counts_; }

  /// Adds the counts of another table of the same family.
  count_table& operator+=(const count_table& other) {
    if (other.child_ != child_ || other.parents_ != parents_) {
      throw model_error("cannot add the counts of '" + other.child_.name() + "' to those of '" +
                        child_.name() + "': the families differ");
    }
    for (std::size_t i = 0; i < counts_.size(); ++i) counts_[i] += other.counts_[i];
    return *this;
  }

  friend bool operator==(const count_table&, const count_table&) = default;

 private:
  variable child_;
  std::vector<variable> parents_;
  mixed_radix radix_;
  std::vector<count_type> counts_;
};

struct count_options {
  /// Worker threads; 0 uses every hardware thread. The counts are the same for any number.
  unsigned threads = 0;
  /// Below this many rows per thread, fewer threads are used (starting one costs ~20 µs).
  std::size_t min_rows_per_thread = std::size_t{1} << 16;
};

/// Rows [begin, end) of a data set.
struct row_range {
  std::size_t begin = 0;
  std::size_t end = std::numeric_limits<std::size_t>::max();
};

namespace detail {

inline constexpr std::size_t count_block_rows = 2048;

/// index[i] = the flat cell of row `first + i`, built one column at a time so that each
/// pass is a simple loop over contiguous codes that the compiler vectorizes.
template <class Code>
void set_cells(const Code* codes, std::uint32_t* index, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) index[i] = codes[i];
}
template <class Code>
void add_cells(const Code* codes, std::uint32_t stride, std::uint32_t* index, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) index[i] += static_cast<std::uint32_t>(codes[i]) * stride;
}

/// Adds the counts of rows [begin, end) into `counts`. `columns[0]` is the child (stride 1),
/// the others are parents with flat strides `strides[k]`.
inline void count_rows(std::span<const code_vector* const> columns,
                       std::span<const std::uint32_t> strides, std::size_t begin, std::size_t end,
                       std::uint64_t* counts) {
  std::uint32_t index[count_block_rows];
  for (std::size_t first = begin; first < end; first += count_block_rows) {
    const std::size_t n = std::min(count_block_rows, end - first);
    std::visit([&](const auto& codes) { set_cells(codes.data() + first, index, n); }, *columns[0]);
    for (std::size_t k = 1; k < columns.size(); ++k) {
      std::visit([&](const auto& codes) { add_cells(codes.data() + first, strides[k], index, n); },
                 *columns[k]);
    }
    for (std::size_t i = 0; i < n; ++i) ++counts[index[i]];
  }
}

}  // namespace detail

/// Counts the family (child | parents) over rows `rows` of the given columns.
[[nodiscard]] inline count_table count_family(const discrete_column& child,
                                              std::span<const discrete_column* const> parents,
                                              const count_options& options = {},
                                              row_range rows = {}) {
  std::vector<variable> parent_variables;
  for (const auto* p : parents) parent_variables.push_back(p->var());
  count_table table(child.var(), std::move(parent_variables));
  if (table.counts().size() > std::numeric_limits<std::uint32_t>::max()) {
    throw model_error("the table of '" + child.name() + "' has " +
                      std::to_string(table.counts().size()) +
                      " cells, more than pgm can count (2^32)");
  }
  const std::size_t end = std::min(rows.end, child.size());
  const std::size_t begin = std::min(rows.begin, end);

  std::vector<const code_vector*> columns{&child.codes()};
  std::vector<std::uint32_t> strides{1};
  const auto j = child.var().cardinality();
  for (std::size_t k = 0; k < parents.size(); ++k) {
    if (parents[k]->size() != child.size()) {
      throw data_error("column '" + parents[k]->name() + "' has " +
                       std::to_string(parents[k]->size()) + " rows, '" + child.name() + "' " +
                       std::to_string(child.size()));
    }
    columns.push_back(&parents[k]->codes());
    strides.push_back(static_cast<std::uint32_t>(j * table.parent_radix().stride(k)));
  }

  const std::size_t n = end - begin;
  unsigned threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<std::size_t>(
      threads, std::max<std::size_t>(1, n / std::max<std::size_t>(1, options.min_rows_per_thread))));
  if (threads <= 1) {
    detail::count_rows(columns, strides, begin, end, table.counts().data());
    return table;
  }
  // A private table per thread over a contiguous row range, summed in thread order.
  std::vector<std::vector<std::uint64_t>> partial(threads,
                                                  std::vector<std::uint64_t>(table.counts().size()));
  {
    std::vector<std::jthread> workers;
    for (unsigned t = 0; t < threads; ++t) {
      const std::size_t lo = begin + n * t / threads;
      const std::size_t hi = begin + n * (t + 1) / threads;
      workers.emplace_back(
          [&, lo, hi, t] { detail::count_rows(columns, strides, lo, hi, partial[t].data()); });
    }
  }
  auto counts = table.counts();
  for (const auto& part : partial) {
    for (std::size_t i = 0; i < counts.size(); ++i) counts[i] += part[i];
  }
  return table;
}

/// Counts the family (child | parents) over rows `rows` of a data set, by column names.
/// Throws data_error for a missing or continuous column.
[[nodiscard]] inline count_table count_family(const dataset& data, std::string_view child,
                                              std::span<const std::string> parents,
                                              const count_options& options = {},
                                              row_range rows = {}) {
  std::vector<const discrete_column*> parent_columns;
  for (const auto& name : parents) parent_columns.push_back(&data.discrete(name));
  return count_family(data.discrete(child), parent_columns, options, rows);
}

}  // namespace pgm
