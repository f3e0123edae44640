// Counting families straight from CSV (count_csv): windows of the input, chunks of a window on
// several threads, provisional per-column ids, tables summed and mapped to the final states.

#include "pgm/io/csv_counts.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "data/csv_input.hpp"
#include "pgm/detail/parallel_for.hpp"

namespace pgm {
namespace detail {

constexpr std::size_t count_chunk_bytes = std::size_t{512} << 10;
constexpr std::size_t count_window_bytes = std::size_t{16} << 20;
// Rows parsed before their ids are counted: the counting kernel then runs over a block of
// codes per column, as it does over a data set.
constexpr std::size_t block_rows = 4 * detail::count_block_rows;
// Counting stops laying out a family's cells past pgm's limit of a table (pgm/core/limits.hpp);
// the tables are then refused by count_table with the limit's message.
constexpr std::uint64_t max_cells = max_table_cells;

enum class count_mode { labels, known, binned };

struct counted_column {
  std::string name;
  std::size_t position = 0;  // field index in a record
  count_mode mode = count_mode::labels;
  variable var{"?", {"?"}};  // the known or interval variable
};

/// A family's counts over provisional ids: child first, then the parents, laid out like a
/// count_table (child fastest, last parent next) with the cardinalities in `cards`. Past pgm's
/// limit of a table the family is kept sparse instead, as the rows it counted: each distinct
/// row's ids (the members one after another) with its count, for a sparse count_table.
struct family_tally {
  std::vector<std::size_t> members;  // counted column indices, child first
  std::vector<std::uint32_t> cards;
  std::vector<std::uint32_t> strides;
  std::vector<std::uint64_t> counts;
  bool sparse = false;              // counted as rows: more cells than max_cells
  std::vector<std::uint32_t> rows;  // sparse: the ids of each row, members.size() at a time
  std::vector<std::uint64_t> row_counts;
  std::size_t compacted = 0;  // sparse: rows when equal rows were last summed
};

}  // namespace detail

namespace {

using detail::block_rows;
using detail::count_mode;
using detail::counted_column;
using detail::family_tally;
using detail::max_cells;

[[nodiscard]] std::vector<std::uint32_t> strides_of(const std::vector<std::uint32_t>& cards) {
  std::vector<std::uint32_t> strides(cards.size(), 1);
  if (cards.empty()) return strides;
  std::uint32_t stride = cards[0];
  for (std::size_t m = cards.size(); m-- > 1;) {
    strides[m] = stride;
    stride *= cards[m];
  }
  return strides;
}

/// Sums the equal rows of a sparse family, so that its memory follows the distinct rows.
void compact(family_tally& family) {
  const std::size_t width = family.members.size();
  const std::size_t n = family.row_counts.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto row = [&](std::size_t i) { return family.rows.begin() + static_cast<std::ptrdiff_t>(i * width); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(row(a), row(a) + static_cast<std::ptrdiff_t>(width), row(b),
                                        row(b) + static_cast<std::ptrdiff_t>(width));
  });
  std::vector<std::uint32_t> rows;
  std::vector<std::uint64_t> counts;
  for (const auto i : order) {
    if (!counts.empty() && std::equal(row(i), row(i) + static_cast<std::ptrdiff_t>(width), rows.end() - width)) {
      counts.back() += family.row_counts[i];
      continue;
    }
    rows.insert(rows.end(), row(i), row(i) + static_cast<std::ptrdiff_t>(width));
    counts.push_back(family.row_counts[i]);
  }
  family.rows = std::move(rows);
  family.row_counts = std::move(counts);
  family.compacted = family.row_counts.size();
}

/// Adds a row of ids to a sparse family, summing equal rows whenever their number doubled.
template <class Ids>
void add_row(family_tally& family, const Ids& ids, std::uint64_t count) {
  family.rows.insert(family.rows.end(), ids.begin(), ids.end());
  family.row_counts.push_back(count);
  if (family.row_counts.size() > 2 * family.compacted + 4096) compact(family);
}

/// Adds the cells of dense `from` to sparse `to` as rows, each member's id mapped by `id_of`
/// (per column; empty or no map at all: the id stays).
void add_cells_as_rows(const family_tally& from, const std::vector<std::vector<std::uint32_t>>* id_of,
                       family_tally& to) {
  std::vector<std::uint32_t> ids(from.members.size());
  for (std::size_t cell = 0; cell < from.counts.size(); ++cell) {
    if (from.counts[cell] == 0) continue;
    for (std::size_t m = 0; m < from.members.size(); ++m) {
      const auto digit = static_cast<std::uint32_t>(cell / from.strides[m] % from.cards[m]);
      ids[m] = id_of == nullptr || (*id_of)[from.members[m]].empty() ? digit : (*id_of)[from.members[m]][digit];
    }
    add_row(to, ids, from.counts[cell]);
  }
}

/// Adds the counts of `from`, dense or sparse, to sparse `to` as rows, ids mapped as by
/// add_cells_as_rows.
void add_as_rows(const family_tally& from, const std::vector<std::vector<std::uint32_t>>* id_of, family_tally& to) {
  if (!from.sparse) {
    add_cells_as_rows(from, id_of, to);
    return;
  }
  std::vector<std::uint32_t> ids(from.members.size());
  for (std::size_t r = 0; r < from.row_counts.size(); ++r) {
    for (std::size_t m = 0; m < ids.size(); ++m) {
      const auto id = from.rows[r * ids.size() + m];
      ids[m] = id_of == nullptr || (*id_of)[from.members[m]].empty() ? id : (*id_of)[from.members[m]][id];
    }
    add_row(to, ids, from.row_counts[r]);
  }
}

/// Makes a dense family sparse, its counts turned into rows.
void make_sparse(family_tally& family) {
  if (family.sparse) return;
  family_tally rows;
  rows.members = family.members;
  rows.sparse = true;
  add_cells_as_rows(family, nullptr, rows);
  family.counts = {};
  family.sparse = true;
  family.rows = std::move(rows.rows);
  family.row_counts = std::move(rows.row_counts);
  family.compacted = rows.compacted;
}

/// Lays `family` out for `cards` (each at least the old one), keeping its counts; past
/// max_cells it becomes sparse.
void relayout(family_tally& family, const std::vector<std::uint32_t>& cards) {
  if (family.sparse || cards == family.cards) return;
  std::uint64_t cells = 1;
  for (auto card : cards) {
    cells *= card;
    if (cells > max_cells) {
      make_sparse(family);
      return;
    }
  }
  const auto strides = strides_of(cards);
  std::vector<std::uint64_t> counts(cells, 0);
  for (std::size_t cell = 0; cell < family.counts.size(); ++cell) {
    if (family.counts[cell] == 0) continue;
    std::size_t moved = 0;
    for (std::size_t m = 0; m < cards.size(); ++m) {
      moved += cell / family.strides[m] % family.cards[m] * strides[m];
    }
    counts[moved] += family.counts[cell];
  }
  family.cards = cards;
  family.strides = strides;
  family.counts = std::move(counts);
}

}  // namespace

