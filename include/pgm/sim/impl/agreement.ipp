#pragma once
// The definitions of pgm/sim/agreement.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/agreement.hpp"

namespace pgm::sim::detail {

PGM_DECL agreement_axis grid_axis(const task_definition& task, const std::string& name) {
  const auto& d = task.at(name).sampling;
  agreement_axis axis{name, d.min, d.max};
  if (d.continuous()) {
    // An untruncated tail: the central 99%.
    const double total = d.raw_cdf(d.max) - d.raw_cdf(d.min);
    if (!std::isfinite(axis.lo)) axis.lo = d.raw_quantile(d.raw_cdf(d.min) + 0.005 * total);
    if (!std::isfinite(axis.hi)) axis.hi = d.raw_quantile(d.raw_cdf(d.max) - 0.005 * total);
  } else if (!d.values.empty()) {
    axis.lo = *std::min_element(d.values.begin(), d.values.end());
    axis.hi = *std::max_element(d.values.begin(), d.values.end());
  }
  if (!(axis.hi > axis.lo)) {
    throw data_error("task '" + task.name + "': '" + name + "' does not vary, so it cannot span an agreement grid");
  }
  return axis;
}

}  // namespace pgm::sim::detail

namespace pgm::sim {

PGM_DECL std::vector<agreement_axis> agreement_axes(const task_definition& task) {
  if (const auto* s = std::get_if<stacking_physics>(&task.physics)) {
    if (s->cubes == 1) return {detail::grid_axis(task, "xOff1"), detail::grid_axis(task, "yOff1")};
    return {detail::grid_axis(task, "xOff1"), detail::grid_axis(task, "xOff" + std::to_string(s->cubes))};
  }
  return {detail::grid_axis(task, "xOff"), detail::grid_axis(task, "yOff"), detail::grid_axis(task, "scalingFactor")};
}

PGM_DECL agreement_table agreement(const task_definition& task, const agreement_options& options) {
  if (options.reference_rows == 0 || options.analytic_rows == 0) {
    throw data_error("an agreement table needs rows from both back-ends (rows must be positive)");
  }
  agreement_table table;
  table.task = task.name;
  table.reference = options.reference;
  table.outcome = task.success;
  table.axes = agreement_axes(task);
  const std::size_t dims = table.axes.size();
  std::size_t count = 1;
  for (std::size_t i = 0; i < dims; ++i) count *= 3;
  table.cells.resize(count);
  for (std::size_t c = 0; c < count; ++c) {
    auto rest = c;
    table.cells[c].third.resize(dims);
    for (std::size_t i = dims; i-- > 0;) {
      table.cells[c].third[i] = rest % 3;
      rest /= 3;
    }
  }
  // Success counts per cell, added up over the blocks of one back-end's rows.
  std::vector<double> hits(count), rows(count);
  auto tally = [&](const dataset& data) {
    const auto& success = data.discrete(task.success);
    std::vector<std::span<const double>> columns;
    for (const auto& axis : table.axes) columns.push_back(data.continuous(axis.variable).values());
    for (std::size_t row = 0; row < data.rows(); ++row) {
      std::size_t c = 0;
      for (std::size_t i = 0; i < dims; ++i) {
        const auto& axis = table.axes[i];
        const double position = (columns[i][row] - axis.lo) / (axis.hi - axis.lo) * 3;
        c = c * 3 + static_cast<std::size_t>(std::clamp(position, 0.0, 2.0));
      }
      rows[c] += 1;
      hits[c] += success.code(row);
    }
  };
  // The rows are simulated in blocks (the data of one run, simulate_options::first_row), so that
  // memory stays that of a block however many rows are asked for.
  constexpr std::size_t block_rows = std::size_t{1} << 18;
  auto run = [&](const std::string& backend, std::size_t total_rows, bool reference) {
    std::fill(hits.begin(), hits.end(), 0.0);
    std::fill(rows.begin(), rows.end(), 0.0);
    simulate_options o;
    o.backend = backend;
    o.seed = options.seed;
    o.threads = options.threads;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t done = 0; done < total_rows; done += o.rows) {
      o.first_row = done;
      o.rows = std::min(block_rows, total_rows - done);
      if (reference && options.progress) {
        o.progress = [&options, done](std::size_t block_done) { options.progress(done + block_done); };
      }
      tally(simulate(task, o));
    }
    (reference ? table.reference_seconds : table.analytic_seconds) =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double total = 0;
    for (std::size_t c = 0; c < count; ++c) {
      auto& cell = table.cells[c];
      total += hits[c];
      (reference ? cell.reference_rows : cell.analytic_rows) = static_cast<std::size_t>(rows[c]);
      (reference ? cell.reference_rate : cell.analytic_rate) = rows[c] > 0 ? hits[c] / rows[c] : 0.0;
    }
    (reference ? table.reference_rate : table.analytic_rate) = total / static_cast<double>(total_rows);
  };
  run(options.reference, options.reference_rows, true);
  run("analytic", options.analytic_rows, false);
  table.reference_rows = options.reference_rows;
  table.analytic_rows = options.analytic_rows;

  double differences = 0, noise = 0, used = 0;
  for (const auto& cell : table.cells) {
    if (cell.reference_rows == 0 || cell.analytic_rows == 0) continue;
    const double n1 = static_cast<double>(cell.reference_rows), n2 = static_cast<double>(cell.analytic_rows);
    const double pooled = (cell.reference_rate * n1 + cell.analytic_rate * n2) / (n1 + n2);
    differences += std::abs(cell.reference_rate - cell.analytic_rate);
    noise += std::sqrt(pooled * (1 - pooled) * (1 / n1 + 1 / n2)) * std::sqrt(2 / std::numbers::pi);
    used += 1;
  }
  table.mean_abs_difference = used > 0 ? differences / used : 0.0;
  table.noise_mean_abs_difference = used > 0 ? noise / used : 0.0;
  const double p = table.reference_rate;
  const double q = table.analytic_rate;
  table.overall_standard_error = std::sqrt(p * (1 - p) / static_cast<double>(table.reference_rows) +
                                           q * (1 - q) / static_cast<double>(table.analytic_rows));
  return table;
}

}  // namespace pgm::sim
