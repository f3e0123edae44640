#pragma once
/// \file
/// A dataset as one binary file that reads back exactly (every double to the bit, every
/// variable with its states, edges and tags), for data that are expensive to make: simulated
/// experiments kept between runs (pgm/eval/disk_cache.hpp).
///
/// The file is one line of JSON, then the data:
///
///     {"format":"pgm-data","version":1,"source":"2-stack (bullet, seed 7)","rows":900000,
///      "columns":[{"name":"xOff1","kind":"continuous","tags":{…}},
///                 {"name":"onTop1","kind":"discrete","width":1,"variable":{"name":…,"states":…}}, …],
///      "meta":{"task":"2-stack", …},"payload_bytes":47700000,"crc32":"5f1c0a3e"}
///     <column 1: rows values><column 2: rows values>…
///
/// Continuous values are IEEE doubles, discrete codes unsigned integers of `width` bytes, all
/// little-endian. Reading checks the header, that the data have exactly `payload_bytes` bytes
/// (a truncated file or one with bytes after its data is an error) and their CRC-32 (a corrupt
/// file is an error); every error names the file.

#include <bit>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/checksum.hpp"
#include "pgm/detail/file.hpp"
#include "pgm/detail/json_reader.hpp"
#include "pgm/io/json_model.hpp"

namespace pgm {

/// Free-form facts stored beside the data (what made them, with which key).
using dataset_file_meta = std::map<std::string, std::string, std::less<>>;

/// What a dataset file holds.
struct dataset_file_content {
  dataset data;
  dataset_file_meta meta;
};

namespace detail {

template <class Unsigned>
void append_little_endian(std::string& out, Unsigned value) {
  for (std::size_t byte = 0; byte < sizeof(Unsigned); ++byte) {
    out.push_back(static_cast<char>(static_cast<unsigned char>(value >> (8 * byte))));
  }
}

template <class Unsigned>
[[nodiscard]] Unsigned read_little_endian(const char* at) {
  std::uint64_t value = 0;  // gathered wide: a narrower Unsigned would be promoted to int
  for (std::size_t byte = 0; byte < sizeof(Unsigned); ++byte) {
    value |= std::uint64_t{static_cast<unsigned char>(at[byte])} << (8 * byte);
  }
  return static_cast<Unsigned>(value);
}

[[nodiscard]] inline nlohmann::json tags_to_json(const semantic_tags& tags) {
  return {{"quantity", tags.quantity}, {"unit", tags.unit}, {"role", tags.role}};
}

/// Reads the header line and the data after it.
class dataset_file_reader : public json_reader {
 public:
  using json_reader::json_reader;

  dataset_file_content read(std::string_view bytes, const std::string& source) const {
    const auto newline = bytes.find('\n');
    if (newline == std::string_view::npos || bytes.substr(0, 1) != "{") {
      throw data_error(source + ": not a pgm-data file (it does not start with a header line)");
    }
    const auto header = parse(bytes.substr(0, newline));
    const auto payload = bytes.substr(newline + 1);
    check_format(header, "pgm-data");

    const auto rows = whole(member(header, "", "rows"), "/rows");
    const auto expected_bytes = whole(member(header, "", "payload_bytes"), "/payload_bytes");
    if (payload.size() < expected_bytes) {
      throw data_error(source + ": truncated: the header promises " + std::to_string(expected_bytes) +
                       " bytes of data, the file holds " + std::to_string(payload.size()));
    }
    if (payload.size() > expected_bytes) {
      throw data_error(source + ": " + std::to_string(payload.size() - expected_bytes) +
                       " unexpected bytes after the data (the header promises " + std::to_string(expected_bytes) + ")");
    }
    const auto crc = string(member(header, "", "crc32"), "/crc32");
    if (const auto actual = crc32_hex(payload); actual != crc) {
      throw data_error(source + ": corrupt: the data's CRC-32 is " + actual + ", the header says " + crc);
    }

    dataset_file_content content{dataset(string(member(header, "", "source"), "/source")), {}};
    if (const auto* meta = optional_member(header, "meta")) {
      if (!meta->is_object()) fail("/meta", "expected an object");
      for (const auto& [key, value] : meta->items()) content.meta.emplace(key, string(value, "/meta/" + key));
    }
    const auto& columns = array(member(header, "", "columns"), "/columns");
    // First where each column's data lie, so that a header that does not fit its data is
    // reported as such before any value is read.
    std::vector<std::size_t> widths;
    std::vector<std::optional<variable>> variables;
    std::size_t offset = 0;
    for (std::size_t i = 0; i < columns.size(); ++i) {
      const auto path = "/columns/" + std::to_string(i);
      const auto kind = string(member(columns[i], path, "kind"), path + "/kind");
      if (kind != "continuous" && kind != "discrete") {
        fail(path + "/kind", "expected \"continuous\" or \"discrete\", found \"" + kind + "\"");
      }
      const std::size_t width = kind == "continuous" ? 0 : whole(member(columns[i], path, "width"), path + "/width");
      std::optional<variable> var;
      if (kind == "discrete") {
        var = read_variable(member(columns[i], path, "variable"), path + "/variable");
        if (width != make_code_vector_width(var->cardinality())) {
          fail(path + "/width", "does not fit the variable's states");
        }
      }
      const std::size_t column_bytes = kind == "continuous" ? 8 : width;
      if (rows > (expected_bytes - offset) / column_bytes) fail(path, "its data run past the end of the data");
      offset += rows * column_bytes;
      widths.push_back(width);
      variables.push_back(std::move(var));
    }
    if (offset != expected_bytes) {
      fail("/payload_bytes", std::to_string(expected_bytes) + " bytes, but the columns hold " + std::to_string(offset));
    }
    offset = 0;
    for (std::size_t i = 0; i < columns.size(); ++i) {
      const auto path = "/columns/" + std::to_string(i);
      const auto& column = columns[i];
      const std::size_t width = widths[i];
      const char* at = payload.data() + offset;
      if (width == 0) {
        offset += rows * 8;
        std::vector<double> values(rows);
        for (std::size_t r = 0; r < rows; ++r) {
          values[r] = std::bit_cast<double>(read_little_endian<std::uint64_t>(at + 8 * r));
        }
        add(content.data, continuous_column(string(member(column, path, "name"), path + "/name"), std::move(values),
                                            read_tags(member(column, path, "tags"), path + "/tags")));
      } else {
        offset += rows * width;
        auto var = std::move(*variables[i]);
        std::vector<std::uint32_t> codes(rows);
        for (std::size_t r = 0; r < rows; ++r) {
          codes[r] = width == 1   ? read_little_endian<std::uint8_t>(at + r)
                     : width == 2 ? read_little_endian<std::uint16_t>(at + 2 * r)
                                  : read_little_endian<std::uint32_t>(at + 4 * r);
        }
        add(content.data, [&] {
          try {
            return discrete_column(std::move(var), codes);
          } catch (const data_error& e) {
            fail(path, e.what());
          }
        }());
      }
    }
    return content;
  }