struct csv_counter::impl {
  std::string source;
  char delimiter = ',';
  std::size_t width = 0;
  std::vector<counted_column> columns;  // in file order
  std::vector<std::vector<std::size_t>> families;
  detail::missing_rule missing;
  std::vector<std::size_t> positions;  // of the columns read, for the policy drop
  unsigned threads = 0;
  std::size_t chunk_bytes = detail::count_chunk_bytes;
  std::size_t window_bytes = detail::count_window_bytes;
};

struct csv_partial_counts::impl {
  const csv_counter::impl* plan = nullptr;  // the counter these counts belong to
  std::size_t rows = 0;
  std::size_t dropped = 0;
  std::size_t lines = 0;
  std::vector<detail::label_dictionary> labels;  // per column: the labels (known: the states)
  std::vector<std::uint64_t> outside;            // per binned column
  std::vector<family_tally> families;
};

namespace {

using partial_impl = csv_partial_counts::impl;
using counter_impl = csv_counter::impl;

[[nodiscard]] partial_impl empty_partial(const counter_impl& plan) {
  partial_impl partial;
  partial.plan = &plan;
  partial.labels.resize(plan.columns.size());
  partial.outside.assign(plan.columns.size(), 0);
  for (std::size_t c = 0; c < plan.columns.size(); ++c) {
    if (plan.columns[c].mode != count_mode::known) continue;
    for (const auto& state : plan.columns[c].var.states()) partial.labels[c].add(state, {});
  }
  for (const auto& members : plan.families) {
    family_tally family;
    family.members = members;
    family.cards.assign(members.size(), 0);
    family.strides.assign(members.size(), 1);
    partial.families.push_back(std::move(family));
  }
  return partial;
}

[[nodiscard]] std::uint32_t cardinality(const counter_impl& plan, const partial_impl& partial, std::size_t column) {
  return static_cast<std::uint32_t>(plan.columns[column].mode == count_mode::binned
                                        ? plan.columns[column].var.cardinality()
                                        : partial.labels[column].size());
}

void fit_layout(const counter_impl& plan, partial_impl& partial, family_tally& family) {
  std::vector<std::uint32_t> cards;
  for (auto column : family.members) cards.push_back(cardinality(plan, partial, column));
  relayout(family, cards);
}

/// A thread's state: its counts over its own ids, and the block of rows not counted yet.
struct count_worker {
  explicit count_worker(const counter_impl& plan) : partial(empty_partial(plan)) {
    block.assign(plan.columns.size(), std::vector<std::uint32_t>{});
    ids.assign(plan.columns.size(), nullptr);
    block_missing.assign(plan.columns.size(), 0);
  }

  /// Doubles the block, up to block_rows. It starts empty so that a worker over a few short
  /// records (tiny windows, many columns) does not pay for a full block per window.
  void grow() {
    capacity = std::min(block_rows, std::max<std::size_t>(64, 2 * capacity));
    for (std::size_t c = 0; c < block.size(); ++c) {
      auto& column = std::get<std::vector<std::uint32_t>>(block[c]);
      column.resize(capacity);
      ids[c] = column.data();
    }
  }

