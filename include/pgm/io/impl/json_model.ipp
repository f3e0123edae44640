#pragma once
// The definitions of pgm/io/json_model.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <tuple>

#include "pgm/core/text.hpp"
#include "pgm/io/json_model.hpp"

namespace pgm::detail {

// A name read from a BIF or NET file may be any bytes.
PGM_DECL void require_utf8(std::string_view text, const std::string& what) {
  for (std::size_t i = 0; i < text.size();) {
    const auto length = text::utf8_sequence(text.substr(i));
    if (length == 0) {
      throw model_error(what + " '" + text::printable(text) + "' is not UTF-8 text, which JSON cannot hold");
    }
    i += length;
  }
}

PGM_DECL nlohmann::json variable_to_json(const variable& v) {
  require_utf8(v.name(), "the variable name");
  for (const auto& state : v.states()) require_utf8(state, "the state of '" + text::printable(v.name()) + "'");
  for (const auto* tag : {&v.tags().quantity, &v.tags().unit, &v.tags().role}) {
    require_utf8(*tag, "the tag of '" + text::printable(v.name()) + "'");
  }
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

PGM_DECL cpt<double> read_sparse_table(const json_reader& reader, const nlohmann::json& entry, const std::string& path,
                                       const variable& child, std::vector<variable> parents) {
  const auto& given = reader.array(reader.member(entry, path, "given"), path + "/given");
  const auto& rows = reader.array(reader.member(entry, path, "values"), path + "/values");
  const auto rest = reader.numbers(reader.member(entry, path, "rest"), path + "/rest");
  if (rows.size() != given.size()) {
    reader.fail(path + "/values", "expected one column per configuration in \"given\" (" +
                                      std::to_string(given.size()) + "), got " + std::to_string(rows.size()));
  }
  static_cast<void>(checked_table_cells(child.name(), child.cardinality(), given.size()));
  std::vector<std::size_t> cards;
  for (const auto& p : parents) cards.push_back(p.cardinality());
  const mixed_radix radix(cards);
  // Each stored configuration's index and where its column is, sorted by index.
  std::vector<std::pair<std::size_t, std::size_t>> order;
  for (std::size_t i = 0; i < given.size(); ++i) {
    const auto where = path + "/given/" + std::to_string(i);
    const auto states = reader.strings(given[i], where);
    if (states.size() != parents.size()) {
      reader.fail(where, "expected the states of the " + std::to_string(parents.size()) + " parents");
    }
    std::vector<std::size_t> codes;
    for (std::size_t k = 0; k < states.size(); ++k) {
      const auto& known = parents[k].states();
      const auto at = std::find(known.begin(), known.end(), states[k]);
      if (at == known.end()) {
        reader.fail(where + "/" + std::to_string(k),
                    "'" + states[k] + "' is not a state of '" + parents[k].name() + "'");
      }
      codes.push_back(static_cast<std::size_t>(at - known.begin()));
    }
    order.emplace_back(radix.encode(codes), i);
  }
  std::sort(order.begin(), order.end());
  sparse_columns<double> columns;
  columns.rest = rest;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto [u, i] = order[k];
    if (k > 0 && order[k - 1].first == u) {
      reader.fail(path + "/given/" + std::to_string(i), "this configuration is given twice");
    }
    const auto where = path + "/values/" + std::to_string(i);
    const auto column = reader.numbers(rows[i], where);
    if (column.size() != child.cardinality()) {
      reader.fail(where, "expected " + std::to_string(child.cardinality()) + " probabilities, one per state of '" +
                             child.name() + "'");
    }
    columns.configurations.push_back(u);
    columns.values.insert(columns.values.end(), column.begin(), column.end());
  }
  return cpt<double>(child, std::move(parents), std::move(columns));
}

/// nlohmann's dump(2) of `value` as it would appear `depth` levels deep in a document: the same
/// text, written straight to `out`.
inline void write_pretty(std::ostream& out, const nlohmann::json& value, std::size_t depth) {
  const std::string inner(2 * (depth + 1), ' ');
  if (value.is_object() && !value.empty()) {
    out << "{\n";
    bool first = true;
    for (const auto& [key, member] : value.items()) {
      out << (first ? "" : ",\n") << inner << nlohmann::json(key).dump() << ": ";
      write_pretty(out, member, depth + 1);
      first = false;
    }
    out << '\n' << std::string(2 * depth, ' ') << '}';
  } else if (value.is_array() && !value.empty()) {
    out << "[\n";
    for (std::size_t i = 0; i < value.size(); ++i) {
      out << (i ? ",\n" : "") << inner;
      write_pretty(out, value[i], depth + 1);
    }
    out << '\n' << std::string(2 * depth, ' ') << ']';
  } else {
    out << value.dump();
  }
}

/// One column of probabilities as dump(2) writes an array of numbers `depth` levels deep.
template <class Numbers>
void write_number_array(std::ostream& out, const Numbers& numbers, std::size_t depth) {
  if (numbers.size() == 0) {
    out << "[]";
    return;
  }
  const std::string inner(2 * (depth + 1), ' ');
  out << "[\n";
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    out << (i ? ",\n" : "") << inner << nlohmann::json(static_cast<double>(numbers[i])).dump();
  }
  out << '\n' << std::string(2 * depth, ' ') << ']';
}

