#pragma once
/// \file
/// Base64 (RFC 4648, with '=' padding), by Boost's archive iterators: how pgm keeps a block of
/// its own (a fit's counts) in a property of a BIF, XMLBIF or NET file, where any other text
/// could collide with the format's own syntax or with a peer's parser.

#include <boost/archive/iterators/base64_from_binary.hpp>
#include <boost/archive/iterators/binary_from_base64.hpp>
#include <boost/archive/iterators/transform_width.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "pgm/core/compilation.hpp"

namespace pgm::detail {

[[nodiscard]] PGM_DECL std::string base64_encode(std::string_view bytes);

/// The bytes `text` encodes, or nothing when it is not base64 (a character outside the
/// alphabet, a length that is not a multiple of 4, padding other than at the end).
[[nodiscard]] PGM_DECL std::optional<std::string> base64_decode(std::string_view text);

}  // namespace pgm::detail

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/detail/impl/base64.ipp"
#endif
