// XMLBIF reading and writing on pugixml (pgm/io/xmlbif.hpp).

#include "pgm/io/xmlbif.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <pugixml.hpp>
#include <sstream>
#include <string_view>
#include <vector>

#include "io/builtin_formats.hpp"
#include "io/network_text.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/text.hpp"

namespace pgm {
namespace {

/// A problem at a byte offset of the file, turned into file:line:column by the reader.
struct xml_problem {
  std::size_t offset;
  std::string what;
};

[[noreturn]] void refuse(std::size_t offset, std::string what) { throw xml_problem{offset, std::move(what)}; }

/// Appends the UTF-8 of `code`, refusing what is no character XML allows (as expat does).
void append_character(std::string& out, std::uint32_t code, std::size_t offset) {
  const bool allowed = code == 0x9 || code == 0xA || code == 0xD || (code >= 0x20 && code <= 0xD7FF) ||
                       (code >= 0xE000 && code <= 0xFFFD) || (code >= 0x10000 && code <= 0x10FFFF);
  if (!allowed) refuse(offset, "a reference to a character XML does not allow");
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

/// The code point of a character reference's body ("#65", "#x41"), or nothing.
std::optional<std::uint32_t> character_code(std::string_view body) {
  if (body.size() < 2 || body[0] != '#') return std::nullopt;
  const bool hex = body[1] == 'x';
  const auto digits = body.substr(hex ? 2 : 1);
  if (digits.empty()) return std::nullopt;
  std::uint32_t code = 0;
  for (const char c : digits) {
    const int digit = c >= '0' && c <= '9'                            ? c - '0'
                      : hex && (c | 0x20) >= 'a' && (c | 0x20) <= 'f' ? (c | 0x20) - 'a' + 10
                                                                      : -1;
    if (digit < 0) return std::nullopt;
    code = code * (hex ? 16 : 10) + static_cast<std::uint32_t>(digit);
    if (code > 0x10FFFF) return 0;  // refused as no character
  }
  return code;
}

/// Text with its references resolved as ElementTree (expat), which pgmpy reads XMLBIF with,
/// resolves them: character references, the five predefined entities, and the general entities
/// the internal DTD subset declares (`<!ENTITY two "2">`), expanded within
/// xml_max_entity_bytes (a "billion laughs" file is refused). What expat refuses is refused:
/// undeclared, external, recursive and parameter entities, and markup inside an entity.
class xml_text_decoder {
 public:
  /// Reads the entity declarations of a DOCTYPE's text (what follows `<!DOCTYPE`), which
  /// starts at byte `offset` of the file.
  void declare(std::string_view doctype, std::size_t offset) {
    std::size_t i = 0;
    const auto skip_quoted_to = [&](char end) {  // to just past `end`, outside quotes
      while (i < doctype.size() && doctype[i] != end) {
        if (doctype[i] == '"' || doctype[i] == '\'') {
          const auto close = doctype.find(doctype[i], i + 1);
          i = close == std::string_view::npos ? doctype.size() : close;
        }
        ++i;
      }
      ++i;
    };
    skip_quoted_to('[');
    while (i < doctype.size()) {
      const auto rest = doctype.substr(i);
      if (std::string_view(" \t\r\n").find(rest[0]) != std::string_view::npos) {
        ++i;
      } else if (rest[0] == ']') {
        return;
      } else if (rest.starts_with("<!--")) {
        const auto end = rest.find("-->");
        i += end == std::string_view::npos ? rest.size() : end + 3;
      } else if (rest.starts_with("<?")) {
        const auto end = rest.find("?>");
        i += end == std::string_view::npos ? rest.size() : end + 2;
      } else if (rest.starts_with("<!ENTITY")) {
        i += declare_entity(rest, offset + i);
      } else if (rest[0] == '%') {
        refuse(offset + i,
               "a parameter entity reference in the DTD; pgm reads only general entities (<!ENTITY name "
               "\"text\">), as pgmpy's ElementTree does");
      } else if (rest.starts_with("<!")) {
        skip_quoted_to('>');  // ELEMENT, ATTLIST, NOTATION: nothing pgm uses
      } else {
        refuse(offset + i, "unexpected text in the DTD");
      }
    }
  }

  /// Refuses a control character in text as the file has it (XML allows none but tab, line
  /// feed and carriage return, raw or by reference) and bytes that are not UTF-8, as expat
  /// (pgmpy's parser) refuses both.
  static void check_characters(std::string_view raw, std::size_t offset) {
    for (std::size_t i = 0; i < raw.size();) {
      const auto c = static_cast<unsigned char>(raw[i]);
      if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') {
        refuse(offset + i, "a control character (byte " + std::to_string(c) + ") that XML does not allow");
      }
      const auto length = text::utf8_sequence(raw.substr(i));
      if (length == 0) refuse(offset + i, "bytes that are not UTF-8, the file's encoding");
      i += length;
    }
  }

  /// The text of character data `raw` (as the file has it) at byte `offset`.
  std::string decode(std::string_view raw, std::size_t offset) {
    // pugixml lets '<' through in an attribute's value; XML (and ElementTree) refuse it.
    if (const auto angle = raw.find('<'); angle != std::string_view::npos) {
      refuse(offset, "a '<' in an attribute's value (write &lt; for '<')");
    }
    check_characters(raw, offset);
    std::string out;
    if (raw.find('&') == std::string_view::npos) return std::string(raw);
    std::vector<std::string_view> open;
    expand(raw, offset, out, open);
    return out;
  }

 private:
  struct entity {
    std::string text;  // the replacement text, character references resolved
    bool external = false;
  };

  /// Reads `<!ENTITY name "value">` at the start of `text`; returns the bytes read.
  std::size_t declare_entity(std::string_view text, std::size_t offset) {
    std::size_t i = std::string_view("<!ENTITY").size();
    const auto spaces = [&] {
      while (i < text.size() && std::string_view(" \t\r\n").find(text[i]) != std::string_view::npos) ++i;
    };
    spaces();
    if (i < text.size() && text[i] == '%') {
      refuse(offset + i,
             "a parameter entity (<!ENTITY % …>); pgm reads only general entities, as pgmpy's "
             "ElementTree does");
    }
    const auto name_start = i;
    while (i < text.size() && std::string_view(" \t\r\n\"'>").find(text[i]) == std::string_view::npos) ++i;
    const std::string name(text.substr(name_start, i - name_start));
    if (name.empty()) refuse(offset + i, "an entity declaration without a name");
    spaces();
    entity declared;
    if (i < text.size() && (text[i] == '"' || text[i] == '\'')) {
      const auto close = text.find(text[i], i + 1);
      if (close == std::string_view::npos) refuse(offset + i, "the value of the entity '" + name + "' is never closed");
      declared.text = literal(text.substr(i + 1, close - i - 1), offset + i + 1);
      i = close + 1;
    } else {
      declared.external = true;  // SYSTEM or PUBLIC: a file or address, never read
    }
    while (i < text.size() && text[i] != '>') {
      if (text[i] == '"' || text[i] == '\'') {
        const auto close = text.find(text[i], i + 1);
        i = close == std::string_view::npos ? text.size() : close;
      }
      ++i;
    }
    if (i >= text.size()) refuse(offset, "the declaration of the entity '" + name + "' is never closed");
    entities_.emplace(name, std::move(declared));  // the first declaration binds
    return i + 1;
  }

  /// An entity's value as declared: character references resolved now, entity references
  /// kept for when the entity is used.
  std::string literal(std::string_view value, std::size_t offset) {
    std::string out;
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (value[i] == '%') refuse(offset + i, "a parameter entity reference in an entity's value");
      if (value[i] == '&' && i + 1 < value.size() && value[i + 1] == '#') {
        const auto end = value.find(';', i);
        const auto code =
            end == std::string_view::npos ? std::nullopt : character_code(value.substr(i + 1, end - i - 1));
        if (!code) refuse(offset + i, "a malformed character reference");
        append_character(out, *code, offset + i);
        i = end;
        continue;
      }
      out += value[i];
    }
    return out;
  }

