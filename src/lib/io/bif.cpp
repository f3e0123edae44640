// The BIF reader (a lexer and a recursive-descent parser over probability blocks) and writer,
// declared in pgm/io/bif.hpp.

#include "pgm/io/bif.hpp"

#include <cctype>
#include <charconv>
#include <map>
#include <optional>
#include <sstream>
#include <system_error>

#include "io/builtin_formats.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/text.hpp"

namespace pgm {

namespace detail {
namespace {

struct bif_token {
  enum class kind { word, symbol, end } type = kind::end;
  std::string text;
  std::size_t line = 0;
  std::size_t column = 0;
};

class bif_lexer {
 public:
  bif_lexer(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

  [[nodiscard]] const std::string& source() const noexcept { return source_; }

  bif_token next() {
    skip_space_and_comments();
    bif_token token;
    token.line = line_;
    token.column = pos_ - line_start_ + 1;
    if (pos_ >= text_.size()) return token;
    const char c = text_[pos_];
    if (c == '"') {
      ++pos_;
      const auto start = pos_;
      while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != '\n') ++pos_;
      if (pos_ >= text_.size() || text_[pos_] != '"') {
        throw parse_error(source_, token.line, token.column, "a quoted name is never closed");
      }
      token.type = bif_token::kind::word;
      token.text = std::string(text_.substr(start, pos_ - start));
      ++pos_;
      return token;
    }
    if (is_symbol(c)) {
      token.type = bif_token::kind::symbol;
      token.text = std::string(1, c);
      ++pos_;
      return token;
    }
    const auto start = pos_;
    while (pos_ < text_.size() && !is_symbol(text_[pos_]) && !is_space(text_[pos_]) && text_[pos_] != '"' &&
           !comment_starts(pos_)) {
      ++pos_;
    }
    token.type = bif_token::kind::word;
    token.text = std::string(text_.substr(start, pos_ - start));
    return token;
  }

  /// Everything up to (not including) the next ';' outside double quotes, for property values
  /// (other tools write `property label = "a; b" ;`).
  std::string raw_until_semicolon() {
    const auto start = pos_;
    bool quoted = false;
    while (pos_ < text_.size() && (quoted || text_[pos_] != ';')) {
      if (text_[pos_] == '"') quoted = !quoted;
      if (text_[pos_] == '\n') {
        ++line_;
        line_start_ = pos_ + 1;
      }
      ++pos_;
    }
    return std::string(text::trim(text_.substr(start, pos_ - start)));
  }

 private:
  static bool is_symbol(char c) {
    return c == '{' || c == '}' || c == '(' || c == ')' || c == '[' || c == ']' || c == ';' || c == ',' || c == '|';
  }
  static bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
  bool comment_starts(std::size_t p) const {
    return p + 1 < text_.size() && text_[p] == '/' && (text_[p + 1] == '/' || text_[p + 1] == '*');
  }

  void skip_space_and_comments() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++pos_;
        ++line_;
        line_start_ = pos_;
      } else if (is_space(c)) {
        ++pos_;
      } else if (comment_starts(pos_) && text_[pos_ + 1] == '/') {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else if (comment_starts(pos_)) {
        const auto line = line_;
        const auto column = pos_ - line_start_ + 1;
        pos_ += 2;
        while (pos_ + 1 < text_.size() && !(text_[pos_] == '*' && text_[pos_ + 1] == '/')) {
          if (text_[pos_] == '\n') {
            ++line_;
            line_start_ = pos_ + 1;
          }
          ++pos_;
        }
        if (pos_ + 1 >= text_.size()) throw parse_error(source_, line, column, "a comment is never closed");
        pos_ += 2;
      } else {
        return;
      }
    }
  }

  std::string_view text_;
  std::string source_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;
};

class bif_parser {
 public:
  bif_parser(std::string_view text, std::string source, const network_read_options& options)
      : lexer_(text, std::move(source)),
        normalizer_(options.tolerance),
        notes_(options.notes),
        properties_(options.properties) {
    advance();
  }

