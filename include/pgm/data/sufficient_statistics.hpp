#pragma once
/// \file
/// Sufficient statistics: the counts M[x, u] of a node X and its parents U in a data set, in
/// one pass over the columns. This is the hot loop everything that learns from data calls
/// (MLE, Bayesian estimation, independence tests, experiments). Count tables are values and
/// add up (`+=`), so counts of data shards or subsets can be merged exactly; that is also how
/// counting runs on several threads (pgm/detail/parallel_for.hpp): each counts chunks of rows
/// into a private table, and the tables are summed.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/missing.hpp"
#include "pgm/detail/parallel_for.hpp"

namespace pgm {

/// Counts M[x, u], laid out like a cpt: configuration major, the child's states contiguous.
/// `Count` is std::uint64_t for rows counted (`count_table`) and double for the expected counts
/// of EM (`expected_count_table`, pgm/learn/expectation_maximization.hpp); the estimators take
/// either.
///
/// A family whose dense table would exceed max_table_cells is counted sparse instead: only the
/// configurations rows hold are stored (ascending), each with its column of counts, so that
/// memory follows the rows, not the configurations. `column`, `total` and `+=` work either
/// way; `counts()` needs a dense table.
template <class Count>
class basic_count_table {
 public:
  using count_type = Count;

  /// One cell's count, for add().
  struct cell {
    std::size_t configuration = 0;
    std::size_t state = 0;
    count_type count = 0;
  };

  basic_count_table(variable child, std::vector<variable> parents)
      : child_(std::move(child)), parents_(std::move(parents)) {
    std::vector<std::size_t> cards;
    for (const auto& p : parents_) cards.push_back(p.cardinality());
    radix_ = mixed_radix(std::move(cards));
    sparse_ = detail::saturating_multiply(child_.cardinality(), radix_.size()) > max_table_cells;
    if (sparse_) {
      zeros_.assign(child_.cardinality(), 0);
    } else {
      counts_.assign(child_.cardinality() * radix_.size(), 0);
    }
  }

  [[nodiscard]] const variable& child() const noexcept { return child_; }
  [[nodiscard]] const std::vector<variable>& parents() const noexcept { return parents_; }
  [[nodiscard]] const mixed_radix& parent_radix() const noexcept { return radix_; }
  [[nodiscard]] std::size_t child_cardinality() const noexcept { return child_.cardinality(); }
  [[nodiscard]] std::size_t configurations() const noexcept { return radix_.size(); }

  /// Whether only the configurations seen are stored.
  [[nodiscard]] bool is_sparse() const noexcept { return sparse_; }
  /// A sparse table's stored configurations, ascending (none for a dense table).
  [[nodiscard]] std::span<const std::size_t> stored_configurations() const noexcept { return stored_; }
  /// The counts of the i-th stored configuration of a sparse table.
  [[nodiscard]] std::span<const count_type> stored_column(std::size_t i) const {
    return {counts_.data() + i * child_cardinality(), child_cardinality()};
  }

  /// M[x, u].
  [[nodiscard]] count_type operator()(state_index x, config_index u) const { return column(u)[x.value()]; }
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
  /// Calls f(u, column) for each configuration u that may have counts, ascending: every one of
  /// a dense table, the stored ones of a sparse table (the others are all zero). What sums over
  /// the columns visits, so that 2⁴⁰ configurations of 200 rows cost 200 columns.
  template <class F>
  void for_each_column(F&& f) const {
    if (!sparse_) {
      for (std::size_t u = 0; u < configurations(); ++u) f(u, column(config_index(u)));
      return;
    }
    for (std::size_t i = 0; i < stored_.size(); ++i) f(stored_[i], stored_column(i));
  }

  [[nodiscard]] std::span<const count_type> column(config_index u) const {
    if (!sparse_) return {counts_.data() + u.value() * child_cardinality(), child_cardinality()};
    const auto at = std::lower_bound(stored_.begin(), stored_.end(), u.value());
    if (at == stored_.end() || *at != u.value()) return zeros_;
    return stored_column(static_cast<std::size_t>(at - stored_.begin()));
  }
  /// Every count, configuration major; throws table_too_large for a sparse table.
  [[nodiscard]] std::span<const count_type> counts() const {
    if (sparse_) throw_sparse();
    return counts_;
  }
  [[nodiscard]] std::span<count_type> counts() {
    if (sparse_) throw_sparse();
    return counts_;
  }