/// A table entry of the "tables" array (depth 2), its keys in nlohmann's order.
inline void write_table_json(std::ostream& out, const cpt<double>& table) {
  nlohmann::json parents = nlohmann::json::array();
  for (const auto& p : table.parents()) parents.push_back(p.name());
  const std::string key(6, ' ');
  out << "    {\n";
  auto columns = [&](auto&& each_configuration) {
    out << key << "\"values\": [";
    bool first = true;
    each_configuration([&](std::size_t u) {
      out << (first ? "\n" : ",\n") << std::string(8, ' ');
      write_number_array(out, table.column(config_index(u)), 4);
      first = false;
    });
    out << (first ? "]" : "\n" + key + "]");
  };
  if (table.is_sparse()) {
    nlohmann::json given = nlohmann::json::array();
    for (const auto u : table.stored_configurations()) {
      const auto codes = table.parent_codes(config_index(u));
      nlohmann::json states = nlohmann::json::array();
      for (std::size_t k = 0; k < codes.size(); ++k) states.push_back(table.parents()[k].states()[codes[k]]);
      given.push_back(std::move(states));
    }
    out << key << "\"given\": ";
    write_pretty(out, given, 3);
    out << ",\n" << key << "\"parents\": ";
    write_pretty(out, parents, 3);
    out << ",\n" << key << "\"rest\": ";
    write_number_array(out, table.rest(), 3);
    out << ",\n";
    columns([&](auto&& write) {
      for (const auto u : table.stored_configurations()) write(u);
    });
  } else {
    out << key << "\"parents\": ";
    write_pretty(out, parents, 3);
    out << ",\n";
    columns([&](auto&& write) {
      for (std::size_t u = 0; u < table.configurations(); ++u) write(u);
    });
  }
  out << ",\n" << key << "\"variable\": " << nlohmann::json(table.child().name()).dump() << "\n    }";
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL void write_model_json(std::ostream& out, const bayesian_network& network, const fit_statistics* statistics) {
  // The keys in nlohmann's (alphabetical) order, as to_json(...).dump(2) writes them.
  nlohmann::json edges = nlohmann::json::array();
  for (const auto& edge : network.structure().edges()) edges.push_back({edge.from, edge.to});
  out << "{\n  \"edges\": ";
  detail::write_pretty(out, edges, 1);
  out << ",\n  \"format\": \"pgm-model\",\n";
  if (statistics) {
    out << "  \"statistics\": ";
    detail::write_pretty(out, to_json(*statistics), 1);
    out << ",\n";
  }
  out << "  \"tables\": [";
  const auto& tables = network.tables();
  for (std::size_t i = 0; i < tables.size(); ++i) {
    out << (i ? ",\n" : "\n");
    detail::write_table_json(out, tables[i]);
  }
  out << (tables.empty() ? "]" : "\n  ]") << ",\n  \"variables\": ";
  nlohmann::json variables = nlohmann::json::array();
  for (const auto& v : network.variables()) variables.push_back(detail::variable_to_json(v));
  detail::write_pretty(out, variables, 1);
  out << ",\n  \"version\": 1\n}\n";
}

PGM_DECL nlohmann::json to_json(const network_structure& structure, const std::vector<cpt<double>>* tables) {
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
      if (table.is_sparse()) {
        // The stored configurations by their parents' states, their columns, and the rest.
        nlohmann::json given = nlohmann::json::array();
        for (const auto u : table.stored_configurations()) {
          const auto codes = table.parent_codes(config_index(u));
          nlohmann::json states = nlohmann::json::array();
          for (std::size_t k = 0; k < codes.size(); ++k) states.push_back(table.parents()[k].states()[codes[k]]);
          given.push_back(std::move(states));
          const auto column = table.column(config_index(u));
          rows.push_back(std::vector<double>(column.begin(), column.end()));
        }
        document["tables"].push_back({{"variable", table.child().name()},
                                      {"parents", parents},
                                      {"given", given},
                                      {"values", rows},
                                      {"rest", std::vector<double>(table.rest().begin(), table.rest().end())}});
        continue;
      }
      for (std::size_t u = 0; u < table.configurations(); ++u) {
        const auto column = table.column(config_index(u));
        rows.push_back(std::vector<double>(column.begin(), column.end()));
      }
      document["tables"].push_back({{"variable", table.child().name()}, {"parents", parents}, {"values", rows}});
    }
  }
  return document;
}

