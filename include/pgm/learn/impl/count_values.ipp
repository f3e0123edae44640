#pragma once
// The definitions of pgm/learn/count_values.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/count_values.hpp"

namespace pgm::detail {

PGM_DECL void count_value_rows(std::span<const value_column> columns, std::span<const value_table_layout> layouts,
                               std::size_t begin, std::size_t end, value_tally& tally) {
  std::uint64_t index[count_block_rows];
  for (std::size_t first = begin; first < end; first += count_block_rows) {
    const std::size_t n = std::min(count_block_rows, end - first);
    for (std::size_t t = 0; t < layouts.size(); ++t) {
      const auto& layout = layouts[t];
      std::fill(index, index + n, std::uint64_t{0});
      const auto mask = [&](std::size_t k) { return (std::uint64_t{1} << layout.bits[k]) - 1; };
      for (std::size_t k = 0; k < layout.columns.size(); ++k) {
        const auto& column = columns[layout.columns[k]];
        if (k + 1 < layout.columns.size()) {  // two contiguous columns of one type: in one pass
          const auto& next = columns[layout.columns[k + 1]];
          const bool paired =
              column.index() == next.index() &&
              std::visit(
                  [&](const auto& c) { return c.stride == 1 && std::get<std::decay_t<decltype(c)>>(next).stride == 1; },
                  column);
          if (paired) {
            std::uint64_t bits[2] = {0, 0};
            const std::uint64_t masks[2] = {mask(k), mask(k + 1)};
            const unsigned shifts[2] = {layout.shifts[k], layout.shifts[k + 1]};
            std::visit(
                [&](const auto& c) {
                  add_value_pair(c, std::get<std::decay_t<decltype(c)>>(next), first, n, masks, shifts, bits, index);
                },
                column);
            tally.bits[layout.columns[k]] |= bits[0];
            tally.bits[layout.columns[k + 1]] |= bits[1];
            ++k;
            continue;
          }
        }
        tally.bits[layout.columns[k]] |= std::visit(
            [&](const auto& c) { return add_values(c, first, n, mask(k), layout.shifts[k], index); }, column);
      }
      auto* counts = tally.tables[t].data();
      for (std::size_t i = 0; i < n; ++i) ++counts[index[i]];
    }
  }
}

PGM_DECL value_tally count_by_value(std::span<const value_column> columns, std::span<const value_table_layout> layouts,
                                    std::size_t rows, const count_options& options) {
  value_tally tally;
  for (const auto& layout : layouts) tally.tables.emplace_back(layout.cells, 0);
  tally.bits.assign(columns.size(), 0);
  parallel_options parallel;
  parallel.threads = options.threads;
  parallel.min_items_per_thread = options.min_rows_per_thread;
  const std::size_t per_thread = rows / std::max<std::size_t>(1, worker_count(rows, parallel));
  parallel.chunk = std::clamp<std::size_t>(per_thread / 4, count_block_rows, count_chunk_rows);
  if (worker_count(rows, parallel) <= 1) {
    count_value_rows(columns, layouts, 0, rows, tally);
    return tally;
  }
  const auto partial = parallel_for(
      rows, parallel, [&] { return tally; },
      [&](value_tally& mine, item_range chunk) { count_value_rows(columns, layouts, chunk.begin, chunk.end, mine); });
  for (const auto& part : partial) {
    for (std::size_t t = 0; t < tally.tables.size(); ++t) {
      for (std::size_t i = 0; i < tally.tables[t].size(); ++i) tally.tables[t][i] += part.tables[t][i];
    }
    for (std::size_t c = 0; c < tally.bits.size(); ++c) tally.bits[c] |= part.bits[c];
  }
  return tally;
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL std::optional<value_counts> count_value_families(std::span<const named_value_column> columns,
                                                          std::span<const value_family> families,
                                                          const count_options& options) {
  const auto size_of = [](const named_value_column& c) {
    return std::visit([](const auto& v) { return v.size; }, c.values);
  };
  if (columns.empty()) return value_counts{};
  const std::size_t rows = size_of(columns.front());
  std::vector<value_column> values;
  std::vector<unsigned> width;  // values of column c lie in [0, 2^width[c]): first a guess from a sample
  for (const auto& c : columns) {
    if (size_of(c) != rows) {
      throw data_error("column '" + c.name + "' has " + std::to_string(size_of(c)) + " rows, '" + columns.front().name +
                       "' " + std::to_string(rows));
    }
    const auto bits = std::visit([](const auto& v) { return detail::sampled_value_bits(v); }, c.values);
    if (bits >= value_count_limit) return std::nullopt;
    values.push_back(c.values);
    width.push_back(detail::value_width(bits));
  }
  if (rows == 0) return std::nullopt;

  // Each family with every column (the child too), then those not in any: a column's states
  // are read off the counts of a family holding it.
  std::vector<std::vector<std::size_t>> members;
  for (const auto& f : families) {
    members.push_back({f.child});
    members.back().insert(members.back().end(), f.parents.begin(), f.parents.end());
    for (const auto c : members.back()) {
      if (c >= columns.size()) {
        throw model_error("a family names column " + std::to_string(c) + " of " + std::to_string(columns.size()));
      }
    }
  }
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const bool held = std::any_of(members.begin(), members.end(),
                                  [&](const auto& m) { return std::find(m.begin(), m.end(), c) != m.end(); });
    if (!held) members.push_back({c});
  }
  // Each family is summed out of the first of the largest families holding all its columns.
  const auto holds = [](const std::vector<std::size_t>& outer, const std::vector<std::size_t>& inner) {
    return std::all_of(inner.begin(), inner.end(),
                       [&](std::size_t c) { return std::find(outer.begin(), outer.end(), c) != outer.end(); });
  };
  std::vector<std::size_t> source(members.size());
  std::vector<std::size_t> counted;  // the members counted by value
  for (std::size_t i = 0; i < members.size(); ++i) {
    std::size_t best = members.size();
    for (std::size_t j = 0; j < members.size(); ++j) {
      if (holds(members[j], members[i]) && (best == members.size() || members[j].size() > members[best].size())) {
        best = j;
      }
    }
    const auto at = std::find(counted.begin(), counted.end(), best);
    source[i] = static_cast<std::size_t>(at - counted.begin());
    if (at == counted.end()) counted.push_back(best);
  }
  const auto layouts_for = [&]() -> std::optional<std::vector<detail::value_table_layout>> {
    std::vector<detail::value_table_layout> layouts;
    for (const auto m : counted) {
      detail::value_table_layout layout;
      unsigned shift = 0;
      for (const auto c : members[m]) {
        layout.columns.push_back(c);
        layout.shifts.push_back(shift);
        layout.bits.push_back(width[c]);
        shift += width[c];
        if ((std::size_t{1} << std::min(shift, 63U)) > value_cell_limit) return std::nullopt;
      }
      layout.cells = std::size_t{1} << shift;
      layouts.push_back(std::move(layout));
    }
    return layouts;
  };

  // One pass over the rows with the guessed ranges; when a value lies beyond, a second with the
  // ranges that pass found.
  auto layouts = layouts_for();
  if (!layouts) return std::nullopt;
  auto tally = detail::count_by_value(values, *layouts, rows, options);
  bool guessed_short = false;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (tally.bits[c] >= value_count_limit) return std::nullopt;
    guessed_short = guessed_short || detail::value_width(tally.bits[c]) > width[c];
    width[c] = std::max(width[c], detail::value_width(tally.bits[c]));
  }
  if (guessed_short) {
    layouts = layouts_for();
    if (!layouts) return std::nullopt;
    tally = detail::count_by_value(values, *layouts, rows, options);
  }