  bayesian_network parse() {
    while (current_.type != bif_token::kind::end) {
      const auto keyword = expect_word("'network', 'variable' or 'probability'");
      if (keyword.text == "network") {
        parse_network();
      } else if (keyword.text == "variable") {
        parse_variable();
      } else if (keyword.text == "probability") {
        parse_probability();
      } else {
        fail(keyword, "expected 'network', 'variable' or 'probability', found '" + keyword.text + "'");
      }
    }
    if (declared_.empty()) fail(current_, "the file declares no variables");
    // Blocks are matched to declarations only now: pgmpy and bnlearn accept a `probability`
    // block before its `variable` declaration.
    for (auto& block : blocks_) {
      const auto it = declared_.find(block.header.text);
      if (it == declared_.end()) {
        fail(block.header, "probability block for '" + block.header.text + "', which is not declared");
      }
      if (it->second.table) fail(block.header, "'" + block.header.text + "' has two probability blocks");
      for (const auto& parent : block.parent_tokens) {
        if (!declared_.contains(parent.text)) fail(parent, "parent '" + parent.text + "' is not declared");
      }
      it->second.table = std::move(block);
    }
    std::vector<cpt<double>> tables;
    std::vector<variable> variables;
    for (const auto& name : order_) {
      const auto& decl = declared_.at(name);
      if (!decl.table) {
        throw parse_error(lexer_.source(), decl.where.line, decl.where.column,
                          "variable '" + name + "' has no probability block");
      }
      variables.push_back(decl.var);
    }
    network_structure structure(variables);
    for (const auto& name : order_) {
      const auto& decl = declared_.at(name);
      try {
        for (const auto& parent : decl.table->parents) structure.add_edge(parent, name);
      } catch (const not_a_dag& e) {
        fail(decl.table->header, "the probability block of '" + name + "' closes a cycle: " + e.what());
      }
    }
    for (const auto& name : order_) tables.push_back(build_table(declared_.at(name)));
    normalizer_.report(lexer_.source(), notes_);
    return bayesian_network(std::move(structure), std::move(tables));
  }

 private:
  struct probability_block {
    bif_token header;  // the child's name in `probability ( child | parents )`
    bif_token where;
    std::vector<std::string> parents;
    std::vector<bif_token> parent_tokens;
    std::map<std::vector<std::string>, std::pair<bif_token, std::vector<double>>> rows;
    std::optional<std::vector<double>> table;
    std::optional<std::vector<double>> fallback;  // `default`
  };
  struct declaration {
    bif_token where;
    variable var;
    std::optional<probability_block> table;
  };

  void advance() { current_ = lexer_.next(); }

  [[noreturn]] void fail(const bif_token& at, const std::string& what) const {
    throw parse_error(lexer_.source(), at.line, at.column, what);
  }

  bif_token expect_word(const std::string& what) {
    if (current_.type != bif_token::kind::word) {
      fail(current_, "expected " + what + ", found " + describe(current_));
    }
    auto token = current_;
    advance();
    return token;
  }
  void expect_symbol(char symbol) {
    if (current_.type != bif_token::kind::symbol || current_.text[0] != symbol) {
      fail(current_, std::string("expected '") + symbol + "', found " + describe(current_));
    }
    advance();
  }
  bool accept_symbol(char symbol) {
    if (current_.type == bif_token::kind::symbol && current_.text[0] == symbol) {
      advance();
      return true;
    }
    return false;
  }
  static std::string describe(const bif_token& token) {
    return token.type == bif_token::kind::end ? "the end of the file" : "'" + token.text + "'";
  }

  /// The text of a `property` statement up to its ';'. The first token has been lexed
  /// already (one token of lookahead), the rest is taken raw.
  std::string property_value() {
    if (accept_symbol(';')) return {};
    auto value = current_.text + " " + lexer_.raw_until_semicolon();
    advance();
    expect_symbol(';');
    return value;
  }

  void parse_network() {
    if (current_.type == bif_token::kind::word) advance();  // the network's name
    expect_symbol('{');
    while (!accept_symbol('}')) {
      const auto keyword = expect_word("'property' or '}'");
      if (keyword.text != "property") fail(keyword, "expected 'property' or '}', found '" + keyword.text + "'");
      keep_pgm_property(property_value(), properties_);
    }
  }

