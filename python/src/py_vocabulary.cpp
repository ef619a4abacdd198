// The vocabulary (asperity/integrals.hpp, instruction_set.hpp): Distribution, Side, InstructionSet,
// orders and the unit densities.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>


#include "bindings.hpp"
#include "helpers.hpp"
#include "asperity/instruction_set.hpp"
#include "asperity/integrals.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

void bind_vocabulary(py::module_& m) {
  // ---- the vocabulary (asperity/model.hpp) ----
  py::enum_<Distribution>(m, "Distribution", "Summit height density: weibull (shape a) or gaussian.")
      .value("weibull", Distribution::weibull)
      .value("gaussian", Distribution::gaussian);
  py::enum_<Side>(m, "Side", "Side of approach: tail (the GW approach, unbounded upper tail) or bounded "
                             "(mirrored heights: worn, polished surfaces; Weibull only).")
      .value("tail", Side::tail)
      .value("bounded", Side::bounded);
  py::enum_<InstructionSet>(m, "InstructionSet", "The batch kernel's instruction set.")
      .value("automatic", InstructionSet::automatic)
      .value("generic", InstructionSet::generic)
      .value("avx2", InstructionSet::avx2)
      .value("avx512", InstructionSet::avx512);
  m.def("best_instruction_set", &best_instruction_set,
        "The widest instruction set this CPU has, which the batch path uses.");

  m.def("order_of", [](const OrderName& order) { return order_of(twice_order_of(order)); }, "twice_order"_a,
        "The order n = twice_order / 2 (twice_order 0..5 or a quantity's name: order_of('load') is 1.5).");
  m.def("weibull_mean", py::vectorize(&weibull_mean), "shape"_a,
        "Mean of the unit Weibull density, mu_a = Gamma(1 + 1/a).");
  m.def("weibull_rms", py::vectorize(&weibull_rms), "shape"_a,
        "Rms about the mean of the unit Weibull density, c_a = sqrt(Gamma(1 + 2/a) - Gamma(1 + 1/a)^2).");
  m.def("weibull_moment", py::vectorize(&weibull_moment), "shape"_a, "power"_a,
        "Raw moment of the unit Weibull density, E z^p = Gamma(1 + p/a).");
  m.def("weibull_log_density", py::vectorize(&weibull_log_density), "shape"_a, "height"_a,
        "ln phi_a(z), phi_a(z) = a z^(a-1) exp(-z^a).");
  m.def("gaussian_log_density", py::vectorize(&gaussian_log_density), "height"_a,
        "ln phi(z), phi(z) = exp(-z^2/2) / sqrt(2 pi).");
}

}  // namespace asperity::python
