// Correspondence maps, --map (pgm/core/correspondence.hpp).

#include "pgm/core/correspondence.hpp"

#include "harness.hpp"

PGM_FUZZ_HARNESS(correspondence) {
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::parse_correspondence(pgm::fuzz::text_of(data, size))); });
}
