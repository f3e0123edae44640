// BIF networks (pgm/io/bif.hpp).

#include "pgm/io/bif.hpp"

#include "harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::parse_bif(pgm::fuzz::text_of(data, size), "fuzz.bif")); });
}