PGM_DECL nlohmann::json to_json(const bayesian_network& network, const fit_statistics& statistics) {
  auto document = to_json(network);
  document["statistics"] = to_json(statistics);
  return document;
}

PGM_DECL void write_markov_json(std::ostream& out, const markov_network& model) {
  out << "{\n  \"format\": \"pgm-model\",\n  \"version\": 1,\n  \"kind\": \"markov\",\n  \"variables\": [";
  const auto& variables = model.variables();
  for (std::size_t i = 0; i < variables.size(); ++i) {
    out << (i ? ",\n    " : "\n    ") << detail::variable_to_json(variables[i]).dump();
  }
  out << (variables.empty() ? "],\n" : "\n  ],\n") << "  \"factors\": [";
  char number[32];
  for (std::size_t f = 0; f < model.factor_count(); ++f) {
    const auto& table = model.factor(f);
    out << (f ? ",\n    " : "\n    ") << "{\"scope\": [";
    for (std::size_t k = 0; k < table.scope().size(); ++k) {
      out << (k ? ", " : "") << nlohmann::json(variables[table.scope()[k].value()].name()).dump();
    }
    out << "], \"values\": [";
    for (std::size_t v = 0; v < table.values().size(); ++v) {
      const auto written = std::to_chars(number, number + sizeof number, table.values()[v]);
      out << (v ? ", " : "") << std::string_view(number, static_cast<std::size_t>(written.ptr - number));
    }
    out << "]}";
  }
  out << (model.factor_count() == 0 ? "]\n}\n" : "\n  ]\n}\n");
}

