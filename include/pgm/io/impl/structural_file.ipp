#pragma once
// The definitions of pgm/io/structural_file.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <map>
#include <optional>
#include <vector>

#include "pgm/core/file.hpp"
#include "pgm/detail/json_reader.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/network_format.hpp"
#include "pgm/io/structural_file.hpp"

namespace pgm {

PGM_DECL nlohmann::ordered_json to_json(const structural_model& model) {
  auto variables = nlohmann::ordered_json::array();
  auto equations = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < model.size(); ++i) {
    const auto id = index_at<variable_id>(i);
    const auto& v = model.at(id);
    variables.push_back(nlohmann::ordered_json(detail::variable_to_json(v)));
    const auto& e = model.equation(id);
    auto parents = nlohmann::ordered_json::array();
    for (const auto p : e.parents) parents.push_back(model.at(p).name());
    auto rows = nlohmann::ordered_json::array();
    const auto configurations = parent_configurations(model, e.parents);
    for (std::size_t c = 0; c < configurations; ++c) {
      auto row = nlohmann::ordered_json::array();
      for (std::size_t k = 0; k < e.noise.size(); ++k) row.push_back(v.states()[model.value(id, c, k)]);
      rows.push_back(std::move(row));
    }
    auto equation = nlohmann::ordered_json::object();
    equation["variable"] = v.name();
    equation["parents"] = std::move(parents);
    equation["noise"] = e.noise;
    equation["values"] = std::move(rows);
    equations.push_back(std::move(equation));
  }
  nlohmann::ordered_json document;
  document["format"] = "pgm-model";
  document["version"] = 1;
  document["kind"] = "structural";
  document["variables"] = std::move(variables);
  document["equations"] = std::move(equations);
  return document;
}

PGM_DECL structural_model parse_structural_json(std::string_view text, const std::string& source) {
  const detail::json_reader reader(source);
  const auto document = reader.parse(text);
  reader.check_format(document, "pgm-model");
  const auto* kind = reader.optional_member(document, "kind");
  if (kind == nullptr || !kind->is_string() || *kind != "structural") {
    const auto held = kind != nullptr && kind->is_string() ? kind->get<std::string>() : std::string("bayesian");
    reader.fail("/kind", "expected \"structural\": the file holds a model of \"kind\": \"" + held +
                             "\", not a structural model");
  }
  reader.only_keys(document, "", {"format", "version", "kind", "variables", "equations", "metadata"});
  std::vector<variable> variables;
  std::map<std::string, std::size_t, std::less<>> index;
  const auto& vars = reader.array(reader.member(document, "", "variables"), "/variables");
  for (std::size_t i = 0; i < vars.size(); ++i) {
    const auto path = "/variables/" + std::to_string(i);
    variables.push_back(reader.read_variable(vars[i], path));
    if (!index.emplace(variables.back().name(), i).second) {
      reader.fail(path, "the variable '" + variables.back().name() + "' is declared twice");
    }
  }
  std::vector<std::optional<structural_equation>> equations(variables.size());
  const auto& list = reader.array(reader.member(document, "", "equations"), "/equations");
  for (std::size_t q = 0; q < list.size(); ++q) {
    const auto path = "/equations/" + std::to_string(q);
    reader.only_keys(list[q], path, {"variable", "parents", "noise", "values"});
    const auto name = reader.string(reader.member(list[q], path, "variable"), path + "/variable");
    const auto it = index.find(name);
    if (it == index.end()) reader.fail(path + "/variable", "'" + name + "' is not among the variables");
    if (equations[it->second]) reader.fail(path + "/variable", "'" + name + "' has a second equation");
    structural_equation e;
    const auto parents = reader.strings(reader.member(list[q], path, "parents"), path + "/parents");
    std::size_t configurations = 1;
    for (std::size_t k = 0; k < parents.size(); ++k) {
      const auto p = index.find(parents[k]);
      if (p == index.end()) {
        reader.fail(path + "/parents/" + std::to_string(k), "'" + parents[k] + "' is not among the variables");
      }
      e.parents.push_back(index_at<variable_id>(p->second));
      configurations = checked_table_cells(name, variables[p->second].cardinality(), configurations);
    }
    e.noise = reader.numbers(reader.member(list[q], path, "noise"), path + "/noise");
    const auto& rows = reader.array(reader.member(list[q], path, "values"), path + "/values");
    if (rows.size() != configurations) {
      reader.fail(path + "/values", "expected " + std::to_string(configurations) +
                                        " rows, one per configuration of the parents; found " +
                                        std::to_string(rows.size()));
    }
    const auto& v = variables[it->second];
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const auto row_path = path + "/values/" + std::to_string(r);
      const auto row = reader.strings(rows[r], row_path);
      if (row.size() != e.noise.size()) {
        reader.fail(row_path, "expected " + std::to_string(e.noise.size()) + " states, one per noise state; found " +
                                  std::to_string(row.size()));
      }
      for (std::size_t k = 0; k < row.size(); ++k) {
        const auto s = v.find_state(row[k]);
        if (!s) {
          reader.fail(row_path + "/" + std::to_string(k),
                      "'" + row[k] + "' is not a state of '" + name + "' (" + text::list_for_message(v.states()) + ")");
        }
        e.values.push_back(s->value());
      }
    }
    equations[it->second] = std::move(e);
  }
  std::vector<structural_equation> all;
  for (std::size_t i = 0; i < variables.size(); ++i) {
    if (!equations[i]) reader.fail("/equations", "'" + variables[i].name() + "' has no equation");
    all.push_back(std::move(*equations[i]));
  }
  try {
    return {std::move(variables), std::move(all)};
  } catch (const model_error& e) {
    reader.fail("/equations", e.what());
  }
}

PGM_DECL bool holds_structural_model(const std::filesystem::path& path) {
  return find_format_of(path) == network_format("json") && declared_model_kind(read_model_text(path)) == "structural";
}

PGM_DECL structural_model read_structural_model(const std::filesystem::path& path) {
  return parse_structural_json(read_model_text(path), path.string());
}

PGM_DECL void write_structural_json(std::ostream& out, const structural_model& model) {
  const auto document = to_json(model);
  const auto lines = [&](const char* key) {
    const auto& items = document.at(key);
    for (std::size_t i = 0; i < items.size(); ++i)
      out << "\n    " << items[i].dump() << (i + 1 < items.size() ? "," : "");
    out << (items.empty() ? "]" : "\n  ]");
  };
  out << "{\n  \"format\": \"pgm-model\",\n  \"version\": 1,\n  \"kind\": \"structural\",\n  \"variables\": [";
  lines("variables");
  out << ",\n  \"equations\": [";
  lines("equations");
  out << "\n}\n";
}

PGM_DECL void write_structural_model(const structural_model& model, const std::filesystem::path& path,
                                     const std::function<void()>& before_replacing) {
  write_file_atomically(
      path, [&](std::ostream& out) { write_structural_json(out, model); }, before_replacing);
}

}  // namespace pgm