  void expand(std::string_view text, std::size_t offset, std::string& out, std::vector<std::string_view>& open) {
    for (std::size_t i = 0; i < text.size(); ++i) {
      // Inside an entity, positions are those of the outermost reference.
      const auto at = open.empty() ? offset + i : offset;
      const char c = text[i];
      if (c == '<') {
        refuse(at, "the entity '" + std::string(open.back()) +
                       "' holds markup ('<'), which pgm does not read in an XMLBIF name, state or table");
      }
      if (c != '&') {
        count(at, open);
        out += c;
        continue;
      }
      const auto end = text.find(';', i);
      if (end == std::string_view::npos) {
        refuse(at, "an '&' that starts no entity or character reference (write &amp; for '&')");
      }
      const auto body = text.substr(i + 1, end - i - 1);
      i = end;
      if (!body.empty() && body[0] == '#') {
        const auto code = character_code(body);
        if (!code) refuse(at, "a malformed character reference '&" + std::string(body) + ";'");
        count(at, open);
        append_character(out, *code, at);
        continue;
      }
      if (const auto predefined = predefined_entity(body)) {
        count(at, open);
        out += *predefined;
        continue;
      }
      const auto it = entities_.find(body);
      if (it == entities_.end()) {
        refuse(at, "an undefined entity '&" + std::string(body) + ";'" +
                       (entities_.empty() ? " (the file declares no entities; write &amp; for '&')" : ""));
      }
      if (it->second.external) {
        refuse(at, "'&" + std::string(body) +
                       ";' is an external entity: pgm reads no other file an XMLBIF file names "
                       "(nor does pgmpy's ElementTree)");
      }
      if (std::find(open.begin(), open.end(), body) != open.end()) {
        refuse(at, "the entity '" + std::string(body) + "' refers to itself");
      }
      count(at, open);
      open.push_back(it->first);
      expand(it->second.text, at, out, open);
      open.pop_back();
    }
  }

