// Tiers of background knowledge, --tiers (pgm/learn/background_knowledge.hpp).

#include "harness.hpp"
#include "pgm/learn/background_knowledge.hpp"

PGM_FUZZ_HARNESS(tiers) {
  return pgm::fuzz::expect_value_or_error([&] { static_cast<void>(pgm::parse_tiers(pgm::fuzz::text_of(data, size))); });
}
