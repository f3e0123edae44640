// The second translation unit of the header-only check (header_only_a.cpp).
#include <pgm/pgm.hpp>