  /// Counts one step of an entity's expansion against the limit (references count, so that
  /// entities of empty text cannot amplify the work either).
  void count(std::size_t at, const std::vector<std::string_view>& open) {
    if (open.empty()) return;
    if (++expanded_ > xml_max_entity_bytes || open.size() > max_nesting) {
      refuse(at, "the file's entities expand to more than " + std::to_string(xml_max_entity_bytes >> 20) +
                     " MiB or nest deeper than " + std::to_string(max_nesting) +
                     " levels, pgm's limit of XML entities (docs/limits.md)");
    }
  }

  static std::optional<char> predefined_entity(std::string_view name) {
    if (name == "lt") return '<';
    if (name == "gt") return '>';
    if (name == "amp") return '&';
    if (name == "apos") return '\'';
    if (name == "quot") return '"';
    return std::nullopt;
  }

  static constexpr std::size_t max_nesting = 64;
  std::map<std::string, entity, std::less<>> entities_;
  std::size_t expanded_ = 0;
};

class xmlbif_reader {
 public:
  xmlbif_reader(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  bayesian_network read(const network_read_options& options) {
    try {
      return read_document(options);
    } catch (const xml_problem& problem) {
      fail(position(problem.offset), problem.what);
    }
  }

  influence_diagram read_diagram() {
    try {
      return read_diagram_document();
    } catch (const xml_problem& problem) {
      fail(position(problem.offset), problem.what);
    }
  }

 private:
  /// The <NETWORK> element of the parsed text, entities declared.
  pugi::xml_node load(pugi::xml_document& document) {
    // References are resolved by xml_text_decoder, as pgmpy's parser resolves them; pugixml
    // would keep an entity it does not know as text ("&two;").
    const auto flags = (pugi::parse_default | pugi::parse_doctype) & ~pugi::parse_escapes;
    const auto result = document.load_buffer(text_.data(), text_.size(), flags);
    if (!result) {
      fail(detail::position_of(text_, static_cast<std::size_t>(std::max<std::ptrdiff_t>(result.offset, 0))),
           std::string("invalid XML: ") + result.description());
    }
    for (const auto& node : document.children()) {
      if (node.type() == pugi::node_doctype) decoder_.declare(node.value(), offset_of(node));
    }
    const auto root = document.document_element();
    if (std::string_view(root.name()) != "BIF") {
      fail(at(root), "expected the XMLBIF root element <BIF>, found <" + std::string(root.name()) + ">");
    }
    const auto network = root.child("NETWORK");
    if (!network) fail(at(root), "<BIF> has no <NETWORK>");
    return network;
  }

  bayesian_network read_document(const network_read_options& options) {
    pugi::xml_document document;
    const auto network = load(document);
    std::vector<detail::declared_variable> variables;
    std::vector<detail::declared_table> tables;
    for (const auto& node : network.children("VARIABLE")) variables.push_back(read_variable(node));
    for (const auto& node : network.children()) {
      if (node.type() != pugi::node_element) continue;
      const std::string_view name = node.name();
      if (name == "DEFINITION" || name == "PROBABILITY") {  // PROBABILITY: XMLBIF 0.2
        tables.push_back(read_table(node, variables));
      } else if (name == "PROPERTY" && options.properties) {
        detail::keep_pgm_property(text_of(node), options.properties);
      }
      // NAME, other properties and elements of later versions carry nothing pgm keeps.
    }
    if (variables.empty()) fail(at(network), "the file declares no variables");
    return detail::build_network(variables, std::move(tables), source_, options,
                                 [this](detail::text_position p, const std::string& what) { fail(p, what); });
  }

  influence_diagram read_diagram_document() {
    pugi::xml_document document;
    const auto network = load(document);
    std::vector<detail::declared_variable> variables;
    std::vector<std::string> types;
    for (const auto& node : network.children("VARIABLE")) {
      types.push_back(type_of(node));
      variables.push_back(read_variable(node, true));
    }
    if (variables.empty()) fail(at(network), "the file declares no variables");
    influence_diagram diagram;
    for (std::size_t i = 0; i < variables.size(); ++i) {
      if (types[i] == "utility") continue;
      try {
        variable v(variables[i].name, variables[i].states, variables[i].tags);
        if (variables[i].edges) v.set_edges(*variables[i].edges);
        types[i] == "decision" ? diagram.add_decision(std::move(v)) : diagram.add_chance(std::move(v));
      } catch (const model_error& e) {
        fail(variables[i].at, e.what());
      }
    }
    const auto type_named = [&](const std::string& name) -> const std::string* {
      for (std::size_t i = 0; i < variables.size(); ++i) {
        if (variables[i].name == name) return &types[i];
      }
      return nullptr;
    };
    std::vector<std::string> defined;
    for (const auto& node : network.children()) {
      const std::string_view element = node.name();
      if (node.type() != pugi::node_element || (element != "DEFINITION" && element != "PROBABILITY")) continue;
      const auto child = single_text(node, "FOR");
      const auto* type = type_named(child);
      if (type == nullptr) fail(at(node), "a definition for '" + child + "', which no <VARIABLE> declares");
      if (std::find(defined.begin(), defined.end(), child) != defined.end()) {
        fail(at(node), "a second definition for '" + child + "'");
      }
      defined.push_back(child);
      std::vector<variable_id> parents;
      for (const auto& given : node.children("GIVEN")) {
        const auto name = text_of(given);
        const auto* parent_type = type_named(name);
        if (parent_type != nullptr && *parent_type == "utility") {
          fail(at(given),
               "the utility '" + name + "' is given as a parent of '" + child + "'; a utility node has no children");
        }
        try {
          parents.push_back(diagram.id(name));
        } catch (const error& e) {
          fail(at(given), e.what());
        }
      }
      try {
        if (*type == "decision") {
          if (node.child("TABLE")) {
            fail(at(node.child("TABLE")), "the decision '" + child +
                                              "' has a <TABLE>: a decision is chosen, so it has no probabilities; "
                                              "its <GIVEN>s are what is known when it is taken");
          }
          diagram.set_observed(diagram.id(child), parents);
        } else if (*type == "utility") {
          diagram.add_utility(child, parents, read_table(node, variables, false).values);
        } else {
          diagram.set_table(diagram.id(child), parents, read_table(node, variables, false).values);
        }
      } catch (const model_error& e) {
        fail(at(node), e.what());
      }
    }
    for (std::size_t i = 0; i < variables.size(); ++i) {
      if (types[i] != "decision" && std::find(defined.begin(), defined.end(), variables[i].name) == defined.end()) {
        fail(variables[i].at, "the " + std::string(types[i] == "utility" ? "utility" : "chance variable") + " '" +
                                  variables[i].name + "' has no <DEFINITION>");
      }
    }
    try {
      diagram.validate();
    } catch (const model_error& e) {
      fail(at(network), e.what());
    }
    return diagram;
  }

  [[noreturn]] void fail(detail::text_position p, const std::string& what) const {
    throw parse_error(source_, p.line, p.column, what);
  }

  static std::size_t offset_of(const pugi::xml_node& node) {
    return static_cast<std::size_t>(std::max<std::ptrdiff_t>(node.offset_debug(), 0));
  }

  /// Where a node starts: offset_debug points at the name after '<' for elements; this is the '<'.
  static std::size_t start_of(const pugi::xml_node& node) {
    const auto o = offset_of(node);
    return node.type() == pugi::node_element && o > 0 ? o - 1 : o;
  }

  detail::text_position at(const pugi::xml_node& node) {
    if (node.offset_debug() < 0) return {};
    return position(start_of(node));
  }

  /// Line and column of a byte of the file, by binary search over the line starts, found once
  /// (each variable and table records where it is declared).
  detail::text_position position(std::size_t offset) {
    if (line_starts_.empty()) {
      line_starts_.push_back(0);
      for (std::size_t i = 0; i < text_.size(); ++i) {
        if (text_[i] == '\n') line_starts_.push_back(i + 1);
      }
    }
    offset = std::min(offset, text_.size());
    const auto line = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset) - line_starts_.begin();
    return {static_cast<std::size_t>(line), offset - line_starts_[static_cast<std::size_t>(line - 1)] + 1};
  }