  void parse_variable() {
    const auto name = expect_word("a variable name");
    if (declared_.contains(name.text)) fail(name, "variable '" + name.text + "' is declared twice");
    expect_symbol('{');
    std::optional<std::vector<std::string>> states;
    semantic_tags tags;
    std::optional<std::pair<bif_token, std::string>> edges_text;
    while (!accept_symbol('}')) {
      const auto keyword = expect_word("'type' or 'property'");
      if (keyword.text == "type") {
        const auto kind = expect_word("'discrete'");
        if (kind.text != "discrete") fail(kind, "only discrete variables are supported, found '" + kind.text + "'");
        expect_symbol('[');
        const auto count_token = expect_word("the number of states");
        std::size_t count = 0;
        const auto& digits = count_token.text;
        const auto [digits_end, failure] = std::from_chars(digits.data(), digits.data() + digits.size(), count);
        if (failure != std::errc() || digits_end != digits.data() + digits.size() || count < 1) {
          fail(count_token, "expected the number of states (a whole number ≥ 1), found '" + count_token.text + "'");
        }
        expect_symbol(']');
        expect_symbol('{');
        std::vector<std::string> labels;
        while (!accept_symbol('}')) {
          labels.push_back(expect_word("a state name").text);
          accept_symbol(',');
        }
        if (labels.size() != count) {
          fail(count_token, "variable '" + name.text + "' declares " + count_token.text + " states but lists " +
                                std::to_string(labels.size()));
        }
        expect_symbol(';');
        states = std::move(labels);
      } else if (keyword.text == "property") {
        const auto where = current_;
        const auto text = property_value();
        const auto eq = text.find('=');
        const auto key = eq == std::string::npos ? std::string() : std::string(text::trim(text.substr(0, eq)));
        const auto value = eq == std::string::npos ? std::string() : std::string(text::trim(text.substr(eq + 1)));
        if (key == "quantity") tags.quantity = value;
        if (key == "unit") tags.unit = value;
        if (key == "role") tags.role = value;
        if (key == "edges") edges_text = std::make_pair(where, value);
      } else {
        fail(keyword, "expected 'type' or 'property', found '" + keyword.text + "'");
      }
    }
    if (!states) fail(name, "variable '" + name.text + "' has no 'type discrete' line");
    try {
      variable var(name.text, std::move(*states), tags);
      if (edges_text) {
        std::vector<double> edges;
        for (const auto& piece : text::split(edges_text->second, ',')) {
          const auto value = text::parse_double(piece);
          if (!value || !std::isfinite(*value)) {
            fail(edges_text->first,
                 "the edges of '" + name.text + "' must be finite numbers, found " + text::quoted_number(piece));
          }
          edges.push_back(*value);
        }
        var.set_edges(std::move(edges));
      }
      declared_.emplace(name.text, declaration{name, std::move(var), std::nullopt});
      order_.push_back(name.text);
    } catch (const model_error& e) {
      fail(name, e.what());
    }
  }

  /// The numbers up to ';'. Past `most` of them the rest are checked and counted but not kept,
  /// and `too_many(count)` fails: a list far longer than its table takes no memory.
  template <class TooMany>
  std::vector<double> parse_numbers(std::size_t most, TooMany too_many) {
    std::vector<double> values;
    std::size_t count = 0;
    while (!accept_symbol(';')) {
      const auto token = expect_word("a probability or ';'");
      const auto value = text::parse_double(token.text);
      if (!value || !std::isfinite(*value)) {
        fail(token, "expected a probability, found " + text::quoted_number(token.text));
      }
      if (++count <= most) values.push_back(*value);
      accept_symbol(',');
    }
    if (count > most) too_many(count);
    return values;
  }

  /// The shape of a block's table when its variables are declared already (as they usually
  /// are), so that its lists are bounded as they are read.
  struct declared_shape {
    std::size_t states = 0;
    std::size_t configurations = 0;
  };

