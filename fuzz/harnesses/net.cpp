// Hugin NET networks (pgm/io/net.hpp), read through the format registry.

#include "network_format_harness.hpp"

PGM_FUZZ_HARNESS(net) { return pgm::fuzz::read_as_network_format("net", data, size); }
