// With header_only_b.cpp, the program of the header-only check (tests/CMakeLists.txt): both
// include every header as pgm::core gives them, so that a definition that is not inline is
// defined twice and the link fails.
#include <pgm/pgm.hpp>

int main() { return pgm::variable("x", {"a", "b"}).cardinality() == 2 ? 0 : 1; }
