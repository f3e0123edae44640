// CSV into a data set in memory (read_csv, parse_csv), the record-at-a-time scanner, the
// reader that opens an input and reads its header, and writing CSV.

#include "pgm/io/csv.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <variant>

#include "data/csv_input.hpp"
#include "pgm/core/file.hpp"
#include "pgm/detail/parallel_for.hpp"

namespace pgm {

// ---- the scanner and the reader ------------------------------------------------------

namespace detail {

csv_scanner::csv_scanner(std::string_view text, std::string source, char delimiter)
    : text_(text.substr(byte_order_mark(text))), source_(std::move(source)), delimiter_(delimiter) {}

bool csv_scanner::next(std::vector<csv_field>& fields) {
  // The deque of unescaped fields lives here so that views stay valid after `reader` is gone.
  csv_record_reader reader(text_, delimiter_, true, cursor_);
  try {
    const auto status = reader.next(fields);
    if (status != csv_record::complete) return false;
  } catch (const csv_failure& failure) {
    throw_at(source_, 0, failure);
  }
  // Quoted fields point into the reader, which ends here: keep their text.
  unescaped_.clear();
  const std::less<const char*> before;
  for (auto& field : fields) {
    const auto* begin = text_.data();
    if (before(field.text.data(), begin) || before(begin + text_.size(), field.text.data())) {
      unescaped_.emplace_back(field.text);
      field.text = unescaped_.back();
    }
  }
  cursor_ = reader.cursor();
  record_line_ = reader.record_line();
  return true;
}

}  // namespace detail

namespace {

constexpr std::size_t dataset_chunk_bytes = std::size_t{1} << 20;
constexpr std::size_t header_fetch_bytes = std::size_t{64} << 10;

void read_header(csv_reader::impl& input) {
  auto& bytes = *input.bytes;
  bytes.fetch(3);
  bytes.consume(detail::byte_order_mark(bytes.available()));
  std::size_t want = header_fetch_bytes;
  std::vector<detail::csv_field> fields;
  while (true) {
    bytes.fetch(want);
    const auto text = bytes.available();
    detail::csv_record_reader reader(text, input.delimiter, bytes.at_end());
    detail::csv_record status;
    try {
      status = reader.next(fields);
    } catch (const detail::csv_failure& failure) {
      detail::throw_at(input.source, 0, failure);
    }
    if (status == detail::csv_record::incomplete) {
      if (text.size() > csv_max_record_bytes) throw parse_error(input.source, 1, 1, detail::record_too_long_message());
      want = std::max(want, text.size()) * 2;
      continue;
    }
    if (status == detail::csv_record::end) {
      throw parse_error(input.source, 1, 1, "the file is empty; expected a header row naming the columns");
    }
    input.header = detail::header_names(fields, input.source);
    bytes.consume(reader.cursor().pos);
    input.first_line = reader.cursor().line;
    return;
  }
}

}  // namespace

csv_reader::csv_reader(const std::filesystem::path& path, char delimiter) : impl_(std::make_unique<impl>()) {
  impl_->source = detail::source_name(path);
  impl_->delimiter = delimiter;
  impl_->bytes = detail::open_source(path, impl_->source);
  read_header(*impl_);
}

csv_reader::csv_reader(std::string_view text, std::string source, char delimiter) : impl_(std::make_unique<impl>()) {
  impl_->source = std::move(source);
  impl_->delimiter = delimiter;
  impl_->bytes = detail::memory_source(text);
  read_header(*impl_);
}

csv_reader::~csv_reader() = default;
csv_reader::csv_reader(csv_reader&&) noexcept = default;
csv_reader& csv_reader::operator=(csv_reader&&) noexcept = default;

const std::string& csv_reader::source() const noexcept { return impl_->source; }
const std::vector<std::string>& csv_reader::header() const noexcept { return impl_->header; }

// ---- a data set in memory ------------------------------------------------------------

namespace {

enum class column_mode { continuous, automatic, labels, known, skip };

struct column_plan {
  std::string name;
  std::size_t position;  // field index in a record
  column_mode mode;
  const variable* known = nullptr;
};

/// One column's values in one chunk.
struct column_part {
  std::size_t missing = 0;  // values kept as missing (policy available)
  std::vector<double> numbers;
  bool text_seen = false;  // an automatic column met a value that is not a number
  std::optional<detail::csv_place> first_non_finite;
  std::string first_non_finite_text;
  detail::label_dictionary labels;
  std::vector<std::uint32_t> codes;
};

struct chunk_part {
  std::size_t rows = 0;
  std::size_t dropped = 0;  // rows left out for a missing value (policy drop)
  std::size_t lines = 0;
  std::vector<column_part> columns;  // empty until the chunk keeps a row (see parse_chunk)
};

/// Column `c` of `part`, empty when the chunk kept no row.
const column_part& column_in(const chunk_part& part, std::size_t c) {
  static const column_part none;
  return part.columns.empty() ? none : part.columns[c];
}

void add_missing(const column_plan& plan, column_part& part) {
  ++part.missing;
  switch (plan.mode) {
    case column_mode::continuous:
    case column_mode::automatic:
      if (!part.text_seen) part.numbers.push_back(std::numeric_limits<double>::quiet_NaN());
      return;
    case column_mode::labels:
    case column_mode::known:
      part.codes.push_back(detail::missing_id);
      return;
    case column_mode::skip:
      return;
  }
}

void add_value(const column_plan& plan, column_part& part, const detail::csv_field& field, std::size_t chunk,
               const detail::missing_rule& missing) {
  if (plan.mode == column_mode::skip) return;
  // A label seen before is no missing token (the common case first), nor is a model's state: a
  // model that declares a state "NA" has it read as that state.
  if (plan.mode == column_mode::labels || plan.mode == column_mode::known) {
    if (const auto id = part.labels.find(field.text); id != detail::label_dictionary::none) {
      part.codes.push_back(id);
      return;
    }
  }
  if (detail::field_missing(field, plan.name, missing)) {
    add_missing(plan, part);
    return;
  }
  switch (plan.mode) {
    case column_mode::continuous:
      part.numbers.push_back(detail::continuous_value(field, plan.name));
      return;
    case column_mode::automatic: {
      if (part.text_seen) return;
      const auto value = text::parse_double(field.text);
      if (!value) {
        part.text_seen = true;  // a text column: a second pass reads its labels
        part.numbers.clear();
        part.numbers.shrink_to_fit();
        return;
      }
      if (!std::isfinite(*value) && !part.first_non_finite) {
        part.first_non_finite = detail::csv_place{field.line, field.column, chunk};
        part.first_non_finite_text = std::string(field.text);
      }
      part.numbers.push_back(*value + 0.0);  // -0 is 0
      return;
    }
    case column_mode::labels: {
      auto id = part.labels.find(field.text);
      if (id == detail::label_dictionary::none) id = part.labels.add(field.text, {field.line, field.column, chunk});
      part.codes.push_back(id);
      return;
    }
    case column_mode::known: {
      const auto id = detail::numeric_state(*plan.known, field.text);  // not a state's text (see above)
      if (id == detail::label_dictionary::none) {
        detail::fail_field(field, plan.name,
                           "'" + std::string(field.text) + "' is not a state of '" + plan.name +
                               "' (states: " + text::list_for_message(plan.known->states()) + ")");
      }
      part.codes.push_back(id);
      return;
    }
    case column_mode::skip:
      return;
  }
}

/// Which fields decide whether a record is dropped (policy drop): those of every column read,
/// with the model's variable of each (if any), whose states are no missing values.
struct drop_rule {
  const detail::missing_rule* missing;
  std::vector<std::size_t> positions;
  std::vector<const variable*> known;
};

/// Whether the policy drops this record: a column read holds a missing value.
[[nodiscard]] bool dropped(const drop_rule& rule, const std::vector<detail::csv_field>& record) {
  if (rule.missing->policy != missing_policy::drop) return false;
  for (std::size_t c = 0; c < rule.positions.size(); ++c) {
    const auto text = record[rule.positions[c]].text;
    if (rule.missing->is_missing(text) && !detail::declared_state(rule.known[c], text)) return true;
  }
  return false;
}

chunk_part parse_chunk(std::string_view text, char delimiter, std::size_t width, const std::vector<column_plan>& plans,
                       std::size_t chunk, const drop_rule& rule) {
  chunk_part part;
  // Columns are made at the first row kept: a chunk of blank or dropped lines costs nothing per
  // column, so memory stays linear in the text however small the chunks (a header of 700
  // columns over 2 000 blank lines cut into one-line chunks took 700 MB before).
  const auto make_columns = [&] {
    part.columns.resize(plans.size());
    for (std::size_t c = 0; c < plans.size(); ++c) {
      if (plans[c].mode != column_mode::known) continue;
      for (const auto& state : plans[c].known->states()) part.columns[c].labels.add(state, {});
    }
  };
  std::vector<detail::csv_field> fields;
  try {
    part.lines = detail::for_each_record(text, delimiter, fields, [&](const std::vector<detail::csv_field>& record) {
      if (record.size() != width) detail::fail_width(record, width);
      if (dropped(rule, record)) {
        ++part.dropped;
        return;
      }
      if (part.columns.empty()) make_columns();
      for (std::size_t c = 0; c < plans.size(); ++c) {
        add_value(plans[c], part.columns[c], record[plans[c].position], chunk, *rule.missing);
      }
      ++part.rows;
    });
  } catch (const detail::csv_failure& failure) {
    throw detail::chunk_failure{chunk, failure};
  }
  return part;
}

/// Parses every chunk of `text` in parallel; chunk k's result goes to parts[k].
void parse_chunks(std::string_view text, const std::vector<std::size_t>& bounds, char delimiter, std::size_t width,
                  const std::vector<column_plan>& plans, const drop_rule& rule, unsigned threads,
                  const std::string& source, std::size_t first_line, std::vector<chunk_part>& parts) {
  const std::size_t chunks = bounds.size() - 1;
  parts.assign(chunks, {});
  std::vector<std::size_t> lines(chunks, 0);
  detail::rethrow_located(source, first_line, lines, [&] {
    detail::parallel_for(chunks, {.threads = threads}, [&](detail::item_range items) {
      for (auto k = items.begin; k < items.end; ++k) {
        parts[k] = parse_chunk(text.substr(bounds[k], bounds[k + 1] - bounds[k]), delimiter, width, plans, k, rule);
        lines[k] = parts[k].lines;
      }
    });
  });
}

template <class Code>
void fill_codes(std::vector<Code>& out, const std::vector<chunk_part>& parts, std::size_t column,
                const std::vector<std::vector<std::uint32_t>>& state_of) {
  std::size_t row = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const auto& map = state_of[k];
    for (auto code : column_in(parts[k], column).codes) {
      out[row++] = code == detail::missing_id ? missing_code<Code> : static_cast<Code>(map.empty() ? code : map[code]);
    }
  }
}

/// The discrete column of `plan` from its chunks' labels and codes.
discrete_column finish_labels(const column_plan& plan, std::size_t column, const std::vector<chunk_part>& parts,
                              const std::vector<std::size_t>& first_lines, std::size_t rows,
                              const std::string& source) {
  std::vector<std::vector<std::uint32_t>> state_of(parts.size());
  std::size_t missing = 0;
  for (const auto& part : parts) missing += column_in(part, column).missing;
  const std::size_t spare = missing ? 1 : 0;  // a code width with room for missing_code
  if (plan.mode == column_mode::known) {
    auto codes = make_code_vector(plan.known->cardinality() + spare, rows);
    std::visit([&](auto& out) { fill_codes(out, parts, column, state_of); }, codes);
    return discrete_column(*plan.known, std::move(codes), std::in_place, missing);
  }
  // Every chunk's labels in order: labels in order of first appearance in the file.
  detail::label_dictionary all;
  std::vector<std::vector<std::uint32_t>> global_of(parts.size());
  for (std::size_t k = 0; k < parts.size(); ++k) {
    for (const auto& label : column_in(parts[k], column).labels.entries()) {
      auto id = all.find(label.text);
      if (id == detail::label_dictionary::none) {
        auto first = label.first;
        first.line += first_lines[k];
        id = all.add(label.text, first);
      }
      global_of[k].push_back(id);
    }
  }
  if (all.size() == 0) throw data_error(source + ": column '" + plan.name + "' has no values to take states from");
  std::vector<std::string_view> labels;
  for (const auto& entry : all.entries()) labels.push_back(entry.text);
  auto order = detail::order_states(labels);
  if (order.non_finite) {
    const auto& entry = all.entries()[*order.non_finite];
    throw parse_error(source, entry.first.line, entry.first.column,
                      "column '" + plan.name + "': " + detail::non_finite_message(entry.text));
  }
  for (std::size_t k = 0; k < parts.size(); ++k) {
    for (auto id : global_of[k]) state_of[k].push_back(order.state_of[id]);
  }
  variable var(plan.name, std::move(order.states));
  auto codes = make_code_vector(var.cardinality() + spare, rows);
  std::visit([&](auto& out) { fill_codes(out, parts, column, state_of); }, codes);
  return discrete_column(std::move(var), std::move(codes), std::in_place, missing);
}

continuous_column finish_numbers(const column_plan& plan, std::size_t column, const std::vector<chunk_part>& parts,
                                 const std::vector<std::size_t>& first_lines, std::size_t rows,
                                 const std::string& source) {
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const auto& part = column_in(parts[k], column);
    if (part.first_non_finite) {
      throw parse_error(source, first_lines[k] + part.first_non_finite->line, part.first_non_finite->column,
                        "column '" + plan.name + "': " + detail::non_finite_message(part.first_non_finite_text));
    }
  }
  std::vector<double> values;
  values.reserve(rows);
  for (const auto& part : parts) {
    const auto& numbers = column_in(part, column).numbers;
    values.insert(values.end(), numbers.begin(), numbers.end());
  }
  return continuous_column(plan.name, std::move(values));
}

