#pragma once
// Internal to the CSV reader (src/lib/data), not installed: the one record scanner every CSV path
// uses (csv_scanner, read_csv, count_csv), how a field's text becomes a value, the label
// dictionary and the order of states. Callable on any byte buffer (for fuzzing, issue 17).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/text.hpp"
#include "pgm/data/missing.hpp"
#include "pgm/data/state_order.hpp"
#include "pgm/io/csv.hpp"

namespace pgm::detail {

/// A problem at a place in a piece of text whose first line is not known yet (a chunk parsed
/// in parallel): `line` counts from the cursor's starting line. The piece's driver turns it
/// into a parse_error once the lines before the piece are known.
struct csv_failure {
  std::size_t line;
  std::size_t column;
  std::string what;
  bool missing_value = false;  // a missing_value_error: a missing value the policy refuses
};

/// The messages of the CSV limits (pgm/core/limits.hpp), one wording for every reader.
[[nodiscard]] inline std::string too_many_columns_message() {
  return "more than " + std::to_string(csv_max_columns) +
         " fields in a record, pgm's limit of CSV columns (docs/limits.md)";
}
[[nodiscard]] inline std::string record_too_long_message() {
  return "a record longer than " + std::to_string(csv_max_record_bytes >> 20) +
         " MiB, pgm's limit of a CSV record (docs/limits.md)";
}

enum class csv_record {
  complete,    // a record was read
  end,         // the text ended (only blank lines were left)
  incomplete,  // the text ended inside a record that may go on: fetch more, then read again
};

/// Reads records from `text`. With `final` false the text is a prefix of the input: a record
/// that reaches its end is `incomplete` and the cursor is left at the record's start.
class csv_record_reader {
 public:
  csv_record_reader(std::string_view text, char delimiter, bool final, csv_cursor start = {})
      : text_(text), delimiter_(delimiter), final_(final), cursor_(start) {
    for (auto& e : ends_) e = false;
    ends_[static_cast<unsigned char>(delimiter)] = true;
    ends_[static_cast<unsigned char>('\n')] = true;
    ends_[static_cast<unsigned char>('\r')] = true;
  }

  [[nodiscard]] const csv_cursor& cursor() const noexcept { return cursor_; }
  /// The line where the last record read starts.
  [[nodiscard]] std::size_t record_line() const noexcept { return record_line_; }

  /// Reads the next non-blank record into `fields`. Throws csv_failure for bad quoting.
  csv_record next(std::vector<csv_field>& fields) {
    fields.clear();
    used_ = 0;
    if (!skip_blank_lines()) return csv_record::incomplete;
    if (cursor_.pos >= text_.size()) return final_ ? csv_record::end : csv_record::incomplete;
    const csv_cursor start = cursor_;
    record_line_ = cursor_.line;
    const auto give_up = [&] {
      cursor_ = start;
      fields.clear();
      return csv_record::incomplete;
    };
    while (true) {
      csv_field field;
      if (!read_field(field)) return give_up();
      fields.push_back(field);
      if (fields.size() > csv_max_columns) throw csv_failure{field.line, field.column, too_many_columns_message()};
      if (cursor_.pos - start.pos > csv_max_record_bytes) {
        throw csv_failure{record_line_, start.pos - start.line_start + 1, record_too_long_message()};
      }
      if (cursor_.pos >= text_.size()) return final_ ? csv_record::complete : give_up();
      const char c = text_[cursor_.pos];
      if (c == delimiter_) {
        ++cursor_.pos;
        continue;
      }
      // End of line: LF, CRLF or a lone CR.
      if (c == '\r') {
        ++cursor_.pos;
        if (cursor_.pos >= text_.size() && !final_) return give_up();
      }
      if (cursor_.pos < text_.size() && text_[cursor_.pos] == '\n') ++cursor_.pos;
      new_line();
      return csv_record::complete;
    }
  }

 private:
  void new_line() {
    ++cursor_.line;
    cursor_.line_start = cursor_.pos;
  }

  // Lines of blanks only, each ended as a record is (LF, CRLF or a lone CR), so that a reading
  // from any line's start meets the same records. False when, before the whole input is here,
  // the text ends in a line that is blank so far, or in a CR whose LF may follow.
  bool skip_blank_lines() {
    while (cursor_.pos < text_.size()) {
      std::size_t p = cursor_.pos;
      while (p < text_.size() && (text_[p] == ' ' || text_[p] == '\t')) ++p;
      if (p >= text_.size()) {
        if (!final_) return false;
        cursor_.pos = p;
      } else if (text_[p] == '\n' || text_[p] == '\r') {
        ++p;
        if (text_[p - 1] == '\r') {
          if (p >= text_.size() && !final_) return false;
          if (p < text_.size() && text_[p] == '\n') ++p;
        }
        cursor_.pos = p;
        new_line();
      } else {
        return true;
      }
    }
    return true;
  }

