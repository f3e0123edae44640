#pragma once
// pgm._core's dynamic networks: the 2-TBN a pgm.DynamicNetwork wraps, read from and written to
// pgm's JSON, and unrolled into a Bayesian network.

#include <pybind11/pybind11.h>

namespace pgm::python {

/// Adds the class DynamicNetwork and the function read_dynamic_json to the module.
void add_dynamic(pybind11::module_& module);

}  // namespace pgm::python
