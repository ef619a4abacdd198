// The parts of the Python module, each in its own source file (module.cpp calls them).
#pragma once
#include <pybind11/pybind11.h>

namespace asperity::python {

// asperity.topography (topography.cpp). physical_state_type: the asperity.PhysicalState record.
void bind_topography(pybind11::module_& parent, pybind11::handle physical_state_type);

}  // namespace asperity::python