namespace detail {

/// The edges of `part` (a model document, or a slice of a dynamic model's) added to `structure`,
/// and its tables if it has any; errors name JSON paths under `path`. With `one_per_variable`,
/// the tables are checked against the edges, one per variable of `structure`.
PGM_DECL std::optional<std::vector<cpt<double>>> read_edges_and_tables(const json_reader& reader,
                                                                       const nlohmann::json& part,
                                                                       const std::string& path,
                                                                       network_structure& structure,
                                                                       bool one_per_variable) {
  if (const auto* edges = reader.optional_member(part, "edges")) {
    reader.array(*edges, path + "/edges");
    for (std::size_t i = 0; i < edges->size(); ++i) {
      const auto at = path + "/edges/" + std::to_string(i);
      const auto pair = reader.strings((*edges)[i], at);
      if (pair.size() != 2) reader.fail(at, "expected [from, to]");
      try {
        structure.add_edge(pair[0], pair[1]);
      } catch (const model_error& e) {
        reader.fail(at, e.what());
      }
    }
  }
  const auto* tables = reader.optional_member(part, "tables");
  if (!tables) return std::nullopt;
  std::vector<cpt<double>> read_tables;
  reader.array(*tables, path + "/tables");
  for (std::size_t i = 0; i < tables->size(); ++i) {
    const auto at = path + "/tables/" + std::to_string(i);
    const auto& entry = (*tables)[i];
    reader.only_keys(entry, at, {"variable", "parents", "values", "given", "rest"});
    const auto child = reader.string(reader.member(entry, at, "variable"), at + "/variable");
    const auto parent_names = reader.strings(reader.member(entry, at, "parents"), at + "/parents");
    const auto& rows = reader.array(reader.member(entry, at, "values"), at + "/values");
    try {
      std::vector<variable> parents;
      std::vector<std::size_t> cards;
      for (const auto& name : parent_names) {
        parents.push_back(structure.at(name));
        cards.push_back(parents.back().cardinality());
      }
      const auto& child_variable = structure.at(child);
      if (reader.optional_member(entry, "rest") || reader.optional_member(entry, "given")) {
        read_tables.push_back(read_sparse_table(reader, entry, at, child_variable, std::move(parents)));
        continue;
      }
      // A table beyond pgm's limit is refused before its values are copied.
      static_cast<void>(checked_table_cells(child, child_variable.cardinality(), mixed_radix(cards).size()));
      std::vector<double> values;
      for (std::size_t u = 0; u < rows.size(); ++u) {
        const auto row = reader.numbers(rows[u], at + "/values/" + std::to_string(u));
        values.insert(values.end(), row.begin(), row.end());
      }
      if (rows.size() > 0 && rows[0].size() != child_variable.cardinality()) {
        reader.fail(at + "/values/0", "expected " + std::to_string(child_variable.cardinality()) +
                                          " probabilities, one per state of '" + child + "'");
      }
      read_tables.emplace_back(child_variable, std::move(parents), std::move(values));
    } catch (const model_error& e) {
      reader.fail(at, e.what());
    }
  }
  if (one_per_variable) {
    try {
      // Checks the tables against the edges, one table per variable.
      static_cast<void>(bayesian_network(structure, read_tables));
    } catch (const model_error& e) {
      reader.fail(path + "/tables", e.what());
    }
  }
  return read_tables;
}

}  // namespace detail

PGM_DECL bool declares_markov_network(std::string_view text) { return declared_model_kind(text) == "markov"; }

namespace detail {

/// Finds the top-level "kind" of a JSON document as it is read, and stops there: knowing which
/// reader to call builds no document (the reader builds it once, its limits checked first).
struct model_kind_finder : nlohmann::json_sax<nlohmann::json> {
  std::size_t depth = 0;
  bool at_kind = false;
  std::string kind = "bayesian";

  /// A value seen; false (stop) once it was the kind's.
  bool value() {
    const bool found = at_kind;
    at_kind = false;
    return !found;
  }
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool string(string_t& text) override {
    if (at_kind) kind = text;
    return value();
  }
  bool start_object(std::size_t) override {
    ++depth;
    return value();
  }
  bool start_array(std::size_t) override {
    ++depth;
    return value() && depth > 1;  // a top-level array is no model: "bayesian", its reader says why
  }
  bool key(string_t& name) override {
    at_kind = depth == 1 && name == "kind";
    return true;
  }
  bool end_object() override { return --depth > 0; }
  bool end_array() override { return --depth > 0; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }
};

}  // namespace detail