  partial_impl partial;
  std::vector<code_vector> block;           // per column: the provisional ids of the rows not counted yet
  std::vector<std::uint32_t*> ids;          // per column: where `block` holds them (a move keeps the buffers)
  std::vector<std::uint8_t> block_missing;  // per column: the block holds a missing id
  std::size_t filled = 0;
  std::size_t capacity = 0;  // rows `block` has room for
  std::vector<detail::csv_field> fields;
};

void count_block(const counter_impl& plan, count_worker& worker) {
  if (worker.filled == 0) return;
  std::vector<const code_vector*> columns;
  for (auto& family : worker.partial.families) {
    fit_layout(plan, worker.partial, family);
    if (family.sparse) {
      std::vector<std::uint32_t> ids(family.members.size());
      for (std::size_t r = 0; r < worker.filled; ++r) {
        bool present = true;
        for (std::size_t m = 0; m < ids.size(); ++m) {
          ids[m] = worker.ids[family.members[m]][r];
          present = present && ids[m] != detail::missing_id;
        }
        if (present) add_row(family, ids, 1);
      }
      continue;
    }
    columns.clear();
    bool missing = false;
    for (auto column : family.members) {
      columns.push_back(&worker.block[column]);
      missing = missing || worker.block_missing[column];
    }
    if (missing) {  // missing_id is the missing code of the uint32 ids: those rows are left out
      detail::count_present_rows(columns, family.strides, 0, worker.filled, family.counts.data());
    } else {
      detail::count_rows(columns, family.strides, 0, worker.filled, family.counts.data());
    }
  }
  std::fill(worker.block_missing.begin(), worker.block_missing.end(), std::uint8_t{0});
  worker.filled = 0;
}

/// The id of a label seen before or of a model's state (the common case, inlined into the
/// record loop), or none. A state is found before the missing tokens are looked at: a model
/// that declares a state "NA" has it read as that state.
[[nodiscard]] inline std::uint32_t known_label_id(const counted_column& column, const partial_impl& partial,
                                                  std::size_t c, const detail::csv_field& field) {
  return column.mode != count_mode::binned ? partial.labels[c].find(field.text) : detail::label_dictionary::none;
}

std::uint32_t provisional_id(const counted_column& column, partial_impl& partial, std::size_t c,
                             const detail::csv_field& field, std::size_t chunk, const detail::missing_rule& missing) {
  if (detail::field_missing(field, column.name, missing)) return detail::missing_id;
  switch (column.mode) {
    case count_mode::labels: {
      auto& labels = partial.labels[c];
      const auto id = labels.find(field.text);
      return id != detail::label_dictionary::none ? id : labels.add(field.text, {field.line, field.column, chunk});
    }
    case count_mode::known: {
      auto id = partial.labels[c].find(field.text);
      if (id == detail::label_dictionary::none) id = detail::numeric_state(column.var, field.text);
      if (id == detail::label_dictionary::none) {
        detail::fail_field(field, column.name,
                           "'" + std::string(field.text) + "' is not a state of '" + column.name +
                               "' (states: " + text::list_for_message(column.var.states()) + ")");
      }
      return id;
    }
    case count_mode::binned: {
      const double value = detail::continuous_value(field, column.name);
      const auto& edges = column.var.edges();
      partial.outside[c] += value < edges.front() || value > edges.back();
      return static_cast<std::uint32_t>(column.var.bin(value).value());
    }
  }
  return 0;
}

/// Counts the records of `text` (chunk `chunk` of a window, whole records); returns the line
/// ends it consumed.
std::size_t count_piece(const counter_impl& plan, count_worker& worker, std::string_view text, std::size_t chunk) {
  try {
    const bool drop = plan.missing.policy == missing_policy::drop;
    return detail::for_each_record(
        text, plan.delimiter, worker.fields, [&](const std::vector<detail::csv_field>& fields) {
          if (fields.size() != plan.width) detail::fail_width(fields, plan.width);
          // Dropped rows are checked first, so that their labels add no states.
          if (drop && std::any_of(plan.columns.begin(), plan.columns.end(), [&](const counted_column& column) {
                const auto field = fields[column.position].text;
                return plan.missing.is_missing(field) &&
                       !detail::declared_state(column.mode == count_mode::known ? &column.var : nullptr, field);
              })) {
            ++worker.partial.dropped;
            return;
          }
          if (worker.filled == worker.capacity) {
            if (worker.capacity < block_rows) {
              worker.grow();
            } else {
              count_block(plan, worker);
            }
          }
          for (std::size_t c = 0; c < plan.columns.size(); ++c) {
            const auto& column = plan.columns[c];
            const auto& field = fields[column.position];
            auto id = known_label_id(column, worker.partial, c, field);
            if (id == detail::label_dictionary::none) {
              id = provisional_id(column, worker.partial, c, field, chunk, plan.missing);
              if (id == detail::missing_id) worker.block_missing[c] = 1;
            }
            worker.ids[c][worker.filled] = id;
          }
          ++worker.partial.rows;
          ++worker.filled;
        });
  } catch (const detail::csv_failure& failure) {
    throw detail::chunk_failure{chunk, failure};
  }
}

/// Adds `label` first seen at `first` to `labels`: a new label, or an earlier first place for
/// one already there. Returns its id.
std::uint32_t merge_label(detail::label_dictionary& labels, std::string_view label, const detail::csv_place& first) {
  const auto id = labels.find(label);
  if (id == detail::label_dictionary::none) return labels.add(label, first);
  auto& known = labels.entries()[id].first;
  if (std::pair(first.line, first.column) < std::pair(known.line, known.column)) known = first;
  return id;
}

/// Adds the cells of `from` to `to`, laid out by `strides` (one per member) after each
/// member's id is mapped by `id_of` (per column; empty: the id stays).
template <class Stride>
void add_mapped(const family_tally& from, const std::vector<std::vector<std::uint32_t>>& id_of,
                const std::vector<Stride>& strides, std::uint64_t* to) {
  for (std::size_t cell = 0; cell < from.counts.size(); ++cell) {
    if (from.counts[cell] == 0) continue;
    std::size_t mapped = 0;
    for (std::size_t m = 0; m < from.members.size(); ++m) {
      const auto digit = cell / from.strides[m] % from.cards[m];
      const auto& map = id_of[from.members[m]];
      mapped += (map.empty() ? digit : map[digit]) * strides[m];
    }
    to[mapped] += from.counts[cell];
  }
}

/// Adds `other` into `into`. Label places in `other` are relative to the first lines of their
/// chunks, `first_lines` (none: they are absolute already).
void merge(const counter_impl& plan, partial_impl& into, partial_impl& other,
           const std::vector<std::size_t>* first_lines) {
  into.rows += other.rows;
  into.dropped += other.dropped;
  into.lines += other.lines;
  std::vector<std::vector<std::uint32_t>> id_of(plan.columns.size());
  for (std::size_t c = 0; c < plan.columns.size(); ++c) {
    into.outside[c] += other.outside[c];
    if (plan.columns[c].mode != count_mode::labels) continue;
    auto& labels = into.labels[c];
    for (auto& entry : other.labels[c].entries()) {
      auto first = entry.first;
      if (first_lines) first.line += (*first_lines)[first.chunk];
      id_of[c].push_back(merge_label(labels, entry.text, first));
    }
  }
  for (std::size_t f = 0; f < into.families.size(); ++f) {
    auto& family = into.families[f];
    const auto& theirs = other.families[f];
    fit_layout(plan, into, family);
    if (theirs.sparse) make_sparse(family);
    if (!family.sparse) {
      add_mapped(theirs, id_of, family.strides, family.counts.data());
    } else {
      add_as_rows(theirs, &id_of, family);
    }
  }
}

/// Counts the whole records at the start of `text` (up to about `limit` bytes; all of them
/// when `final`) in chunks on several threads and adds the counts to `into`; returns the bytes
/// consumed, 0 when `text` does not hold a whole record yet.
std::size_t count_window(const counter_impl& plan, partial_impl& into, std::string_view text, std::size_t limit,
                         bool final, std::size_t first_line) {
  const auto bounds = detail::record_chunks(text, plan.delimiter, plan.chunk_bytes, limit, final);
  const std::size_t chunks = bounds.size() - 1;
  std::vector<std::size_t> lines(chunks, 0);
  std::vector<count_worker> workers;
  detail::rethrow_located(plan.source, first_line, lines, [&] {
    workers = detail::parallel_for(
        chunks, {.threads = plan.threads}, [&] { return count_worker(plan); },
        [&](count_worker& worker, detail::item_range items) {
          for (auto k = items.begin; k < items.end; ++k) {
            lines[k] = count_piece(plan, worker, text.substr(bounds[k], bounds[k + 1] - bounds[k]), k);
          }
        });
  });
  const auto first_lines = detail::chunk_first_lines(first_line, lines);
  for (auto& worker : workers) {
    count_block(plan, worker);
    merge(plan, into, worker.partial, &first_lines);
  }
  for (auto l : lines) into.lines += l;
  return bounds.back();
}

}  // namespace

