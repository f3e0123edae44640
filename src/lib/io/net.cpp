// Hugin NET reading and writing (pgm/io/net.hpp): a hand-written lexer and recursive parser
// in the style of the BIF one.

#include "pgm/io/net.hpp"

#include <cctype>
#include <map>
#include <sstream>
#include <vector>

#include "io/builtin_formats.hpp"
#include "io/network_text.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/text.hpp"

namespace pgm {
namespace {

struct net_token {
  enum class kind { word, string, symbol, end } type = kind::end;
  std::string text;
  detail::text_position at;
};

class net_parser {
 public:
  net_parser(std::string_view text, const std::string& source) : text_(text), source_(source) { advance(); }

  bayesian_network parse(const network_read_options& options) {
    while (current_.type != net_token::kind::end) {
      const auto keyword = expect_word("'net', 'node' or 'potential'");
      if (keyword.text == "net") {
        read_net_attributes(options.properties);
      } else if (keyword.text == "node") {
        read_node(keyword);
      } else if (keyword.text == "discrete" && current_.type == net_token::kind::word && current_.text == "node") {
        advance();
        read_node(keyword);
      } else if (keyword.text == "potential") {
        read_potential();
      } else if (keyword.text == "continuous" || keyword.text == "decision" || keyword.text == "utility") {
        fail(keyword.at, "'" + keyword.text + "' nodes are not supported; pgm reads discrete chance nodes");
      } else if (keyword.text == "class") {
        fail(keyword.at, "object-oriented NET files ('class') are not supported; export the network flat");
      } else {
        fail(keyword.at, "expected 'net', 'node' or 'potential', found '" + keyword.text + "'");
      }
    }
    if (variables_.empty()) fail(current_.at, "the file declares no nodes");
    return detail::build_network(variables_, std::move(tables_), source_, options,
                                 [this](detail::text_position p, const std::string& what) { fail(p, what); });
  }

 private:
  [[noreturn]] void fail(detail::text_position p, const std::string& what) const {
    throw parse_error(source_, p.line, p.column, what);
  }
  static std::string describe(const net_token& t) {
    if (t.type == net_token::kind::end) return "the end of the file";
    if (t.type == net_token::kind::string) return "the string \"" + t.text + "\"";
    return "'" + t.text + "'";
  }

  static bool is_symbol(char c) { return std::string_view("{}()=;|,").find(c) != std::string_view::npos; }
  static bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

  void advance() {
    while (pos_ < text_.size()) {  // spaces and % comments
      if (is_space(text_[pos_])) {
        ++pos_;
      } else if (text_[pos_] == '%') {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else {
        break;
      }
    }
    current_ = net_token{};
    current_.at = position(pos_);
    if (pos_ >= text_.size()) return;
    const char c = text_[pos_];
    if (c == '"') {
      ++pos_;
      std::string value;
      while (pos_ < text_.size() && text_[pos_] != '"') {
        if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) ++pos_;  // \" and \\ stand for themselves
        value += text_[pos_++];
      }
      if (pos_ >= text_.size()) fail(current_.at, "a string is never closed");
      ++pos_;
      current_.type = net_token::kind::string;
      current_.text = std::move(value);
      return;
    }
    if (is_symbol(c)) {
      current_.type = net_token::kind::symbol;
      current_.text = std::string(1, c);
      ++pos_;
      return;
    }
    const auto start = pos_;
    while (pos_ < text_.size() && !is_symbol(text_[pos_]) && !is_space(text_[pos_]) && text_[pos_] != '"' &&
           text_[pos_] != '%') {
      ++pos_;
    }
    current_.type = net_token::kind::word;
    current_.text = std::string(text_.substr(start, pos_ - start));
  }

  /// Positions are computed incrementally: tokens only move forward.
  detail::text_position position(std::size_t offset) {
    for (; scanned_ < offset; ++scanned_) {
      if (text_[scanned_] == '\n') {
        ++line_;
        line_start_ = scanned_ + 1;
      }
    }
    return {line_, offset - line_start_ + 1};
  }