PGM_DECL std::string declared_model_kind(std::string_view text) {
  detail::model_kind_finder finder;
  static_cast<void>(nlohmann::json::sax_parse(text, &finder, nlohmann::json::input_format_t::json, false));
  return finder.kind;
}

PGM_DECL nlohmann::json to_json(const dynamic_network& model, const dynamic_fit_statistics* statistics) {
  auto document = to_json(model.initial());
  nlohmann::json initial = {{"edges", document["edges"]}, {"tables", document["tables"]}};
  auto transition = to_json(model.transition_structure(), &model.transition_tables());
  document.erase("edges");
  document.erase("tables");
  document["kind"] = "dynamic";
  document["initial"] = std::move(initial);
  document["transition"] = {{"edges", transition["edges"]}, {"tables", transition["tables"]}};
  if (statistics) {
    document["statistics"] = {{"initial", to_json(statistics->initial)},
                              {"transition", to_json(statistics->transition)}};
  }
  return document;
}

PGM_DECL void write_dynamic_json(const dynamic_network& model, const std::filesystem::path& path,
                                 const std::function<void()>& before_replacing,
                                 const dynamic_fit_statistics* statistics) {
  const auto text = to_json(model, statistics).dump(2) + "\n";
  write_file_atomically(
      path, [&](std::ostream& out) { out << text; }, before_replacing);
}

namespace detail {

PGM_DECL dynamic_fit_statistics parse_dynamic_statistics(const json_reader& reader, const nlohmann::json& value,
                                                         const dynamic_network& model) {
  reader.only_keys(value, "/statistics", {"initial", "transition"});
  const auto& first = model.initial().structure();
  const auto& both = model.transition_structure();
  const auto templates = first.size();
  std::vector<expected_count_table> initial;
  std::vector<expected_count_table> transition;
  for (std::size_t i = 0; i < templates; ++i) {
    const auto node = index_at<variable_id>(i);
    const auto now = index_at<variable_id>(templates + i);
    initial.emplace_back(first.at(node), first.parent_variables(node));
    transition.emplace_back(both.at(now), both.parent_variables(now));
  }
  return {parse_statistics_json(reader, reader.member(value, "/statistics", "initial"), "/statistics/initial",
                                std::move(initial)),
          parse_statistics_json(reader, reader.member(value, "/statistics", "transition"), "/statistics/transition",
                                std::move(transition))};
}

}  // namespace detail

PGM_DECL dynamic_network parse_dynamic_json(std::string_view text, const std::string& source) {
  return parse_dynamic_model_json(text, source).model;
}