  /// The declared shape of `block`'s table, refused by name beyond max_table_cells before its
  /// rows are read; nullopt when a variable is declared later (checked when the network is built).
  std::optional<declared_shape> declared_shape_of(const probability_block& block) const {
    const auto child = declared_.find(block.header.text);
    if (child == declared_.end()) return std::nullopt;
    std::vector<std::size_t> cards;
    for (const auto& parent : block.parents) {
      const auto it = declared_.find(parent);
      if (it == declared_.end()) return std::nullopt;
      cards.push_back(it->second.var.cardinality());
    }
    const declared_shape shape{child->second.var.cardinality(), mixed_radix(cards).size()};
    try {
      static_cast<void>(checked_table_cells(block.header.text, shape.states, shape.configurations));
    } catch (const model_error& e) {
      fail(block.where, e.what());
    }
    return shape;
  }

  void parse_probability() {
    expect_symbol('(');
    const auto child = expect_word("the variable's name");
    probability_block block;
    block.header = child;
    block.where = child;
    if (accept_symbol('|')) {
      while (!accept_symbol(')')) {
        const auto parent = expect_word("a parent's name");
        block.parents.push_back(parent.text);
        block.parent_tokens.push_back(parent);
        accept_symbol(',');
      }
    } else {
      expect_symbol(')');
    }
    const auto shape = declared_shape_of(block);
    // A variable declared later bounds nothing yet: a list then stops at a whole table's limit.
    const auto row_most = shape ? shape->states : max_table_cells;
    const auto table_most = shape ? shape->states * shape->configurations : max_table_cells;
    const auto numbers = [&](const bif_token& at, std::size_t most) {
      return parse_numbers(most, [&](std::size_t count) {
        if (!shape)
          fail(at, "more than " + std::to_string(most) + " probabilities for '" + child.text + "', " +
                       "pgm's limit of cells per table (docs/limits.md)");
        fail(at, "expected " + std::to_string(most) + " probabilities for '" + child.text + "', found " +
                     std::to_string(count));
      });
    };
    expect_symbol('{');
    while (!accept_symbol('}')) {
      const auto at = current_;
      if (accept_symbol('(')) {
        if (block.rows.size() == (shape ? shape->configurations : max_table_cells)) {
          fail(at, "more rows than the " + std::to_string(block.rows.size()) + " configurations of the parents of '" +
                       child.text + "'");
        }
        std::vector<std::string> labels;
        while (!accept_symbol(')')) {
          labels.push_back(expect_word("a parent state").text);
          accept_symbol(',');
        }
        auto values = numbers(at, row_most);
        if (!block.rows.emplace(labels, std::make_pair(at, std::move(values))).second) {
          fail(at, "this configuration of the parents of '" + child.text + "' is given twice");
        }
        continue;
      }
      const auto keyword = expect_word("'(', 'table', 'default' or '}'");
      if (keyword.text == "table") {
        block.table = numbers(keyword, block.parents.empty() ? row_most : table_most);
        block.where = keyword;
      } else if (keyword.text == "default") {
        block.fallback = numbers(keyword, row_most);
      } else if (keyword.text == "property") {
        property_value();
      } else {
        fail(keyword, "expected '(', 'table', 'default' or '}', found '" + keyword.text + "'");
      }
    }
    blocks_.push_back(std::move(block));
  }

