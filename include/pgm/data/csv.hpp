#pragma once
/// \file
/// CSV reading and writing. A header row names the columns; fields may be quoted ("a, b",
/// with "" for a quote). Numeric columns become continuous, other columns discrete, unless
/// `csv_options` says otherwise. Every error names the file, line, column and what was
/// expected.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/state_order.hpp"
#include "pgm/detail/file.hpp"
#include "pgm/detail/text.hpp"

namespace pgm {

enum class column_kind {
  automatic,   ///< continuous if every value is a number, else discrete
  continuous,  ///< numbers only
  discrete,    ///< states; numeric labels sort numerically, others alphabetically
};

struct csv_options {
  char delimiter = ',';
  /// Read only these columns (in file order); empty reads all. Naming a column the file lacks
  /// is an error.
  std::vector<std::string> columns;
  /// The kind of each named column; others get `default_kind`.
  std::map<std::string, column_kind, std::less<>> kinds;
  column_kind default_kind = column_kind::automatic;
  /// Discrete columns whose variable is known already (from a model): their values must be
  /// its state labels, and the codes follow its state order.
  std::map<std::string, variable, std::less<>> variables;
  /// A header with no rows is an error unless this is set.
  bool allow_empty = false;
};

namespace detail {

/// One field of a CSV record. `text` stays valid until the next record is read.
struct csv_field {
  std::string_view text;
  std::size_t line;
  std::size_t column;  // 1-based byte column where the field starts
};

/// Splits CSV text into records of fields (RFC 4180 quoting; unquoted fields are trimmed;
/// blank lines are skipped; CRLF and LF line ends).
class csv_scanner {
 public:
  csv_scanner(std::string_view text, std::string source, char delimiter)
      : text_(text), source_(std::move(source)), delimiter_(delimiter) {
    if (text_.starts_with("\xEF\xBB\xBF")) {
      text_.remove_prefix(3);
      line_start_ = 0;
    }
  }

  [[nodiscard]] const std::string& source() const noexcept { return source_; }
  [[nodiscard]] std::size_t line() const noexcept { return line_; }

  /// Reads the next non-blank record; false at the end of the text.
  bool next(std::vector<csv_field>& fields) {
    fields.clear();
    unescaped_.clear();
    skip_blank_lines();
    if (pos_ >= text_.size()) return false;
    record_line_ = line_;
    while (true) {
      fields.push_back(read_field());
      if (pos_ >= text_.size()) return true;
      const char c = text_[pos_];
      if (c == delimiter_) {
        ++pos_;
        continue;
      }
      // End of line.
      if (c == '\r') ++pos_;
      if (pos_ < text_.size() && text_[pos_] == '\n') ++pos_;
      new_line();
      return true;
    }
  }

  /// Where the current record ends, for "expected N fields" messages.
  [[nodiscard]] std::size_t record_line() const noexcept { return record_line_; }

 private:
  void new_line() {
    ++line_;
    line_start_ = pos_;
  }

  void skip_blank_lines() {
    while (pos_ < text_.size()) {
      std::size_t p = pos_;
      while (p < text_.size() && (text_[p] == ' ' || text_[p] == '\t' || text_[p] == '\r')) ++p;
      if (p < text_.size() && text_[p] == '\n') {
        pos_ = p + 1;
        new_line();
      } else if (p >= text_.size()) {
        pos_ = p;
      } else {
        return;
      }
    }
  }

  [[nodiscard]] bool at_field_end(std::size_t p) const {
    return p >= text_.size() || text_[p] == delimiter_ || text_[p] == '\n' || text_[p] == '\r';
  }

  csv_field read_field() {
    // Leading blanks before a quote are tolerated.
    std::size_t p = pos_;
    while (p < text_.size() && (text_[p] == ' ' || text_[p] == '\t')) ++p;
    if (p < text_.size() && text_[p] == '"') return read_quoted(p);
    const std::size_t start = pos_;
    const std::size_t column = start - line_start_ + 1;
    while (!at_field_end(pos_)) ++pos_;
    return {trim(text_.substr(start, pos_ - start)), line_, column};
  }

