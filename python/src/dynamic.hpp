#pragma once
// pgm._core's dynamic networks: the 2-TBN a pgm.DynamicNetwork wraps, with the counts it keeps,
// fitted from episodes and updated with new ones, read from and written to pgm's JSON, and
// unrolled into a Bayesian network.

#include <pybind11/pybind11.h>

namespace pgm::python {

/// Adds the classes DynamicNetwork and DynamicCounts and the functions read_dynamic_json,
/// fit_dynamic and update_dynamic to the module.
void add_dynamic(pybind11::module_& module);

}  // namespace pgm::python
