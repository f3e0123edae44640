// XMLBIF networks (pgm/io/xmlbif.hpp): the XML parser underneath and the reader above it.

#include "pgm/io/xmlbif.hpp"

#include "harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::parse_xmlbif(pgm::fuzz::text_of(data, size), "fuzz.xml")); });
}
