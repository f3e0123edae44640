// The learner conformance kit (pgm/testing/learner_conformance.hpp) over every registered
// structure learner: pc, hc, tabu and mmhc recover the sampled network; empty, and the chain of
// structure_learner_test.cpp, learn a fixed shape.

#include "pgm/testing/learner_conformance.hpp"

namespace pgm::learner_conformance_tests {

using testing::learner_conformance;

INSTANTIATE_TEST_SUITE_P(registered, learner_conformance,
                         ::testing::ValuesIn(testing::registered_learner_cases({
                             {.learner = "empty", .recovers = false},
                             {.learner = "chain", .recovers = false},
                         })),
                         testing::learner_case_name);

}  // namespace pgm::learner_conformance_tests
