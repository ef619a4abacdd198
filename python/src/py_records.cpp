// The answers' record types asperity.ContactState, asperity.PhysicalState and
// asperity.ContactCurvesState (namedtuples).
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "helpers.hpp"
#include "asperity/contact.hpp"
#include "asperity/contact_curves.hpp"
#include "asperity/record_fields.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

void bind_records(py::module_& m) {
  auto collections = py::module_::import("collections");
  // the fields' names from their one list (ContactState's, contact.hpp)
  py::list contact_state_names;
  for (const RecordField& field : RecordFields<ContactState>::fields) contact_state_names.append(field.name);
  py::object contact_state = collections.attr("namedtuple")("ContactState", py::tuple(contact_state_names),
                                                            "module"_a = "asperity");
  contact_state.attr("__doc__") =
      "contact_at's answer (floats, or arrays shaped like the separations): count N X_0, area pi N R sigma_s X_1, "
      "load (4/3) N E* R^1/2 sigma_s^3/2 X_3/2, stiffness 2 N E* R^1/2 sigma_s^1/2 X_1/2 and the stiffness/load "
      "ratio (3/2) X_1/2 / X_3/2 (in separation units).";
  m.attr("ContactState") = contact_state;
  contact_state_type = contact_state.release();
  // the fields' names and meanings from their one list (physical_state_fields.hpp)
  py::list physical_state_names;
  std::string physical_state_doc = "ContactModel's answer (floats, or arrays shaped like the input), SI units:";
  for (const PhysicalStateField& field : physical_state_fields) {
    physical_state_names.append(field.name);
    physical_state_doc += std::string(" ") + field.name + " (" + field.meaning + "),";
  }
  physical_state_doc.back() = '.';
  py::object physical_state = collections.attr("namedtuple")("PhysicalState", py::tuple(physical_state_names),
                                                             "module"_a = "asperity");
  physical_state.attr("__doc__") = physical_state_doc;
  m.attr("PhysicalState") = physical_state;
  physical_state_type = physical_state.release();
  // ContactCurves' answer: the fields of ContactCurvesState's one list (contact_curves.hpp)
  py::list curves_state_names;
  std::string curves_state_doc = "ContactCurves' answer at_separation / at_pressure (floats, or arrays shaped like the "
                                 "input), SI units:";
  for (const RecordField& field : RecordFields<ContactCurvesState>::fields) {
    curves_state_names.append(field.name);
    curves_state_doc += std::string(" ") + field.name + " (" + field.meaning + "),";
  }
  curves_state_doc.back() = '.';
  py::object curves_state = collections.attr("namedtuple")("ContactCurvesState", py::tuple(curves_state_names),
                                                           "module"_a = "asperity");
  curves_state.attr("__doc__") = curves_state_doc;
  m.attr("ContactCurvesState") = curves_state;
  contact_curves_state_type = curves_state.release();
}

}  // namespace asperity::python