  // The values seen, then each column's states and the state of each value.
  const auto value_of = [](const detail::value_table_layout& layout, std::size_t cell, std::size_t k) {
    return (cell >> layout.shifts[k]) & ((std::size_t{1} << layout.bits[k]) - 1);
  };
  std::vector<std::vector<std::uint8_t>> seen(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) seen[c].assign(std::size_t{1} << width[c], 0);
  for (std::size_t t = 0; t < layouts->size(); ++t) {
    const auto& layout = (*layouts)[t];
    for (std::size_t cell = 0; cell < layout.cells; ++cell) {
      if (tally.tables[t][cell] == 0) continue;
      for (std::size_t k = 0; k < layout.columns.size(); ++k) seen[layout.columns[k]][value_of(layout, cell, k)] = 1;
    }
  }
  value_counts result;
  std::vector<std::vector<std::uint32_t>> state(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    std::vector<std::size_t> distinct;
    std::vector<std::string> labels;
    for (std::size_t v = 0; v < seen[c].size(); ++v) {
      if (!seen[c][v]) continue;
      distinct.push_back(v);
      labels.push_back(std::to_string(v));
    }
    auto order = order_states(labels);
    state[c].assign(seen[c].size(), 0);
    for (std::size_t i = 0; i < distinct.size(); ++i) state[c][distinct[i]] = order.state_of[i];
    result.variables.emplace_back(columns[c].name, std::move(order.states));
  }

  // Each family's table: the counts by value of its source, summed onto the family's states.
  for (std::size_t i = 0; i < families.size(); ++i) {
    const auto& layout = (*layouts)[source[i]];
    const auto& counts = tally.tables[source[i]];
    std::vector<variable> parents;
    for (const auto p : families[i].parents) parents.push_back(result.variables[p]);
    count_table table(result.variables[families[i].child], std::move(parents));
    // For each column of the family: its place in the source's layout and its stride in `table`.
    std::vector<std::size_t> place;
    std::vector<std::size_t> stride{1};
    for (const auto c : members[i]) {
      place.push_back(static_cast<std::size_t>(std::find(layout.columns.begin(), layout.columns.end(), c) -
                                               layout.columns.begin()));
    }
    for (std::size_t k = 0; k < families[i].parents.size(); ++k) {
      stride.push_back(table.child_cardinality() * table.parent_radix().stride(k));
    }
    auto cells = table.counts();
    for (std::size_t cell = 0; cell < layout.cells; ++cell) {
      if (counts[cell] == 0) continue;
      std::size_t at = 0;
      for (std::size_t k = 0; k < place.size(); ++k) {
        at += state[members[i][k]][value_of(layout, cell, place[k])] * stride[k];
      }
      cells[at] += counts[cell];
    }
    result.tables.push_back(std::move(table));
  }
  return result;
}

}  // namespace pgm
