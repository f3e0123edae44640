#pragma once
/// \file
/// gzip data in memory, inflated: how a model file compressed as `.bif.gz`, `.xml.gz`,
/// `.net.gz` or `.json.gz` (as the bnlearn repository and pgmpy ship them) is read. Compiled
/// (src/lib/io/gzip.cpp, pgm::pgm, zlib).

#include <cstdint>
#include <string>
#include <string_view>

namespace pgm {

/// Whether `bytes` begin with gzip's magic bytes (1f 8b).
[[nodiscard]] inline bool is_gzip(std::string_view bytes) noexcept {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

/// The inflated bytes of gzip data (concatenated members too). Throws io_error naming `source`
/// for data that is not gzip or is damaged, and when the inflated bytes would exceed
/// `max_bytes` (checked as they are produced, so a small file that inflates to gigabytes stops
/// at the bound).
[[nodiscard]] std::string inflate_gzip(std::string_view bytes, const std::string& source, std::uint64_t max_bytes);

}  // namespace pgm
