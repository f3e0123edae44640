// The UAI competitions' formats (pgm/io/uai.hpp): a whitespace-separated token reader that
// knows the line and column of every token, numbers read with std::from_chars.

#include "pgm/io/uai.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>

#include "io/builtin_formats.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/text.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/read_options.hpp"

namespace pgm {
namespace {

/// The largest number of variables or factors a file may declare, checked before anything of
/// that size is allocated: the competition's largest problems have some 10^5.
constexpr std::size_t most_declared = std::size_t{1} << 24;

class uai_tokens {
 public:
  uai_tokens(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

  /// The next word, or nothing at the end of the text.
  std::optional<std::string_view> next() {
    while (at_ < text_.size() && is_space(text_[at_])) {
      if (text_[at_++] == '\n') {
        ++line_;
        line_start_ = at_;
      }
    }
    start_ = at_;
    if (at_ == text_.size()) return std::nullopt;
    while (at_ < text_.size() && !is_space(text_[at_])) ++at_;
    return text_.substr(start_, at_ - start_);
  }

  std::string_view word(std::string_view what) {
    const auto w = next();
    if (!w) fail("expected " + std::string(what) + ", found the end of the file");
    return *w;
  }

  /// A whole number in [lo, hi].
  std::size_t count(std::string_view what, std::size_t lo, std::size_t hi) {
    const auto w = word(what);
    std::size_t value = 0;
    const auto [end, problem] = std::from_chars(w.data(), w.data() + w.size(), value);
    if (problem == std::errc::result_out_of_range) fail(std::string(what) + " " + std::string(w) + " is too large");
    if (problem != std::errc() || end != w.data() + w.size()) {
      fail("expected " + std::string(what) + " (a whole number), found '" + text::printable(std::string(w)) + "'");
    }
    if (value < lo || value > hi) {
      fail(std::string(what) + " " + std::string(w) + " is out of range: expected " + std::to_string(lo) + " to " +
           std::to_string(hi));
    }
    return value;
  }

  /// A finite number ≥ 0.
  double value(std::string_view what) {
    const auto w = word(what);
    double value = 0;
    const auto [end, problem] = std::from_chars(w.data(), w.data() + w.size(), value);
    if (problem != std::errc() || end != w.data() + w.size() || !std::isfinite(value)) {
      fail("expected " + std::string(what) + " (a finite number), found '" + text::printable(std::string(w)) + "'");
    }
    if (value < 0) fail(std::string(what) + " is negative (" + std::string(w) + "); factor values are not");
    return value;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw parse_error(source_, line_, start_ - line_start_ + 1, what);
  }

  [[nodiscard]] bool at_end() {
    const auto saved = *this;
    const bool end = !next();
    *this = saved;
    return end;
  }

  [[nodiscard]] const std::string& source() const noexcept { return source_; }

 private:
  static bool is_space(char c) noexcept {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
  }

  std::string_view text_;
  std::string source_;
  std::size_t at_ = 0;
  std::size_t start_ = 0;  // of the last word
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;
};

std::vector<variable> numbered_variables(const std::vector<std::size_t>& cards) {
  std::vector<variable> variables;
  variables.reserve(cards.size());
  for (std::size_t v = 0; v < cards.size(); ++v) {
    std::vector<std::string> states;
    states.reserve(cards[v]);
    for (std::size_t s = 0; s < cards[v]; ++s) states.push_back(std::to_string(s));
    variables.emplace_back("v" + std::to_string(v), std::move(states));
  }
  return variables;
}

}  // namespace

uai_model parse_uai(std::string_view text, const std::string& source) {
  uai_tokens in(text, source);
  uai_model result;
  const auto kind = in.word("MARKOV or BAYES");
  if (kind == "MARKOV") {
    result.kind = uai_kind::markov;
  } else if (kind == "BAYES") {
    result.kind = uai_kind::bayes;
  } else {
    in.fail("expected MARKOV or BAYES, found '" + text::printable(std::string(kind)) + "'");
  }
  // Every declared thing takes at least two bytes of the text: memory follows the text's size,
  // not what a short file claims.
  const auto n = in.count("the number of variables", 0, most_declared);
  std::vector<std::size_t> cards;
  cards.reserve(std::min(n, text.size() / 2));
  // Each state is a labelled object: a variable's states are at most a table's cells, and the
  // states of all variables at most what the file's bytes could give values for (or 2^16).
  const std::size_t most_states = std::max<std::size_t>(std::size_t{1} << 16, text.size());
  std::size_t states = 0;
  for (std::size_t v = 0; v < n; ++v) {
    cards.push_back(in.count("a cardinality", 1, max_table_cells));
    states += cards.back();
    if (states > most_states) {
      in.fail("the variables have more than " + std::to_string(most_states) +
              " states in all, more than pgm reads from a UAI file of " + std::to_string(text.size()) +
              " bytes (at most 65536 or the file's size; docs/limits.md)");
    }
  }
  const auto m = in.count("the number of factors", 0, most_declared);
  if (result.kind == uai_kind::bayes && m != n) {
    in.fail("a BAYES file has one table per variable: expected " + std::to_string(n) + " factors, found " +
            std::to_string(m));
  }
  std::vector<std::vector<variable_id>> scopes;
  scopes.reserve(std::min(m, text.size() / 2));
  for (std::size_t f = 0; f < m; ++f) {
    auto& scope = scopes.emplace_back();
    scope.resize(in.count("the size of a factor's scope", result.kind == uai_kind::bayes ? 1 : 0, n));
    std::size_t cells = 1;
    for (auto& v : scope) {
      const auto id = in.count("a variable of factor " + std::to_string(f) + "'s scope", 0, n == 0 ? 0 : n - 1);
      if (n == 0) in.fail("factor " + std::to_string(f) + " names a variable, but the model has none");
      if (std::find(scope.data(), &v, index_at<variable_id>(id)) != &v) {
        in.fail("factor " + std::to_string(f) + " names variable " + std::to_string(id) + " twice");
      }
      v = index_at<variable_id>(id);
      cells = detail::saturating_multiply(cells, cards[id]);
    }
    if (cells > max_table_cells) {
      in.fail("factor " + std::to_string(f) + " would have " + std::to_string(cells) +
              " entries, more than pgm's limit of " + std::to_string(max_table_cells) + " (docs/limits.md)");
    }
  }
  std::vector<factor_table> factors;
  factors.reserve(m);
  for (std::size_t f = 0; f < m; ++f) {
    std::size_t cells = 1;
    std::vector<std::size_t> scope_cards;
    for (auto v : scopes[f]) {
      scope_cards.push_back(cards[v.value()]);
      cells *= cards[v.value()];
    }
    const auto entries = in.count("the number of entries of factor " + std::to_string(f), 0, max_table_cells);
    if (entries != cells) {
      in.fail("factor " + std::to_string(f) + " has " + std::to_string(cells) + " entries (the product of its " +
              "scope's cardinalities), but its table says " + std::to_string(entries));
    }
    std::vector<double> values;
    values.reserve(std::min(cells, text.size() / 2));
    const auto what = "an entry of factor " + std::to_string(f);
    for (std::size_t i = 0; i < cells; ++i) values.push_back(in.value(what));
    factors.emplace_back(std::move(scopes[f]), std::move(scope_cards), std::move(values));
  }
  if (!in.at_end()) {
    static_cast<void>(in.next());
    in.fail("expected the end of the file after the last factor's table");
  }
  result.model = markov_network(numbered_variables(cards), std::move(factors));
  return result;
}

uai_model read_uai(const std::filesystem::path& path) { return parse_uai(read_model_text(path), path.string()); }

bayesian_network to_bayesian_network(const uai_model& model, const std::string& source) {
  if (model.kind != uai_kind::bayes) {
    throw model_error("'" + source +
                      "' holds a Markov network (MARKOV): pgm solve and the Markov network functions read it; the "
                      "commands for Bayesian networks need a BAYES file");
  }
  const auto& variables = model.model.variables();
  detail::column_normalizer normalizer(network_read_options{}.tolerance);
  // Node i of the network is variable i of the file, whatever order the tables come in.
  std::vector<std::optional<cpt<double>>> by_child(variables.size());
  for (std::size_t f = 0; f < model.model.factor_count(); ++f) {
    const auto& table = model.model.factor(f);
    const auto child = table.scope().back();
    if (by_child[child.value()]) {
      throw model_error("'" + source + "': factors " + std::to_string(f) + " and an earlier one are both tables of " +
                        variables[child.value()].name() + " (a BAYES factor's last variable is its child)");
    }
    std::vector<variable> parents;
    for (std::size_t k = 0; k + 1 < table.scope().size(); ++k) parents.push_back(variables[table.scope()[k].value()]);
    auto values = table.values();
    if (const auto off = normalizer.normalize(values, variables[child.value()].cardinality())) {
      throw model_error("'" + source + "': factor " + std::to_string(f) + ": " +
                        normalizer.refusal(variables[child.value()].name(), off->second));
    }
    by_child[child.value()].emplace(variables[child.value()], std::move(parents), std::move(values));
  }
  std::vector<cpt<double>> tables;
  tables.reserve(variables.size());
  for (auto& table : by_child) tables.push_back(std::move(*table));
  return bayesian_network::from_tables(std::move(tables));
}

std::string to_uai(const markov_network& model) {
  std::string out = "MARKOV\n" + std::to_string(model.size()) + '\n';
  for (const auto& v : model.variables()) out += std::to_string(v.cardinality()) + ' ';
  out += '\n' + std::to_string(model.factor_count()) + '\n';
  for (const auto& f : model.factors()) {
    out += std::to_string(f.scope().size());
    for (auto v : f.scope()) out += ' ' + std::to_string(v.value());
    out += '\n';
  }
  for (const auto& f : model.factors()) {
    out += '\n' + std::to_string(f.size()) + '\n';
    for (const double v : f.values()) out += ' ' + text::format_double(v);
    out += '\n';
  }
  return out;
}

std::string to_uai(const bayesian_network& network) {
  std::ostringstream out;
  out << "BAYES\n" << network.size() << '\n';
  for (const auto& v : network.variables()) out << v.cardinality() << ' ';
  out << '\n' << network.size() << '\n';
  for (std::size_t f = 0; f < network.factor_count(); ++f) {
    const auto scope = network.factor_scope(f);
    out << scope.size();
    for (auto v : scope) out << ' ' << v.value();
    out << '\n';
  }
  for (std::size_t f = 0; f < network.factor_count(); ++f) {
    const auto table = network.factor(f);
    out << '\n' << table.size() << '\n';
    for (const double p : table.values()) out << ' ' << text::format_double(p);
    out << '\n';
  }
  return out.str();
}

std::vector<std::vector<std::pair<variable_id, std::size_t>>> parse_uai_evidence(std::string_view text,
                                                                                 const std::string& source,
                                                                                 const markov_network& model) {
  // The 2014 form is one sample without a count of samples; the older form starts with one.
  // Counting the words tells them apart: k pairs after k is 2k + 1 words.
  std::size_t words = 0;
  {
    uai_tokens count(text, source);
    while (count.next()) ++words;
  }
  uai_tokens in(text, source);
  if (words == 0) return {{}};
  const auto n = model.size();
  auto read_sample = [&](std::size_t sample) {
    const auto k = in.count("the number of observed variables", 0, n);
    std::vector<std::pair<variable_id, std::size_t>> observed;
    std::vector<bool> seen(n, false);
    for (std::size_t i = 0; i < k; ++i) {
      const auto v = in.count("an observed variable", 0, n == 0 ? 0 : n - 1);
      if (n == 0) in.fail("the evidence names a variable, but the model has none");
      if (seen[v])
        in.fail("variable " + std::to_string(v) + " is observed twice" + (sample > 0 ? " in one sample" : ""));
      seen[v] = true;
      const auto card = model.variables()[v].cardinality();
      const auto s = in.count("the state of variable " + std::to_string(v), 0, card - 1);
      observed.emplace_back(index_at<variable_id>(v), s);
    }
    return observed;
  };
  std::vector<std::vector<std::pair<variable_id, std::size_t>>> samples;
  uai_tokens peek(text, source);
  const auto first = peek.count("the number of observed variables", 0, most_declared);
  if (words == 2 * first + 1) {
    samples.push_back(read_sample(0));
  } else {
    const auto count = in.count("the number of evidence samples", 0, most_declared);
    for (std::size_t s = 0; s < count; ++s) samples.push_back(read_sample(s));
  }
  if (!in.at_end()) {
    static_cast<void>(in.next());
    in.fail("expected the end of the evidence");
  }
  if (samples.empty()) samples.emplace_back();
  return samples;
}

std::vector<variable_id> parse_uai_query(std::string_view text, const std::string& source,
                                         const markov_network& model) {
  uai_tokens in(text, source);
  const auto n = model.size();
  const auto k = in.count("the number of query variables", 1, n);
  std::vector<variable_id> query;
  std::vector<bool> seen(n, false);
  for (std::size_t i = 0; i < k; ++i) {
    const auto v = in.count("a query variable", 0, n - 1);
    if (seen[v]) in.fail("variable " + std::to_string(v) + " is queried twice");
    seen[v] = true;
    query.push_back(index_at<variable_id>(v));
  }
  if (!in.at_end()) {
    static_cast<void>(in.next());
    in.fail("expected the end of the query");
  }
  return query;
}

uai_result parse_uai_result(std::string_view text, const std::string& source) {
  uai_tokens in(text, source);
  uai_result result;
  result.task = std::string(in.word("PR, MAR, MAP or MMAP"));
  if (result.task != "PR" && result.task != "MAR" && result.task != "MAP" && result.task != "MMAP") {
    in.fail("expected PR, MAR, MAP or MMAP, found '" + text::printable(result.task) + "'");
  }
  while (const auto w = in.next()) {
    double value = 0;
    const auto [end, problem] = std::from_chars(w->data(), w->data() + w->size(), value);
    if (problem != std::errc() || end != w->data() + w->size()) {
      in.fail("expected a number, found '" + text::printable(std::string(*w)) + "'");
    }
    result.numbers.push_back(value);
  }
  return result;
}

std::string uai_pr_text(double log10_partition) { return "PR\n" + text::format_short(log10_partition, 17) + '\n'; }

std::string uai_mar_text(const std::vector<std::vector<double>>& marginals) {
  std::string out = "MAR\n" + std::to_string(marginals.size());
  for (const auto& m : marginals) {
    out += ' ' + std::to_string(m.size());
    for (const double p : m) out += ' ' + text::format_short(p, 17);
  }
  return out + '\n';
}

std::string uai_assignment_text(std::string_view task, std::span<const std::size_t> states) {
  std::string out = std::string(task) + '\n' + std::to_string(states.size());
  for (const auto s : states) out += ' ' + std::to_string(s);
  return out + '\n';
}

namespace detail {

network_format_codec uai_format() {
  return {.name = "uai",
          .title = "UAI",
          .extensions = {".uai"},
          .read =
              [](std::string_view text, const std::string& source, const network_read_options&) {
                const auto network = to_bayesian_network(parse_uai(text, source), source);
                return model_document{network.structure(), network.tables(), std::nullopt};
              },
          .write = [](const bayesian_network& network, const network_write_options&) { return to_uai(network); }};
}

}  // namespace detail
}  // namespace pgm