PGM_DECL dynamic_model_file parse_dynamic_model_json(std::string_view text, const std::string& source) {
  const detail::json_reader reader(source);
  const auto document = reader.parse(text);
  reader.check_format(document, "pgm-model");
  reader.only_keys(document, "",
                   {"format", "version", "kind", "variables", "initial", "transition", "metadata", "statistics"});
  if (reader.string(reader.member(document, "", "kind"), "/kind") != "dynamic") {
    reader.fail("/kind", "expected \"dynamic\": this reader reads dynamic networks");
  }
  std::vector<variable> variables;
  const auto& vars = reader.array(reader.member(document, "", "variables"), "/variables");
  for (std::size_t i = 0; i < vars.size(); ++i) {
    variables.push_back(reader.read_variable(vars[i], "/variables/" + std::to_string(i)));
    if (variables.back().name().find('@') != std::string::npos) {
      reader.fail("/variables/" + std::to_string(i),
                  "a template variable's name may not hold '@', which marks a slice");
    }
  }
  network_structure first;
  try {
    first = network_structure(variables);
  } catch (const model_error& e) {
    reader.fail("/variables", e.what());
  }
  const auto& initial = reader.member(document, "", "initial");
  reader.only_keys(initial, "/initial", {"edges", "tables"});
  auto first_tables = detail::read_edges_and_tables(reader, initial, "/initial", first, true);
  if (!first_tables) reader.fail("/initial", "the first slice needs its tables");

  // The transition's names first: each edge into this slice from it or the one before.
  const auto& transition = reader.member(document, "", "transition");
  reader.only_keys(transition, "/transition", {"edges", "tables"});
  const auto check_edge = [&](const std::string& from, const std::string& to, const std::string& at) {
    if (to.find('@') != std::string::npos) {
      reader.fail(at,
                  "'" + to + "' is of another slice: a transition's edges and tables are of this slice's variables");
    }
    try {
      static_cast<void>(detail::slice_of_parent(from, to));
    } catch (const model_error& e) {
      reader.fail(at, e.what());
    }
  };
  if (const auto* edges = reader.optional_member(transition, "edges"); edges && edges->is_array()) {
    for (std::size_t i = 0; i < edges->size(); ++i) {
      const auto at = "/transition/edges/" + std::to_string(i);
      const auto pair = reader.strings((*edges)[i], at);
      if (pair.size() == 2) check_edge(pair[0], pair[1], at);
    }
  }
  if (const auto* tables = reader.optional_member(transition, "tables"); tables && tables->is_array()) {
    for (std::size_t i = 0; i < tables->size(); ++i) {
      const auto at = "/transition/tables/" + std::to_string(i);
      const auto* child = reader.optional_member((*tables)[i], "variable");
      const auto* parents = reader.optional_member((*tables)[i], "parents");
      if (!child || !child->is_string() || !parents) continue;
      for (const auto& parent : reader.strings(*parents, at + "/parents")) {
        check_edge(parent, child->get<std::string>(), at);
      }
    }
  }
  network_structure both;
  try {
    both = dynamic_network::two_slices(variables);
  } catch (const model_error& e) {
    reader.fail("/variables", e.what());
  }
  auto tables = detail::read_edges_and_tables(reader, transition, "/transition", both, false);
  if (!tables) reader.fail("/transition", "the transition needs its tables");
  std::optional<dynamic_network> model;
  try {
    model.emplace(bayesian_network(first, std::move(*first_tables)), std::move(*tables));
  } catch (const model_error& e) {
    reader.fail("/transition", e.what());
  }
  const auto sorted = [](std::vector<named_edge> edges) {
    std::sort(edges.begin(), edges.end(),
              [](const named_edge& a, const named_edge& b) { return std::tie(a.from, a.to) < std::tie(b.from, b.to); });
    return edges;
  };
  if (sorted(model->transition_structure().edges()) != sorted(both.edges())) {
    reader.fail("/transition/edges", "the edges differ from the tables' parents");
  }
  dynamic_model_file file{std::move(*model), std::nullopt};
  if (const auto* statistics = reader.optional_member(document, "statistics")) {
    file.statistics = detail::parse_dynamic_statistics(reader, *statistics, file.model);
  }
  return file;
}