  net_token expect_word(const std::string& what) {
    if (current_.type != net_token::kind::word) fail(current_.at, "expected " + what + ", found " + describe(current_));
    auto token = current_;
    advance();
    return token;
  }
  void expect_symbol(char symbol) {
    if (!accept_symbol(symbol)) {
      fail(current_.at, std::string("expected '") + symbol + "', found " + describe(current_));
    }
  }
  bool accept_symbol(char symbol) {
    if (current_.type == net_token::kind::symbol && current_.text[0] == symbol) {
      advance();
      return true;
    }
    return false;
  }

  /// One attribute value: a string, a word (number or name) or a parenthesized list of values,
  /// each leaf handed to `leaf(token)` as it is read (a table's values are never held as
  /// tokens). Lists nest at most json_max_depth levels, as a JSON file's do.
  template <class Leaf>
  void read_value(Leaf&& leaf, std::size_t depth = 0) {
    if (current_.type == net_token::kind::symbol && current_.text[0] == '(') {
      if (depth == json_max_depth) {
        fail(current_.at, "lists nested deeper than " + std::to_string(json_max_depth) + " levels, pgm's limit");
      }
      advance();
      while (!accept_symbol(')')) {
        if (current_.type == net_token::kind::end) fail(current_.at, "a '(' is never closed");
        read_value(leaf, depth + 1);
        accept_symbol(',');
      }
      return;
    }
    if (current_.type == net_token::kind::word || current_.type == net_token::kind::string) {
      leaf(current_);
      advance();
      return;
    }
    fail(current_.at, "expected a value, found " + describe(current_));
  }

  /// `{ name = value; … }`, calling `use(name, value_start)` for each attribute, which reads the
  /// value (read_value) or leaves it to be skipped.
  template <class Use>
  void read_attributes(Use&& use) {
    expect_symbol('{');
    while (!accept_symbol('}')) {
      const auto name = expect_word("an attribute name or '}'");
      expect_symbol('=');
      const auto start = current_;
      if (!use(name, start)) read_value([](const net_token&) {});
      expect_symbol(';');
    }
  }
  void skip_attributes_block() {
    read_attributes([](const net_token&, const net_token&) { return false; });
  }
  /// The net block: pgm's own attributes (`pgm_KEY = "VALUE";`) into `properties`, the others skipped.
  void read_net_attributes(std::map<std::string, std::string>* properties) {
    read_attributes([&](const net_token& attribute, const net_token&) {
      if (!properties || !attribute.text.starts_with("pgm_")) return false;
      (*properties)[attribute.text.substr(4)] = joined(leaves_of_value(1, "values of '" + attribute.text + "'"));
      return true;
    });
  }

  /// The leaves of one value, at most `limit` of them (`what` names them in the refusal).
  std::vector<net_token> leaves_of_value(std::size_t limit, const std::string& what) {
    std::vector<net_token> leaves;
    read_value([&](const net_token& leaf) {
      if (leaves.size() == limit) {
        fail(leaf.at, "more than " + std::to_string(limit) + " " + what + ", pgm's limit of cells per table");
      }
      leaves.push_back(leaf);
    });
    return leaves;
  }

  static std::string joined(const std::vector<net_token>& leaves) {
    std::string text;
    for (const auto& leaf : leaves) text += (text.empty() ? "" : " ") + leaf.text;
    return text;
  }

