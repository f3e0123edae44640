#pragma once
/// \file
/// pgm's JSON model file: variables (states, interval edges, semantic tags), edges and,
/// optionally, tables. A file without tables is a structure (what `learn-structure` writes
/// and `fit --model` reads). Errors name the file and either the line and column (syntax) or
/// the JSON path of the offending value (content). Numbers are written as the shortest text
/// that reads back to the same double.
///
/// {
///   "format": "pgm-model", "version": 1,
///   "variables": [{"name": "xOff1", "states": ["0", "1"], "edges": [-3, 0, 3],
///                  "tags": {"quantity": "x-offset", "unit": "cm", "role": "cubeUp1"}}, …],
///   "edges": [["xOff1", "onTop1"], …],
///   "tables": [{"variable": "onTop1", "parents": ["xOff1"],
///               "values": [[0.1, 0.9], [0.8, 0.2]]}, …]   // one row per configuration
/// }

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/discretizer.hpp"
#include "pgm/detail/file.hpp"

namespace pgm {

/// What a model file holds: a structure, and tables if it is a fitted network.
struct model_document {
  network_structure structure;
  std::optional<std::vector<cpt<double>>> tables;

  /// The network; throws model_error if the file has no tables.
  [[nodiscard]] bayesian_network network() const {
    if (!tables) throw model_error("the model has a structure but no tables; fit it first");
    return bayesian_network(structure, *tables);
  }
};

namespace detail {

/// Reads typed values out of a parsed document, naming the JSON path of anything amiss.
class json_reader {
 public:
  explicit json_reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw data_error(source_ + ": " + (path.empty() ? "/" : path) + ": " + what);
  }

  const nlohmann::json& member(const nlohmann::json& object, const std::string& path,
                               const char* key) const {
    if (!object.is_object()) fail(path, "expected an object");
    const auto it = object.find(key);
    if (it == object.end()) fail(path, std::string("the key '") + key + "' is missing");
    return *it;
  }
  const nlohmann::json* optional_member(const nlohmann::json& object, const char* key) const {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }
  std::string string(const nlohmann::json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, "expected a string");
    return value.get<std::string>();
  }
  double number(const nlohmann::json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, "expected a number");
    return value.get<double>();
  }
  const nlohmann::json& array(const nlohmann::json& value, const std::string& path) const {
    if (!value.is_array()) fail(path, "expected an array");
    return value;
  }
  std::vector<std::string> strings(const nlohmann::json& value, const std::string& path) const {
    std::vector<std::string> result;
    std::size_t i = 0;
    for (const auto& item : array(value, path)) result.push_back(string(item, path + "/" + std::to_string(i++)));
    return result;
  }
  std::vector<double> numbers(const nlohmann::json& value, const std::string& path) const {
    std::vector<double> result;
    std::size_t i = 0;
    for (const auto& item : array(value, path)) result.push_back(number(item, path + "/" + std::to_string(i++)));
    return result;
  }

  variable read_variable(const nlohmann::json& value, const std::string& path) const {
    const auto name = string(member(value, path, "name"), path + "/name");
    auto states = strings(member(value, path, "states"), path + "/states");
    semantic_tags tags;
    if (const auto* t = optional_member(value, "tags")) {
      const auto tags_path = path + "/tags";
      if (!t->is_object()) fail(tags_path, "expected an object");
      if (const auto* q = optional_member(*t, "quantity")) tags.quantity = string(*q, tags_path + "/quantity");
      if (const auto* u = optional_member(*t, "unit")) tags.unit = string(*u, tags_path + "/unit");
      if (const auto* r = optional_member(*t, "role")) tags.role = string(*r, tags_path + "/role");
    }
    try {
      variable result(name, std::move(states), std::move(tags));
      if (const auto* e = optional_member(value, "edges")) result.set_edges(numbers(*e, path + "/edges"));
      return result;
    } catch (const model_error& e) {
      fail(path, e.what());
    }
  }

  nlohmann::json parse(std::string_view text) const {
    try {
      return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
      // e.byte is 1-based; turn it into a line and column.
      std::size_t line = 1;
      std::size_t column = 1;
      for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
          ++line;
          column = 1;
        } else {
          ++column;
        }
      }
      std::string what = e.what();
      if (const auto colon = what.rfind(": "); colon != std::string::npos) what = what.substr(colon + 2);
      throw parse_error(source_, line, column, "invalid JSON: " + what);
    } catch (const nlohmann::json::out_of_range& e) {
      // A number too large for a double ("1e999"): nlohmann gives no position, so find the
      // number it names in the text.
      const std::string what = e.what();
      const auto open = what.find('\''), close = what.rfind('\'');
      const auto number = open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : std::string();
      const auto at = number.empty() ? std::string_view::npos : text.find(number);
      std::size_t line = 1, column = 1;
      for (std::size_t i = 0; at != std::string_view::npos && i < at; ++i) {
        if (text[i] == '\n') {
          ++line;
          column = 1;
        } else {
          ++column;
        }
      }
      throw parse_error(source_, line, column, "number out of range: '" + number + "'");
    }
  }

  void check_format(const nlohmann::json& document, const char* expected) const {
    const auto format = string(member(document, "", "format"), "/format");
    if (format != expected) {
      fail("/format", "expected \"" + std::string(expected) + "\", found \"" + format + "\"");
    }
    const auto version = number(member(document, "", "version"), "/version");
    if (version != 1) fail("/version", "this pgm reads version 1, the file is version " + format_double(version));
  }

 private:
  std::string source_;
};