// ---- csv_partial_counts --------------------------------------------------------------

csv_partial_counts::csv_partial_counts() : impl_(std::make_unique<impl>()) {}
csv_partial_counts::~csv_partial_counts() = default;
csv_partial_counts::csv_partial_counts(csv_partial_counts&&) noexcept = default;
csv_partial_counts& csv_partial_counts::operator=(csv_partial_counts&&) noexcept = default;
std::size_t csv_partial_counts::rows() const noexcept { return impl_->rows; }
std::size_t csv_partial_counts::dropped() const noexcept { return impl_->dropped; }
std::size_t csv_partial_counts::lines() const noexcept { return impl_->lines; }

// ---- csv_counter ---------------------------------------------------------------------

csv_counter::csv_counter(std::string source, std::vector<std::string> header, const family_count_request& request,
                         char delimiter)
    : impl_(std::make_unique<impl>()) {
  auto& plan = *impl_;
  plan.source = std::move(source);
  plan.delimiter = delimiter;
  plan.width = header.size();
  plan.threads = request.threads;
  plan.missing = detail::missing_rule(request.missing);
  if (request.chunk_bytes) plan.chunk_bytes = request.chunk_bytes;
  if (request.window_bytes) plan.window_bytes = request.window_bytes;
  for (auto position : detail::column_positions(header, request.columns, plan.source)) {
    counted_column column;
    column.name = header[position];
    column.position = position;
    if (const auto it = request.intervals.find(column.name); it != request.intervals.end()) {
      if (!it->second.has_intervals()) {
        throw model_error("variable '" + column.name + "' has no interval edges to bin values by");
      }
      column.mode = count_mode::binned;
      column.var = it->second;
    } else if (const auto known = request.variables.find(column.name); known != request.variables.end()) {
      column.mode = count_mode::known;
      column.var = known->second;
    }
    plan.columns.push_back(std::move(column));
    plan.positions.push_back(position);
  }
  auto index_of = [&](const std::string& name) {
    for (std::size_t c = 0; c < plan.columns.size(); ++c) {
      if (plan.columns[c].name == name) return c;
    }
    throw data_error(plan.source + ": the column '" + name + "' of a family to count is not among the columns read");
  };
  for (const auto& family : request.families) {
    std::vector<std::size_t> members{index_of(family.child)};
    for (const auto& parent : family.parents) members.push_back(index_of(parent));
    plan.families.push_back(std::move(members));
  }
}

