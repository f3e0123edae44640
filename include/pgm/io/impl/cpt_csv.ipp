#pragma once
// The definitions of pgm/io/cpt_csv.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/io/cpt_csv.hpp"

namespace pgm {

PGM_DECL void write_cpt_csv(const cpt<double>& table, std::ostream& out, const std::string& value_header) {
  // A row per configuration and state, as many as a dense table holds: within the same limit.
  static_cast<void>(checked_table_cells(table.child().name(), table.child_cardinality(), table.configurations()));
  std::string text;
  for (const auto& p : table.parents()) text += text::csv_escape(p.name(), ',') + ",";
  text += text::csv_escape(table.child().name(), ',') + "," + text::csv_escape(value_header, ',') + "\n";
  for (std::size_t u = 0; u < table.configurations(); ++u) {
    const auto codes = table.parent_codes(config_index(u));
    std::string prefix;
    for (std::size_t p = 0; p < codes.size(); ++p) {
      prefix += text::csv_escape(table.parents()[p].states()[codes[p]], ',') + ",";
    }
    const auto column = table.column(config_index(u));
    for (std::size_t x = 0; x < column.size(); ++x) {
      text += prefix + text::csv_escape(table.child().states()[x], ',') + "," + text::format_double(column[x]) + "\n";
    }
  }
  out << text;
}

PGM_DECL cpt<double> parse_cpt_csv(std::string_view text, const std::string& source, const variable& child,
                                   const std::vector<variable>& parents) {
  csv_options options;
  for (const auto& p : parents) options.variables.emplace(p.name(), p);
  options.variables.emplace(child.name(), child);
  const auto data = parse_csv(text, source, options);
  const auto names = data.names();
  if (names.size() != parents.size() + 2) {
    throw data_error(source + ": expected the columns " + [&] {
      std::string list;
      for (const auto& p : parents) list += p.name() + ", ";
      return list + child.name() + " and a probability";
    }());
  }
  const auto& probability = data.continuous(names.back());
  cpt<double> shape(child, parents);
  std::vector<double> values(shape.size(), 0.0);
  std::vector<bool> seen(shape.size(), false);
  for (std::size_t row = 0; row < data.rows(); ++row) {
    std::vector<std::size_t> codes;
    for (const auto& p : parents) codes.push_back(data.discrete(p.name()).code(row));
    const auto cell = shape.configuration(codes).value() * child.cardinality() + data.discrete(child.name()).code(row);
    if (seen[cell]) {
      throw data_error(source + ": row " + std::to_string(row + 1) + " repeats a configuration");
    }
    seen[cell] = true;
    values[cell] = probability.values()[row];
  }
  if (data.rows() != shape.size()) {
    throw data_error(source + ": expected " + std::to_string(shape.size()) + " rows, found " +
                     std::to_string(data.rows()));
  }
  return cpt<double>(child, parents, std::move(values));
}

}  // namespace pgm