inline nlohmann::json variable_to_json(const variable& v) {
  nlohmann::json out = {{"name", v.name()}, {"states", v.states()}};
  if (v.has_intervals()) out["edges"] = v.edges();
  if (!v.tags().empty()) {
    nlohmann::json tags = nlohmann::json::object();
    if (!v.tags().quantity.empty()) tags["quantity"] = v.tags().quantity;
    if (!v.tags().unit.empty()) tags["unit"] = v.tags().unit;
    if (!v.tags().role.empty()) tags["role"] = v.tags().role;
    out["tags"] = tags;
  }
  return out;
}

}  // namespace detail

[[nodiscard]] inline nlohmann::json to_json(const network_structure& structure,
                                            const std::vector<cpt<double>>* tables = nullptr) {
  nlohmann::json document = {{"format", "pgm-model"}, {"version", 1}};
  document["variables"] = nlohmann::json::array();
  for (const auto& v : structure.variables()) document["variables"].push_back(detail::variable_to_json(v));
  document["edges"] = nlohmann::json::array();
  for (const auto& edge : structure.edges()) document["edges"].push_back({edge.from, edge.to});
  if (tables) {
    document["tables"] = nlohmann::json::array();
    for (const auto& table : *tables) {
      nlohmann::json parents = nlohmann::json::array();
      for (const auto& p : table.parents()) parents.push_back(p.name());
      nlohmann::json rows = nlohmann::json::array();
      for (std::size_t u = 0; u < table.configurations(); ++u) {
        const auto column = table.column(config_index(u));
        rows.push_back(std::vector<double>(column.begin(), column.end()));
      }
      document["tables"].push_back(
          {{"variable", table.child().name()}, {"parents", parents}, {"values", rows}});
    }
  }
  return document;
}

[[nodiscard]] inline nlohmann::json to_json(const bayesian_network& network) {
  return to_json(network.structure(), &network.tables());
}

