// Edge lists, --edges (pgm/core/network_structure.hpp).

#include "harness.hpp"
#include "pgm/core/network_structure.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::parse_edge_list(pgm::fuzz::text_of(data, size))); });
}