  cpt<double> build_table(const declaration& decl) {
    const auto& block = *decl.table;
    std::vector<variable> parents;
    for (const auto& name : block.parents) parents.push_back(declared_.at(name).var);
    const std::size_t j = decl.var.cardinality();
    mixed_radix radix = [&] {
      std::vector<std::size_t> cards;
      for (const auto& p : parents) cards.push_back(p.cardinality());
      return mixed_radix(cards);
    }();
    std::vector<double> values;
    try {
      values.resize(checked_table_cells(decl.var.name(), j, radix.size()));
    } catch (const model_error& e) {
      fail(block.where, e.what());
    }
    auto check_count = [&](const bif_token& at, const std::vector<double>& row) {
      if (row.size() != j) {
        fail(at, "expected " + std::to_string(j) + " probabilities for '" + decl.var.name() + "', found " +
                     std::to_string(row.size()));
      }
    };
    if (block.table) {
      if (!parents.empty()) {
        fail(block.where, "'table' for '" + decl.var.name() +
                              "', which has parents, is ordered differently by different tools; "
                              "write one '(parent states) probabilities;' line per configuration");
      }
      check_count(block.where, *block.table);
      values = *block.table;
    } else {
      std::vector<bool> filled(radix.size(), false);
      for (const auto& [labels, row] : block.rows) {
        const auto& [at, probabilities] = row;
        if (labels.size() != parents.size()) {
          fail(at, "expected states of " + std::to_string(parents.size()) + " parents of '" + decl.var.name() +
                       "', found " + std::to_string(labels.size()));
        }
        std::vector<std::size_t> codes;
        for (std::size_t i = 0; i < labels.size(); ++i) {
          const auto state = parents[i].find_state(labels[i]);
          if (!state) {
            fail(at, "'" + labels[i] + "' is not a state of '" + parents[i].name() +
                         "' (states: " + text::list_for_message(parents[i].states()) + ")");
          }
          codes.push_back(state->value());
        }
        check_count(at, probabilities);
        const auto u = radix.encode(codes);
        std::copy(probabilities.begin(), probabilities.end(), values.begin() + static_cast<std::ptrdiff_t>(u * j));
        filled[u] = true;
      }
      for (std::size_t u = 0; u < radix.size(); ++u) {
        if (filled[u]) continue;
        if (!block.fallback) {
          fail(block.where, "the probability block of '" + decl.var.name() +
                                "' misses a parent configuration and has no 'default' line");
        }
        check_count(block.where, *block.fallback);
        std::copy(block.fallback->begin(), block.fallback->end(), values.begin() + static_cast<std::ptrdiff_t>(u * j));
      }
    }
    if (const auto bad = normalizer_.normalize(values, j)) {
      auto where = block.where;
      if (!block.table) {
        const auto codes = radix.decode(bad->first);
        std::vector<std::string> labels;
        for (std::size_t i = 0; i < codes.size(); ++i) labels.push_back(parents[i].states()[codes[i]]);
        const auto row = block.rows.find(labels);
        if (row != block.rows.end()) where = row->second.first;
      }
      fail(where, normalizer_.refusal(decl.var.name(), bad->second));
    }
    try {
      return cpt<double>(decl.var, std::move(parents), std::move(values));
    } catch (const model_error& e) {
      fail(block.where, e.what());
    }
  }

  bif_lexer lexer_;
  bif_token current_;
  column_normalizer normalizer_;
  std::vector<std::string>* notes_;
  std::map<std::string, std::string>* properties_;
  std::map<std::string, declaration, std::less<>> declared_;
  std::vector<std::string> order_;
  std::vector<probability_block> blocks_;
};

}  // namespace

std::optional<std::string> bif_name_problem(std::string_view text) {
  if (text.empty()) return "it is empty";
  for (char c : text) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) {
      return std::string("BIF names hold letters, digits, '_', '-' and '.' only (found '") + c + "')";
    }
  }
  return std::nullopt;
}

std::optional<std::string> bif_state_problem(std::string_view text) {
  if (text.empty()) return "it is empty";
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u <= 32 || u >= 127) return "BIF states cannot hold spaces or characters outside printable ASCII";
    if (std::string_view("{}()[];,|\"").find(c) != std::string_view::npos) {
      return std::string("BIF states cannot hold '") + c + "' (pgmpy and bnlearn split states there)";
    }
  }
  if (text.find("//") != std::string_view::npos || text.find("/*") != std::string_view::npos) {
    return "BIF states cannot hold '//' or '/*' (they start comments)";
  }
  return std::nullopt;
}

}  // namespace detail

bayesian_network parse_bif(std::string_view text, const std::string& source, const network_read_options& options) {
  return detail::bif_parser(text, source, options).parse();
}

bayesian_network read_bif(const std::filesystem::path& path, const network_read_options& options) {
  return parse_bif(pgm::read_file(path), path.string(), options);
}

