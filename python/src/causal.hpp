#pragma once
// pgm._core's causal questions: d-separation, checking a DAG against a frame, the mutilated
// network of an intervention and the back-door sets.

#include <pybind11/pybind11.h>

namespace pgm::python {

/// Adds d_separated, check, intervene and backdoor_sets to the module.
void add_causal(pybind11::module_& module);

}  // namespace pgm::python
