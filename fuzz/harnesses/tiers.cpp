// Tiers of background knowledge, --tiers (pgm/learn/background_knowledge.hpp).

#include "harness.hpp"
#include "pgm/learn/background_knowledge.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgm::fuzz::expect_value_or_error([&] { static_cast<void>(pgm::parse_tiers(pgm::fuzz::text_of(data, size))); });
}