void write_bif(const bayesian_network& network, std::ostream& out, const bif_write_options& options) {
  if (network.has_sparse_tables()) {
    write_bif(network.dense("writing BIF, which has no sparse form (pgm's JSON model has),"), out, options);
    return;
  }
  std::vector<std::string> dotted;
  auto checked = [&](const std::string& word, const std::string& what) -> const std::string& {
    if (const auto problem = detail::bif_name_problem(word)) {
      throw model_error(what + " '" + word + "' cannot be written to BIF: " + *problem);
    }
    if (word.find('.') != std::string::npos) dotted.push_back(word);
    return word;
  };
  auto checked_state = [](const std::string& state, const std::string& variable_name) -> const std::string& {
    if (const auto problem = detail::bif_state_problem(state)) {
      throw model_error("state '" + state + "' of '" + variable_name + "' cannot be written to BIF: " + *problem);
    }
    return state;
  };
  std::ostringstream text;
  text << "network " << checked(options.network_name, "network name") << " {\n";
  for (const auto& [key, value] : options.network_properties)
    text << "  property pgm." << key << " = " << value << " ;\n";
  text << "}\n";
  for (const auto& v : network.variables()) {
    text << "variable " << checked(v.name(), "variable name") << " {\n  type discrete [ " << v.cardinality() << " ] { ";
    for (std::size_t s = 0; s < v.cardinality(); ++s) {
      text << (s ? ", " : "") << checked_state(v.states()[s], v.name());
    }
    text << " };\n";
    if (options.properties) {
      if (v.has_intervals()) {
        text << "  property edges = ";
        for (std::size_t e = 0; e < v.edges().size(); ++e) {
          text << (e ? ", " : "") << text::format_double(v.edges()[e]);
        }
        text << " ;\n";
      }
      const auto& tags = v.tags();
      for (const auto& [key, value] : {std::pair<const char*, const std::string*>{"quantity", &tags.quantity},
                                       {"unit", &tags.unit},
                                       {"role", &tags.role}}) {
        if (value->empty()) continue;
        if (value->find(';') != std::string::npos) {
          throw model_error("the " + std::string(key) + " tag of '" + v.name() + "' contains ';'");
        }
        text << "  property " << key << " = " << *value << " ;\n";
      }
    }
    text << "}\n";
  }
  for (const auto& table : network.tables()) {
    text << "probability ( " << table.child().name();
    for (std::size_t p = 0; p < table.parents().size(); ++p) {
      text << (p ? ", " : " | ") << table.parents()[p].name();
    }
    text << " ) {\n";
    auto write_values = [&](std::span<const double> values) {
      for (std::size_t x = 0; x < values.size(); ++x) {
        text << (x ? ", " : " ") << text::format_double(values[x]);
      }
      text << ";\n";
    };
    if (table.parents().empty()) {
      text << "  table";
      write_values(table.column(config_index(0)));
    } else {
      for (std::size_t u = 0; u < table.configurations(); ++u) {
        const auto codes = table.parent_codes(config_index(u));
        text << "  (";
        for (std::size_t p = 0; p < codes.size(); ++p) {
          text << (p ? ", " : "") << table.parents()[p].states()[codes[p]];
        }
        text << ")";
        write_values(table.column(config_index(u)));
      }
    }
    text << "}\n";
  }
  if (options.notes != nullptr && !dotted.empty()) {
    options.notes->push_back("names with '.' (" + text::list_for_message(dotted) +
                             ") are written as they are; pgmpy 0.1.26 cannot read them in 'probability' lines "
                             "(pgm reads them)");
  }
  out << text.str();
}

std::string to_bif(const bayesian_network& network, const bif_write_options& options) {
  std::ostringstream out;
  write_bif(network, out, options);
  return out.str();
}

void write_bif(const bayesian_network& network, const std::filesystem::path& path, const bif_write_options& options) {
  const auto text = to_bif(network, options);  // fails before the file is touched
  pgm::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

network_format_codec detail::bif_format() {
  return {.name = "bif",
          .title = "BIF",
          .extensions = {".bif"},
          .read =
              [](std::string_view text, const std::string& source, const network_read_options& options) {
                return read_keeping_statistics(parse_bif, text, source, options);
              },
          .write =
              [](const bayesian_network& network, const network_write_options& options) {
                return to_bif(network, {.properties = options.properties,
                                        .notes = options.notes,
                                        .network_properties = kept_properties(options)});
              }};
}

}  // namespace pgm
