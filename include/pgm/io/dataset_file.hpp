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

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/checksum.hpp"
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

  PGM_DECL dataset_file_content read(std::string_view bytes, const std::string& source) const;

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
  PGM_DECL void add(dataset& data, data_column column) const;
};

}  // namespace detail

/// The file's bytes: the header line, then the data.
[[nodiscard]] PGM_DECL std::string encode_dataset(const dataset& data, const dataset_file_meta& meta = {});

/// Reads the bytes of a dataset file; `source` names it in errors.
[[nodiscard]] inline dataset_file_content decode_dataset(std::string_view bytes, const std::string& source) {
  return detail::dataset_file_reader(source).read(bytes, source);
}

/// Writes `data` to `path` atomically (a temporary file renamed once complete).
PGM_DECL void write_dataset_file(const std::filesystem::path& path, const dataset& data,
                                 const dataset_file_meta& meta = {});

/// Reads a dataset file; errors name it. Its size is not bounded: the file holds the data set
/// it is read into (and its header's length and checksum are checked).
[[nodiscard]] inline dataset_file_content read_dataset_file(const std::filesystem::path& path) {
  return decode_dataset(pgm::read_file(path, std::numeric_limits<std::uint64_t>::max()), path.string());
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/io/impl/dataset_file.ipp"
#endif