csv_counter::~csv_counter() = default;
csv_counter::csv_counter(csv_counter&&) noexcept = default;
csv_counter& csv_counter::operator=(csv_counter&&) noexcept = default;

csv_partial_counts csv_counter::count(std::string_view bytes, std::size_t first_line) const {
  csv_partial_counts result;
  auto& partial = detail::csv_access::of(result);
  partial = empty_partial(*impl_);
  count_window(*impl_, partial, bytes, bytes.size(), true, first_line);
  return result;
}

csv_partial_counts& csv_partial_counts::operator+=(csv_partial_counts&& other) {
  if (!other.impl_->plan) return *this;
  if (!impl_->plan) {
    std::swap(impl_, other.impl_);
    return *this;
  }
  if (impl_->plan != other.impl_->plan) throw std::invalid_argument("counts of different csv_counters cannot be added");
  merge(*impl_->plan, *impl_, *other.impl_, nullptr);
  return *this;
}

family_counts csv_counter::finish(const csv_partial_counts& counts) const {
  const auto& plan = *impl_;
  const auto& partial = detail::csv_access::of(counts);
  if (partial.rows == 0 && partial.dropped > 0) {
    throw data_error(plan.source + ": every one of the " + std::to_string(partial.dropped) +
                     " data rows has a missing value, so dropping them leaves none");
  }
  // A header alone is zero rows of data when every column's states are known (a model gives
  // them): the tables are then their priors. Without rows, states found in data are unknown.
  if (partial.rows == 0) {
    for (const auto& column : plan.columns) {
      if (column.mode == count_mode::labels) {
        throw data_error(plan.source + ": there are no data rows after the header, so the states of '" + column.name +
                         "' are unknown (a model that lists them, e.g. fit --model, allows a header alone)");
      }
    }
  }
  family_counts result;
  result.rows = partial.rows;
  result.dropped = partial.dropped;
  // Each column's variable and the state of each provisional id.
  std::vector<std::vector<std::uint32_t>> state_of(plan.columns.size());
  for (std::size_t c = 0; c < plan.columns.size(); ++c) {
    const auto& column = plan.columns[c];
    if (column.mode != count_mode::labels) {
      result.variables.push_back(column.var);
      if (column.mode == count_mode::binned) result.outside.emplace(column.name, partial.outside[c]);
      continue;
    }
    const auto& entries = partial.labels[c].entries();
    // Labels in order of first appearance, as read_csv meets them.
    std::vector<std::uint32_t> order(entries.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](auto a, auto b) {
      return std::pair(entries[a].first.line, entries[a].first.column) <
             std::pair(entries[b].first.line, entries[b].first.column);
    });
    std::vector<std::string_view> labels;
    for (auto id : order) labels.push_back(entries[id].text);
    auto states = detail::order_states(labels);
    if (states.non_finite) {
      const auto& entry = entries[order[*states.non_finite]];
      throw parse_error(plan.source, entry.first.line, entry.first.column,
                        "column '" + column.name + "': " + detail::non_finite_message(entry.text));
    }
    state_of[c].resize(entries.size());
    for (std::size_t i = 0; i < order.size(); ++i) state_of[c][order[i]] = states.state_of[i];
    result.variables.emplace_back(column.name, std::move(states.states));
  }
  for (std::size_t f = 0; f < plan.families.size(); ++f) {
    const auto& members = plan.families[f];
    std::vector<variable> parents;
    for (std::size_t m = 1; m < members.size(); ++m) parents.push_back(result.variables[members[m]]);
    count_table table(result.variables[members[0]], std::move(parents));  // sparse past max_table_cells
    const auto& family = partial.families[f];
    PGM_ASSERT(family.sparse == table.is_sparse(), "a family is counted sparse where its table is");
    if (family.sparse) {
      std::vector<count_table::cell> cells;
      cells.reserve(family.row_counts.size());
      for (std::size_t r = 0; r < family.row_counts.size(); ++r) {
        const auto* ids = family.rows.data() + r * members.size();
        auto state = [&](std::size_t m) -> std::size_t {
          const auto& map = state_of[members[m]];
          return map.empty() ? ids[m] : map[ids[m]];
        };
        count_table::cell cell{.configuration = 0, .state = state(0), .count = family.row_counts[r]};
        for (std::size_t m = 1; m < members.size(); ++m)
          cell.configuration += state(m) * table.parent_radix().stride(m - 1);
        cells.push_back(cell);
      }
      table.add(std::move(cells));
      result.families.push_back(std::move(table));
      continue;
    }
    // Final strides: the child's state, then each parent's state times its stride in the table.
    std::vector<std::size_t> strides{1};
    for (std::size_t m = 1; m < members.size(); ++m) {
      strides.push_back(table.child_cardinality() * table.parent_radix().stride(m - 1));
    }
    add_mapped(family, state_of, strides, table.counts().data());
    result.families.push_back(std::move(table));
  }
  return result;
}

