#include "cli/report_template.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"

namespace pgm::cli {
namespace {

using text::format_short;
using text::join;
using text::list_for_message;
using text::parse_double;
using text::split;

class report_template_renderer {
 public:
  report_template_renderer(const std::vector<named_summary>& summaries, std::string source)
      : summaries_(summaries), source_(std::move(source)) {
    if (summaries_.empty()) throw error("a report needs at least one summary");
  }

  [[nodiscard]] std::string render(std::string_view text) const {
    std::string out;
    std::size_t line = 1, line_start = 0, pos = 0;
    while (pos < text.size()) {
      const auto open = text.find("{{", pos);
      const auto end_of_text = open == std::string_view::npos ? text.size() : open;
      for (std::size_t i = pos; i < end_of_text; ++i) {
        if (text[i] == '\n') {
          ++line;
          line_start = i + 1;
        }
      }
      if (open == std::string_view::npos) {
        out.append(text.substr(pos));
        break;
      }
      if (open > pos && text[open - 1] == '\\') {  // "\{{" stands for "{{" itself
        out.append(text.substr(pos, open - 1 - pos));
        out += "{{";
        pos = open + 2;
        continue;
      }
      out.append(text.substr(pos, open - pos));
      const std::size_t column = open - line_start + 1;
      const auto close = text.find("}}", open + 2);
      const auto newline = text.find('\n', open + 2);
      if (close == std::string_view::npos || (newline != std::string_view::npos && newline < close)) {
        throw parse_error(source_, line, column, "a placeholder '{{' is not closed by '}}' on its line");
      }
      out += evaluate(text.substr(open + 2, close - open - 2), line, column);
      pos = close + 2;
    }
    return out;
  }

 private:
  using fields = std::array<std::string, 6>;  // scenario, target, strategy, w, rows, metric

  struct item {
    const aggregated_point* row;  // null for a number
    double value;
  };
  struct values {
    std::vector<item> items;
    fields pattern;  // how each field was selected, to pair two selections
    bool number = false;
  };
  struct format {
    enum class kind { percent, fixed, count } type = kind::fixed;
    int decimals = 0;
    bool sign = false;
  };
  struct context {
    std::string placeholder;
    std::size_t line, column;
  };

  [[noreturn]] void fail(const context& at, const std::string& what) const {
    throw parse_error(source_, at.line, at.column, "{{" + at.placeholder + "}}: " + what);
  }

  std::string evaluate(std::string_view placeholder, std::size_t line, std::size_t column) const {
    const context at{std::string(placeholder), line, column};
    std::vector<std::string> tokens;
    for (const auto& piece : split_blanks(placeholder)) tokens.push_back(piece);
    if (tokens.size() < 2) fail(at, "expected a format and an expression, e.g. {{pct:1 scenario/target/…}}");
    const auto spec = parse_format(tokens[0], at);
    std::size_t next = 1;
    const bool is_range = tokens[next] == "range";
    if (is_range) ++next;
    const auto result = expression(tokens, next, at);
    if (next != tokens.size()) fail(at, "unexpected '" + tokens[next] + "' after the expression");
    if (result.items.empty()) fail(at, "the expression gives no value");
    if (is_range) {
      double lo = INFINITY, hi = -INFINITY;
      for (const auto& i : result.items) {
        lo = std::min(lo, i.value);
        hi = std::max(hi, i.value);
      }
      const auto low = print(lo, spec), high = print(hi, spec);
      return low == high ? low : low + "–" + high;
    }
    if (result.items.size() != 1) {
      fail(at, "gives " + std::to_string(result.items.size()) + " values; reduce them with range, min or max");
    }
    return print(result.items.front().value, spec);
  }

  static std::vector<std::string> split_blanks(std::string_view text) {
    std::vector<std::string> pieces;
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
      const auto start = i;
      while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
      if (i > start) pieces.emplace_back(text.substr(start, i - start));
    }
    return pieces;
  }

  format parse_format(std::string_view token, const context& at) const {
    format f;
    if (token.starts_with('+')) {
      f.sign = true;
      token.remove_prefix(1);
    }
    if (token == "count") {
      f.type = format::kind::count;
      return f;
    }
    const auto colon = token.find(':');
    const auto name = token.substr(0, colon);
    if (name == "pct") {
      f.type = format::kind::percent;
    } else if (name == "num") {
      f.type = format::kind::fixed;
    } else {
      fail(at, "unknown format '" + std::string(token) + "' (formats: pct:N, num:N, count, each with an optional +)");
    }
    const auto digits = colon == std::string_view::npos ? std::string_view() : token.substr(colon + 1);
    if (digits.size() != 1 || digits[0] < '0' || digits[0] > '6') {
      fail(at, "the format '" + std::string(token) + "' needs a number of decimals from 0 to 6, e.g. " +
                   std::string(name) + ":1");
    }
    f.decimals = digits[0] - '0';
    return f;
  }

