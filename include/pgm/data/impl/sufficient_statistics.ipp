#pragma once
// The definitions of pgm/data/sufficient_statistics.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/data/sufficient_statistics.hpp"

namespace pgm::detail {

PGM_DECL void block_cells(std::span<const code_vector* const> columns, std::span<const std::uint32_t> strides,
                          std::size_t first, std::size_t n, std::uint32_t* index) {
  std::visit([&](const auto& codes) { set_cells(codes.data() + first, index, n); }, *columns[0]);
  for (std::size_t k = 1; k < columns.size(); ++k) {
    std::visit([&](const auto& codes) { add_cells(codes.data() + first, strides[k], index, n); }, *columns[k]);
  }
}

PGM_DECL void row_cells(std::span<const code_vector* const> columns, std::span<const std::uint32_t> strides,
                        std::size_t begin, std::size_t end, std::uint32_t* cells) {
  for (std::size_t first = begin; first < end; first += count_block_rows) {
    block_cells(columns, strides, first, std::min(count_block_rows, end - first), cells + (first - begin));
  }
}

PGM_DECL void count_rows(std::span<const code_vector* const> columns, std::span<const std::uint32_t> strides,
                         std::size_t begin, std::size_t end, std::uint64_t* counts) {
  std::uint32_t index[count_block_rows];
  for (std::size_t first = begin; first < end; first += count_block_rows) {
    const std::size_t n = std::min(count_block_rows, end - first);
    block_cells(columns, strides, first, n, index);
    for (std::size_t i = 0; i < n; ++i) ++counts[index[i]];
  }
}

PGM_DECL void count_present_rows(std::span<const code_vector* const> columns, std::span<const std::uint32_t> strides,
                                 std::size_t begin, std::size_t end, std::uint64_t* counts) {
  std::uint32_t index[count_block_rows];
  std::uint8_t present[count_block_rows];
  for (std::size_t first = begin; first < end; first += count_block_rows) {
    const std::size_t n = std::min(count_block_rows, end - first);
    block_cells(columns, strides, first, n, index);  // a missing row's cell is never touched
    std::fill_n(present, n, std::uint8_t{1});
    for (const auto* column : columns) {
      std::visit(
          [&](const auto& codes) {
            using code_type = typename std::decay_t<decltype(codes)>::value_type;
            const auto* c = codes.data() + first;
            for (std::size_t i = 0; i < n; ++i) present[i] &= c[i] != missing_code<code_type>;
          },
          *column);
    }
    for (std::size_t i = 0; i < n; ++i) counts[present[i] ? index[i] : 0] += present[i];
  }
}

PGM_DECL void count_rows_parallel(std::span<const code_vector* const> columns, std::span<const std::uint32_t> strides,
                                  std::size_t begin, std::size_t end, std::span<std::uint64_t> counts, unsigned threads,
                                  std::size_t min_rows_per_thread, bool skip_missing) {
  const auto count = skip_missing ? count_present_rows : count_rows;
  const std::size_t rows = end > begin ? end - begin : 0;
  parallel_options options{.threads = threads, .min_items_per_thread = min_rows_per_thread};
  // About four chunks per thread, so that a thread slowed by others on the machine is helped out.
  const std::size_t per_thread = rows / std::max<std::size_t>(1, worker_count(rows, options));
  options.chunk = std::clamp<std::size_t>(per_thread / 4, count_block_rows, count_chunk_rows);
  if (worker_count(rows, options) <= 1) {
    count(columns, strides, begin, end, counts.data());
    return;
  }
  const auto partial = parallel_for(
      rows, options, [&] { return std::vector<std::uint64_t>(counts.size()); },
      [&](std::vector<std::uint64_t>& mine, item_range chunk) {
        count(columns, strides, begin + chunk.begin, begin + chunk.end, mine.data());
      });
  for (const auto& part : partial) {
    for (std::size_t i = 0; i < counts.size(); ++i) counts[i] += part[i];
  }
}

PGM_DECL family_columns columns_of(const count_table& table, const discrete_column& child,
                                   std::span<const discrete_column* const> parents) {
  if (table.counts().size() > std::numeric_limits<std::uint32_t>::max()) {
    throw model_error("the table of '" + child.name() + "' has " + std::to_string(table.counts().size()) +
                      " cells, more than pgm can count (2^32)");
  }
  family_columns family{{&child.codes()}, {1}};
  const auto j = child.var().cardinality();
  for (std::size_t k = 0; k < parents.size(); ++k) {
    if (parents[k]->size() != child.size()) {
      throw data_error("column '" + parents[k]->name() + "' has " + std::to_string(parents[k]->size()) + " rows, '" +
                       child.name() + "' " + std::to_string(child.size()));
    }
    family.columns.push_back(&parents[k]->codes());
    family.strides.push_back(static_cast<std::uint32_t>(j * table.parent_radix().stride(k)));
  }
  return family;
}

PGM_DECL void count_rows_sparse(const discrete_column& child, std::span<const discrete_column* const> parents,
                                std::size_t begin, std::size_t end, count_table& table) {
  const std::size_t n = end > begin ? end - begin : 0;
  std::vector<count_table::cell> cells(n, count_table::cell{.count = 1});
  std::vector<std::uint8_t> present(n, 1);
  auto visit_codes = [&](const discrete_column& column, auto&& each) {
    std::visit(
        [&](const auto& codes) {
          using code_type = typename std::decay_t<decltype(codes)>::value_type;
          for (std::size_t i = 0; i < n; ++i) {
            const auto code = codes[begin + i];
            if (code == missing_code<code_type> && column.missing() != 0) {
              present[i] = 0;
            } else {
              each(i, static_cast<std::size_t>(code));
            }
          }
        },
        column.codes());
  };
  visit_codes(child, [&](std::size_t i, std::size_t code) { cells[i].state = code; });
  for (std::size_t k = 0; k < parents.size(); ++k) {
    if (parents[k]->size() != child.size()) {
      throw data_error("column '" + parents[k]->name() + "' has " + std::to_string(parents[k]->size()) + " rows, '" +
                       child.name() + "' " + std::to_string(child.size()));
    }
    const std::size_t stride = table.parent_radix().stride(k);
    visit_codes(*parents[k], [&](std::size_t i, std::size_t code) { cells[i].configuration += code * stride; });
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (present[i]) cells[kept++] = cells[i];
  }
  cells.resize(kept);
  table.add(std::move(cells));
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL count_table count_family(const discrete_column& child, std::span<const discrete_column* const> parents,
                                  const count_options& options, row_range rows) {
  std::vector<variable> parent_variables;
  for (const auto* p : parents) parent_variables.push_back(p->var());
  count_table table(child.var(), std::move(parent_variables));
  const std::size_t end = std::min(rows.end, child.size());
  const std::size_t begin = std::min(rows.begin, end);
  if (table.is_sparse()) {
    detail::count_rows_sparse(child, parents, begin, end, table);
    return table;
  }
  const auto family = detail::columns_of(table, child, parents);
  bool skip_missing = child.missing() != 0;
  for (const auto* p : parents) skip_missing = skip_missing || p->missing() != 0;
  detail::count_rows_parallel(family.columns, family.strides, begin, end, table.counts(), options.threads,
                              options.min_rows_per_thread, skip_missing);
  return table;
}

PGM_DECL count_table count_family(const dataset& data, std::string_view child, std::span<const std::string> parents,
                                  const count_options& options, row_range rows) {
  std::vector<const discrete_column*> parent_columns;
  for (const auto& name : parents) parent_columns.push_back(&data.discrete(name));
  return count_family(data.discrete(child), parent_columns, options, rows);
}

}  // namespace pgm
