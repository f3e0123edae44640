#include "columns.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/data/state_order.hpp"
#include "pgm/learn/family_source.hpp"

namespace pgm::python {
namespace py = pybind11;
namespace {

template <class T>
std::span<const T> typed(const column_buffer& c) {
  return {static_cast<const T*>(c.data), c.size};
}

std::string where(const std::string& source, const std::string& name) { return source + ": column '" + name + "'"; }

/// Calls `f` with the buffer as a span of its integer type.
template <class F>
decltype(auto) visit_integers(const column_buffer& c, const std::string& source, F&& f) {
  if (c.type == 'i') {
    switch (c.item_size) {
      case 1:
        return f(typed<std::int8_t>(c));
      case 2:
        return f(typed<std::int16_t>(c));
      case 4:
        return f(typed<std::int32_t>(c));
      case 8:
        return f(typed<std::int64_t>(c));
      default:
        break;
    }
  } else if (c.type == 'u') {
    switch (c.item_size) {
      case 1:
        return f(typed<std::uint8_t>(c));
      case 2:
        return f(typed<std::uint16_t>(c));
      case 4:
        return f(typed<std::uint32_t>(c));
      case 8:
        return f(typed<std::uint64_t>(c));
      default:
        break;
    }
  }
  throw data_error(where(source, c.name) + ": expected an integer array");
}

/// Codes at the narrowest width for `cardinality` states; row r gets code_of(r).
template <class F>
code_vector fill_codes(std::size_t cardinality, std::size_t rows, F&& code_of) {
  auto codes = make_code_vector(cardinality, rows);
  std::visit(
      [&](auto& stored) {
        using code = typename std::decay_t<decltype(stored)>::value_type;
        for (std::size_t r = 0; r < rows; ++r) stored[r] = static_cast<code>(code_of(r));
      },
      codes);
  return codes;
}

/// Values spanning fewer than this many integers are mapped by a table, others by search.
constexpr std::uint64_t dense_range = std::uint64_t{1} << 20;

/// The states of the distinct values, in order, each named by its decimal text as the CSV
/// reader would read it, ordered as that reader orders them (by value).
template <class T>
state_order order_values(const std::vector<T>& distinct) {
  std::vector<std::string> labels;
  labels.reserve(distinct.size());
  for (const T v : distinct) labels.push_back(std::to_string(v));
  return order_states(labels);
}

/// Values below this are read in one pass, as the codes of a byte-wide table (codes such as
/// 0..k-1, the usual case); others take a pass for the range first.
constexpr std::uint64_t byte_values = 256;

/// The column when every value is in [0, 256): the values are copied as bytes in one pass over
/// the (wide) input, the ones seen marked from the bytes, and the bytes mapped to their states
/// if those are not the values themselves.
/// None when a value is outside (the caller then takes the general way).
template <class T>
std::optional<discrete_column> byte_column(const std::string& name, std::span<const T> values) {
  std::vector<std::uint8_t> codes(values.size());
  std::uint64_t bits = 0;  // every bit set in some value: ≥ 256 when a value is (or is negative)
  for (std::size_t r = 0; r < values.size(); ++r) {  // branch-free, so that it vectorizes
    const auto v = static_cast<std::uint64_t>(values[r]);
    bits |= v;
    codes[r] = static_cast<std::uint8_t>(v);
  }
  if (bits >= byte_values) return std::nullopt;
  std::array<std::uint8_t, byte_values> seen{};
  for (const auto c : codes) seen[c] = 1;
  std::vector<T> distinct;
  for (std::size_t v = 0; v < byte_values; ++v) {
    if (seen[v]) distinct.push_back(static_cast<T>(v));
  }
  auto order = order_values(distinct);
  std::array<std::uint8_t, byte_values> state{};
  bool own = true;  // each value is its own state: 0..k-1, all seen
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    const auto v = static_cast<std::size_t>(distinct[i]);
    state[v] = static_cast<std::uint8_t>(order.state_of[i]);
    own = own && state[v] == v;
  }
  if (!own) {
    for (auto& c : codes) c = state[c];
  }
  return discrete_column(variable(name, std::move(order.states)), code_vector(std::move(codes)), std::in_place);
}

/// An integer column: its states are the values seen, ordered as the CSV reader orders them.
template <class T>
discrete_column integer_column(const std::string& name, std::span<const T> values, const std::string& source) {
  if (values.empty()) throw data_error(where(source, name) + " has no values to take states from");
  if (auto column = byte_column(name, values)) return std::move(*column);
  T lo = values.front();
  T hi = values.front();
  for (const T v : values) {  // a plain loop, which the compiler vectorizes
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  // hi − lo without overflow: unsigned arithmetic is exact modulo 2^64 and the difference fits.
  const std::uint64_t range = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
  auto offset = [lo](T v) {
    return static_cast<std::size_t>(static_cast<std::uint64_t>(v) - static_cast<std::uint64_t>(lo));
  };

  std::vector<T> distinct;
  std::vector<std::uint32_t> table;  // dense: offset → position in `distinct`, then → state
  if (range < dense_range) {
    table.assign(static_cast<std::size_t>(range) + 1, 0);
    for (const T v : values) table[offset(v)] = 1;
    for (std::size_t i = 0; i < table.size(); ++i) {
      if (table[i] == 0) continue;
      table[i] = static_cast<std::uint32_t>(distinct.size());
      distinct.push_back(static_cast<T>(static_cast<std::uint64_t>(lo) + i));
    }
  } else {
    distinct.assign(values.begin(), values.end());
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  }
  auto order = order_values(distinct);
  const auto cardinality = order.states.size();
  code_vector codes;
  if (!table.empty()) {
    for (auto& entry : table) entry = order.state_of[entry];  // absent offsets are never read
    codes = fill_codes(cardinality, values.size(), [&](std::size_t r) { return table[offset(values[r])]; });
  } else {
    codes = fill_codes(cardinality, values.size(), [&](std::size_t r) {
      const auto at = std::lower_bound(distinct.begin(), distinct.end(), values[r]) - distinct.begin();
      return order.state_of[static_cast<std::size_t>(at)];
    });
  }
  return {variable(name, std::move(order.states)), std::move(codes), std::in_place};
}

/// A column of codes into labels (a pandas categorical, or factorized strings): its states are
/// the labels seen, ordered as the CSV reader orders them.
template <class T>
discrete_column coded_column(const column_buffer& c, std::span<const T> codes, const std::string& source) {
  const auto labels = c.labels.size();
  std::vector<std::uint8_t> seen(labels, 0);
  std::size_t missing = 0;  // code -1; pgm/_frame.py has applied the missing-value rule already
  for (std::size_t r = 0; r < codes.size(); ++r) {
    const auto k = static_cast<std::int64_t>(codes[r]);
    if (k < 0 || static_cast<std::uint64_t>(k) >= labels) {
      if (k == -1) {
        ++missing;
        continue;
      }
      throw data_error(where(source, c.name) + ": code " + std::to_string(k) + " at position " + std::to_string(r) +
                       " is not one of the " + std::to_string(labels) + " labels");
    }
    seen[static_cast<std::size_t>(k)] = 1;
  }
  // Distinct label texts in the order given (two labels may read alike, e.g. 1 and "1").
  std::vector<std::string> texts;
  std::unordered_map<std::string_view, std::uint32_t> text_of;
  std::vector<std::uint32_t> label_text(labels, 0);
  for (std::size_t k = 0; k < labels; ++k) {
    if (!seen[k]) continue;
    const auto [it, fresh] = text_of.emplace(c.labels[k], static_cast<std::uint32_t>(texts.size()));
    if (fresh) texts.push_back(c.labels[k]);
    label_text[k] = it->second;
  }
  if (texts.empty()) throw data_error(where(source, c.name) + " has no values to take states from");
  auto order = order_states(texts);
  if (order.non_finite) {
    const auto& bad = texts[*order.non_finite];
    std::size_t r = 0;
    while (r < codes.size() && (codes[r] < 0 || c.labels[static_cast<std::size_t>(codes[r])] != bad)) ++r;
    throw data_error(where(source, c.name) + ": the value at position " + std::to_string(r) + ", '" + bad +
                     "', is not a finite number (NaN and infinities are not supported)");
  }
  std::vector<std::uint32_t> state(labels, 0);
  for (std::size_t k = 0; k < labels; ++k) state[k] = order.state_of[label_text[k]];
  const auto cardinality = order.states.size();
  auto stored = make_code_vector(cardinality + (missing ? 1 : 0), codes.size());
  std::visit(
      [&](auto& out) {
        using code = typename std::decay_t<decltype(out)>::value_type;
        for (std::size_t r = 0; r < codes.size(); ++r) {
          out[r] = codes[r] < 0 ? missing_code<code> : static_cast<code>(state[static_cast<std::size_t>(codes[r])]);
        }
      },
      stored);
  return {variable(c.name, std::move(order.states)), std::move(stored), std::in_place, missing};
}

continuous_column float_column(const column_buffer& c, const std::string& source) {
  std::vector<double> values(c.size);
  if (c.type == 'f' && c.item_size == sizeof(double)) {
    const auto typed_values = typed<double>(c);
    std::copy(typed_values.begin(), typed_values.end(), values.begin());
  } else if (c.type == 'f' && c.item_size == sizeof(float)) {
    const auto typed_values = typed<float>(c);
    std::copy(typed_values.begin(), typed_values.end(), values.begin());
  } else {
    visit_integers(c, source, [&](auto typed_values) {
      for (std::size_t r = 0; r < typed_values.size(); ++r) values[r] = static_cast<double>(typed_values[r]);
    });
  }
  return {c.name, std::move(values)};
}

template <class Code>
py::array_t<Code> to_numpy(const std::vector<Code>& values) {
  py::array_t<Code> result(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), result.mutable_data());
  return result;
}

}  // namespace

