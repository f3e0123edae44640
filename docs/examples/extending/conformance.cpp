// The conformance kits run on a user's components: the enumeration engine of
// enumeration_engine.cpp, registered as "enumerate", held to brute force on random Bayesian
// networks and checked to refuse a Markov network by name; the libDAI format of fg_format.cpp,
// which numbers its variables, reading back what it writes. A GoogleTest program; its output ends
// "[  PASSED  ] 6 tests."
#include <pgm/testing/engine_conformance.hpp>
#include <pgm/testing/format_conformance.hpp>

using pgm::testing::engine_conformance;  // the macros take the suites' names unqualified
using pgm::testing::format_conformance;

INSTANTIATE_TEST_SUITE_P(mine, engine_conformance, ::testing::Values(pgm::testing::engine_case{"enumerate"}),
                         pgm::testing::engine_case_name);

INSTANTIATE_TEST_SUITE_P(mine, format_conformance,
                         ::testing::Values(pgm::testing::format_case{.format = "fg", .keeps_names = false}),
                         pgm::testing::format_case_name);
