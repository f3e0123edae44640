#pragma once
// The compiled instances of pgm/inference/junction_tree_engine.hpp: its members are templates
// in the header, instantiated once into libpgm for the two model classes under
// PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/junction_tree_engine.hpp"

#if defined(PGM_SEPARATE_COMPILATION)
namespace pgm {
template class junction_tree_engine<bayesian_network>;
template class junction_tree_engine<markov_network>;
}  // namespace pgm
#endif