csv_data read_dataset(csv_reader::impl& input, const csv_options& options) {
  auto& bytes = *input.bytes;
  // All of it (the data set is in memory anyway), in growing steps, so that a stream whose last
  // line runs past the limit of a record is refused there rather than read to its end.
  for (std::size_t want = header_fetch_bytes; !bytes.at_end(); want *= 2) {
    bytes.fetch(want);
    const auto text = bytes.available();
    const auto last_end = text.find_last_of("\n\r");
    const auto open = last_end == std::string_view::npos ? text.size() : text.size() - last_end - 1;
    if (open > csv_max_record_bytes) {
      const auto lines = std::count(text.begin(), text.end() - static_cast<std::ptrdiff_t>(open), '\n');
      throw parse_error(input.source, input.first_line + static_cast<std::size_t>(lines), 1,
                        detail::record_too_long_message());
    }
  }
  const auto text = bytes.available();
  const auto& header = input.header;
  const auto wanted = detail::column_positions(header, options.columns, input.source);

  std::vector<column_plan> plans;
  for (auto position : wanted) {
    const auto& name = header[position];
    column_plan plan{name, position, column_mode::automatic};
    const auto kind = options.kinds.find(name);
    switch (kind != options.kinds.end() ? kind->second : options.default_kind) {
      case column_kind::automatic:
        plan.mode = column_mode::automatic;
        break;
      case column_kind::continuous:
        plan.mode = column_mode::continuous;
        break;
      case column_kind::discrete:
        plan.mode = column_mode::labels;
        break;
    }
    if (const auto known = options.variables.find(name); known != options.variables.end()) {
      plan.mode = column_mode::known;
      plan.known = &known->second;
    }
    plans.push_back(plan);
  }

  const detail::missing_rule missing(options.missing);
  drop_rule rule{&missing, {}, {}};
  for (const auto& plan : plans) {
    rule.positions.push_back(plan.position);
    rule.known.push_back(plan.known);
  }

  const auto chunks = detail::record_chunks(
      text, input.delimiter, options.chunk_bytes ? options.chunk_bytes : dataset_chunk_bytes, text.size(), true);
  std::vector<chunk_part> parts;
  parse_chunks(text, chunks, input.delimiter, header.size(), plans, rule, options.threads, input.source,
               input.first_line, parts);
  std::size_t rows = 0;
  std::size_t dropped = 0;
  std::vector<std::size_t> lines;
  for (const auto& part : parts) {
    rows += part.rows;
    dropped += part.dropped;
    lines.push_back(part.lines);
  }
  if (rows == 0 && dropped > 0 && !options.allow_empty) {
    throw data_error(input.source + ": every one of the " + std::to_string(dropped) +
                     " data rows has a missing value, so dropping them leaves none");
  }
  if (rows == 0 && !options.allow_empty) throw data_error(input.source + ": there are no data rows after the header");
  const auto first_lines = detail::chunk_first_lines(input.first_line, lines);

  // Automatic columns that met text are read once more, as labels.
  std::vector<column_plan> text_plans = plans;
  bool any_text = false;
  for (std::size_t c = 0; c < plans.size(); ++c) {
    bool text_seen = false;
    for (const auto& part : parts) text_seen = text_seen || column_in(part, c).text_seen;
    text_plans[c].mode = plans[c].mode == column_mode::automatic && text_seen ? column_mode::labels : column_mode::skip;
    any_text = any_text || text_seen;
  }
  if (any_text) {
    std::vector<chunk_part> text_parts;
    parse_chunks(text, chunks, input.delimiter, header.size(), text_plans, rule, options.threads, input.source,
                 input.first_line, text_parts);
    for (std::size_t c = 0; c < plans.size(); ++c) {
      if (text_plans[c].mode == column_mode::skip) continue;
      plans[c].mode = column_mode::labels;
      for (std::size_t k = 0; k < parts.size(); ++k) {
        if (!parts[k].columns.empty()) parts[k].columns[c] = std::move(text_parts[k].columns[c]);
      }
    }
  }

  dataset result(input.source);
  for (std::size_t c = 0; c < plans.size(); ++c) {
    const bool numeric = plans[c].mode == column_mode::continuous || plans[c].mode == column_mode::automatic;
    if (numeric) {
      result.add(finish_numbers(plans[c], c, parts, first_lines, rows, input.source));
    } else {
      result.add(finish_labels(plans[c], c, parts, first_lines, rows, input.source));
    }
    for (auto& part : parts) {
      if (!part.columns.empty()) part.columns[c] = {};  // give the memory back column by column
    }
  }
  return {std::move(result), dropped};
}

}  // namespace

