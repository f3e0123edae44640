// A network format of your own: libDAI's factor graph files (.fg), which libDAI's programs and
// its Python and MATLAB bindings read. Registered here, pgm::read_network, pgm::write_network and
// pgm::network_formats() know it, and compiled into the program (PGM_PLUGIN_SOURCES) so does every
// command: `pgm convert sachs.bif sachs.fg`. A .fg file keeps no names and no directions: a network
// reads back with variables v0, v1, … and states 0, 1, …, each table a factor whose last variable
// is its child, as this writer lists them.
//
// The file: the number of factors, then per factor its number of variables, their labels, their
// cardinalities, the number of entries listed and one "index value" line each, the index counting
// the first variable fastest (libDAI's order; pgm's tables count the last fastest).

#include <cctype>
#include <cstddef>
#include <pgm/core/text.hpp>
#include <pgm/io/network_format.hpp>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

// The file's words, one at a time, with the line and column of the last for errors.
class fg_tokens {
 public:
  fg_tokens(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

  std::string word(std::string_view what) {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) {
      if (text_[at_++] == '\n') {
        ++line_;
        line_start_ = at_;
      }
    }
    start_ = at_;
    if (at_ == text_.size()) fail("expected " + std::string(what) + ", found the end of the file");
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    return std::string(text_.substr(start_, at_ - start_));
  }

  std::size_t count(std::string_view what, std::size_t at_most) {
    const auto text = word(what);
    std::size_t value = 0;
    for (const char c : text) {
      if (!std::isdigit(static_cast<unsigned char>(c)) || value > at_most)
        fail("expected " + std::string(what) + ", found '" + text + "'");
      value = value * 10 + static_cast<std::size_t>(c - '0');
    }
    if (value > at_most) fail(std::string(what) + " " + text + " is over " + std::to_string(at_most));
    return value;
  }

  double probability(std::string_view what) {
    const auto text = word(what);
    const auto value = pgm::text::parse_double(text);
    if (!value || !(*value >= 0 && *value <= 1)) fail("expected " + std::string(what) + ", found '" + text + "'");
    return *value;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw pgm::parse_error(source_, line_, start_ - line_start_ + 1, what);
  }

 private:
  std::string_view text_;
  std::string source_;
  std::size_t at_ = 0;
  std::size_t start_ = 0;  // of the last word
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;
};

// libDAI's index of pgm's value `i` of a table over `cards` (pgm: last fastest; libDAI: first).
std::size_t first_fastest(std::size_t i, const std::vector<std::size_t>& cards) {
  std::size_t index = 0;
  std::size_t stride = 1;
  std::vector<std::size_t> digits(cards.size());
  for (std::size_t k = cards.size(); k-- > 0;) {
    digits[k] = i % cards[k];
    i /= cards[k];
  }
  for (std::size_t k = 0; k < cards.size(); ++k) {
    index += digits[k] * stride;
    stride *= cards[k];
  }
  return index;
}

pgm::model_document read_fg(std::string_view text, const std::string& source, const pgm::network_read_options&) {
  constexpr std::size_t most = 100000;
  fg_tokens in(text, source);
  const auto factors = in.count("the number of factors", most);
  std::vector<std::vector<std::size_t>> scopes(factors);
  std::vector<std::size_t> cardinality_of;  // by label
  std::vector<std::vector<double>> values(factors);
  for (std::size_t f = 0; f < factors; ++f) {
    scopes[f].resize(in.count("a factor's number of variables", 64));
    if (scopes[f].empty()) in.fail("a factor without variables");
    for (auto& label : scopes[f]) {
      label = in.count("a variable's label", most - 1);
      if (label >= cardinality_of.size()) cardinality_of.resize(label + 1, 0);
    }
    std::vector<std::size_t> cards;
    std::size_t size = 1;
    for (const auto label : scopes[f]) {
      const auto card = in.count("a cardinality", 1000);
      if (card == 0) in.fail("a cardinality of 0");
      if (cardinality_of[label] != 0 && cardinality_of[label] != card) in.fail("a variable with two cardinalities");
      cardinality_of[label] = card;
      cards.push_back(card);
      if ((size *= card) > most * 10) in.fail("a factor of more than " + std::to_string(most * 10) + " entries");
    }
    // pgm's order for the table: the same variables, the last fastest.
    std::vector<double> libdai(size, 0.0);
    const auto entries = in.count("the number of entries", size);
    for (std::size_t e = 0; e < entries; ++e) {
      const auto index = in.count("an entry's index", size - 1);
      libdai[index] = in.probability("a probability");
    }
    values[f].resize(size);
    for (std::size_t i = 0; i < size; ++i) values[f][i] = libdai[first_fastest(i, cards)];
  }
  std::vector<pgm::variable> variables;
  for (std::size_t label = 0; label < cardinality_of.size(); ++label) {
    std::vector<std::string> states;
    for (std::size_t s = 0; s < cardinality_of[label]; ++s) states.push_back(std::to_string(s));
    if (states.empty()) in.fail("variable " + std::to_string(label) + " is in no factor");
    variables.emplace_back("v" + std::to_string(label), states);
  }
  std::vector<pgm::cpt<double>> tables;
  for (std::size_t f = 0; f < factors; ++f) {
    std::vector<pgm::variable> parents;
    for (std::size_t k = 0; k + 1 < scopes[f].size(); ++k) parents.push_back(variables[scopes[f][k]]);
    tables.emplace_back(variables[scopes[f].back()], std::move(parents), std::move(values[f]));
  }
  const auto network = pgm::bayesian_network::from_tables(std::move(tables));
  return {network.structure(), network.tables(), std::nullopt};
}

std::string write_fg(const pgm::bayesian_network& network, const pgm::network_write_options&) {
  std::ostringstream out;
  out << network.size() << '\n';
  for (std::size_t f = 0; f < network.factor_count(); ++f) {
    const auto table = network.factor(f);  // over (parents…, child), the child last
    out << '\n' << table.scope().size() << '\n';
    for (const auto v : table.scope()) out << v.value() << ' ';
    out << '\n';
    for (const auto c : table.cardinalities()) out << c << ' ';
    out << '\n' << table.size() << '\n';
    for (std::size_t i = 0; i < table.size(); ++i) {
      out << first_fastest(i, table.cardinalities()) << ' ' << pgm::text::format_double(table.values()[i]) << '\n';
    }
  }
  return out.str();
}

const pgm::register_network_format registered(
    {.name = "fg", .title = "libDAI factor graph", .extensions = {".fg"}, .read = read_fg, .write = write_fg});

}  // namespace