  /// An element's text as ElementTree's `.text` gives it (what pgmpy reads): its character
  /// data and CDATA sections up to its first child element, references resolved.
  std::string text_of(const pugi::xml_node& node) {
    std::string text;
    for (const auto& child : node.children()) {
      if (child.type() == pugi::node_element) break;
      if (child.type() == pugi::node_pcdata) text += decoder_.decode(child.value(), offset_of(child));
      if (child.type() == pugi::node_cdata) {
        xml_text_decoder::check_characters(child.value(), offset_of(child));
        text += child.value();
      }
    }
    return text;
  }

  /// The text of the one child `name` of `node`, failing when it is missing.
  std::string single_text(const pugi::xml_node& node, const char* name) {
    const auto child = node.child(name);
    if (!child) fail(at(node), "<" + std::string(node.name()) + "> has no <" + name + ">");
    if (child.next_sibling(name)) fail(at(child.next_sibling(name)), "a second <" + std::string(name) + ">");
    return text_of(child);
  }

  /// A VARIABLE's TYPE: "nature" (also when absent), "decision" or "utility".
  std::string type_of(const pugi::xml_node& node) {
    auto type = decoder_.decode(node.attribute("TYPE").value(), start_of(node));
    if (type.empty()) type = "nature";
    if (type != "nature" && type != "decision" && type != "utility") {
      fail(at(node), "TYPE=\"" + type + "\"; expected \"nature\", \"decision\" or \"utility\"");
    }
    return type;
  }

