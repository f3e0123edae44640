// BIF networks (pgm/io/bif.hpp), read through the format registry.

#include "network_format_harness.hpp"

PGM_FUZZ_HARNESS(bif) { return pgm::fuzz::read_as_network_format("bif", data, size); }
