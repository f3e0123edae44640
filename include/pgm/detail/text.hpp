#pragma once
/// \file
/// The text functions of pgm/core/text.hpp under the names the library's own code uses.

#include "pgm/core/text.hpp"

namespace pgm::detail {

using text::closest_name;
using text::edit_distance;
using text::format_double;
using text::format_short;
using text::join;
using text::list_for_message;
using text::number_hint;
using text::parse_double;
using text::printable;
using text::quoted_number;
using text::split;
using text::trim;
using text::utf8_sequence;

}  // namespace pgm::detail