// ---- count_csv -----------------------------------------------------------------------

family_counts count_csv(csv_reader& input, const family_count_request& request) {
  auto& reader = detail::csv_access::of(input);
  const csv_counter counter(reader.source, reader.header, request, reader.delimiter);
  const auto& plan = detail::csv_access::of(counter);
  csv_partial_counts total;
  auto& sum = detail::csv_access::of(total);
  sum = empty_partial(plan);
  auto& bytes = *reader.bytes;
  std::size_t line = reader.first_line;
  while (true) {
    bytes.fetch(plan.window_bytes);
    const auto text = bytes.available();
    if (text.empty()) break;
    const std::size_t lines_before = sum.lines;
    const auto consumed = count_window(plan, sum, text, plan.window_bytes, bytes.at_end(), line);
    line += sum.lines - lines_before;
    if (consumed == 0) {
      if (bytes.at_end()) break;  // only blank space was left
      if (text.size() > csv_max_record_bytes)
        throw parse_error(reader.source, line, 1, detail::record_too_long_message());
      bytes.fetch(text.size() * 2);  // a record longer than what is here
      continue;
    }
    bytes.consume(consumed);
  }
  return counter.finish(total);
}

// ---- over processes -------------------------------------------------------------------

namespace {

// Over processes the provisional ids of a label differ by process, so the processes first
// agree on one id per label (process 0 merges their labels in file order and broadcasts the
// result); then each lays its counts out over those ids and one reduction sums them.

/// This process's labels and their first places, per column of labels, for process 0.
[[nodiscard]] std::string labels_to_bytes(const counter_impl& plan, const partial_impl& partial) {
  detail::byte_writer out;
  for (std::size_t c = 0; c < plan.columns.size(); ++c) {
    if (plan.columns[c].mode != count_mode::labels) continue;
    out.put<std::uint64_t>(partial.labels[c].size());
    for (const auto& entry : partial.labels[c].entries()) {
      out.put(entry.text);
      out.put<std::uint64_t>(entry.first.line);
      out.put<std::uint64_t>(entry.first.column);
    }
  }
  return out.take();
}

/// Adds the labels of one process (labels_to_bytes) to `labels`, as merge adds them.
void merge_labels(const counter_impl& plan, std::vector<detail::label_dictionary>& labels, std::string_view bytes) {
  detail::byte_reader in(bytes);
  for (std::size_t c = 0; c < plan.columns.size(); ++c) {
    if (plan.columns[c].mode != count_mode::labels) continue;
    for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
      const auto text = in.get_string();
      detail::csv_place first;
      first.line = in.get<std::uint64_t>();
      first.column = in.get<std::uint64_t>();
      static_cast<void>(merge_label(labels[c], text, first));
    }
  }
  if (!in.at_end()) throw std::logic_error("labels from another process do not fit their counter");
}

/// The labels of every column of labels in the order of their ids, for every process.
[[nodiscard]] std::string ids_to_bytes(const counter_impl& plan, const std::vector<detail::label_dictionary>& labels) {
  detail::byte_writer out;
  for (std::size_t c = 0; c < plan.columns.size(); ++c) {
    if (plan.columns[c].mode != count_mode::labels) continue;
    out.put<std::uint64_t>(labels[c].size());
    for (const auto& entry : labels[c].entries()) out.put(entry.text);
  }
  return out.take();
}

[[nodiscard]] std::vector<detail::label_dictionary> ids_from_bytes(const counter_impl& plan, std::string_view bytes) {
  std::vector<detail::label_dictionary> labels(plan.columns.size());
  detail::byte_reader in(bytes);
  for (std::size_t c = 0; c < plan.columns.size(); ++c) {
    if (plan.columns[c].mode != count_mode::labels) continue;
    for (auto n = in.get<std::uint64_t>(); n > 0; --n) labels[c].add(in.get_string(), {});
  }
  if (!in.at_end()) throw std::logic_error("label ids from process 0 do not fit their counter");
  return labels;
}

/// The numbers every process adds up: rows, dropped rows, line ends, each column's values
/// outside its intervals, then the cells of every family (laid out for the labels of all
/// processes) one after another.
struct summed_layout {
  static constexpr std::size_t rows = 0;
  static constexpr std::size_t dropped = 1;
  static constexpr std::size_t lines = 2;
  static constexpr std::size_t outside = 3;  // then one per column
  std::vector<family_tally> families;        // their cards and strides, no counts
  std::vector<std::size_t> offsets;          // of each family's cells
  std::size_t size = 0;
};

