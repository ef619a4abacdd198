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

namespace {

// A record type: a namedtuple `name` of `fields` (each with a name and a meaning) in module
// asperity, its docstring `doc` followed by each field's meaning unless `doc` says it all already
template <class Fields>
py::handle record_type(py::module_& m, const char* name, const Fields& fields, std::string doc, bool list_fields) {
  py::list names;
  for (const auto& field : fields) {
    names.append(field.name);
    if (list_fields) doc += std::string(" ") + field.name + " (" + field.meaning + "),";
  }
  if (list_fields) doc.back() = '.';
  py::object type = py::module_::import("collections").attr("namedtuple")(name, py::tuple(names), "module"_a = "asperity");
  type.attr("__doc__") = doc;
  m.attr(name) = type;
  return type.release();
}

}  // namespace

void bind_records(py::module_& m) {
  // each from its fields' one list: ContactState's (contact.hpp), PhysicalState's
  // (physical_state_fields.hpp), ContactCurvesState's (contact_curves.hpp)
  contact_state_type = record_type(
      m, "ContactState", RecordFields<ContactState>::fields,
      "contact_at's answer (floats, or arrays shaped like the separations): count N X_0, area pi N R sigma_s X_1, "
      "load (4/3) N E* R^1/2 sigma_s^3/2 X_3/2, stiffness 2 N E* R^1/2 sigma_s^1/2 X_1/2 and the stiffness/load "
      "ratio (3/2) X_1/2 / X_3/2 (in separation units).",
      false);
  physical_state_type = record_type(m, "PhysicalState", physical_state_fields,
                                    "ContactModel's answer (floats, or arrays shaped like the input), SI units:", true);
  contact_curves_state_type =
      record_type(m, "ContactCurvesState", RecordFields<ContactCurvesState>::fields,
                  "ContactCurves' answer at_separation / at_pressure (floats, or arrays shaped like the input), SI "
                  "units:",
                  true);
}

}  // namespace asperity::python