  csv_field read_quoted(std::size_t quote) {
    const std::size_t line = line_;
    const std::size_t column = quote - line_start_ + 1;
    std::string value;
    pos_ = quote + 1;
    while (true) {
      if (pos_ >= text_.size()) {
        throw parse_error(source_, line, column, "a quoted field is never closed");
      }
      const char c = text_[pos_++];
      if (c == '"') {
        if (pos_ < text_.size() && text_[pos_] == '"') {
          value += '"';
          ++pos_;
          continue;
        }
        break;
      }
      if (c == '\n') new_line();
      value += c;
    }
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
    if (!at_field_end(pos_)) {
      throw parse_error(source_, line_, pos_ - line_start_ + 1,
                        "expected a delimiter or the end of the line after a closing quote");
    }
    unescaped_.push_back(std::move(value));
    return {unescaped_.back(), line, column};
  }

  std::string_view text_;
  std::string source_;
  char delimiter_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;
  std::size_t record_line_ = 1;
  std::deque<std::string> unescaped_;  // deque: views into it survive push_back
};

/// Collects one column's values while the file is scanned.
class csv_column_builder {
 public:
  csv_column_builder(std::string name, column_kind kind, const variable* known,
                     const std::string& source)
      : name_(std::move(name)), kind_(kind), known_(known), source_(&source) {
    if (known_) {
      kind_ = column_kind::discrete;
      for (const auto& state : known_->states()) intern(state);
    }
  }
  // ids_ holds views into labels_: copying would leave them pointing at the original.
  csv_column_builder(const csv_column_builder&) = delete;
  csv_column_builder& operator=(const csv_column_builder&) = delete;
  csv_column_builder(csv_column_builder&&) = default;
  csv_column_builder& operator=(csv_column_builder&&) = default;

  [[nodiscard]] column_kind kind() const noexcept { return kind_; }
  [[nodiscard]] const std::string& name() const noexcept { return name_; }
  /// An automatic column that met text: it must be read again as discrete.
  [[nodiscard]] bool needs_text_pass() const noexcept { return text_seen_; }

  void add(const csv_field& field) {
    if (field.text.empty()) fail(field, "the value is empty (missing values are not supported)");
    if (kind_ == column_kind::discrete) {
      add_label(field);
    } else if (!text_seen_) {
      add_number(field);
    }
  }

  [[nodiscard]] data_column finish() {
    if (kind_ == column_kind::discrete) return finish_discrete();
    if (first_non_finite_) fail(*first_non_finite_, non_finite_message(first_non_finite_text_));
    return continuous_column(name_, std::move(numbers_));
  }

 private:
  void add_number(const csv_field& field) {
    const auto value = parse_double(field.text);
    if (!value) {
      if (kind_ == column_kind::continuous) {
        fail(field, "expected a number, got '" + std::string(field.text) + "'");
      }
      text_seen_ = true;  // automatic: a text column; a second pass reads its labels
      numbers_.clear();
      numbers_.shrink_to_fit();
      return;
    }
    if (!std::isfinite(*value)) {
      if (kind_ == column_kind::continuous) fail(field, non_finite_message(field.text));
      if (!first_non_finite_) {
        first_non_finite_ = field;
        first_non_finite_text_ = std::string(field.text);
      }
    }
    numbers_.push_back(*value);
  }

  void add_label(const csv_field& field) {
    const auto it = ids_.find(field.text);
    if (it != ids_.end()) {
      codes_.push_back(it->second);
      return;
    }
    if (known_) {
      fail(field, "'" + std::string(field.text) + "' is not a state of '" + name_ +
                      "' (states: " + list_for_message(known_->states()) + ")");
    }
    const auto value = parse_double(field.text);
    if (value && !std::isfinite(*value) && !first_non_finite_) {
      first_non_finite_ = field;
      first_non_finite_text_ = std::string(field.text);
    }
    codes_.push_back(intern(field.text));
  }

