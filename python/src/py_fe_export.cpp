// FE export of a tabulated curve (asperity/pressure_overclosure.hpp); the models' own cards are
// methods of ContactModel and ContactCurves.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "card_settings.hpp"
#include "helpers.hpp"
#include "asperity/pressure_overclosure.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

// The card options of ContactModel's and ContactCurves' cards, as the command line has them:
// max_points None is the format's cap (200 for calculix); face_size in the card's units, returned
// in metres (NaN: None). ValueError for a bad value.
std::size_t card_points_option(std::optional<long long> max_points, CardFormat format) {
  if (!max_points) return default_card_points(format);
  if (*max_points < static_cast<long long>(card_points_min) || *max_points > static_cast<long long>(card_points_max))
    throw py::value_error("max_points must be from " + std::to_string(card_points_min) + " to " +
                          std::to_string(card_points_max) + ", got " + std::to_string(*max_points));
  return static_cast<std::size_t>(*max_points);
}

double face_size_option(std::optional<double> face_size, CardFormat format, CardUnits units) {
  if (!face_size) return NAN;
  if (!(*face_size > 0 && std::isfinite(*face_size)))
    throw py::value_error("face_size must be a positive length in the card's units (m; mm with units='mm')");
  if (format != CardFormat::calculix)
    throw py::value_error("face_size checks CalculiX's contact-spring cut-off: it goes with format='calculix'");
  return *face_size * card_length_unit(units);
}

void warn_spring_cutoff(const std::vector<PressureOverclosurePoint>& rows, double face_size, CardUnits units);

CardSettings card_settings(const std::string& format, const std::string& units, const char* datum_keyword,
                           const std::string& datum, std::optional<long long> max_points,
                           std::optional<double> face_size) {
  CardSettings settings;
  if (!parse_overclosure_datum(datum, settings.datum))
    throw py::value_error(std::string("unknown ") + datum_keyword + " '" + datum +
                          "': expected 'zero-pressure', 'mean-summit', 'origin' or 'mean-plane'");
  settings.format = card_format(format);
  settings.units = card_units(units);
  settings.max_points = card_points_option(max_points, settings.format);
  settings.face_size = face_size_option(face_size, settings.format, settings.units);
  return settings;
}

std::string card_text(const PressureOverclosureTable& table, const CardSettings& settings,
                      const std::string& description) {
  std::ostringstream out;
  write_pressure_overclosure(out, table, settings.format, settings.units, description, settings.face_size);
  if (settings.format == CardFormat::calculix) warn_spring_cutoff(table.points, settings.face_size, settings.units);
  return out.str();
}

// Warns (UserWarning) where a CalculiX card reaches beyond the contact-spring cut-off of faces of
// face_size [m], as the command line does; the card's header says it too.
void warn_spring_cutoff(const std::vector<PressureOverclosurePoint>& rows, double face_size, CardUnits units) {
  std::string text = calculix_cutoff_warning(rows, face_size, units);
  if (text.empty()) return;
  for (std::size_t at; (at = text.find("\n  ")) != std::string::npos;) text.replace(at, 3, " ");
  text += "; use overclosure_datum='zero-pressure' (and start the model with the surfaces touching) or larger faces";
  if (PyErr_WarnEx(PyExc_UserWarning, text.c_str(), 1) < 0) throw py::error_already_set();
}

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
