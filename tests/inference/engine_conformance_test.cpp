// The engine conformance kit (pgm/testing/engine_conformance.hpp) over every engine the registry
// holds: the exact ones to 1e-12, the samplers within their error at 10^5 samples, loopy belief
// propagation on trees, where it is exact.

#include "pgm/testing/engine_conformance.hpp"

namespace pgm::engine_conformance_tests {

using testing::engine_conformance;

INSTANTIATE_TEST_SUITE_P(registered, engine_conformance,
                         ::testing::ValuesIn(testing::registered_engine_cases({
                             {.engine = "lw", .tolerance = 0.03},
                             {.engine = "gibbs", .tolerance = 0.03, .estimates_evidence_probability = false},
                             {.engine = "bp", .tolerance = 1e-8, .exact_on_loops = false},
                         })),
                         testing::engine_case_name);

}  // namespace pgm::engine_conformance_tests