csv_data parse_csv_data(std::string_view text, const std::string& source, const csv_options& options) {
  csv_reader input(text, source, options.delimiter);
  return read_dataset(detail::csv_access::of(input), options);
}

csv_data read_csv_data(const std::filesystem::path& path, const csv_options& options) {
  csv_reader input(path, options.delimiter);
  return read_dataset(detail::csv_access::of(input), options);
}

dataset parse_csv(std::string_view text, const std::string& source, const csv_options& options) {
  return parse_csv_data(text, source, options).data;
}

dataset read_csv(const std::filesystem::path& path, const csv_options& options) {
  return read_csv_data(path, options).data;
}

// ---- writing -------------------------------------------------------------------------

void write_csv(const dataset& data, std::ostream& out, char delimiter, std::string_view missing) {
  const auto& columns = data.columns();
  std::string line;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    line += (c ? std::string(1, delimiter) : std::string()) + text::csv_escape(column_name(columns[c]), delimiter);
  }
  out << line << '\n';
  write_csv_rows(data, out, delimiter, missing);
}

void write_csv_rows(const dataset& data, std::ostream& out, char delimiter, std::string_view missing) {
  const auto& columns = data.columns();
  // Labels are escaped once per state, not once per row.
  std::vector<std::vector<std::string>> escaped_labels(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (const auto* d = std::get_if<discrete_column>(&columns[c])) {
      for (const auto& state : d->var().states()) escaped_labels[c].push_back(text::csv_escape(state, delimiter));
    }
  }
  // Missing values: the code past the states, or NaN.
  const auto escaped_missing = text::csv_escape(missing, delimiter);
  std::string buffer;
  for (std::size_t row = 0; row < data.rows(); ++row) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c) buffer += delimiter;
      if (const auto* d = std::get_if<discrete_column>(&columns[c])) {
        const auto code = d->code(row);
        buffer += code < escaped_labels[c].size() ? escaped_labels[c][code] : escaped_missing;
      } else {
        const double value = std::get<continuous_column>(columns[c]).values()[row];
        buffer += std::isnan(value) ? escaped_missing : text::format_double(value);
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

void write_csv(const dataset& data, const std::filesystem::path& path, char delimiter, std::string_view missing) {
  pgm::write_file_atomically(path, [&](std::ostream& out) { write_csv(data, out, delimiter, missing); });
}

}  // namespace pgm
