#pragma once
/// \file
/// The file functions of pgm/core/file.hpp under the names the library's own code uses.

#include "pgm/core/file.hpp"

namespace pgm::detail {

using pgm::check_output_path;
using pgm::read_file;
using pgm::write_file_atomically;

}  // namespace pgm::detail