  void read_node(const net_token& keyword) {
    const auto name = expect_word("a node name");
    detail::declared_variable v;
    v.name = name.text;
    v.at = name.at;
    for (const auto& other : variables_) {
      if (other.name == v.name) fail(name.at, "node '" + v.name + "' is declared twice");
    }
    bool has_states = false;
    read_attributes([&](const net_token& attribute, const net_token& start) {
      if (attribute.text == "states") {
        // A variable with more states than a table has cells cannot have a table.
        for (const auto& leaf : leaves_of_value(max_table_cells, "states of '" + v.name + "'")) {
          if (leaf.type != net_token::kind::string) {
            fail(leaf.at, "the states of '" + v.name + "' must be quoted strings, found '" + leaf.text + "'");
          }
          v.states.push_back(leaf.text);
        }
        has_states = true;
        return true;
      }
      if (!attribute.text.starts_with("pgm_")) return false;
      const auto leaves = leaves_of_value(max_table_cells, "values of '" + attribute.text + "'");
      try {
        detail::apply_pgm_property(v, std::string_view(attribute.text).substr(4), joined(leaves), " ");
      } catch (const model_error& e) {
        fail(start.at, e.what());
      }
      return true;
    });
    if (!has_states) fail(keyword.at, "node '" + v.name + "' has no 'states'");
    variables_.push_back(std::move(v));
  }

  void read_potential() {
    detail::declared_table table;
    expect_symbol('(');
    const auto child = expect_word("the node's name");
    table.child = child.text;
    table.at = child.at;
    if (current_.type == net_token::kind::word) {
      fail(current_.at, "a potential over several nodes ('" + child.text + " " + current_.text +
                            "') is not a conditional table; pgm reads 'potential ( child | parents )'");
    }
    if (accept_symbol('|')) {
      while (!accept_symbol(')')) {
        const auto parent = expect_word("a parent's name or ')'");
        table.parents.emplace_back(parent.text, parent.at);
        accept_symbol(',');
      }
    } else {
      expect_symbol(')');
    }
    // A table beyond pgm's limit is refused before its values are read when its nodes are
    // declared already (as Hugin writes them).
    const auto cells =
        detail::check_table_cells(variables_, table.child, table.parents, child.at,
                                  [this](detail::text_position p, const std::string& what) { fail(p, what); });
    bool has_data = false;
    read_attributes([&](const net_token& attribute, const net_token& start) {
      if (attribute.text != "data") return false;  // experience, model_nodes, … carry nothing pgm keeps
      has_data = true;
      table.values_at = start.at;
      read_value([&](const net_token& leaf) {
        const auto value = leaf.type == net_token::kind::word ? text::parse_double(leaf.text) : std::nullopt;
        if (!value || !std::isfinite(*value)) {
          fail(leaf.at, "expected a probability in the data of '" + table.child + "', found " + describe(leaf));
        }
        if (!table.add_value(*value, cells)) {
          fail(leaf.at, "more than " + std::to_string(max_table_cells) + " probabilities in the table of '" +
                            table.child + "', pgm's limit of cells per table (docs/limits.md)");
        }
      });
      return true;
    });
    if (!has_data) fail(child.at, "the potential of '" + table.child + "' has no 'data'");
    tables_.push_back(std::move(table));
  }

  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  std::size_t scanned_ = 0;
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;
  net_token current_;
  std::vector<detail::declared_variable> variables_;
  std::vector<detail::declared_table> tables_;
};

std::string quoted(const std::string& text, const std::string& what) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '\n' || c == '\r') throw model_error(what + " holds a line break, which NET strings cannot");
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

/// `data` nested as Hugin writes it: one level of parentheses per parent, the child innermost,
/// one configuration per line.
void write_data(const cpt<double>& table, std::ostream& out) {
  const auto j = table.child_cardinality();
  const auto values = table.values();
  std::vector<std::size_t> cards;
  for (const auto& p : table.parents()) cards.push_back(p.cardinality());
  const mixed_radix radix(cards);
  out << "  data = ";
  for (std::size_t u = 0; u < radix.size(); ++u) {
    const auto codes = radix.decode(u);
    std::size_t opening = 0;  // a list opens for each trailing parent whose state starts again
    for (std::size_t p = codes.size(); p-- > 0 && codes[p] == 0;) ++opening;
    std::size_t closing = 0;  // and closes for each that reaches its last state
    for (std::size_t p = codes.size(); p-- > 0 && codes[p] + 1 == cards[p];) ++closing;
    if (u > 0) out << "\n         " << std::string(codes.size() - opening, ' ');
    out << std::string(opening, '(') << '(';
    for (std::size_t x = 0; x < j; ++x) out << (x ? " " : "") << text::format_double(values[u * j + x]);
    out << ')' << std::string(closing, ')');
  }
  out << ";\n";
}

}  // namespace

