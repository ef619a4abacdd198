// asperity.Curve and asperity.CurveOptions (asperity/curve.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include "helpers.hpp"
#include "asperity/curve.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {
namespace {

std::string describe(const Curve& curve) {
  std::string text = std::string("<asperity.Curve ") + to_string(curve.distribution()) + " " + to_string(curve.side());
  if (curve.distribution() == Distribution::weibull) text += " shape=" + py::repr(py::float_(curve.shape())).cast<std::string>();
  return text + ">";
}

}  // namespace

void bind_curve(py::module_& m) {
  // ---- curves (asperity/curve.hpp) ----
  py::class_<Curve>(m, "Curve",
                    "One resolved curve (distribution, side, shape): the hot handle. Immutable; any number of "
                    "threads may query it at once. Made by Table.curve.")
      .def(
          "value",
          [](const Curve& curve, const OrderName& order, const ArrayLike& separation, const OptionalOut& out) {
            const int twice_order = twice_order_of(order);
            return map_batch(separation.object, "separation", out.object, [&](const double* in, double* result, std::size_t n) {
              curve.value_batch(twice_order, in, result, n);
            }, [&](double x) { return curve.value(twice_order, x); });
          },
          "twice_order"_a, "separation"_a, py::kw_only(), "out"_a = py::none(),
          "X_n(s) for n = twice_order/2 (0 count, 1 stiffness, 2 area, 3 load, 4 F_2, 5 F_5/2) at the\n"
          "separations s (origin convention, units of sigma_s; docs/model.md). The order is twice_order or\n"
          "the quantity's name: 'count', 'stiffness', 'area', 'load', 'F2', 'F5/2' (quantity_twice_order).\n\n"
          "separation: a number (the answer is a float) or an array of any shape (the answer is a float64\n"
          "array of that shape), computed by the vectorized batch path without the GIL. NaN for a NaN or\n"
          "infinite separation; underflows to 0 below ~1e-308 (use log_value there). out: an optional\n"
          "C-contiguous float64 array of the same size to write into (returned).")
      .def(
          "log_value",
          [](const Curve& curve, const OrderName& order, const ArrayLike& separation, const OptionalOut& out) {
            const int twice_order = twice_order_of(order);
            return map_batch(separation.object, "separation", out.object, [&](const double* in, double* result, std::size_t n) {
              curve.log_value_batch(twice_order, in, result, n);
            }, [&](double x) { return curve.log_value(twice_order, x); });
          },
          "twice_order"_a, "separation"_a, py::kw_only(), "out"_a = py::none(),
          "ln X_n(s): finite wherever X_n > 0 (far below 1e-308), -inf where it is exactly 0 (bounded side,\n"
          "s >= 0). Arguments as for value().")
      .def("has_order", [](const Curve& curve, const OrderName& order) { return curve.has_order(twice_order_of(order)); },
           "twice_order"_a, "Whether the curve holds this order (twice_order or a quantity's name; order_mask).")
      .def_property_readonly("distribution", &Curve::distribution)
      .def_property_readonly("side", &Curve::side)
      .def_property_readonly("shape", &Curve::shape, "The Weibull shape a (2 for the Gaussian).")
      .def_property_readonly("order_mask", &Curve::order_mask, "Bit 1 << twice_order for each order held.")
      .def_property_readonly("served_min_separation", &Curve::served_min_separation,
                             "The separations the curve serves start here: -inf for a full table's curves, a scene\n"
                             "table's range for its curves. Outside them value() and log_value() answer NaN\n"
                             "(the bounded side at s >= 0 excepted: exactly 0).")
      .def_property_readonly("served_max_separation", &Curve::served_max_separation,
                             "The separations the curve serves end here: +inf for a full table's curves.")
      .def("serves", py::vectorize(&Curve::serves), "separation"_a,
           "True where the curve answers: inside [served_min_separation, served_max_separation], or the\n"
           "bounded side at s >= 0 (exactly 0); False for NaN.")
      .def_property_readonly("table_min_separation", &Curve::table_min_separation,
                             "Where the knots start (below: the all-touching segment).")
      .def_property_readonly("table_max_separation", &Curve::table_max_separation,
                             "Where the knots end (beyond: the series).")
      .def_property_readonly("memory_bytes", &Curve::memory_bytes, "Bytes of the curve's data (shared by its copies).")
      .def_property_readonly("grid_intervals", &Curve::grid_intervals,
                             "Intervals of the lookup grid per order (CurveOptions.grid_tolerance sets how many).")
      .def_property_readonly("grid_error", &Curve::grid_error,
                             "The largest difference in ln X from the table the grid showed where it was checked.")
      .def("__copy__", [](const Curve& curve) { return curve; }, "A handle sharing the same data (curves are immutable).")
      .def("__deepcopy__", [](const Curve& curve, py::dict) { return curve; }, "memo"_a)
      .def("__repr__", &describe);

  py::class_<CurveOptions>(m, "CurveOptions",
                           "The lookup grid of a curve (Table.curve(..., options=)): the largest error it may add to\n"
                           "the table's own, in ln X (relative in X where X >= 1e-100; 100 times that below), and the\n"
                           "separations it covers (outside, the table's own layout answers). A smaller tolerance costs\n"
                           "memory, never time.")
      .def(py::init([](double grid_tolerance, double grid_min_separation, double grid_max_separation) {
             CurveOptions options;
             options.grid_tolerance = grid_tolerance;
             options.grid_min_separation = grid_min_separation;
             options.grid_max_separation = grid_max_separation;
             return options;
           }),
           "grid_tolerance"_a = CurveOptions{}.grid_tolerance,
           "grid_min_separation"_a = CurveOptions{}.grid_min_separation,
           "grid_max_separation"_a = CurveOptions{}.grid_max_separation)
      .def_readwrite("grid_tolerance", &CurveOptions::grid_tolerance)
      .def_readwrite("grid_min_separation", &CurveOptions::grid_min_separation)
      .def_readwrite("grid_max_separation", &CurveOptions::grid_max_separation)
      .def("__repr__", [](const CurveOptions& o) {
        return py::str("CurveOptions(grid_tolerance={!r}, grid_min_separation={!r}, grid_max_separation={!r})")
            .format(o.grid_tolerance, o.grid_min_separation, o.grid_max_separation);
      });
}

}  // namespace asperity::python