std::vector<column_buffer> read_column_buffers(const py::list& columns, std::vector<py::array>& keep) {
  std::vector<column_buffer> result;
  result.reserve(columns.size());
  keep.reserve(keep.size() + columns.size());
  for (const auto& item : columns) {
    const auto spec = item.cast<py::tuple>();
    column_buffer c;
    c.name = spec[0].cast<std::string>();
    c.kind = spec[1].cast<std::string>();
    // An integer column is read in place, whatever its stride; the others as contiguous arrays.
    auto array = c.kind == "int" ? py::array::ensure(spec[2]) : py::array::ensure(spec[2], py::array::c_style);
    if (!array || array.ndim() != 1) throw data_error("column '" + c.name + "': expected a one-dimensional array");
    // Values are read as this machine stores numbers: a column of the other byte order (a
    // big-endian '>i8' here) is converted first, else 1 would read as 2^56.
    const char order = array.dtype().byteorder();
    if (order != '=' && order != '|' && order != (std::endian::native == std::endian::little ? '<' : '>')) {
      array = py::array::ensure(array.attr("astype")(array.dtype().attr("newbyteorder")("=")));
    }
    c.type = array.dtype().kind();
    c.item_size = static_cast<std::size_t>(array.itemsize());
    if (array.size() > 1 && array.strides(0) % array.itemsize() != 0) {
      array = py::array::ensure(array, py::array::c_style);  // an unaligned view: copied
    }
    c.data = array.data();
    c.size = static_cast<std::size_t>(array.size());
    c.stride = array.size() > 1 ? array.strides(0) / array.itemsize() : 1;
    if (!spec[3].is_none()) c.labels = spec[3].cast<std::vector<std::string>>();
    keep.push_back(std::move(array));
    result.push_back(std::move(c));
  }
  return result;
}