  [[nodiscard]] bool at_field_end(std::size_t p) const {
    return p >= text_.size() || ends_[static_cast<unsigned char>(text_[p])];
  }

  bool read_field(csv_field& field) {
    // Leading blanks before a quote are tolerated.
    std::size_t p = cursor_.pos;
    while (p < text_.size() && (text_[p] == ' ' || text_[p] == '\t')) ++p;
    if (p < text_.size() && text_[p] == '"') return read_quoted(p, field);
    const std::size_t start = cursor_.pos;
    std::size_t pos = start;
    while (pos < text_.size() && !ends_[static_cast<unsigned char>(text_[pos])]) ++pos;
    cursor_.pos = pos;
    // Trim blanks (a field holds no line end).
    std::size_t first = start;
    std::size_t last = pos;
    while (first < last && (text_[first] == ' ' || text_[first] == '\t')) ++first;
    while (last > first && (text_[last - 1] == ' ' || text_[last - 1] == '\t')) --last;
    field = {text_.substr(first, last - first), cursor_.line, start - cursor_.line_start + 1};
    return true;
  }

  bool read_quoted(std::size_t quote, csv_field& field) {
    const std::size_t line = cursor_.line;
    const std::size_t column = quote - cursor_.line_start + 1;
    if (used_ == unescaped_.size()) unescaped_.emplace_back();
    std::string& value = unescaped_[used_++];
    value.clear();
    cursor_.pos = quote + 1;
    while (true) {
      if (cursor_.pos >= text_.size()) {
        if (!final_) return false;
        throw csv_failure{line, column, "a quoted field is never closed"};
      }
      const char c = text_[cursor_.pos++];
      // Not a byte more than the limit of a record is copied into one field.
      if (cursor_.pos - quote > csv_max_record_bytes) throw csv_failure{line, column, record_too_long_message()};
      if (c == '"') {
        if (cursor_.pos >= text_.size() && !final_) return false;  // "" may be split
        if (cursor_.pos < text_.size() && text_[cursor_.pos] == '"') {
          value += '"';
          ++cursor_.pos;
          continue;
        }
        break;
      }
      if (c == '\n') new_line();
      value += c;
    }
    while (cursor_.pos < text_.size() && (text_[cursor_.pos] == ' ' || text_[cursor_.pos] == '\t')) ++cursor_.pos;
    if (cursor_.pos >= text_.size() && !final_) return false;
    if (!at_field_end(cursor_.pos)) {
      throw csv_failure{cursor_.line, cursor_.pos - cursor_.line_start + 1,
                        "expected a delimiter or the end of the line after a closing quote"};
    }
    field = {value, line, column};
    return true;
  }

  std::string_view text_;
  char delimiter_;
  bool final_;
  csv_cursor cursor_;
  std::size_t record_line_ = 1;
  bool ends_[256];
  std::deque<std::string> unescaped_;  // deque: views into it survive emplace_back
  std::size_t used_ = 0;
};

/// Reads the records of text that holds no quote, all of whose records are whole (the final
/// text of csv_record_reader): the same records, fields, lines and columns as that reader, in
/// one tighter scan. The fast path of every chunk without a quote.
class csv_plain_reader {
 public:
  csv_plain_reader(std::string_view text, char delimiter) : text_(text), delimiter_(delimiter) {
    for (auto& e : ends_) e = false;
    ends_[static_cast<unsigned char>(delimiter)] = true;
    ends_[static_cast<unsigned char>('\n')] = true;
    ends_[static_cast<unsigned char>('\r')] = true;
  }

  /// Line ends consumed so far.
  [[nodiscard]] std::size_t lines() const noexcept { return line_; }

