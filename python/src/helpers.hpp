// What the binding files of the module share: the names a user passes (a distribution, a side, an
// order), the record types made at import, the warnings the module raises, and the element-wise
// mapping of a number or an array.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/error.hpp"
#include "asperity/integrals.hpp"
#include "asperity/number_text.hpp"
#include "asperity/pressure_overclosure.hpp"
#include "asperity/scene.hpp"

namespace asperity::python {

namespace py = pybind11;

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The record types (collections.namedtuple, made once at import by bind_records): fields are
// floats for a number in, arrays for an array in.
inline py::handle contact_state_type, physical_state_type, contact_curves_state_type;


inline Distribution to_distribution(const py::handle& value) {
  if (py::isinstance<Distribution>(value)) return value.cast<Distribution>();
  if (py::isinstance<py::str>(value)) {
    const std::string name = value.cast<std::string>();
    Distribution out;
    if (parse_distribution(name, out)) return out;
    throw py::value_error("unknown distribution '" + name + "': expected 'weibull' or 'gaussian'");
  }
  throw py::type_error("distribution must be 'weibull', 'gaussian' or an asperity.Distribution");
}

inline Side to_side(const py::handle& value) {
  if (py::isinstance<Side>(value)) return value.cast<Side>();
  if (py::isinstance<py::str>(value)) {
    const std::string name = value.cast<std::string>();
    Side out;
    if (parse_side(name, out)) return out;
    throw py::value_error("unknown side '" + name + "': expected 'tail' or 'bounded'");
  }
  throw py::type_error("side must be 'tail', 'bounded' or an asperity.Side");
}

// twice_order from an int 0..5 or a quantity's name, as scene files name them (quantity_twice_order,
// docs/model.md): 'count', 'stiffness', 'area', 'load', 'F2', 'F5/2', ...
inline constexpr const char* order_names = "'count', 'stiffness', 'area', 'load' (or 'F0', 'F1/2', 'F1', 'F3/2', 'F2', 'F5/2')";
inline int twice_order_of(const OrderName& order) {
  const py::handle value = order.object;
  if (py::isinstance<py::str>(value)) {
    const std::string name = value.cast<std::string>();
    const int twice_order = quantity_twice_order(name);
    if (twice_order < 0)
      throw py::value_error("unknown order " + std::string(py::repr(value)) + ": expected " + order_names +
                            " or twice_order 0..5");
    return twice_order;
  }
  if (PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr()))
    throw py::type_error(std::string("the order must be twice_order 0..5 (an int) or a quantity's name (") +
                         order_names + "), not '" +
                         std::string(py::str(py::type::handle_of(value).attr("__name__"))) + "'");
  const Py_ssize_t twice_order = PyNumber_AsSsize_t(value.ptr(), nullptr);  // clipped, never overflows
  if (twice_order == -1 && PyErr_Occurred()) throw py::error_already_set();
  if (twice_order < 0 || twice_order >= order_count)
    throw py::value_error("twice_order " + std::to_string(twice_order) + " is outside 0..5");
  return static_cast<int>(twice_order);
}

// A vector's values as a new 1-d array.
template <class T>
py::array_t<T> to_array(const std::vector<T>& values) {
  py::array_t<T> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// A record (a namedtuple type) from its fields.
inline py::object make_record(py::handle type, const std::vector<py::object>& fields) {
  py::tuple arguments(fields.size());
  for (std::size_t i = 0; i < fields.size(); ++i) arguments[i] = fields[i];
  return type(*arguments);
}

// asperity.AreaFractionWarning (a UserWarning), made once at import (bind_errors).
inline PyObject* area_fraction_warning = nullptr;

// As the command warns (asperity contact), a Python warning where the real area passes
// gw_area_fraction_limit of the nominal area; raises if warnings are errors (-W error).
inline void warn_past_gw(double area_fraction) {
  const std::string text = gw_area_fraction_warning(area_fraction);  // the command's sentence (contact_model.hpp)
  if (text.empty()) return;
  if (PyErr_WarnEx(area_fraction_warning, text.c_str(), 1) < 0) throw py::error_already_set();
}

// asperity.OutOfRangeWarning (a UserWarning), made once at import (bind_errors).
inline PyObject* out_of_range_warning = nullptr;

// Queries outside the range a table serves (a scene table's, contact curves') are answered NaN,
// as the C++ API answers them; where the command refuses them, Python warns once per call,
// naming how many and the range in the query's unit. Raises if warnings are errors.
inline void warn_out_of_range(std::size_t outside, std::size_t total, const char* what, const std::string& range) {
  if (outside == 0) return;
  const std::string text = std::to_string(outside) + " of " + std::to_string(total) + " " + what +
                           " outside the range the table serves (answered NaN): " + range;
  if (PyErr_WarnEx(out_of_range_warning, text.c_str(), 1) < 0) throw py::error_already_set();
}

// A number as the library writes it (the shortest text that reads back the same).
inline std::string g(double value) { return format_double(value); }

template <class Function>
FloatOrArray map_scalar(py::handle input, const char* name, Function function) {
  return map_batch(
      input, name, py::none(),
      [&](const double* in, double* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = function(in[i]);
      },
      function);
}

inline CardFormat card_format(const std::string& name) {
  CardFormat format;
  if (!parse_card_format(name, format)) throw Error("unknown card format '" + name + "' (calculix, abaqus or csv)");
  return format;
}
inline CardUnits card_units(const std::string& name) {
  CardUnits units;
  if (!parse_card_units(name, units)) throw Error("unknown card units '" + name + "' (si or mm)");
  return units;
}

}  // namespace asperity::python
