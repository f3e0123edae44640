// Edge lists, --edges (pgm/core/network_structure.hpp).

#include "harness.hpp"
#include "pgm/core/network_structure.hpp"

PGM_FUZZ_HARNESS(edge_list) {
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::parse_edge_list(pgm::fuzz::text_of(data, size))); });
}
