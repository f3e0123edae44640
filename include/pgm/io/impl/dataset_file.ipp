#pragma once
// The definitions of pgm/io/dataset_file.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/io/dataset_file.hpp"

namespace pgm::detail {

PGM_DECL dataset_file_content dataset_file_reader::read(std::string_view bytes, const std::string& source) const {
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

PGM_DECL void dataset_file_reader::add(dataset& data, data_column column) const {
  try {
    data.add(std::move(column));
  } catch (const data_error& e) {
    fail("/columns", e.what());
  }
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL std::string encode_dataset(const dataset& data, const dataset_file_meta& meta) {
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

PGM_DECL void write_dataset_file(const std::filesystem::path& path, const dataset& data,
                                 const dataset_file_meta& meta) {
  const auto bytes = encode_dataset(data, meta);
  pgm::write_file_atomically(
      path, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

}  // namespace pgm
