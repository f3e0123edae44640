#pragma once
// The definitions of pgm/io/influence_file.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <map>
#include <vector>

#include "pgm/core/file.hpp"
#include "pgm/detail/json_reader.hpp"
#include "pgm/io/influence_file.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/xmlbif.hpp"

namespace pgm {

PGM_DECL nlohmann::json to_json(const influence_diagram& diagram) {
  const auto names = [&](const std::vector<variable_id>& ids) {
    auto list = nlohmann::json::array();
    for (const auto id : ids) list.push_back(diagram.at(id).name());
    return list;
  };
  auto variables = nlohmann::json::array();
  auto tables = nlohmann::json::array();
  auto decisions = nlohmann::json::array();
  for (std::size_t i = 0; i < diagram.size(); ++i) {
    const auto id = index_at<variable_id>(i);
    variables.push_back(detail::variable_to_json(diagram.at(id)));
    if (diagram.is_decision(id)) {
      decisions.push_back({{"variable", diagram.at(id).name()}, {"observes", names(diagram.parents(id))}});
      continue;
    }
    const auto& values = diagram.table(id);
    const auto states = diagram.at(id).cardinality();
    auto rows = nlohmann::json::array();
    for (std::size_t c = 0; c < values.size(); c += states) {
      rows.push_back(std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>(c),
                                         values.begin() + static_cast<std::ptrdiff_t>(c + states)));
    }
    tables.push_back({{"variable", diagram.at(id).name()}, {"parents", names(diagram.parents(id))}, {"values", rows}});
  }
  auto utilities = nlohmann::json::array();
  for (const auto& u : diagram.utilities()) {
    detail::require_utf8(u.name, "the utility name");
    utilities.push_back({{"name", u.name}, {"parents", names(u.parents)}, {"values", u.values}});
  }
  return {{"format", "pgm-model"}, {"version", 1},           {"kind", "influence"},   {"variables", variables},
          {"tables", tables},      {"decisions", decisions}, {"utilities", utilities}};
}

PGM_DECL influence_diagram parse_influence_json(std::string_view text, const std::string& source) {
  const detail::json_reader reader(source);
  const auto document = reader.parse(text);
  reader.check_format(document, "pgm-model");
  const auto* kind = reader.optional_member(document, "kind");
  if (kind == nullptr || !kind->is_string() || *kind != "influence") {
    const auto held = kind != nullptr && kind->is_string() ? kind->get<std::string>() : std::string("bayesian");
    reader.fail("/kind", "expected \"influence\": the file holds a model of \"kind\": \"" + held +
                             "\", not an influence diagram");
  }
  reader.only_keys(document, "",
                   {"format", "version", "kind", "variables", "tables", "decisions", "utilities", "metadata"});
  const auto& decisions = reader.array(reader.member(document, "", "decisions"), "/decisions");
  std::map<std::string, std::size_t, std::less<>> decision_entry;
  for (std::size_t k = 0; k < decisions.size(); ++k) {
    const auto path = "/decisions/" + std::to_string(k);
    reader.only_keys(decisions[k], path, {"variable", "observes"});
    const auto name = reader.string(reader.member(decisions[k], path, "variable"), path + "/variable");
    if (!decision_entry.emplace(name, k).second) reader.fail(path, "'" + name + "' is listed twice");
  }
  influence_diagram diagram;
  const auto& vars = reader.array(reader.member(document, "", "variables"), "/variables");
  for (std::size_t i = 0; i < vars.size(); ++i) {
    const auto path = "/variables/" + std::to_string(i);
    auto v = reader.read_variable(vars[i], path);
    try {
      decision_entry.contains(v.name()) ? diagram.add_decision(std::move(v)) : diagram.add_chance(std::move(v));
    } catch (const model_error& e) {
      reader.fail(path, e.what());
    }
  }
  const auto ids_of = [&](const nlohmann::json& value, const std::string& path) {
    std::vector<variable_id> ids;
    const auto names = reader.strings(value, path);
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (!diagram.contains(names[k])) {
        reader.fail(path + "/" + std::to_string(k), "'" + names[k] + "' is not a chance or decision variable");
      }
      ids.push_back(diagram.id(names[k]));
    }
    return ids;
  };
  for (const auto& [name, k] : decision_entry) {
    const auto path = "/decisions/" + std::to_string(k);
    if (!diagram.contains(name)) reader.fail(path + "/variable", "'" + name + "' is not among the variables");
    const auto observes = ids_of(reader.member(decisions[k], path, "observes"), path + "/observes");
    try {
      diagram.set_observed(diagram.id(name), observes);
    } catch (const model_error& e) {
      reader.fail(path, e.what());
    }
  }
  const auto& tables = reader.array(reader.member(document, "", "tables"), "/tables");
  for (std::size_t t = 0; t < tables.size(); ++t) {
    const auto path = "/tables/" + std::to_string(t);
    reader.only_keys(tables[t], path, {"variable", "parents", "values"});
    const auto name = reader.string(reader.member(tables[t], path, "variable"), path + "/variable");
    if (!diagram.contains(name)) reader.fail(path + "/variable", "'" + name + "' is not among the variables");
    const auto parents = ids_of(reader.member(tables[t], path, "parents"), path + "/parents");
    const auto& rows = reader.array(reader.member(tables[t], path, "values"), path + "/values");
    std::vector<double> values;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const auto row = reader.numbers(rows[r], path + "/values/" + std::to_string(r));
      values.insert(values.end(), row.begin(), row.end());
    }
    try {
      diagram.set_table(diagram.id(name), parents, std::move(values));
    } catch (const model_error& e) {
      reader.fail(path, e.what());
    }
  }
  const auto& utilities = reader.array(reader.member(document, "", "utilities"), "/utilities");
  for (std::size_t u = 0; u < utilities.size(); ++u) {
    const auto path = "/utilities/" + std::to_string(u);
    reader.only_keys(utilities[u], path, {"name", "parents", "values"});
    auto name = reader.string(reader.member(utilities[u], path, "name"), path + "/name");
    const auto parents = ids_of(reader.member(utilities[u], path, "parents"), path + "/parents");
    try {
      diagram.add_utility(std::move(name), parents,
                          reader.numbers(reader.member(utilities[u], path, "values"), path + "/values"));
    } catch (const model_error& e) {
      reader.fail(path, e.what());
    }
  }
  try {
    diagram.validate();
  } catch (const model_error& e) {
    reader.fail("", e.what());
  }
  return diagram;
}

PGM_DECL influence_diagram read_influence_diagram(const std::filesystem::path& path) {
  if (path.extension() == ".json") return parse_influence_json(read_file(path), path.string());
  return read_xmlbif_influence_diagram(path);
}

PGM_DECL void write_influence_diagram(const influence_diagram& diagram, const std::filesystem::path& path) {
  const auto text = path.extension() == ".json" ? to_json(diagram).dump(2) + "\n" : to_xmlbif(diagram);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace pgm
