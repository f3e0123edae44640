// XMLBIF reading and writing on pugixml (pgm/io/xmlbif.hpp).

#include "pgm/io/xmlbif.hpp"

#include <pugixml.hpp>
#include <sstream>
#include <vector>

#include "io/network_text.hpp"
#include "pgm/core/error.hpp"
#include "pgm/detail/file.hpp"
#include "pgm/detail/text.hpp"

namespace pgm {
namespace {

class xmlbif_reader {
 public:
  xmlbif_reader(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  bayesian_network read(const network_read_options& options) {
    pugi::xml_document document;
    const auto result = document.load_buffer(text_.data(), text_.size(), pugi::parse_default);
    if (!result) {
      fail(detail::position_of(text_, static_cast<std::size_t>(std::max<std::ptrdiff_t>(result.offset, 0))),
           std::string("invalid XML: ") + result.description());
    }
    const auto root = document.document_element();
    if (std::string_view(root.name()) != "BIF") {
      fail(at(root), "expected the XMLBIF root element <BIF>, found <" + std::string(root.name()) + ">");
    }
    const auto network = root.child("NETWORK");
    if (!network) fail(at(root), "<BIF> has no <NETWORK>");
    std::vector<detail::declared_variable> variables;
    std::vector<detail::declared_table> tables;
    for (const auto& node : network.children()) {
      if (node.type() != pugi::node_element) continue;
      const std::string_view name = node.name();
      if (name == "VARIABLE") {
        variables.push_back(read_variable(node));
      } else if (name == "DEFINITION" || name == "PROBABILITY") {  // PROBABILITY: XMLBIF 0.2
        tables.push_back(read_table(node));
      }
      // NAME, PROPERTY and elements of later versions carry nothing pgm keeps.
    }
    if (variables.empty()) fail(at(network), "the file declares no variables");
    return detail::build_network(variables, std::move(tables), source_, options,
                                 [this](detail::text_position p, const std::string& what) { fail(p, what); });
  }

 private:
  [[noreturn]] void fail(detail::text_position p, const std::string& what) const {
    throw parse_error(source_, p.line, p.column, what);
  }

  detail::text_position at(const pugi::xml_node& node) const {
    const auto offset = node.offset_debug();
    if (offset < 0) return {};
    // offset_debug points at the name after '<' for elements; report the '<'.
    const auto o = static_cast<std::size_t>(offset);
    return detail::position_of(text_, node.type() == pugi::node_element && o > 0 ? o - 1 : o);
  }

  /// The text of the one child `name` of `node`, failing when it is missing.
  std::string single_text(const pugi::xml_node& node, const char* name) const {
    const auto child = node.child(name);
    if (!child) fail(at(node), "<" + std::string(node.name()) + "> has no <" + name + ">");
    if (child.next_sibling(name)) fail(at(child.next_sibling(name)), "a second <" + std::string(name) + ">");
    return child.text().get();
  }

  detail::declared_variable read_variable(const pugi::xml_node& node) {
    detail::declared_variable v;
    v.at = at(node);
    v.name = single_text(node, "NAME");
    const auto type = std::string_view(node.attribute("TYPE").value());
    if (!type.empty() && type != "nature") {
      fail(v.at, "variable '" + v.name + "' has TYPE=\"" + std::string(type) +
                     "\"; only chance (\"nature\") variables are supported");
    }
    for (const auto& outcome : node.children("OUTCOME")) v.states.emplace_back(outcome.text().get());
    if (v.states.empty()) fail(v.at, "variable '" + v.name + "' has no <OUTCOME>");
    for (const auto& property : node.children("PROPERTY")) {
      const std::string_view text = property.text().get();
      const auto eq = text.find('=');
      if (eq == std::string_view::npos) continue;  // pgmpy writes an empty <PROPERTY/>
      try {
        detail::apply_pgm_property(v, detail::trim(text.substr(0, eq)), detail::trim(text.substr(eq + 1)), ", \t\n");
      } catch (const model_error& e) {
        fail(at(property), e.what());
      }
    }
    return v;
  }

  detail::declared_table read_table(const pugi::xml_node& node) {
    detail::declared_table table;
    table.at = at(node);
    table.child = single_text(node, "FOR");
    for (const auto& given : node.children("GIVEN")) table.parents.emplace_back(given.text().get(), at(given));
    const auto values = node.child("TABLE");
    if (!values) fail(at(node), "the definition of '" + table.child + "' has no <TABLE>");
    table.values_at = at(values);
    const auto text_node = values.first_child();
    const std::string_view numbers = values.text().get();
    const auto base = text_node ? at(text_node) : table.values_at;
    std::size_t i = 0;
    while (i < numbers.size()) {
      while (i < numbers.size() && std::string_view(" \t\r\n").find(numbers[i]) != std::string_view::npos) ++i;
      const auto start = i;
      while (i < numbers.size() && std::string_view(" \t\r\n").find(numbers[i]) == std::string_view::npos) ++i;
      if (start == i) break;
      const auto word = numbers.substr(start, i - start);
      const auto value = detail::parse_double(word);
      if (!value || !std::isfinite(*value)) {
        auto p = base;
        if (text_node && text_node.offset_debug() >= 0) {
          p = detail::position_of(text_, static_cast<std::size_t>(text_node.offset_debug()) + start);
        }
        fail(p, "expected a probability in the table of '" + table.child + "', found '" + std::string(word) + "'");
      }
      table.values.push_back(*value);
    }
    return table;
  }

  std::string_view text_;
  const std::string& source_;
};

void add_text(pugi::xml_node parent, const char* name, const std::string& text) {
  parent.append_child(name).text().set(text.c_str());
}

}  // namespace

bayesian_network parse_xmlbif(std::string_view text, const std::string& source, const network_read_options& options) {
  return xmlbif_reader(text, source).read(options);
}

bayesian_network read_xmlbif(const std::filesystem::path& path, const network_read_options& options) {
  return parse_xmlbif(detail::read_file(path), path.string(), options);
}

void write_xmlbif(const bayesian_network& network, std::ostream& out, const xmlbif_write_options& options) {
  pugi::xml_document document;
  auto declaration = document.append_child(pugi::node_declaration);
  declaration.append_attribute("version") = "1.0";
  declaration.append_attribute("encoding") = "UTF-8";
  auto root = document.append_child("BIF");
  root.append_attribute("VERSION") = "0.3";
  auto net = root.append_child("NETWORK");
  add_text(net, "NAME", options.network_name);
  for (const auto& v : network.variables()) {
    auto node = net.append_child("VARIABLE");
    node.append_attribute("TYPE") = "nature";
    add_text(node, "NAME", v.name());
    for (const auto& state : v.states()) add_text(node, "OUTCOME", state);
    if (!options.properties) continue;
    if (v.has_intervals()) {
      std::vector<std::string> edges;
      for (const double e : v.edges()) edges.push_back(detail::format_double(e));
      add_text(node, "PROPERTY", "edges = " + detail::join(edges, ", "));
    }
    const auto& tags = v.tags();
    for (const auto& [key, value] : {std::pair<const char*, const std::string*>{"quantity", &tags.quantity},
                                     {"unit", &tags.unit},
                                     {"role", &tags.role}}) {
      if (value->empty()) continue;
      if (value->find('=') != std::string::npos) {
        throw model_error("the " + std::string(key) + " tag of '" + v.name() +
                          "' contains '=', which pgmpy's XMLBIF reader splits properties at");
      }
      add_text(node, "PROPERTY", std::string(key) + " = " + *value);
    }
  }
  for (const auto& table : network.tables()) {
    auto node = net.append_child("DEFINITION");
    add_text(node, "FOR", table.child().name());
    for (const auto& parent : table.parents()) add_text(node, "GIVEN", parent.name());
    std::string values;
    for (const double value : table.values()) {
      if (!values.empty()) values += ' ';
      values += detail::format_double(value);
    }
    add_text(node, "TABLE", values);
  }
  document.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
}

std::string to_xmlbif(const bayesian_network& network, const xmlbif_write_options& options) {
  std::ostringstream out;
  write_xmlbif(network, out, options);
  return out.str();
}

void write_xmlbif(const bayesian_network& network, const std::filesystem::path& path,
                  const xmlbif_write_options& options) {
  const auto text = to_xmlbif(network, options);
  detail::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace pgm
