// asperity.InverseCurve (asperity/inverse.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>


#include "bindings.hpp"
#include "helpers.hpp"
#include "asperity/inverse.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

void bind_inverse(py::module_& m) {
  py::class_<InverseCurve>(m, "InverseCurve",
                           "The separation where X_n takes a value (n = twice_order/2 > 1/2): a tabulated inverse "
                           "and one Newton step on the curve (iterated where one is not enough: the Weibull tail side near "
                           "s = 0), ln X_n within 1e-13 (1 + |ln X_n|) of the value.")
      .def(py::init([](const Curve& curve, const OrderName& order) { return InverseCurve(curve, twice_order_of(order)); }),
           "curve"_a, "twice_order"_a,
           "The curve must hold twice_order and twice_order - 2 (asperity.Error otherwise); twice_order 2..5 or\n"
           "a quantity's name ('area', 'load', 'F2', 'F5/2'). The inverse holds the curve's data: it may outlive\n"
           "the Curve and the Table.")
      .def(
          "separation_at",
          [](const InverseCurve& inverse, const ArrayLike& value) {
            return map_scalar(value.object, "value", [&](double x) { return inverse.separation_at(x); });
          },
          "value"_a, "s with X_n(s) = value (a number or an array).")
      .def(
          "separation_at_log",
          [](const InverseCurve& inverse, const ArrayLike& log_value) {
            return map_scalar(log_value.object, "log_value", [&](double y) { return inverse.separation_at_log(y); });
          },
          "log_value"_a, "s with ln X_n(s) = log_value.")
      .def_property_readonly("twice_order", &InverseCurve::twice_order)
      .def_property_readonly("curve", &InverseCurve::curve, py::return_value_policy::copy,
                             "The curve it inverts (a handle sharing its data).")
      .def_property_readonly("memory_bytes", &InverseCurve::memory_bytes)
      .def("__copy__", [](const InverseCurve& inverse) { return inverse; })
      .def("__deepcopy__", [](const InverseCurve& inverse, py::dict) { return inverse; }, "memo"_a);
}

}  // namespace asperity::python
