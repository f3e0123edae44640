#pragma once
// The definitions of pgm/data/bin_columns.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/data/bin_columns.hpp"

namespace pgm {

PGM_DECL discrete_column values_as_states(const continuous_column& values) {
  std::set<double> distinct;  // -0 and 0 are one value, as they are one state
  for (double v : values.values()) {
    if (!std::isnan(v)) distinct.insert(v);
  }
  const std::vector<double> levels(distinct.begin(), distinct.end());
  std::vector<std::string> labels;
  for (double level : levels) labels.push_back(text::format_double(level));
  variable var(values.name(), std::move(labels), values.tags());
  const auto missing = values.missing();
  auto codes = make_code_vector(var.cardinality() + (missing ? 1 : 0), values.size());
  std::visit(
      [&](auto& stored) {
        using code = typename std::decay_t<decltype(stored)>::value_type;
        const auto v = values.values();
        for (std::size_t row = 0; row < v.size(); ++row) {
          stored[row] =
              std::isnan(v[row])
                  ? missing_code<code>
                  : static_cast<code>(std::lower_bound(levels.begin(), levels.end(), v[row]) - levels.begin());
        }
      },
      codes);
  return discrete_column(std::move(var), std::move(codes), std::in_place, missing);
}

PGM_DECL binned_columns bin_columns(const dataset& data, const column_binning& request) {
  binned_columns result;
  const auto& wanted = request.columns;
  if (request.saved) {
    for (const auto& [name, v] : *request.saved) {
      if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), name) == wanted.end()) continue;
      result.edges.emplace(name, v);
    }
    for (const auto& name : wanted) {
      if (!request.saved->contains(name)) {
        throw data_error("'" + request.saved_source + "' has no edges for '" + name + "'");
      }
    }
  } else {
    auto columns = wanted;
    if (columns.empty()) {
      for (const auto& c : data.columns()) {
        const auto* values = std::get_if<continuous_column>(&c);
        if (!values) continue;
        std::set<double> distinct;
        for (double v : values->values()) {
          if (std::isnan(v)) continue;  // missing
          if (distinct.insert(v).second && distinct.size() > request.bins) break;
        }
        if (distinct.size() > request.bins) {
          columns.push_back(values->name());
        } else {
          result.left.emplace_back(values->name(), distinct.size());
        }
      }
      if (columns.empty()) {
        throw data_error((data.source().empty() ? std::string("the data") : data.source()) +
                         ": no numeric column has more than " + std::to_string(request.bins) +
                         " distinct values to bin");
      }
    }
    result.edges = fit_discretization(data, columns, request.method, request.bins);
  }
  result.data = apply_discretization(data, result.edges);
  return result;
}

}  // namespace pgm
