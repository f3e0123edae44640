// A network format of your own: the UAI competitions' Bayesian network files (.uai), which
// libDAI, Merlin and toulbar2 read. Registered here, pgm::read_network, pgm::write_network and
// pgm::network_formats() know it, and compiled into the program (PGM_PLUGIN_SOURCES) so does every
// command: `pgm convert sachs.bif sachs.uai`. UAI keeps no names, so a network reads back with
// variables v0, v1, … and states 0, 1, …; writing a network loses its names.

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
class uai_tokens {
 public:
  uai_tokens(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

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
    std::size_t used = 0;
    double value = -1;
    try {
      value = std::stod(text, &used);
    } catch (const std::exception&) {
    }
    if (used != text.size() || !(value >= 0 && value <= 1))
      fail("expected " + std::string(what) + ", found '" + text + "'");
    return value;
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

// Parent configurations in UAI's order, the last parent fastest, as pgm's parent codes.
bool next_codes(std::vector<std::size_t>& codes, const std::vector<pgm::variable>& parents) {
  for (std::size_t i = codes.size(); i-- > 0;) {
    if (++codes[i] < parents[i].cardinality()) return true;
    codes[i] = 0;
  }
  return false;
}

pgm::model_document read_uai(std::string_view text, const std::string& source, const pgm::network_read_options&) {
  constexpr std::size_t most = 100000;
  uai_tokens in(text, source);
  if (const auto kind = in.word("BAYES"); kind != "BAYES")
    in.fail("expected BAYES (a Bayesian network), found '" + kind + "'");
  std::vector<pgm::variable> variables;
  const auto n = in.count("the number of variables", most);
  for (std::size_t v = 0; v < n; ++v) {
    std::vector<std::string> states;
    const auto k = in.count("a cardinality", 1000);
    for (std::size_t s = 0; s < k; ++s) states.push_back(std::to_string(s));
    variables.emplace_back("v" + std::to_string(v), states);
  }
  if (in.count("the number of tables", most) != n) in.fail("expected one table per variable");
  std::vector<std::vector<std::size_t>> scopes(n);
  for (auto& scope : scopes) {
    scope.resize(in.count("a scope's size", n));
    for (auto& v : scope) v = in.count("a variable of the scope", n - 1);
    if (scope.empty()) in.fail("a scope without its child");
  }
  std::vector<pgm::cpt<double>> tables;
  for (const auto& scope : scopes) {
    std::vector<pgm::variable> parents;
    for (std::size_t i = 0; i + 1 < scope.size(); ++i) parents.push_back(variables[scope[i]]);
    pgm::cpt<double> table(variables[scope.back()], parents);  // for its layout
    std::vector<double> values(table.size());
    if (in.count("the number of entries", most * 10) != values.size())
      in.fail("the number of entries is not the table's size");
    std::vector<std::size_t> codes(parents.size(), 0);
    do {
      const auto u = table.configuration(codes).value();
      for (std::size_t x = 0; x < table.child_cardinality(); ++x)
        values[u * table.child_cardinality() + x] = in.probability("a probability");
    } while (next_codes(codes, parents));
    tables.emplace_back(variables[scope.back()], parents, std::move(values));
  }
  const auto network = pgm::bayesian_network::from_tables(std::move(tables));
  return {network.structure(), network.tables(), std::nullopt};
}

std::string write_uai(const pgm::bayesian_network& network, const pgm::network_write_options&) {
  std::ostringstream out;
  out << "BAYES\n" << network.size() << '\n';
  for (const auto& v : network.variables()) out << v.cardinality() << ' ';
  out << '\n' << network.size() << '\n';
  for (const auto& table : network.tables()) {
    out << table.parents().size() + 1;
    for (const auto& parent : table.parents()) out << ' ' << network.id(parent.name()).value();
    out << ' ' << network.id(table.child().name()).value() << '\n';
  }
  for (const auto& table : network.tables()) {
    out << '\n' << table.size() << '\n';
    std::vector<std::size_t> codes(table.parents().size(), 0);
    do {
      for (const double p : table.column(table.configuration(codes))) out << ' ' << pgm::text::format_double(p);
      out << '\n';
    } while (next_codes(codes, table.parents()));
  }
  return out.str();
}

const pgm::register_network_format registered(
    {.name = "uai", .title = "UAI", .extensions = {".uai"}, .read = read_uai, .write = write_uai});

}  // namespace