bayesian_network parse_net(std::string_view text, const std::string& source, const network_read_options& options) {
  return net_parser(text, source).parse(options);
}

bayesian_network read_net(const std::filesystem::path& path, const network_read_options& options) {
  return parse_net(pgm::read_file(path), path.string(), options);
}

std::optional<std::string> net_name_problem(std::string_view name) {
  if (name.empty()) return "it is empty";
  if (!(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) {
    return "NET names start with a letter or '_'";
  }
  for (const char c : name) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) {
      return std::string("NET names hold letters, digits and '_' only (found '") + c + "')";
    }
  }
  return std::nullopt;
}

void write_net(const bayesian_network& network, std::ostream& out, const net_write_options& options) {
  if (network.has_sparse_tables()) {
    write_net(network.dense("writing NET, which has no sparse form (pgm's JSON model has),"), out, options);
    return;
  }
  std::ostringstream text;
  text << "net\n{\n";
  for (const auto& [key, value] : options.network_properties) {
    text << "  pgm_" << key << " = " << quoted(value, "the network property '" + key + "'") << ";\n";
  }
  text << "}\n";
  for (const auto& v : network.variables()) {
    if (const auto problem = net_name_problem(v.name())) {
      throw model_error("variable '" + v.name() + "' cannot be written to NET: " + *problem);
    }
    text << "\nnode " << v.name() << "\n{\n  label = " << quoted(v.name(), "the name of '" + v.name() + "'")
         << ";\n  states = (";
    for (std::size_t s = 0; s < v.cardinality(); ++s) {
      text << (s ? " " : "") << quoted(v.states()[s], "state '" + v.states()[s] + "' of '" + v.name() + "'");
    }
    text << ");\n";
    if (options.properties) {
      if (v.has_intervals()) {
        std::vector<std::string> edges;
        for (const double e : v.edges()) edges.push_back(text::format_double(e));
        text << "  pgm_edges = \"" << text::join(edges, " ") << "\";\n";
      }
      const auto& tags = v.tags();
      for (const auto& [key, value] : {std::pair<const char*, const std::string*>{"quantity", &tags.quantity},
                                       {"unit", &tags.unit},
                                       {"role", &tags.role}}) {
        if (value->empty()) continue;
        text << "  pgm_" << key << " = " << quoted(*value, "the " + std::string(key) + " tag of '" + v.name() + "'")
             << ";\n";
      }
    }
    text << "}\n";
  }
  for (const auto& table : network.tables()) {
    text << "\npotential ( " << table.child().name();
    if (!table.parents().empty()) {
      text << " |";
      for (const auto& parent : table.parents()) text << ' ' << parent.name();
    }
    text << " )\n{\n";
    write_data(table, text);
    text << "}\n";
  }
  out << text.str();
}

std::string to_net(const bayesian_network& network, const net_write_options& options) {
  std::ostringstream out;
  write_net(network, out, options);
  return out.str();
}

void write_net(const bayesian_network& network, const std::filesystem::path& path, const net_write_options& options) {
  const auto text = to_net(network, options);
  pgm::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

network_format_codec detail::net_format() {
  return {.name = "net",
          .title = "Hugin NET",
          .extensions = {".net"},
          .read =
              [](std::string_view text, const std::string& source, const network_read_options& options) {
                return read_keeping_statistics(parse_net, text, source, options);
              },
          .write =
              [](const bayesian_network& network, const network_write_options& options) {
                return to_net(network,
                              {.properties = options.properties, .network_properties = kept_properties(options)});
              }};
}

}  // namespace pgm
