#pragma once
// Internal: not part of pgm's API, may change without notice.
//
// The CRC-32 of some bytes as 8 hex digits: how pgm's files notice that their content changed
// (dataset files, the data cache's record of the task file the data came from).

#include <boost/crc.hpp>
#include <cstdio>
#include <string>
#include <string_view>

#include "pgm/core/compilation.hpp"

namespace pgm::detail {

[[nodiscard]] PGM_DECL std::string crc32_hex(std::string_view bytes);

}  // namespace pgm::detail

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/detail/impl/checksum.ipp"
#endif
