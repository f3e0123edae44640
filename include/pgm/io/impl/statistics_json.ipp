#pragma once
// The definitions of pgm/io/statistics_json.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/io/statistics_json.hpp"

namespace pgm::detail {

PGM_DECL nlohmann::json rows_of(std::span<const double> values, std::size_t width) {
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t begin = 0; begin < values.size(); begin += width) {
    rows.push_back(std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>(begin),
                                       values.begin() + static_cast<std::ptrdiff_t>(begin + width)));
  }
  return rows;
}

PGM_DECL nlohmann::json prior_to_json(const parameter_prior& prior, const expected_count_table& family) {
  if (const auto choice = prior.choice()) {
    nlohmann::json written{{"kind", choice->name}};
    const auto& declared = choice->options.declarations();
    for (std::size_t i = 0; i < declared.size(); ++i) {
      std::visit([&](const auto& value) { written[declared[i].name] = value; }, choice->options.values()[i]);
    }
    return written;
  }
  // Made otherwise: kept as its pseudo-counts.
  const auto width = family.child_cardinality();
  const auto alpha = prior.pseudo_counts(family.child(), family.parents());
  if (const auto* uniform = alpha.uniform_alpha()) return {{"kind", "dirichlet"}, {"alpha", *uniform}};
  if (const auto* weighted = alpha.weighted()) {
    return {{"kind", "weighted"}, {"w", weighted->weight}, {"table", rows_of(weighted->table.values(), width)}};
  }
  return {{"kind", "pseudo-counts"}, {"alpha", rows_of(*alpha.cells(), width)}};
}

PGM_DECL std::vector<double> cells_of(const json_reader& reader, const nlohmann::json& rows, const std::string& path,
                                      const expected_count_table& family) {
  const auto width = family.child_cardinality();
  std::vector<double> values;
  const auto& array = reader.array(rows, path);
  if (array.size() != family.configurations()) {
    reader.fail(path, "expected " + std::to_string(family.configurations()) +
                          " rows, one per configuration of the parents of '" + family.child().name() + "'");
  }
  for (std::size_t u = 0; u < array.size(); ++u) {
    const auto row_path = path + "/" + std::to_string(u);
    const auto row = reader.numbers(array[u], row_path);
    if (row.size() != width) {
      reader.fail(row_path,
                  "expected " + std::to_string(width) + " values, one per state of '" + family.child().name() + "'");
    }
    for (std::size_t x = 0; x < row.size(); ++x) {
      if (!std::isfinite(row[x]) || row[x] < 0.0) {
        reader.fail(row_path + "/" + std::to_string(x),
                    "expected a finite number >= 0, got " + text::format_double(row[x]));
      }
    }
    values.insert(values.end(), row.begin(), row.end());
  }
  return values;
}

