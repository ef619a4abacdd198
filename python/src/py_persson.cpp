// asperity.PerssonLaw (asperity/persson.hpp): Persson's law for comparison.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>


#include "bindings.hpp"
#include "helpers.hpp"
#include "asperity/persson.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

void bind_persson(py::module_& m) {
  py::class_<PerssonLaw>(m, "PerssonLaw",
                         "Persson's (2007) law for comparison: p = reference_pressure exp(-s / beta).")
      .def(py::init([](double beta, double reference_pressure) { return PerssonLaw{beta, reference_pressure}; }),
           "beta"_a = 0.5, "reference_pressure"_a = 1.0)
      .def_readwrite("beta", &PerssonLaw::beta)
      .def_readwrite("reference_pressure", &PerssonLaw::reference_pressure)
      .def(
          "pressure",
          [](PerssonLaw law, const ArrayLike& s) {  // by value: read without the GIL
            return map_scalar(s.object, "separation", [&](double x) { return law.pressure(x); });
          },
          "separation"_a)
      .def(
          "separation_at",
          [](PerssonLaw law, const ArrayLike& p) {
            return map_scalar(p.object, "pressure", [&](double x) { return law.separation_at(x); });
          },
          "pressure"_a)
      .def("stiffness_over_load", &PerssonLaw::stiffness_over_load, "The constant 1/beta.");
}

}  // namespace asperity::python