 private:
  static std::size_t make_code_vector_width(std::size_t cardinality) {
    return std::visit([](const auto& c) { return sizeof(c[0]); }, make_code_vector(cardinality, 1));
  }
  std::size_t whole(const nlohmann::json& value, const std::string& path) const {
    if (!value.is_number_unsigned()) fail(path, "expected a whole number");
    return value.get<std::size_t>();
  }
  semantic_tags read_tags(const nlohmann::json& value, const std::string& path) const {
    return {string(member(value, path, "quantity"), path + "/quantity"),
            string(member(value, path, "unit"), path + "/unit"), string(member(value, path, "role"), path + "/role")};
  }
  void add(dataset& data, data_column column) const {
    try {
      data.add(std::move(column));
    } catch (const data_error& e) {
      fail("/columns", e.what());
    }
  }
};

}  // namespace detail

/// The file's bytes: the header line, then the data.
[[nodiscard]] inline std::string encode_dataset(const dataset& data, const dataset_file_meta& meta = {}) {
  std::string payload;
  nlohmann::json columns = nlohmann::json::array();
  for (const auto& column : data.columns()) {
    if (const auto* c = std::get_if<continuous_column>(&column)) {
      columns.push_back({{"name", c->name()}, {"kind", "continuous"}, {"tags", detail::tags_to_json(c->tags())}});
      for (double v : c->values()) detail::append_little_endian(payload, std::bit_cast<std::uint64_t>(v));
    } else {
      const auto& d = std::get<discrete_column>(column);
      columns.push_back({{"name", d.name()},
                         {"kind", "discrete"},
                         {"width", d.code_width()},
                         {"variable", detail::variable_to_json(d.var())}});
      std::visit(
          [&](const auto& codes) {
            for (auto code : codes) detail::append_little_endian(payload, code);
          },
          d.codes());
    }
  }
  nlohmann::json header = {{"format", "pgm-data"},
                           {"version", 1},
                           {"source", data.source()},
                           {"rows", data.rows()},
                           {"columns", std::move(columns)},
                           {"meta", meta},
                           {"payload_bytes", payload.size()},
                           {"crc32", detail::crc32_hex(payload)}};
  return header.dump() + '\n' + payload;
}

/// Reads the bytes of a dataset file; `source` names it in errors.
[[nodiscard]] inline dataset_file_content decode_dataset(std::string_view bytes, const std::string& source) {
  return detail::dataset_file_reader(source).read(bytes, source);
}

/// Writes `data` to `path` atomically (a temporary file renamed once complete).
inline void write_dataset_file(const std::filesystem::path& path, const dataset& data,
                               const dataset_file_meta& meta = {}) {
  const auto bytes = encode_dataset(data, meta);
  detail::write_file_atomically(
      path, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

/// Reads a dataset file; errors name it. Its size is not bounded: the file holds the data set
/// it is read into (and its header's length and checksum are checked).
[[nodiscard]] inline dataset_file_content read_dataset_file(const std::filesystem::path& path) {
  return decode_dataset(detail::read_file(path, std::numeric_limits<std::uint64_t>::max()), path.string());
}

}  // namespace pgm
