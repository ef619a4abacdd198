// asperity.Error (the library's errors, with its messages) and the warnings the module raises.
#include <pybind11/pybind11.h>

#include <cstring>
#include <exception>

#include "bindings.hpp"
#include "helpers.hpp"
#include "asperity/error.hpp"
#include "asperity/interrupt.hpp"

namespace py = pybind11;

namespace asperity::python {

void bind_errors(py::module_& m) {
  // asperity::Error as asperity.Error with the library's message; a message naming a file whose
  // name is not UTF-8 keeps those bytes as \xNN escapes (pybind11's own translation would fail).
  // A ValueError (what Python code expects of a bad value, as a typo's ValueError is) and a
  // RuntimeError (what it was before: `except RuntimeError` still catches it).
  static PyObject* const error_type = [] {
    PyObject* bases = PyTuple_Pack(2, PyExc_ValueError, PyExc_RuntimeError);
    if (!bases) throw py::error_already_set();
    PyObject* type = PyErr_NewException("asperity.Error", bases, nullptr);
    Py_DECREF(bases);
    if (!type) throw py::error_already_set();
    return type;  // kept for the module's life
  }();
  m.attr("Error") = py::reinterpret_borrow<py::object>(error_type);
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const Interrupted&) {  // a stop asked (interrupt.hpp): the signal handler's exception
      if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const Error& error) {
      const char* message = error.what();
      PyObject* text = PyUnicode_DecodeUTF8(message, static_cast<Py_ssize_t>(std::strlen(message)), "backslashreplace");
      if (!text) return;  // the decoding error stands
      PyErr_SetObject(error_type, text);
      Py_DECREF(text);
    }
  });
  area_fraction_warning = PyErr_NewExceptionWithDoc(
      "asperity.AreaFractionWarning",
      "Warned (warnings.warn) where a ContactModel's real contact area passes gw_area_fraction_limit (0.1) of the\n"
      "nominal area, as the command asperity contact warns: Greenwood-Williamson's asperity contacts are\n"
      "sparse and independent only below it. warnings.simplefilter('error', asperity.AreaFractionWarning)\n"
      "makes it an exception; 'ignore' silences it.",
      PyExc_UserWarning, nullptr);
  if (!area_fraction_warning) throw py::error_already_set();
  m.attr("AreaFractionWarning") = py::reinterpret_borrow<py::object>(area_fraction_warning);  // the module keeps it
  out_of_range_warning = PyErr_NewExceptionWithDoc(
      "asperity.OutOfRangeWarning",
      "Warned (warnings.warn) where a query lies outside the range a table serves and is answered NaN: a\n"
      "ContactModel on a scene table (its scene's separations, and the loads, pressures and real areas there) or\n"
      "ContactCurves (a contact-curves table: a law's or a measured surface's). The message names how many and\n"
      "the range, in the query's unit; the command asperity contact refuses such a query.\n"
      "warnings.simplefilter('error', asperity.OutOfRangeWarning) makes it an exception.",
      PyExc_UserWarning, nullptr);
  if (!out_of_range_warning) throw py::error_already_set();
  m.attr("OutOfRangeWarning") = py::reinterpret_borrow<py::object>(out_of_range_warning);
  m.attr("gw_area_fraction_limit") = gw_area_fraction_limit;
  m.attr("Error").attr("__doc__") =
      "An error of the asperity library (a missing or bad table or scene, a shape outside the table, a bad "
      "physical parameter); its message is the library's. A ValueError (as a misspelled keyword's) and a "
      "RuntimeError.";
}

}  // namespace asperity::python