  static std::string print(double value, const format& f) {
    std::string text;
    if (f.type == format::kind::count) {
      const auto whole = std::llround(std::fabs(value));
      std::string digits = std::to_string(whole);
      for (auto i = static_cast<std::ptrdiff_t>(digits.size()) - 3; i > 0; i -= 3) {
        digits.insert(static_cast<std::size_t>(i), ",");
      }
      text = (value < 0 && whole != 0 ? "−" : "") + digits;
    } else {
      char buffer[64];
      const double shown = f.type == format::kind::percent ? 100 * value : value;
      std::snprintf(buffer, sizeof buffer, "%.*f", f.decimals, std::fabs(shown));
      text = buffer;
      const bool zero = text.find_first_not_of("0.") == std::string::npos;
      if (shown < 0 && !zero) text = "−" + text;
    }
    if (f.sign && !text.starts_with("−") && text.find_first_not_of("0.,") != std::string::npos) text = "+" + text;
    return text;
  }

  values expression(const std::vector<std::string>& tokens, std::size_t& next, const context& at) const {
    if (next >= tokens.size()) fail(at, "the expression ends early");
    const auto& token = tokens[next++];
    if (token == "diff") {
      auto a = expression(tokens, next, at);
      auto b = expression(tokens, next, at);
      return difference(a, b, at);
    }
    if (token == "abs") {
      auto a = expression(tokens, next, at);
      for (auto& i : a.items) i.value = std::fabs(i.value);
      return a;
    }
    if (token == "min" || token == "max") {
      const auto a = expression(tokens, next, at);
      values reduced;
      reduced.number = true;
      double best = token == "min" ? INFINITY : -INFINITY;
      for (const auto& i : a.items) best = token == "min" ? std::min(best, i.value) : std::max(best, i.value);
      reduced.items.push_back({nullptr, best});
      return reduced;
    }
    if (token == "sd" || token == "reps") {
      if (next >= tokens.size()) fail(at, "'" + token + "' needs a selector");
      auto a = select(tokens[next++], at);
      for (auto& i : a.items) {
        i.value = token == "sd" ? i.row->standard_deviation : static_cast<double>(i.row->repetitions);
      }
      return a;
    }
    if (token == "first-within") {
      const auto tolerance = expression(tokens, next, at);
      if (!tolerance.number || tolerance.items.size() != 1) fail(at, "first-within needs a number first, e.g. 0.005");
      auto a = expression(tokens, next, at);
      auto b = expression(tokens, next, at);
      return first_within(tolerance.items.front().value, a, b, at);
    }
    if (token == "range") fail(at, "range must come first, right after the format");
    if (token.find('/') == std::string::npos) {
      const auto number = text::parse_double(token);
      if (!number || !std::isfinite(*number)) {
        fail(at, "'" + token +
                     "' is neither a number, a selector (scenario/target/strategy/w/rows/metric) nor one of "
                     "diff, abs, min, max, sd, reps, range, first-within");
      }
      values literal;
      literal.number = true;
      literal.items.push_back({nullptr, *number});
      return literal;
    }
    return select(token, at);
  }

  static fields key_of(const aggregated_point& p) {
    return {p.scenario, p.target, p.strategy, p.weight, std::to_string(p.rows), std::string(to_string(p.metric))};
  }