  std::uint32_t intern(std::string_view label) {
    labels_.emplace_back(label);
    const auto id = static_cast<std::uint32_t>(labels_.size() - 1);
    ids_.emplace(labels_.back(), id);
    return id;
  }

  data_column finish_discrete() {
    if (known_) return discrete_column(*known_, codes_);
    if (labels_.empty()) {
      throw data_error(*source_ + ": column '" + name_ + "' has no values to take states from");
    }
    // Numbers by value, other labels alphabetically (pgm/data/state_order.hpp).
    auto order = order_states(labels_);
    if (order.numeric && first_non_finite_) {
      fail(*first_non_finite_, non_finite_message(first_non_finite_text_));
    }
    for (auto& code : codes_) code = order.state_of[code];
    return discrete_column(variable(name_, std::move(order.states)), codes_);
  }

  static std::string non_finite_message(std::string_view text) {
    return "'" + std::string(text) + "' is not a finite number (NaN and infinities are not "
           "supported)";
  }

  [[noreturn]] void fail(const csv_field& field, const std::string& what) const {
    throw parse_error(*source_, field.line, field.column, "column '" + name_ + "': " + what);
  }

  std::string name_;
  column_kind kind_;
  const variable* known_;
  const std::string* source_;
  bool text_seen_ = false;
  std::vector<double> numbers_;
  std::optional<csv_field> first_non_finite_;
  std::string first_non_finite_text_;
  std::deque<std::string> labels_;  // deque: ids_ keys view into it
  std::unordered_map<std::string_view, std::uint32_t> ids_;
  std::vector<std::uint32_t> codes_;
};

}  // namespace detail

/// Parses CSV text. `source` names it in error messages.
[[nodiscard]] inline dataset parse_csv(std::string_view text, const std::string& source,
                                       const csv_options& options = {}) {
  detail::csv_scanner scanner(text, source, options.delimiter);
  std::vector<detail::csv_field> fields;
  if (!scanner.next(fields)) {
    throw parse_error(source, 1, 1, "the file is empty; expected a header row naming the columns");
  }
  std::vector<std::string> header;
  for (const auto& field : fields) {
    if (field.text.empty()) {
      throw parse_error(source, field.line, field.column, "a column in the header has no name");
    }
    if (std::find(header.begin(), header.end(), field.text) != header.end()) {
      throw parse_error(source, field.line, field.column,
                        "the column '" + std::string(field.text) + "' appears twice in the header");
    }
    header.emplace_back(field.text);
  }
  const std::size_t width = header.size();

  // Which columns to read, and how.
  std::vector<std::size_t> wanted;
  if (options.columns.empty()) {
    for (std::size_t i = 0; i < width; ++i) wanted.push_back(i);
  } else {
    for (const auto& name : options.columns) {
      const auto it = std::find(header.begin(), header.end(), name);
      if (it == header.end()) {
        throw data_error(source + ": there is no column '" + name +
                         "' (columns: " + detail::list_for_message(header) + ")");
      }
      wanted.push_back(static_cast<std::size_t>(it - header.begin()));
    }
    std::sort(wanted.begin(), wanted.end());
    wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  }
  auto make_builder = [&](std::size_t i, std::optional<column_kind> forced) {
    const auto& name = header[i];
    const auto known = options.variables.find(name);
    const auto kind = options.kinds.find(name);
    return detail::csv_column_builder(
        name, forced.value_or(kind != options.kinds.end() ? kind->second : options.default_kind),
        known != options.variables.end() ? &known->second : nullptr, source);
  };

  auto scan = [&](std::vector<detail::csv_column_builder>& builders,
                  const std::vector<std::size_t>& positions) {
    detail::csv_scanner rows(text, source, options.delimiter);
    rows.next(fields);  // the header
    std::size_t count = 0;
    while (rows.next(fields)) {
      if (fields.size() != width) {
        const auto& last = fields.back();
        throw parse_error(source, last.line, last.column,
                          "expected " + std::to_string(width) + " fields as in the header, found " +
                              std::to_string(fields.size()));
      }
      for (std::size_t k = 0; k < positions.size(); ++k) builders[k].add(fields[positions[k]]);
      ++count;
    }
    return count;
  };

  std::vector<detail::csv_column_builder> builders;
  builders.reserve(wanted.size());
  for (auto i : wanted) builders.push_back(make_builder(i, std::nullopt));
  const std::size_t rows = scan(builders, wanted);
  if (rows == 0 && !options.allow_empty) {
    throw data_error(source + ": there are no data rows after the header");
  }

  // Automatic columns that met text are read once more, as labels.
  std::vector<std::size_t> text_positions;
  std::vector<std::size_t> text_slots;
  for (std::size_t k = 0; k < builders.size(); ++k) {
    if (builders[k].needs_text_pass()) {
      text_positions.push_back(wanted[k]);
      text_slots.push_back(k);
    }
  }
  if (!text_positions.empty()) {
    std::vector<detail::csv_column_builder> text_builders;
    text_builders.reserve(text_positions.size());
    for (auto i : text_positions) text_builders.push_back(make_builder(i, column_kind::discrete));
    scan(text_builders, text_positions);
    for (std::size_t k = 0; k < text_slots.size(); ++k) {
      builders[text_slots[k]] = std::move(text_builders[k]);
    }
  }

  dataset result(source);
  for (auto& builder : builders) result.add(builder.finish());
  return result;
}

/// Reads a CSV file; see parse_csv.
[[nodiscard]] inline dataset read_csv(const std::filesystem::path& path,
                                      const csv_options& options = {}) {
  return parse_csv(detail::read_file(path), path.string(), options);
}

namespace detail {

[[nodiscard]] inline std::string csv_escape(std::string_view text, char delimiter) {
  const bool needs_quotes =
      text.find_first_of(std::string{delimiter, '"', '\n', '\r'}) != std::string_view::npos ||
      (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!needs_quotes) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return quoted + '"';
}

}  // namespace detail

/// Writes a data set as CSV: discrete columns by state label, continuous ones as the
/// shortest decimal text that reads back to the same double.
inline void write_csv(const dataset& data, std::ostream& out, char delimiter = ',') {
  const auto& columns = data.columns();
  std::string line;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    line += (c ? std::string(1, delimiter) : std::string()) +
            detail::csv_escape(column_name(columns[c]), delimiter);
  }
  out << line << '\n';
  // Labels are escaped once per state, not once per row.
  std::vector<std::vector<std::string>> escaped_labels(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (const auto* d = std::get_if<discrete_column>(&columns[c])) {
      for (const auto& state : d->var().states()) {
        escaped_labels[c].push_back(detail::csv_escape(state, delimiter));
      }
    }
  }
  std::string buffer;
  for (std::size_t row = 0; row < data.rows(); ++row) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c) buffer += delimiter;
      if (const auto* d = std::get_if<discrete_column>(&columns[c])) {
        buffer += escaped_labels[c][d->code(row)];
      } else {
        buffer += detail::format_double(std::get<continuous_column>(columns[c]).values()[row]);
      }
    }
    buffer += '\n';
    if (buffer.size() > (1u << 16)) {
      out << buffer;
      buffer.clear();
    }
  }
  out << buffer;
}

/// Writes a data set to a CSV file atomically (see write_csv).
inline void write_csv(const dataset& data, const std::filesystem::path& path, char delimiter = ',') {
  detail::write_file_atomically(path, [&](std::ostream& out) { write_csv(data, out, delimiter); });
}

}  // namespace pgm
