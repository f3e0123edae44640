#pragma once
// Internal: not part of pgm's API, may change without notice.
//
// The CRC-32 of some bytes as 8 hex digits: how pgm's files notice that their content changed
// (dataset files, the data cache's record of the task file the data came from).

#include <boost/crc.hpp>
#include <cstdio>
#include <string>
#include <string_view>

namespace pgm::detail {

[[nodiscard]] inline std::string crc32_hex(std::string_view bytes) {
  boost::crc_32_type crc;
  crc.process_bytes(bytes.data(), bytes.size());
  char text[9];
  std::snprintf(text, sizeof text, "%08x", static_cast<unsigned>(crc.checksum()));
  return text;
}

}  // namespace pgm::detail
