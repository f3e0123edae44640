#pragma once
// The harness of a network format (pgm/io/network_format.hpp): the bytes read through the format
// registry, as every command reads a model file, kept counts included. A new format's harness
// is one call of read_as_network_format with its name.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "harness.hpp"
#include "pgm/io/network_file.hpp"

namespace pgm::fuzz {

inline int read_as_network_format(std::string_view name, const std::uint8_t* data, std::size_t size) {
  const network_format format(name);
  const auto source = "fuzz" + format.codec().extensions.front();
  return expect_value_or_error([&] { static_cast<void>(parse_model(text_of(data, size), format, source)); });
}

}  // namespace pgm::fuzz
