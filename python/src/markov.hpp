#pragma once
// pgm._core's Markov networks: the model a pgm.MarkovNetwork wraps, the four UAI tasks on it,
// and reading a .uai file as whichever model it declares.

#include <pybind11/pybind11.h>

#include "pgm/core/markov_network.hpp"

namespace pgm::python {

/// The model a Python pgm.MarkovNetwork wraps (pgm.InferenceEngine's engines refer to it).
struct markov_handle {
  markov_network model;
};

/// Adds the class MarkovNetwork and the function read_uai to the module.
void add_markov(pybind11::module_& module);

}  // namespace pgm::python
