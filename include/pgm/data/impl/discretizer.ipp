#pragma once
// The definitions of pgm/data/discretizer.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/data/discretizer.hpp"

namespace pgm::detail {

PGM_DECL void check_finite(std::span<const double> values, const std::string& name) {
  for (std::size_t row = 0; row < values.size(); ++row) {
    if (std::isinf(values[row])) {
      throw data_error("column '" + name + "' row " + std::to_string(row + 1) +
                       ": cannot discretize a value that is not finite");
    }
  }
}

PGM_DECL std::vector<double> distinct_edges(std::vector<double> edges, const std::string& name) {
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  if (edges.size() < 2) {
    throw data_error("column '" + name + "' holds a single value; it cannot be split into bins");
  }
  return edges;
}

PGM_DECL std::vector<double> present_values(std::span<const double> values) {
  std::vector<double> present;
  present.reserve(values.size());
  for (double v : values) {
    if (!std::isnan(v)) present.push_back(v);
  }
  return present;
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL std::vector<double> quantile_edges(std::span<const double> values, std::size_t bins, const std::string& name) {
  if (bins == 0) throw data_error("the number of bins must be positive");
  detail::check_finite(values, name);
  auto sorted = detail::present_values(values);
  if (sorted.empty()) throw data_error("column '" + name + "' has no values to discretize");
  std::sort(sorted.begin(), sorted.end());
  const auto n = sorted.size();
  std::vector<double> edges;
  edges.reserve(bins + 1);
  for (std::size_t k = 0; k <= bins; ++k) {
    const double h = static_cast<double>(n - 1) * static_cast<double>(k) / static_cast<double>(bins);
    const auto lower = static_cast<std::size_t>(std::floor(h));
    const auto upper = std::min(lower + 1, n - 1);
    edges.push_back(sorted[lower] + (h - static_cast<double>(lower)) * (sorted[upper] - sorted[lower]));
  }
  return detail::distinct_edges(std::move(edges), name);
}

PGM_DECL std::vector<double> equal_width_edges(std::span<const double> values, std::size_t bins,
                                               const std::string& name) {
  if (bins == 0) throw data_error("the number of bins must be positive");
  detail::check_finite(values, name);
  const auto present = detail::present_values(values);
  if (present.empty()) throw data_error("column '" + name + "' has no values to discretize");
  const auto [lo, hi] = std::minmax_element(present.begin(), present.end());
  std::vector<double> edges;
  for (std::size_t k = 0; k <= bins; ++k) {
    edges.push_back(k == bins ? *hi : *lo + (*hi - *lo) * static_cast<double>(k) / static_cast<double>(bins));
  }
  return detail::distinct_edges(std::move(edges), name);
}

PGM_DECL discretization fit_discretization(const dataset& data, std::span<const std::string> columns, binning method,
                                           std::size_t bins) {
  discretization result;
  for (const auto& name : columns) {
    const auto& c = data.continuous(name);
    auto edges = method == binning::quantile ? quantile_edges(c.values(), bins, name)
                                             : equal_width_edges(c.values(), bins, name);
    result.insert_or_assign(name, variable::intervals(name, std::move(edges), c.tags()));
  }
  return result;
}

PGM_DECL discrete_column discretize(const continuous_column& values, const variable& intervals) {
  if (!intervals.has_intervals()) {
    throw model_error("variable '" + intervals.name() + "' has no interval edges to bin values by");
  }
  detail::check_finite(values.values(), values.name());
  const auto missing = values.missing();
  auto codes = make_code_vector(intervals.cardinality() + (missing ? 1 : 0), values.size());
  std::visit(
      [&](auto& stored) {
        using code = typename std::decay_t<decltype(stored)>::value_type;
        const auto v = values.values();
        for (std::size_t row = 0; row < v.size(); ++row) {
          stored[row] = std::isnan(v[row]) ? missing_code<code> : static_cast<code>(intervals.bin(v[row]).value());
        }
      },
      codes);
  return discrete_column(intervals, std::move(codes), std::in_place, missing);
}

PGM_DECL dataset apply_discretization(const dataset& data, const discretization& d) {
  dataset result = data;
  for (const auto& [name, intervals] : d) {
    const auto& c = data.at(name);
    if (const auto* values = std::get_if<continuous_column>(&c)) {
      result.replace(discretize(*values, intervals));
    } else if (std::get<discrete_column>(c).var().states() != intervals.states()) {
      throw data_error("column '" + name + "' is discrete already, with other states than the " + "discretization");
    }
  }
  return result;
}

}  // namespace pgm
