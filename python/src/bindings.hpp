// The parts of the Python module, each in its own source file (module.cpp calls them).
#pragma once
#include <pybind11/pybind11.h>

namespace asperity::python {

// asperity.topography (topography.cpp). physical_state_type: the asperity.PhysicalState record.
void bind_topography(pybind11::module_& parent, pybind11::handle physical_state_type);
// asperity.law_curves, asperity.tabulate_law_scene (law_curves.cpp): needs asperity.ContactCurves bound
void bind_law_curves(pybind11::module_& m);
// asperity._output: the output policy for the pure-Python parts (output.cpp)
void bind_output(pybind11::module_& m);

}  // namespace asperity::python