  detail::declared_variable read_variable(const pugi::xml_node& node, bool diagram = false) {
    detail::declared_variable v;
    v.at = at(node);
    v.name = single_text(node, "NAME");
    const auto type = type_of(node);
    if (!diagram && type != "nature") {
      fail(v.at, "variable '" + v.name + "' has TYPE=\"" + type +
                     "\": the file is an influence diagram, which `pgm decide` reads; a Bayesian network has "
                     "chance (\"nature\") variables only");
    }
    if (type == "utility") {  // aGrUM writes a dummy <OUTCOME>; its one "state" counts the table
      v.states = {"utility"};
      return v;
    }
    for (const auto& outcome : node.children("OUTCOME")) {
      // A variable with more states than a table has cells cannot have a table.
      if (v.states.size() == max_table_cells) {
        fail(at(outcome), "more than " + std::to_string(max_table_cells) + " states of '" + v.name +
                              "', pgm's limit of cells per table (docs/limits.md)");
      }
      v.states.push_back(text_of(outcome));
    }
    if (v.states.empty()) fail(v.at, "variable '" + v.name + "' has no <OUTCOME>");
    for (const auto& property : node.children("PROPERTY")) {
      const auto text = text_of(property);
      const auto eq = text.find('=');
      if (eq == std::string::npos) continue;  // pgmpy writes an empty <PROPERTY/>
      const std::string_view view = text;
      try {
        detail::apply_pgm_property(v, text::trim(view.substr(0, eq)), text::trim(view.substr(eq + 1)), ", \t\n");
      } catch (const model_error& e) {
        fail(at(property), e.what());
      }
    }
    return v;
  }

