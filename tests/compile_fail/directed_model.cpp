// Only an engine over a DirectedModel has a network(): on a Markov network it does not compile.
#include <pgm/inference/variable_elimination.hpp>

#ifdef PGM_CONTROL
using model = pgm::bayesian_network;
#else
using model = pgm::markov_network;
#endif

const auto& network_of(const pgm::variable_elimination<model>& engine) { return engine.network(); }