  /// Reads the next non-blank record into `fields`; false at the end of the text.
  bool next(std::vector<csv_field>& fields) {
    fields.clear();
    const std::size_t n = text_.size();
    const char* const text = text_.data();
    while (true) {  // blank lines: only blanks before a line end (LF, CRLF or a lone CR)
      std::size_t p = pos_;
      while (p < n && (text[p] == ' ' || text[p] == '\t')) ++p;
      if (p >= n) {
        pos_ = n;
        return false;
      }
      if (text[p] != '\n' && text[p] != '\r') break;
      if (text[p++] == '\r' && p < n && text[p] == '\n') ++p;
      pos_ = p;
      ++line_;
      line_start_ = pos_;
    }
    const std::size_t record_start = pos_;
    while (true) {
      const std::size_t start = pos_;
      std::size_t p = start;
      while (p < n && !ends_[static_cast<unsigned char>(text[p])]) ++p;
      std::size_t first = start;
      std::size_t last = p;
      while (first < last && (text[first] == ' ' || text[first] == '\t')) ++first;
      while (last > first && (text[last - 1] == ' ' || text[last - 1] == '\t')) --last;
      fields.push_back({text_.substr(first, last - first), line_, start - line_start_ + 1});
      if (fields.size() > csv_max_columns)
        throw csv_failure{line_, start - line_start_ + 1, too_many_columns_message()};
      if (p - record_start > csv_max_record_bytes) {
        throw csv_failure{line_, record_start - line_start_ + 1, record_too_long_message()};
      }
      if (p >= n) {
        pos_ = n;
        return true;
      }
      const char c = text[p++];
      if (c == delimiter_) {
        pos_ = p;
        continue;
      }
      if (c == '\r' && p < n && text[p] == '\n') ++p;  // CRLF; else LF or a lone CR
      pos_ = p;
      ++line_;
      line_start_ = p;
      return true;
    }
  }

 private:
  std::string_view text_;
  char delimiter_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
  std::size_t line_start_ = 0;
  bool ends_[256];
};

/// Calls `on_record(fields)` for every non-blank record of `text`, which holds whole records
/// only, and returns the line ends consumed; lines and columns in `fields` count from the start
/// of `text` (line 0, column 1). Text without a quote takes csv_plain_reader. Throws
/// csv_failure for bad quoting, and whatever `on_record` throws.
template <class OnRecord>
std::size_t for_each_record(std::string_view text, char delimiter, std::vector<csv_field>& fields,
                            OnRecord&& on_record) {
  if (text.find('"') == std::string_view::npos) {
    csv_plain_reader reader(text, delimiter);
    while (reader.next(fields)) on_record(fields);
    return reader.lines();
  }
  csv_record_reader reader(text, delimiter, true, {0, 0, 0});
  while (reader.next(fields) == csv_record::complete) on_record(fields);
  return reader.cursor().line;
}

/// Skips a UTF-8 byte order mark at the start of the input.
[[nodiscard]] inline std::size_t byte_order_mark(std::string_view text) {
  return text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
}

/// The header record: column names, none empty, none repeated. Throws parse_error.
[[nodiscard]] inline std::vector<std::string> header_names(const std::vector<csv_field>& fields,
                                                           const std::string& source) {
  std::vector<std::string> header;
  std::unordered_set<std::string_view> seen;  // views into `fields`, which outlive this call
  for (const auto& field : fields) {
    if (field.text.empty()) throw parse_error(source, field.line, field.column, "a column in the header has no name");
    if (!seen.insert(field.text).second) {
      throw parse_error(source, field.line, field.column,
                        "the column '" + std::string(field.text) + "' appears twice in the header");
    }
    header.emplace_back(field.text);
  }
  return header;
}

/// The positions of `names` in `header`, in file order, each once; all of them for no names.
[[nodiscard]] inline std::vector<std::size_t> column_positions(const std::vector<std::string>& header,
                                                               const std::vector<std::string>& names,
                                                               const std::string& source) {
  std::vector<std::size_t> wanted;
  if (names.empty()) {
    for (std::size_t i = 0; i < header.size(); ++i) wanted.push_back(i);
    return wanted;
  }
  for (const auto& name : names) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) {
      throw data_error(source + ": there is no column '" + name + "' (columns: " + text::list_for_message(header) +
                       ")");
    }
    wanted.push_back(static_cast<std::size_t>(it - header.begin()));
  }
  std::sort(wanted.begin(), wanted.end());
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  return wanted;
}

/// A record with another number of fields than the header.
[[noreturn]] inline void fail_width(const std::vector<csv_field>& fields, std::size_t width) {
  const auto& last = fields.back();
  throw csv_failure{
      last.line, last.column,
      "expected " + std::to_string(width) + " fields as in the header, found " + std::to_string(fields.size())};
}

[[noreturn]] inline void fail_field(const csv_field& field, const std::string& column, const std::string& what) {
  throw csv_failure{field.line, field.column, "column '" + column + "': " + what};
}

[[nodiscard]] inline std::string non_finite_message(std::string_view text) {
  return "'" + std::string(text) + "' is not a finite number (" + text::number_hint(text) + ")";
}