  /// A <DEFINITION>'s table. Its values past the declared size are counted, not kept, unless
  /// not `bounded` (a diagram's tables, which the diagram checks by their number).
  detail::declared_table read_table(const pugi::xml_node& node, const std::vector<detail::declared_variable>& variables,
                                    bool bounded = true) {
    detail::declared_table table;
    table.at = at(node);
    table.child = single_text(node, "FOR");
    for (const auto& given : node.children("GIVEN")) table.parents.emplace_back(text_of(given), at(given));
    const auto values = node.child("TABLE");
    if (!values) fail(at(node), "the definition of '" + table.child + "' has no <TABLE>");
    table.values_at = at(values);
    auto cells = detail::check_table_cells(variables, table.child, table.parents, table.at,
                                           [this](detail::text_position p, const std::string& what) { fail(p, what); });
    if (!bounded) cells.reset();
    const auto text_node = values.first_child();
    // The file's text is read in place when it is one piece without references (as tables are
    // written), and then positions of the numbers are exact; otherwise it is decoded first.
    const bool verbatim = text_node && text_node.type() == pugi::node_pcdata && !text_node.next_sibling() &&
                          text_node.offset_debug() >= 0 &&
                          std::string_view(text_node.value()).find('&') == std::string_view::npos;
    std::string decoded;
    if (verbatim) {
      xml_text_decoder::check_characters(text_node.value(), offset_of(text_node));
    } else {
      decoded = text_of(values);
    }
    const std::string_view numbers = verbatim ? std::string_view(text_node.value()) : std::string_view(decoded);
    std::size_t i = 0;
    while (i < numbers.size()) {
      while (i < numbers.size() && std::string_view(" \t\r\n").find(numbers[i]) != std::string_view::npos) ++i;
      const auto start = i;
      while (i < numbers.size() && std::string_view(" \t\r\n").find(numbers[i]) == std::string_view::npos) ++i;
      if (start == i) break;
      const auto word = numbers.substr(start, i - start);
      // Found only for an error: a scan of the file per number would make reading quadratic.
      const auto where = [&] { return verbatim ? position(offset_of(text_node) + start) : table.values_at; };
      const auto value = text::parse_double(word);
      if (!value || !std::isfinite(*value)) {
        fail(where(),
             "expected a probability in the table of '" + table.child + "', found '" + std::string(word) + "'");
      }
      if (!table.add_value(*value, cells)) {
        fail(where(), "more than " + std::to_string(max_table_cells) + " probabilities in the table of '" +
                          table.child + "', pgm's limit of cells per table (docs/limits.md)");
      }
    }
    return table;
  }

  std::string_view text_;
  const std::string& source_;
  xml_text_decoder decoder_;
  std::vector<std::size_t> line_starts_;
};

void add_text(pugi::xml_node parent, const char* name, const std::string& text) {
  for (const char c : text) {
    if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
      throw model_error("'" + text::printable(text) + "' holds a control character, which XML cannot hold");
    }
  }
  parent.append_child(name).text().set(text.c_str());
}

}  // namespace

bayesian_network parse_xmlbif(std::string_view text, const std::string& source, const network_read_options& options) {
  return xmlbif_reader(text, source).read(options);
}

bayesian_network read_xmlbif(const std::filesystem::path& path, const network_read_options& options) {
  return parse_xmlbif(pgm::read_file(path), path.string(), options);
}

