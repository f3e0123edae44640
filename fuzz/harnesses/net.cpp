// Hugin NET networks (pgm/io/net.hpp), read through the format registry.

#include "network_format_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgm::fuzz::read_as_network_format("net", data, size);
}