[[nodiscard]] inline model_document parse_model_json(std::string_view text, const std::string& source) {
  const detail::json_reader reader(source);
  const auto document = reader.parse(text);
  reader.check_format(document, "pgm-model");
  std::vector<variable> variables;
  const auto& vars = reader.array(reader.member(document, "", "variables"), "/variables");
  for (std::size_t i = 0; i < vars.size(); ++i) {
    variables.push_back(reader.read_variable(vars[i], "/variables/" + std::to_string(i)));
  }
  model_document result;
  try {
    result.structure = network_structure(variables);
  } catch (const model_error& e) {
    reader.fail("/variables", e.what());
  }
  if (const auto* edges = reader.optional_member(document, "edges")) {
    reader.array(*edges, "/edges");
    for (std::size_t i = 0; i < edges->size(); ++i) {
      const auto path = "/edges/" + std::to_string(i);
      const auto pair = reader.strings((*edges)[i], path);
      if (pair.size() != 2) reader.fail(path, "expected [from, to]");
      try {
        result.structure.add_edge(pair[0], pair[1]);
      } catch (const model_error& e) {
        reader.fail(path, e.what());
      }
    }
  }
  if (const auto* tables = reader.optional_member(document, "tables")) {
    std::vector<cpt<double>> read_tables;
    reader.array(*tables, "/tables");
    for (std::size_t i = 0; i < tables->size(); ++i) {
      const auto path = "/tables/" + std::to_string(i);
      const auto& entry = (*tables)[i];
      const auto child = reader.string(reader.member(entry, path, "variable"), path + "/variable");
      const auto parent_names = reader.strings(reader.member(entry, path, "parents"), path + "/parents");
      const auto& rows = reader.array(reader.member(entry, path, "values"), path + "/values");
      std::vector<double> values;
      for (std::size_t u = 0; u < rows.size(); ++u) {
        const auto row = reader.numbers(rows[u], path + "/values/" + std::to_string(u));
        values.insert(values.end(), row.begin(), row.end());
      }
      try {
        std::vector<variable> parents;
        for (const auto& name : parent_names) parents.push_back(result.structure.at(name));
        const auto& child_variable = result.structure.at(child);
        if (rows.size() > 0 && rows[0].size() != child_variable.cardinality()) {
          reader.fail(path + "/values/0", "expected " + std::to_string(child_variable.cardinality()) +
                                              " probabilities, one per state of '" + child + "'");
        }
        read_tables.emplace_back(child_variable, std::move(parents), std::move(values));
      } catch (const model_error& e) {
        reader.fail(path, e.what());
      }
    }
    try {
      // Checks the tables against the edges, one table per variable.
      static_cast<void>(bayesian_network(result.structure, read_tables));
    } catch (const model_error& e) {
      reader.fail("/tables", e.what());
    }
    result.tables = std::move(read_tables);
  }
  return result;
}

[[nodiscard]] inline model_document read_model_json(const std::filesystem::path& path) {
  return parse_model_json(detail::read_file(path), path.string());
}

inline void write_model_json(const nlohmann::json& document, const std::filesystem::path& path) {
  const auto text = document.dump(2) + "\n";
  detail::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

// ---- discretization files ------------------------------------------------------------------

[[nodiscard]] inline nlohmann::json to_json(const discretization& d) {
  nlohmann::json document = {{"format", "pgm-discretization"}, {"version", 1}};
  document["variables"] = nlohmann::json::array();
  for (const auto& [name, v] : d) document["variables"].push_back(detail::variable_to_json(v));
  return document;
}

[[nodiscard]] inline discretization parse_discretization_json(std::string_view text,
                                                              const std::string& source) {
  const detail::json_reader reader(source);
  const auto document = reader.parse(text);
  reader.check_format(document, "pgm-discretization");
  discretization result;
  const auto& vars = reader.array(reader.member(document, "", "variables"), "/variables");
  for (std::size_t i = 0; i < vars.size(); ++i) {
    const auto path = "/variables/" + std::to_string(i);
    auto v = reader.read_variable(vars[i], path);
    if (!v.has_intervals()) reader.fail(path, "a discretized variable needs interval edges");
    const auto name = v.name();
    if (!result.emplace(name, std::move(v)).second) reader.fail(path, "'" + name + "' appears twice");
  }
  return result;
}

[[nodiscard]] inline discretization read_discretization_json(const std::filesystem::path& path) {
  return parse_discretization_json(detail::read_file(path), path.string());
}

}  // namespace pgm