  /// Adds counts cell by cell, in any order; the way a sparse table is filled.
  void add(std::vector<cell> cells) {
    const std::size_t j = child_cardinality();
    for (const auto& c : cells) {
      if (c.configuration >= configurations() || c.state >= j) {
        throw model_error("a count of '" + child_.name() + "' is out of its table (configuration " +
                          std::to_string(c.configuration) + ", state " + std::to_string(c.state) + ")");
      }
    }
    if (!sparse_) {
      for (const auto& c : cells) counts_[c.configuration * j + c.state] += c.count;
      return;
    }
    std::sort(cells.begin(), cells.end(), [](const cell& a, const cell& b) {
      return a.configuration < b.configuration || (a.configuration == b.configuration && a.state < b.state);
    });
    // The configurations of `cells` as a sparse table of their own, then merged into this one.
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      distinct += i == 0 || cells[i].configuration != cells[i - 1].configuration;
    }
    check_stored(distinct);
    std::vector<std::size_t> stored;
    std::vector<count_type> counts;
    stored.reserve(distinct);
    counts.reserve(distinct * j);
    for (const auto& c : cells) {
      if (stored.empty() || stored.back() != c.configuration) {
        stored.push_back(c.configuration);
        counts.resize(counts.size() + j, 0);
      }
      counts[counts.size() - j + c.state] += c.count;
    }
    merge(stored, counts);
  }

  /// The same counts under other variables with the same numbers of states (the structure's
  /// own, say, which may carry intervals and tags). Throws model_error otherwise.
  [[nodiscard]] basic_count_table with_variables(variable child, std::vector<variable> parents) const {
    bool same_shape = child.cardinality() == child_.cardinality() && parents.size() == parents_.size();
    for (std::size_t k = 0; same_shape && k < parents.size(); ++k) {
      same_shape = parents[k].cardinality() == parents_[k].cardinality();
    }
    if (!same_shape) {
      throw model_error("the counts of '" + child_.name() + "' cannot be given the variables of '" + child.name() +
                        "' and its parents: the numbers of states differ");
    }
    basic_count_table result(std::move(child), std::move(parents));
    result.counts_ = counts_;
    result.stored_ = stored_;
    return result;
  }

  /// Adds the counts of another table of the same family.
  basic_count_table& operator+=(const basic_count_table& other) {
    if (other.child_ != child_ || other.parents_ != parents_) {
      throw model_error("cannot add the counts of '" + other.child_.name() + "' to those of '" + child_.name() +
                        "': the families differ");
    }
    if (sparse_) {
      merge(other.stored_, other.counts_);
    } else {
      for (std::size_t i = 0; i < counts_.size(); ++i) counts_[i] += other.counts_[i];
    }
    return *this;
  }

  friend bool operator==(const basic_count_table&, const basic_count_table&) = default;

 private:
  [[noreturn]] void throw_sparse() const {
    throw table_too_large("the counts of '" + child_.name() + "' are kept sparse (" + std::to_string(stored_.size()) +
                          " of " + std::to_string(configurations()) +
                          " parent configurations seen), since a dense table would have more than pgm's limit of " +
                          std::to_string(max_table_cells) +
                          " cells (docs/limits.md), and this step needs every count of it");
  }

  /// Throws table_too_large when `configurations` stored columns would exceed max_table_cells:
  /// a sparse table bounds what it holds as a dense one does (a child with thousands of states
  /// is a continuous column read as labels, whose every row is a configuration of its own).
  void check_stored(std::size_t configurations) const {
    static_cast<void>(checked_table_cells(child_.name(), child_cardinality(), configurations));
  }

  /// Adds a sparse table's stored configurations and counts (ascending) into this sparse one.
  void merge(const std::vector<std::size_t>& stored, const std::vector<count_type>& counts) {
    const std::size_t j = child_cardinality();
    std::vector<std::size_t> merged;
    std::set_union(stored_.begin(), stored_.end(), stored.begin(), stored.end(), std::back_inserter(merged));
    check_stored(merged.size());
    std::vector<count_type> merged_counts(merged.size() * j, 0);
    std::size_t a = 0, b = 0;
    for (std::size_t i = 0; i < merged.size(); ++i) {
      auto* into = merged_counts.data() + i * j;
      if (a < stored_.size() && stored_[a] == merged[i]) {
        for (std::size_t x = 0; x < j; ++x) into[x] += counts_[a * j + x];
        ++a;
      }
      if (b < stored.size() && stored[b] == merged[i]) {
        for (std::size_t x = 0; x < j; ++x) into[x] += counts[b * j + x];
        ++b;
      }
    }
    stored_ = std::move(merged);
    counts_ = std::move(merged_counts);
  }