PGM_DECL markov_network parse_markov_json(std::string_view text, const std::string& source) {
  const detail::json_reader reader(source);
  const auto document = reader.parse(text);
  reader.check_format(document, "pgm-model");
  reader.only_keys(document, "", {"format", "version", "kind", "variables", "factors", "metadata"});
  if (reader.string(reader.member(document, "", "kind"), "/kind") != "markov") {
    reader.fail("/kind", "expected \"markov\": this reader reads Markov networks");
  }
  std::vector<variable> variables;
  const auto& vars = reader.array(reader.member(document, "", "variables"), "/variables");
  for (std::size_t i = 0; i < vars.size(); ++i) {
    variables.push_back(reader.read_variable(vars[i], "/variables/" + std::to_string(i)));
  }
  // Names to ids; two variables of one name are the model's to refuse below.
  std::map<std::string, std::size_t, std::less<>> ids;
  for (std::size_t i = 0; i < variables.size(); ++i) ids.emplace(variables[i].name(), i);
  std::vector<factor_table> factors;
  const auto& entries = reader.array(reader.member(document, "", "factors"), "/factors");
  for (std::size_t f = 0; f < entries.size(); ++f) {
    const auto path = "/factors/" + std::to_string(f);
    reader.only_keys(entries[f], path, {"scope", "values"});
    const auto names = reader.strings(reader.member(entries[f], path, "scope"), path + "/scope");
    std::vector<variable_id> scope;
    std::vector<std::size_t> cards;
    for (std::size_t k = 0; k < names.size(); ++k) {
      const auto at = ids.find(names[k]);
      if (at == ids.end()) {
        reader.fail(path + "/scope/" + std::to_string(k), "'" + names[k] + "' is not a variable of the model");
      }
      scope.push_back(index_at<variable_id>(at->second));
      cards.push_back(variables[at->second].cardinality());
    }
    // A factor beyond pgm's limit is refused before its values are read.
    std::size_t cells = 1;
    for (const auto c : cards) cells = detail::saturating_multiply(cells, c);
    if (cells > max_table_cells) {
      reader.fail(path, "a factor of " + std::to_string(cells) + " cells is more than pgm's limit of " +
                            std::to_string(max_table_cells) + " (docs/limits.md)");
    }
    const auto values = reader.numbers(reader.member(entries[f], path, "values"), path + "/values");
    try {
      factors.emplace_back(std::move(scope), std::move(cards), values);
    } catch (const model_error& e) {
      reader.fail(path, e.what());
    }
  }
  try {
    return markov_network(std::move(variables), std::move(factors));
  } catch (const model_error& e) {
    reader.fail("", e.what());
  }
}

PGM_DECL model_document parse_model_json(std::string_view text, const std::string& source) {
  const detail::json_reader reader(source);
  const auto document = reader.parse(text);
  reader.check_format(document, "pgm-model");
  if (const auto* kind = reader.optional_member(document, "kind"); kind && kind->is_string() && *kind == "markov") {
    reader.fail("/kind",
                "this file holds a Markov network, not a Bayesian network or structure; pgm query, "
                "show, solve and convert read it");
  }
  if (const auto* kind = reader.optional_member(document, "kind"); kind && kind->is_string() && *kind == "dynamic") {
    reader.fail("/kind",
                "this file holds a dynamic network, not a Bayesian network or structure; pgm unroll makes one of it "
                "over a number of slices");
  }
  if (const auto* kind = reader.optional_member(document, "kind"); kind && kind->is_string() && *kind == "structural") {
    reader.fail("/kind",
                "this file holds a structural model, not a Bayesian network or structure; pgm counterfactual reads it");
  }
  // Free for people and tools: "metadata" (io/decision_model.hpp reads its "success") and
  // "learned" (how pgm learn-structure found the structure).
  reader.only_keys(document, "",
                   {"format", "version", "kind", "variables", "edges", "tables", "statistics", "metadata", "learned"});
  if (const auto* kind = reader.optional_member(document, "kind")) {
    if (reader.string(*kind, "/kind") != "bayesian") {
      reader.fail("/kind", "expected \"bayesian\", \"markov\" or \"dynamic\"");
    }
  }
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
  result.tables = detail::read_edges_and_tables(reader, document, "", result.structure, true);
  if (const auto* statistics = reader.optional_member(document, "statistics")) {
    if (!result.tables) reader.fail("/statistics", "statistics need the tables they were estimated into");
    result.statistics = parse_statistics_json(reader, *statistics, result.structure);
  }
  return result;
}

PGM_DECL nlohmann::json to_json(const discretization& d) {
  nlohmann::json document = {{"format", "pgm-discretization"}, {"version", 1}};
  document["variables"] = nlohmann::json::array();
  for (const auto& [name, v] : d) document["variables"].push_back(detail::variable_to_json(v));
  return document;
}

PGM_DECL discretization parse_discretization_json(std::string_view text, const std::string& source) {
  const detail::json_reader reader(source);
  const auto document = reader.parse(text);
  reader.check_format(document, "pgm-discretization");
  reader.only_keys(document, "", {"format", "version", "variables"});
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

}  // namespace pgm