PGM_DECL parameter_prior prior_from_json(const json_reader& reader, const nlohmann::json& value,
                                         const std::string& path, const expected_count_table& family) {
  const auto kind = reader.string(reader.member(value, path, "kind"), path + "/kind");
  if (kind == "pseudo-counts") {
    reader.only_keys(value, path, {"kind", "alpha"});
    return pseudo_counts_prior{cells_of(reader, reader.member(value, path, "alpha"), path + "/alpha", family)};
  }
  if (kind == "weighted") {
    reader.only_keys(value, path, {"kind", "w", "table"});
    auto table = cells_of(reader, reader.member(value, path, "table"), path + "/table", family);
    const double w = reader.number(reader.member(value, path, "w"), path + "/w");
    if (!std::isfinite(w) || w < 0.0) reader.fail(path + "/w", "expected a finite number >= 0");
    return weighted_prior{cpt<double>(family.child(), family.parents(), std::move(table)), w};
  }
  // A prior of the registry: its options are the other keys.
  const auto& registry = parameter_priors();
  const auto entry = registry.find(kind);
  if (!entry) {
    auto known = registry.names();
    known.insert(known.end(), {"pseudo-counts", "weighted"});
    reader.fail(path + "/kind", unknown_name("prior", kind, known).what());
  }
  std::vector<std::string_view> keys{"kind"};
  std::string settings;
  for (const auto& option : entry->options) {
    keys.push_back(option.name);
    if (!value.contains(option.name)) continue;
    const auto& given = value.at(option.name);
    const auto key_path = path + "/" + option.name;
    std::string written;
    if (given.is_number_integer()) {
      written = std::to_string(given.get<std::int64_t>());
    } else if (given.is_number()) {
      written = text::format_double(reader.number(given, key_path));
    } else if (given.is_boolean()) {
      written = given.get<bool>() ? "true" : "false";
    } else {
      written = reader.string(given, key_path);
    }
    const auto refusal = option_value_refusal(option, written);
    if (!refusal.empty()) reader.fail(key_path, "the " + option.name + refusal);
    settings += (settings.empty() ? "" : ",") + option.name + "=" + written;
  }
  reader.only_keys(value, path, keys);
  return registry.make(settings.empty() ? kind : kind + "[" + settings + "]");
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL nlohmann::json to_json(const fit_statistics& statistics) {
  nlohmann::json families = nlohmann::json::array();
  for (std::size_t i = 0; i < statistics.counts.size(); ++i) {
    const auto& counts = statistics.counts[i];
    const auto width = counts.child_cardinality();
    families.push_back({{"variable", counts.child().name()},
                        {"counts", detail::rows_of(counts.counts(), width)},
                        {"prior", detail::prior_to_json(statistics.priors[i], counts)}});
  }
  return {{"rows", statistics.rows},
          {"empty", std::string(to_string(statistics.estimation.empty))},
          {"families", families}};
}

PGM_DECL fit_statistics parse_statistics_json(const detail::json_reader& reader, const nlohmann::json& value,
                                              const network_structure& structure) {
  std::vector<expected_count_table> families;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    families.emplace_back(structure.at(node), structure.parent_variables(node));
  }
  return parse_statistics_json(reader, value, "/statistics", std::move(families));
}

PGM_DECL fit_statistics parse_statistics_json(const detail::json_reader& reader, const nlohmann::json& value,
                                              const std::string& path, std::vector<expected_count_table> families) {
  reader.only_keys(value, path, {"rows", "empty", "families"});
  fit_statistics result;
  result.rows = reader.number(reader.member(value, path, "rows"), path + "/rows");
  if (!std::isfinite(result.rows) || result.rows < 0.0) reader.fail(path + "/rows", "expected a finite number >= 0");
  const auto empty = reader.string(reader.member(value, path, "empty"), path + "/empty");
  try {
    result.estimation.empty = parse_empty_configuration(empty);
  } catch (const unknown_name& e) {
    reader.fail(path + "/empty", e.what());
  }
  const auto& entries = reader.array(reader.member(value, path, "families"), path + "/families");
  if (entries.size() != families.size()) {
    reader.fail(path + "/families", "expected " + std::to_string(families.size()) + " families, one per variable");
  }
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto family_path = path + "/families/" + std::to_string(i);
    const auto& entry = entries[i];
    reader.only_keys(entry, family_path, {"variable", "counts", "prior"});
    auto& counts = families[i];
    const auto name = reader.string(reader.member(entry, family_path, "variable"), family_path + "/variable");
    if (name != counts.child().name()) {
      reader.fail(family_path + "/variable",
                  "expected '" + counts.child().name() + "' (the families are in the variables' order)");
    }
    const auto cells =
        detail::cells_of(reader, reader.member(entry, family_path, "counts"), family_path + "/counts", counts);
    std::copy(cells.begin(), cells.end(), counts.counts().begin());
    result.priors.push_back(
        detail::prior_from_json(reader, reader.member(entry, family_path, "prior"), family_path + "/prior", counts));
    result.counts.push_back(std::move(counts));
  }
  return result;
}

}  // namespace pgm