[[nodiscard]] summed_layout layout_for(const counter_impl& plan, const std::vector<detail::label_dictionary>& labels) {
  summed_layout layout;
  layout.size = summed_layout::outside + plan.columns.size();
  for (const auto& members : plan.families) {
    family_tally family;
    family.members = members;
    std::uint64_t cells = 1;
    for (auto column : members) {
      const auto card = static_cast<std::uint32_t>(plan.columns[column].mode == count_mode::labels
                                                       ? labels[column].size()
                                                       : plan.columns[column].var.cardinality());
      family.cards.push_back(card);
      cells *= card;
      family.sparse = family.sparse || cells > max_cells;
      if (family.sparse) cells = max_cells + 1;  // no overflow however many members follow
    }
    family.strides = strides_of(family.cards);
    layout.offsets.push_back(layout.size);
    if (!family.sparse) layout.size += cells;
    layout.families.push_back(std::move(family));
  }
  return layout;
}

/// For each column of labels, the id in `labels` (process 0's) of each of this process's ids.
[[nodiscard]] std::vector<std::vector<std::uint32_t>> ids_in(const counter_impl& plan, const partial_impl& partial,
                                                             const std::vector<detail::label_dictionary>& labels) {
  std::vector<std::vector<std::uint32_t>> id_of(plan.columns.size());
  for (std::size_t c = 0; c < plan.columns.size(); ++c) {
    if (plan.columns[c].mode != count_mode::labels) continue;
    for (const auto& entry : partial.labels[c].entries()) {
      const auto id = labels[c].find(entry.text);
      if (id == detail::label_dictionary::none) throw std::logic_error("a label is missing from process 0's ids");
      id_of[c].push_back(id);
    }
  }
  return id_of;
}

/// This process's counts laid out in `layout`, its labels mapped to the ids of `labels`.
[[nodiscard]] std::vector<std::uint64_t> summands(const counter_impl& plan, const partial_impl& partial,
                                                  const std::vector<detail::label_dictionary>& labels,
                                                  const summed_layout& layout) {
  std::vector<std::uint64_t> values(layout.size, 0);
  values[summed_layout::rows] = partial.rows;
  values[summed_layout::dropped] = partial.dropped;
  values[summed_layout::lines] = partial.lines;
  std::copy(partial.outside.begin(), partial.outside.end(), values.begin() + summed_layout::outside);
  const auto id_of = ids_in(plan, partial, labels);
  for (std::size_t f = 0; f < layout.families.size(); ++f) {
    const auto& family = layout.families[f];
    // A process's cards are at most those of all processes: too large here is too large there.
    PGM_ASSERT(family.sparse || !partial.families[f].sparse, "a family too large on one process fits");
    if (family.sparse) continue;
    add_mapped(partial.families[f], id_of, family.strides, values.data() + layout.offsets[f]);
  }
  return values;
}

/// This process's rows of the families `layout` keeps sparse, over the ids of `labels`: a
/// sparse table is not summed but gathered on process 0.
[[nodiscard]] std::string sparse_rows_to_bytes(const counter_impl& plan, const partial_impl& partial,
                                               const std::vector<detail::label_dictionary>& labels,
                                               const summed_layout& layout) {
  const auto id_of = ids_in(plan, partial, labels);
  detail::byte_writer out;
  for (std::size_t f = 0; f < layout.families.size(); ++f) {
    if (!layout.families[f].sparse) continue;
    family_tally rows;
    rows.members = partial.families[f].members;
    rows.sparse = true;
    add_as_rows(partial.families[f], &id_of, rows);
    out.put<std::uint64_t>(rows.row_counts.size());
    out.put_all(std::span<const std::uint32_t>(rows.rows));
    out.put_all(std::span<const std::uint64_t>(rows.row_counts));
  }
  return out.take();
}

/// Adds one process's sparse rows (sparse_rows_to_bytes) to the sparse families of `partial`.
void add_sparse_rows(partial_impl& partial, std::string_view bytes) {
  detail::byte_reader in(bytes);
  for (auto& family : partial.families) {
    if (!family.sparse) continue;
    const auto n = in.get<std::uint64_t>();
    std::vector<std::uint32_t> rows(n * family.members.size());
    std::vector<std::uint64_t> counts(n);
    in.get_all(std::span<std::uint32_t>(rows));
    in.get_all(std::span<std::uint64_t>(counts));
    for (std::size_t r = 0; r < n; ++r) {
      add_row(family, std::span<const std::uint32_t>(rows).subspan(r * family.members.size(), family.members.size()),
              counts[r]);
    }
  }
  if (!in.at_end()) throw std::logic_error("sparse rows from another process do not fit their counter");
}

