// The strategy conformance kit (pgm/testing/strategy_conformance.hpp) over every strategy the
// registry holds: the paper's three and the blend example of docs/extending.md.

#include "pgm/testing/strategy_conformance.hpp"

namespace pgm::strategy_conformance_tests {

using testing::strategy_conformance;

INSTANTIATE_TEST_SUITE_P(registered, strategy_conformance, ::testing::ValuesIn(testing::registered_strategy_names()),
                         testing::strategy_name);

}  // namespace pgm::strategy_conformance_tests