/// Whether a field's text is one of the missing tokens, in one table look-up for most texts
/// (a code such as "3" never starts like "NA" or "?").
class missing_matcher {
 public:
  explicit missing_matcher(const std::vector<std::string>& tokens) {
    for (auto& f : first_) f = false;
    for (const auto& token : tokens) {
      if (token.empty()) {
        empty_ = true;
        continue;
      }
      first_[static_cast<unsigned char>(token.front())] = true;
      tokens_.push_back(token);
    }
  }

  [[nodiscard]] bool operator()(std::string_view text) const noexcept {
    if (text.empty()) return empty_;
    if (!first_[static_cast<unsigned char>(text.front())]) return false;  // small enough to inline
    return is_token(text);
  }

  [[nodiscard]] bool empty_is_missing() const noexcept { return empty_; }

 private:
  [[nodiscard]] bool is_token(std::string_view text) const noexcept {
    for (const auto& token : tokens_) {
      if (text == token) return true;
    }
    return false;
  }

  bool empty_ = false;
  bool first_[256];
  std::vector<std::string> tokens_;
};

/// The provisional id of a missing value in a column's ids (never a label's id).
inline constexpr std::uint32_t missing_id = missing_code<std::uint32_t>;

/// How a reader treats missing values: which texts are missing and what to do with them.
struct missing_rule {
  missing_rule() : missing_rule(missing_values{}) {}
  explicit missing_rule(const missing_values& missing) : is_missing(missing.tokens), policy(missing.policy) {}
  missing_matcher is_missing;
  missing_policy policy;
};

/// A missing value under the policy `error`: its place, and how to read such data instead.
[[noreturn]] inline void fail_missing(const csv_field& field, const std::string& column) {
  throw csv_failure{field.line, field.column,
                    "column '" + column + "': " +
                        (field.text.empty() ? std::string("the value is empty, a missing value")
                                            : "'" + std::string(field.text) + "' is a missing value") +
                        " (missing values are refused by default: choose the missing-value policy drop or available "
                        "to read incomplete rows, or other texts as missing)",
                    true};
}

/// Whether a field is missing: false for a value, true for a missing one where the policy
/// reads them; fails where the policy is `error`, and for an empty field that is no missing token.
[[nodiscard]] inline bool field_missing(const csv_field& field, const std::string& column, const missing_rule& rule) {
  if (!rule.is_missing(field.text)) {
    if (field.text.empty()) {
      throw csv_failure{field.line, field.column,
                        "column '" + column + "': the value is empty (the empty field is not a missing token here)",
                        true};
    }
    return false;
  }
  if (rule.policy == missing_policy::error) fail_missing(field, column);
  return true;
}

/// A field's number for a continuous column: fails on text and on NaN or an infinity.
[[nodiscard]] inline double continuous_value(const csv_field& field, const std::string& column) {
  const auto value = text::parse_double(field.text);
  if (!value) fail_field(field, column, "expected a number, got " + text::quoted_number(field.text));
  if (!std::isfinite(*value)) fail_field(field, column, non_finite_message(field.text));
  return *value + 0.0;  // -0 is 0 (docs/limits.md): written back as "0"
}

/// The value of a label that is a small whole number written the one canonical way ("7", not
/// "07" or "7.0"), or -1: such labels are looked up by value, with no hashing.
[[nodiscard]] inline int small_whole_number(std::string_view text) {
  if (text.empty() || text.size() > 3) return -1;
  int value = 0;
  for (char c : text) {
    const unsigned digit = static_cast<unsigned char>(c) - static_cast<unsigned>('0');
    if (digit > 9) return -1;
    value = value * 10 + static_cast<int>(digit);
  }
  if (text.size() > 1 && text.front() == '0') return -1;
  return value;
}

/// Where a value first appears: its line (relative to the first line of chunk `chunk` until
/// the lines before the chunk are known) and column. Within a column, (line, column) orders
/// fields as they stand in the file.
struct csv_place {
  std::size_t line = 0;
  std::size_t column = 0;
  std::size_t chunk = 0;
};

struct string_hash {
  using is_transparent = void;
  [[nodiscard]] std::size_t operator()(std::string_view text) const noexcept {
    return std::hash<std::string_view>{}(text);
  }
};

/// The labels of a discrete column and their provisional ids, in the order added.
class label_dictionary {
 public:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  struct entry {
    std::string text;
    csv_place first;
  };

