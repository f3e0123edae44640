// The conformance kit run on a user's engine: the enumeration engine of enumeration_engine.cpp,
// registered as "enumerate", held to brute force on random Bayesian networks and checked to
// refuse a Markov network by name. A GoogleTest program; its output ends "[  PASSED  ] 3 tests."
#include <pgm/testing/engine_conformance.hpp>

using pgm::testing::engine_conformance;  // the macro takes the suite's name unqualified

INSTANTIATE_TEST_SUITE_P(mine, engine_conformance, ::testing::Values(pgm::testing::engine_case{"enumerate"}),
                         pgm::testing::engine_case_name);