dataset make_dataset(const std::vector<column_buffer>& columns, const std::string& source) {
  dataset data(source);
  for (const auto& c : columns) {
    if (c.kind == "float") {
      data.add(float_column(c, source));
    } else if (c.kind == "int") {
      data.add(visit_integers(c, source, [&](auto values) {
        if (c.stride == 1) return integer_column(c.name, values, source);
        using value = typename decltype(values)::value_type;
        std::vector<value> gathered(c.size);
        for (std::size_t r = 0; r < c.size; ++r) gathered[r] = values.data()[static_cast<std::ptrdiff_t>(r) * c.stride];
        return integer_column(c.name, std::span<const value>(gathered), source);
      }));
    } else if (c.kind == "coded") {
      data.add(visit_integers(c, source, [&](auto codes) { return coded_column(c, codes, source); }));
    } else {
      throw data_error(where(source, c.name) + ": unknown column kind '" + c.kind + "'");
    }
  }
  return data;
}

std::vector<std::string> numpy_source::columns() const {
  std::vector<std::string> names;
  for (const auto& c : *columns_) names.push_back(c.name);
  return names;
}

family_counts numpy_source::count(const family_count_request& request) {
  if (auto counts = count_by_value(request)) return std::move(*counts);
  if (!data_) data_ = make_dataset(*columns_, name_);
  return dataset_source(*data_).count(request);
}