  [[nodiscard]] std::uint32_t find(std::string_view text) const {
    // A one-digit label (the common case of codes) first, small enough to be inlined.
    if (text.size() == 1 && !dense_.empty()) {
      const unsigned digit = static_cast<unsigned char>(text[0]) - static_cast<unsigned>('0');
      if (digit <= 9) return dense_[digit];
    }
    return find_any(text);
  }

  /// Adds a label that is not there yet.
  std::uint32_t add(std::string_view text, const csv_place& first) {
    const auto id = static_cast<std::uint32_t>(entries_.size());
    entries_.push_back({std::string(text), first});
    const int small = small_whole_number(text);
    if (small >= 0) {
      if (dense_.empty()) dense_.assign(1000, none);
      dense_[static_cast<std::size_t>(small)] = id;
    } else {
      others_.emplace(entries_.back().text, id);
    }
    return id;
  }

  [[nodiscard]] std::size_t size() const noexcept { return entries_.size(); }
  [[nodiscard]] const std::vector<entry>& entries() const noexcept { return entries_; }
  [[nodiscard]] std::vector<entry>& entries() noexcept { return entries_; }

 private:
  [[nodiscard]] std::uint32_t find_any(std::string_view text) const {
    const int small = small_whole_number(text);
    if (small >= 0) return dense_.empty() ? none : dense_[static_cast<std::size_t>(small)];
    const auto it = others_.find(text);
    return it == others_.end() ? none : it->second;
  }

  std::vector<std::uint32_t> dense_;  // by value, for small_whole_number labels
  std::unordered_map<std::string, std::uint32_t, string_hash, std::equal_to<>> others_;
  std::vector<entry> entries_;
};

// A discrete column's states come from its labels in pgm's one order: pgm/data/state_order.hpp.
using pgm::order_states;

/// The state of `known` that is exactly the number `text` is ("1.0" for the state "1"), or
/// label_dictionary::none: a label and a state are compared as text unless both are numbers
/// exactly equal (pgm/data/state_order.hpp). Looked up only for a label that is no state's text.
[[nodiscard]] inline std::uint32_t numeric_state(const variable& known, std::string_view text) {
  const auto value = exact_decimal_of(text);
  if (!value || !text::parse_double(text)) return label_dictionary::none;
  for (std::size_t s = 0; s < known.cardinality(); ++s) {
    if (exact_decimal_of(known.states()[s]) == value) return static_cast<std::uint32_t>(s);
  }
  return label_dictionary::none;
}

/// Whether a field that is a missing token is, in this column, a state of the model's variable
/// (pathfinder declares a state "NA"): then it is that state, not a missing value.
[[nodiscard]] inline bool declared_state(const variable* known, std::string_view text) {
  return known != nullptr && known->find_state(text).has_value();
}

/// Splits `text`, which starts at a record boundary, into chunks of whole records that can be
/// parsed independently: the start of every chunk, then the end of the last. A chunk is about
/// `bytes` long and ends just after a line end; where it holds a quote, a line end may lie
/// inside a quoted field, so a sequential scan of its records finds where it ends. Chunks
/// stop once one ends at or past `limit`. When not `final` the text is a prefix of the input
/// and only complete records are taken (perhaps none). Bad quoting ends the splitting: the last
/// chunk then runs to the end of the text, where parsing meets the same problem in its place.
[[nodiscard]] inline std::vector<std::size_t> record_chunks(std::string_view text, char delimiter, std::size_t bytes,
                                                            std::size_t limit, bool final) {
  std::vector<std::size_t> bounds{0};
  std::vector<csv_field> fields;
  std::size_t at = 0;
  bytes = std::max<std::size_t>(bytes, 1);
  while (at < text.size() && at < limit) {
    const auto newline = text.find('\n', std::min(text.size(), at + bytes) - 1);
    std::size_t end = newline == std::string_view::npos ? text.size() : newline + 1;
    if (newline == std::string_view::npos && !final) {  // the last line may go on
      const auto last = text.rfind('\n');
      if (last == std::string_view::npos || last < at) break;
      end = last + 1;
    }
    if (text.substr(at, end - at).find('"') != std::string_view::npos) {
      csv_record_reader reader(text.substr(at), delimiter, final, {0, 0, 0});
      try {
        while (at + reader.cursor().pos < end && reader.next(fields) == csv_record::complete) {
        }
      } catch (const csv_failure&) {
        bounds.push_back(text.size());
        return bounds;
      }
      end = at + reader.cursor().pos;
      if (end == at) break;  // no whole record here yet
    }
    bounds.push_back(end);
    at = end;
  }
  return bounds;
}

}  // namespace pgm::detail