namespace {

/// A document with its declaration and an open <NETWORK>.
pugi::xml_node start_document(pugi::xml_document& document, const xmlbif_write_options& options) {
  auto declaration = document.append_child(pugi::node_declaration);
  declaration.append_attribute("version") = "1.0";
  declaration.append_attribute("encoding") = "UTF-8";
  auto root = document.append_child("BIF");
  root.append_attribute("VERSION") = "0.3";
  auto net = root.append_child("NETWORK");
  add_text(net, "NAME", options.network_name);
  for (const auto& [key, value] : options.network_properties) add_text(net, "PROPERTY", "pgm." + key + " = " + value);
  return net;
}

void add_variable(pugi::xml_node net, const variable& v, const char* type, const xmlbif_write_options& options) {
  auto node = net.append_child("VARIABLE");
  node.append_attribute("TYPE") = type;
  add_text(node, "NAME", v.name());
  for (const auto& state : v.states()) add_text(node, "OUTCOME", state);
  if (!options.properties) return;
  if (v.has_intervals()) {
    std::vector<std::string> edges;
    for (const double e : v.edges()) edges.push_back(text::format_double(e));
    add_text(node, "PROPERTY", "edges = " + text::join(edges, ", "));
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

/// A <DEFINITION> of `child` given `parents`, with a <TABLE> of `values` unless it is null.
void add_definition(pugi::xml_node net, const std::string& child, const std::vector<std::string>& parents,
                    const std::vector<double>* values) {
  auto node = net.append_child("DEFINITION");
  add_text(node, "FOR", child);
  for (const auto& parent : parents) add_text(node, "GIVEN", parent);
  if (values == nullptr) return;
  std::string text;
  for (const double value : *values) {
    if (!text.empty()) text += ' ';
    text += text::format_double(value);
  }
  add_text(node, "TABLE", text);
}

}  // namespace

void write_xmlbif(const bayesian_network& network, std::ostream& out, const xmlbif_write_options& options) {
  if (network.has_sparse_tables()) {
    write_xmlbif(network.dense("writing XMLBIF, which has no sparse form (pgm's JSON model has),"), out, options);
    return;
  }
  pugi::xml_document document;
  auto net = start_document(document, options);
  for (const auto& v : network.variables()) add_variable(net, v, "nature", options);
  for (const auto& table : network.tables()) {
    std::vector<std::string> parents;
    for (const auto& parent : table.parents()) parents.push_back(parent.name());
    const std::vector<double> values(table.values().begin(), table.values().end());
    add_definition(net, table.child().name(), parents, &values);
  }
  document.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
}

void write_xmlbif(const influence_diagram& diagram, std::ostream& out, const xmlbif_write_options& options) {
  pugi::xml_document document;
  auto net = start_document(document, options);
  for (std::size_t i = 0; i < diagram.size(); ++i) {
    const auto id = index_at<variable_id>(i);
    add_variable(net, diagram.at(id), diagram.is_decision(id) ? "decision" : "nature", options);
  }
  for (const auto& u : diagram.utilities()) {
    auto node = net.append_child("VARIABLE");
    node.append_attribute("TYPE") = "utility";
    add_text(node, "NAME", u.name);
  }
  const auto names = [&](const std::vector<variable_id>& ids) {
    std::vector<std::string> result;
    for (const auto id : ids) result.push_back(diagram.at(id).name());
    return result;
  };
  for (std::size_t i = 0; i < diagram.size(); ++i) {
    const auto id = index_at<variable_id>(i);
    add_definition(net, diagram.at(id).name(), names(diagram.parents(id)),
                   diagram.is_decision(id) ? nullptr : &diagram.table(id));
  }
  for (const auto& u : diagram.utilities()) add_definition(net, u.name, names(u.parents), &u.values);
  document.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
}

std::string to_xmlbif(const influence_diagram& diagram, const xmlbif_write_options& options) {
  std::ostringstream out;
  write_xmlbif(diagram, out, options);
  return out.str();
}

influence_diagram parse_xmlbif_influence_diagram(std::string_view text, const std::string& source) {
  return xmlbif_reader(text, source).read_diagram();
}

influence_diagram read_xmlbif_influence_diagram(const std::filesystem::path& path) {
  return parse_xmlbif_influence_diagram(pgm::read_file(path), path.string());
}

std::string to_xmlbif(const bayesian_network& network, const xmlbif_write_options& options) {
  std::ostringstream out;
  write_xmlbif(network, out, options);
  return out.str();
}

void write_xmlbif(const bayesian_network& network, const std::filesystem::path& path,
                  const xmlbif_write_options& options) {
  const auto text = to_xmlbif(network, options);
  pgm::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

network_format_codec detail::xmlbif_format() {
  return {.name = "xmlbif",
          .title = "XMLBIF",
          .extensions = {".xml", ".xmlbif", ".bifxml"},
          .read =
              [](std::string_view text, const std::string& source, const network_read_options& options) {
                return read_keeping_statistics(parse_xmlbif, text, source, options);
              },
          .write =
              [](const bayesian_network& network, const network_write_options& options) {
                return to_xmlbif(network,
                                 {.properties = options.properties, .network_properties = kept_properties(options)});
              }};
}

}  // namespace pgm
