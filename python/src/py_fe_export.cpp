// FE export of a tabulated curve (asperity/pressure_overclosure.hpp); the models' own cards are
// methods of ContactModel and ContactCurves.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "helpers.hpp"
#include "asperity/pressure_overclosure.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

void bind_fe_export(py::module_& m) {
  m.def(
      "tabulated_pressure_overclosure_card",
      [](const std::vector<double>& pressures, const std::vector<double>& overclosures, const std::string& format,
         const std::string& units, const std::string& description, const std::string& notes) {
        if (pressures.size() != overclosures.size())
          throw Error("tabulated_pressure_overclosure_card: as many pressures as overclosures");
        std::vector<PressureOverclosurePoint> points(pressures.size());
        for (std::size_t i = 0; i < points.size(); ++i) points[i] = {pressures[i], overclosures[i]};
        std::ostringstream out;
        write_tabulated_pressure_overclosure(out, points, card_format(format), card_units(units), description, notes);
        return out.str();
      },
      "pressures"_a, "overclosures"_a, "format"_a = "calculix", "units"_a = "si", "description"_a = "",
      "notes"_a = "",
      "FE export of a curve given by its points (a tabulated law: the exact contact of a measured map): the\n"
      "pressure-overclosure card of CalculiX or Abaqus (format 'calculix', 'abaqus' or 'csv'; units 'si' for\n"
      "m and Pa, 'mm' for mm and MPa) as text. Points ascending in overclosure [m] (positive where the\n"
      "surfaces overlap), pressures [Pa] never falling. Raises asperity.Error for fewer than two points or\n"
      "points out of order.");
}

}  // namespace asperity::python
