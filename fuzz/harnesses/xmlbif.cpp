// XMLBIF networks (pgm/io/xmlbif.hpp): the XML parser underneath and the reader above it, read
// through the format registry.

#include "network_format_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgm::fuzz::read_as_network_format("xmlbif", data, size);
}