  variable child_;
  std::vector<variable> parents_;
  mixed_radix radix_;
  std::vector<count_type> counts_;   // dense: every cell; sparse: the stored columns
  std::vector<std::size_t> stored_;  // sparse: the stored configurations, ascending
  std::vector<count_type> zeros_;    // sparse: the column of a configuration not stored
  bool sparse_ = false;
};

/// Rows counted.
using count_table = basic_count_table<std::uint64_t>;
/// Expected counts: sums of posterior probabilities over rows with missing values.
using expected_count_table = basic_count_table<double>;

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
/// The largest chunk of rows a counting thread takes at a time; smaller chunks balance better.
inline constexpr std::size_t count_chunk_rows = std::size_t{1} << 16;

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

/// index[i] = the flat cell of row `first + i` for i < n (n at most count_block_rows, so that
/// `index` stays in the first-level cache over all the passes). `columns[0]` is the child
/// (stride 1), the others are parents with flat strides `strides[k]`.
PGM_DECL void block_cells(std::span<const code_vector* const> columns, std::span<const std::uint32_t> strides,
                          std::size_t first, std::size_t n, std::uint32_t* index);

/// cells[r - begin] = the flat cell of row r, for the rows [begin, end).
PGM_DECL void row_cells(std::span<const code_vector* const> columns, std::span<const std::uint32_t> strides,
                        std::size_t begin, std::size_t end, std::uint32_t* cells);

/// Adds the counts of rows [begin, end) into `counts`.
PGM_DECL void count_rows(std::span<const code_vector* const> columns, std::span<const std::uint32_t> strides,
                         std::size_t begin, std::size_t end, std::uint64_t* counts);

/// Adds the counts of rows [begin, end) into `counts`, leaving out every row where a column
/// holds its missing code: the slower loop for columns with missing values.
PGM_DECL void count_present_rows(std::span<const code_vector* const> columns, std::span<const std::uint32_t> strides,
                                 std::size_t begin, std::size_t end, std::uint64_t* counts);

/// Adds the counts of rows [begin, end) into `counts` on up to `threads` threads (0: every one),
/// each with at least `min_rows_per_thread` rows: every thread counts its chunks into a private
/// table and the tables are summed, which gives the same counts for any split. With
/// `skip_missing`, rows where a column holds its missing code are left out.
PGM_DECL void count_rows_parallel(std::span<const code_vector* const> columns, std::span<const std::uint32_t> strides,
                                  std::size_t begin, std::size_t end, std::span<std::uint64_t> counts, unsigned threads,
                                  std::size_t min_rows_per_thread, bool skip_missing = false);

/// The kernel's view of the family in `table`: the child's codes (stride 1), then each parent's
/// codes with its flat stride in the table. Throws model_error if the table has 2^32 cells or
/// more, data_error if a parent has another number of rows than the child.
struct family_columns {
  std::vector<const code_vector*> columns;
  std::vector<std::uint32_t> strides;
};

[[nodiscard]] PGM_DECL family_columns columns_of(const count_table& table, const discrete_column& child,
                                                 std::span<const discrete_column* const> parents);

/// Adds the counts of rows [begin, end) into a sparse `table`, leaving out rows where a column
/// is missing: each row's configuration in 64 bits, then the cells sorted and merged.
PGM_DECL void count_rows_sparse(const discrete_column& child, std::span<const discrete_column* const> parents,
                                std::size_t begin, std::size_t end, count_table& table);

}  // namespace detail

/// Counts the family (child | parents) over rows `rows` of the given columns; a row where the
/// child or a parent is missing is left out (available-case counting). A family too large for
/// a dense table is counted sparse (count_table).
[[nodiscard]] PGM_DECL count_table count_family(const discrete_column& child,
                                                std::span<const discrete_column* const> parents,
                                                const count_options& options = {}, row_range rows = {});

/// Counts the family (child | parents) over rows `rows` of a data set, by column names.
/// Throws data_error for a missing or continuous column.
[[nodiscard]] PGM_DECL count_table count_family(const dataset& data, std::string_view child,
                                                std::span<const std::string> parents, const count_options& options = {},
                                                row_range rows = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/data/impl/sufficient_statistics.ipp"
#endif