/// The partial counts of all processes, from their sum (on process 0).
[[nodiscard]] partial_impl from_sum(const counter_impl& plan, std::vector<detail::label_dictionary> labels,
                                    summed_layout layout, const std::vector<std::uint64_t>& values) {
  auto partial = empty_partial(plan);
  partial.rows = values[summed_layout::rows];
  partial.dropped = values[summed_layout::dropped];
  partial.lines = values[summed_layout::lines];
  for (std::size_t c = 0; c < plan.columns.size(); ++c) {
    partial.outside[c] = values[summed_layout::outside + c];
    if (plan.columns[c].mode == count_mode::labels) partial.labels[c] = std::move(labels[c]);
  }
  for (std::size_t f = 0; f < layout.families.size(); ++f) {
    auto& family = layout.families[f];
    if (!family.sparse) {
      std::uint64_t cells = 1;
      for (auto card : family.cards) cells *= card;
      const auto first = values.begin() + static_cast<std::ptrdiff_t>(layout.offsets[f]);
      family.counts.assign(first, first + static_cast<std::ptrdiff_t>(cells));
    }
    partial.families[f] = std::move(family);
  }
  return partial;
}

/// The start of the record that holds byte `at` of `text`, or the next one: `at` itself when
/// a line ends just before it.
[[nodiscard]] std::size_t record_start(std::string_view text, std::size_t at) {
  if (at == 0 || at >= text.size()) return std::min(at, text.size());
  const auto end = text.find('\n', at - 1);
  return end == std::string_view::npos ? text.size() : end + 1;
}

}  // namespace

family_counts count_csv(csv_reader& input, const family_count_request& request, process_group& group) {
  if (group.size() == 1) return count_csv(input, request);
  auto& reader = detail::csv_access::of(input);
  const csv_counter counter(reader.source, reader.header, request, reader.delimiter);
  const auto& plan = detail::csv_access::of(counter);
  auto& bytes = *reader.bytes;
  const std::size_t ranks = group.size();
  const std::size_t rank = group.rank();

  // This process's byte range, its line ends and whether it holds a quote, made known to all
  // by one sum: slot r holds rank r's line ends, the last slot the ranks that cannot split.
  bytes.fetch(0);
  const bool whole = bytes.at_end();
  const auto text = whole ? bytes.available() : std::string_view();
  const auto raw = detail::process_share{rank, ranks}.of(text.size());
  const std::string_view mine =
      text.substr(record_start(text, raw.begin), record_start(text, raw.end) - record_start(text, raw.begin));
  std::vector<std::uint64_t> facts(ranks + 1, 0);
  facts[rank] = static_cast<std::uint64_t>(std::count(mine.begin(), mine.end(), '\n'));
  facts[ranks] = !whole || mine.find('"') != std::string_view::npos ? 1 : 0;
  detail::sum_over_processes(group, facts);
  const bool split = facts[ranks] == 0;

  csv_partial_counts partial;
  std::string labels;
  std::exception_ptr failure;
  std::size_t failed_at = 0;
  try {
    if (split) {
      std::size_t first_line = reader.first_line;
      for (std::size_t r = 0; r < rank; ++r) first_line += facts[r];
      failed_at = raw.begin;
      partial = counter.count(mine, first_line);
      labels = labels_to_bytes(plan, detail::csv_access::of(partial));
    } else if (rank == 0) {
      return count_csv(input, request);
    }
  } catch (...) {
    failure = std::current_exception();
  }
  if (!split) {
    // Process 0 counted alone; its failure, if any, is met at the program's end.
    if (failure) std::rethrow_exception(failure);
    return {};
  }
  agree(group, failure, failed_at);

  // One id per label: process 0 merges the labels of all processes in file order.
  const auto every_label = group.gather(labels);
  std::vector<detail::label_dictionary> merged(plan.columns.size());
  std::string ids;
  run_agreed(group, [&] {
    if (rank != 0) return;
    for (const auto& theirs : every_label) merge_labels(plan, merged, theirs);
    ids = ids_to_bytes(plan, merged);
  });
  ids = group.broadcast(std::move(ids), 0);

  // The counts of all processes over those ids, summed by one reduction.
  summed_layout layout;
  std::vector<std::uint64_t> values;
  failure = nullptr;
  try {
    if (rank != 0) merged = ids_from_bytes(plan, ids);
    layout = layout_for(plan, merged);
    values = summands(plan, detail::csv_access::of(partial), merged, layout);
  } catch (...) {
    failure = std::current_exception();
  }
  detail::sum_over_processes(group, values, failure);
  // The families kept sparse (the same on every process, by the same layout) are gathered as
  // rows instead.
  std::vector<std::string> every_process_rows;
  if (std::any_of(layout.families.begin(), layout.families.end(), [](const family_tally& f) { return f.sparse; })) {
    std::string sparse_rows;
    run_agreed(group,
               [&] { sparse_rows = sparse_rows_to_bytes(plan, detail::csv_access::of(partial), merged, layout); });
    every_process_rows = group.gather(sparse_rows);
  }
  if (rank != 0) return {};
  csv_partial_counts total;
  auto& sum = detail::csv_access::of(total);
  sum = from_sum(plan, std::move(merged), std::move(layout), values);
  for (const auto& theirs : every_process_rows) add_sparse_rows(sum, theirs);
  return counter.finish(total);
}

}  // namespace pgm
