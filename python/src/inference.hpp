#pragma once
// pgm._core's inference: an engine compiled once per network (pgm.InferenceEngine), and the
// one-call query and MPE the package's pgm.query and pgm.mpe make on a cached engine.

#include <pybind11/pybind11.h>

namespace pgm::python {

/// Adds the class Engine and the function engine_names to the module.
void add_inference(pybind11::module_& module);

}  // namespace pgm::python
