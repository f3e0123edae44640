// Hugin NET networks (pgm/io/net.hpp).

#include "pgm/io/net.hpp"

#include "harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::parse_net(pgm::fuzz::text_of(data, size), "fuzz.net")); });
}
