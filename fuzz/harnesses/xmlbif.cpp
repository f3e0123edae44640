// XMLBIF networks (pgm/io/xmlbif.hpp): the XML parser underneath and the reader above it, read
// through the format registry.

#include "network_format_harness.hpp"

PGM_FUZZ_HARNESS(xmlbif) { return pgm::fuzz::read_as_network_format("xmlbif", data, size); }