  values select(const std::string& selector, const context& at) const {
    static constexpr std::array<const char*, 6> names{"scenario", "target", "strategy", "w", "rows", "metric"};
    const named_summary* summary = &summaries_.front();
    std::string_view path = selector;
    if (const auto colon = path.find(':'); colon != std::string_view::npos && colon < path.find('/')) {
      const auto name = path.substr(0, colon);
      path.remove_prefix(colon + 1);
      summary = nullptr;
      std::vector<std::string> known;
      for (const auto& s : summaries_) {
        if (s.name == name) summary = &s;
        if (!s.name.empty()) known.push_back(s.name);
      }
      if (!summary) {
        fail(at, "no summary is named '" + std::string(name) +
                     "' (named: " + (known.empty() ? std::string("none") : join(known)) + ")");
      }
    }
    const auto parts = split(path, '/');
    if (parts.size() != names.size()) {
      fail(at, "'" + selector + "' has " + std::to_string(parts.size()) +
                   " fields; a selector is scenario/target/strategy/w/rows/metric");
    }
    // The largest |D| of each scenario and target, for rows = max.
    std::map<std::pair<std::string, std::string>, std::size_t> largest;
    for (const auto& p : summary->rows) {
      auto& m = largest[{p.scenario, p.target}];
      m = std::max(m, p.rows);
    }
    std::vector<const aggregated_point*> rows;
    for (const auto& p : summary->rows) rows.push_back(&p);
    values result;
    for (std::size_t f = 0; f < names.size(); ++f) {
      result.pattern[f] = parts[f];
      if (parts[f] == "*") continue;
      const auto wanted = split(parts[f], ',');
      std::vector<const aggregated_point*> kept;
      std::vector<std::string> seen;
      for (const auto* p : rows) {
        const auto value = key_of(*p)[f];
        if (std::find(seen.begin(), seen.end(), value) == seen.end()) seen.push_back(value);
        for (const auto& w : wanted) {
          const bool match = f == 4 && w == "max" ? p->rows == largest[{p->scenario, p->target}] : value == w;
          if (match) {
            kept.push_back(p);
            break;
          }
        }
      }
      if (kept.empty()) {
        fail(at, "no summary row matches '" + selector + "': " + names[f] + " '" + parts[f] +
                     "' is none of those left (" + text::list_for_message(seen) + ")");
      }
      rows = std::move(kept);
    }
    for (const auto* p : rows) result.items.push_back({p, p->mean});
    return result;
  }

  /// The b row paired with a's row: equal on every field both selections wrote alike.
  values difference(const values& a, const values& b, const context& at) const {
    values result;
    if (a.number || b.number) {
      const auto& many = a.number ? b : a;
      result = many;
      for (auto& i : result.items) {
        i.value = a.number ? a.items.front().value - i.value : i.value - b.items.front().value;
      }
      result.number = a.number && b.number;
      return result;
    }
    result.pattern = a.pattern;
    for (std::size_t f = 0; f < a.pattern.size(); ++f) {
      if (a.pattern[f] != b.pattern[f]) result.pattern[f] = "\x01";  // not comparable any more
    }
    for (const auto& x : a.items) {
      const auto key = key_of(*x.row);
      const item* partner = nullptr;
      for (const auto& y : b.items) {
        const auto other = key_of(*y.row);
        bool same = true;
        for (std::size_t f = 0; f < key.size(); ++f) {
          if (a.pattern[f] == b.pattern[f] && a.pattern[f] != "\x01" && key[f] != other[f]) same = false;
        }
        if (!same) continue;
        if (partner) fail(at, "diff: more than one row of the second selection pairs with " + join(key, "/"));
        partner = &y;
      }
      if (!partner) fail(at, "diff: no row of the second selection pairs with " + join(key, "/"));
      result.items.push_back({x.row, x.value - partner->value});
    }
    return result;
  }

  values first_within(double tolerance, const values& a, const values& b, const context& at) const {
    if (a.number || b.number) fail(at, "first-within compares two selections over |D|");
    auto gap = difference(a, b, at);
    std::sort(gap.items.begin(), gap.items.end(),
              [](const item& x, const item& y) { return x.row->rows < y.row->rows; });
    for (std::size_t i = 1; i < gap.items.size(); ++i) {
      if (gap.items[i].row->rows == gap.items[i - 1].row->rows) {
        fail(at, "first-within needs one series over |D|, but |D| = " + std::to_string(gap.items[i].row->rows) +
                     " appears more than once");
      }
    }
    for (const auto& i : gap.items) {
      if (std::fabs(i.value) <= tolerance) {
        values result;
        result.number = true;
        result.items.push_back({nullptr, static_cast<double>(i.row->rows)});
        return result;
      }
    }
    fail(at, "the two never come within " + text::format_short(tolerance));
  }

  const std::vector<named_summary>& summaries_;
  std::string source_;
};

}  // namespace

std::string render_report_template(std::string_view text, const std::string& source,
                                   const std::vector<named_summary>& summaries) {
  return report_template_renderer(summaries, source).render(text);
}

}  // namespace pgm::cli
