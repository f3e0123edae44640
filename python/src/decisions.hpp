#pragma once
// pgm._core's influence diagrams: read from XMLBIF, solved (exactly with perfect recall, or by
// single policy updating), the value of information, written back.

#include <pybind11/pybind11.h>

#include "pgm/core/influence_diagram.hpp"

namespace pgm::python {

/// The model a Python pgm.InfluenceDiagram wraps.
struct diagram_handle {
  influence_diagram model;
};

/// Adds the class InfluenceDiagram and the function read_influence_diagram to the module.
void add_decisions(pybind11::module_& module);

}  // namespace pgm::python