dataset numpy_source::read(const family_count_request& request, family_counts& result) {
  if (!data_) data_ = make_dataset(*columns_, name_);
  return dataset_source(*data_).read(request, result);
}

std::optional<family_counts> numpy_source::count_by_value(const family_count_request& request) const {
  if (!request.variables.empty() || !request.intervals.empty()) return std::nullopt;
  std::vector<named_value_column> values;
  std::vector<std::string> names;
  std::size_t rows = 0;
  for (const auto& c : *columns_) {
    if (std::find(request.columns.begin(), request.columns.end(), c.name) == request.columns.end()) continue;
    if (c.kind != "int") return std::nullopt;
    values.push_back({c.name, visit_integers(c, name_, [&](auto typed_values) -> value_column {
                        using value = typename decltype(typed_values)::value_type;
                        return value_span<value>{typed_values.data(), typed_values.size(), c.stride};
                      })});
    names.push_back(c.name);
    rows = c.size;
  }
  const auto index_of = [&](const std::string& name) {
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) throw data_error(name_ + ": there is no column '" + name + "'");
    return static_cast<std::size_t>(found - names.begin());
  };
  std::vector<value_family> families;
  for (const auto& family : request.families) {
    value_family by_index{index_of(family.child), {}};
    for (const auto& parent : family.parents) by_index.parents.push_back(index_of(parent));
    families.push_back(std::move(by_index));
  }
  auto counted = count_value_families(values, families, {.threads = request.threads});
  if (!counted) return std::nullopt;
  family_counts result;
  result.rows = rows;
  result.variables = std::move(counted->variables);
  result.families = std::move(counted->tables);
  return result;
}

void require_columns(const std::vector<std::string>& wanted, const std::vector<std::string>& available,
                     const std::string& source) {
  for (const auto& name : wanted) {
    if (std::find(available.begin(), available.end(), name) == available.end()) {
      throw data_error(source + ": there is no column '" + name + "' (columns: " + text::list_for_message(available) +
                       ")");
    }
  }
}

py::list dataset_columns(const dataset& data) {
  py::list result;
  for (const auto& column : data.columns()) {
    if (const auto* d = std::get_if<discrete_column>(&column)) {
      auto codes = std::visit([](const auto& stored) -> py::array { return to_numpy(stored); }, d->codes());
      result.append(py::make_tuple(d->name(), "coded", std::move(codes), d->var().states()));
    } else {
      const auto& c = std::get<continuous_column>(column);
      const std::vector<double> values(c.values().begin(), c.values().end());
      result.append(py::make_tuple(c.name(), "float", to_numpy(values), py::none()));
    }
  }
  return result;
}

discrete_column with_model_states(const discrete_column& column, const variable& model) {
  std::vector<std::uint32_t> map(column.var().cardinality());
  for (std::size_t s = 0; s < map.size(); ++s) {
    const auto& label = column.var().states()[s];
    const auto& states = model.states();
    const auto it = std::find(states.begin(), states.end(), label);
    if (it == states.end()) {
      throw data_error("column '" + column.name() + "' holds the value '" + label +
                       "', which is not a state of the network's variable (states: " + text::list_for_message(states) +
                       ")");
    }
    map[s] = static_cast<std::uint32_t>(it - states.begin());
  }
  const bool missing = column.missing() != 0;
  auto codes = make_code_vector(model.cardinality() + (missing ? 1 : 0), column.size());
  std::visit(
      [&](auto& out) {
        using code_type = typename std::decay_t<decltype(out)>::value_type;
        for (std::size_t row = 0; row < out.size(); ++row) {
          const auto c = column.code(row);
          out[row] = c < map.size() ? static_cast<code_type>(map[c]) : missing_code<code_type>;
        }
      },
      codes);
  return discrete_column(model, std::move(codes), std::in_place, column.missing());
}

}  // namespace pgm::python
