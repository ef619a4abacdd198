// The pressure-overclosure cards' options in Python (py_fe_export.cpp), shared by ContactModel's
// and ContactCurves' cards: one declaration for both binding files.
#pragma once
#include <pybind11/pybind11.h>

#include <cstddef>
#include <optional>
#include <string>

#include "asperity/pressure_overclosure.hpp"

namespace asperity::python {

// The card's options (ValueError naming a bad one, `datum_keyword` the datum's keyword) and the
// card written with them (a UserWarning where a CalculiX card passes the spring cut-off).
struct CardSettings {
  CardFormat format = CardFormat::calculix;
  CardUnits units = CardUnits::si;
  OverclosureDatum datum = OverclosureDatum::zero_pressure;
  std::size_t max_points = 0;
  double face_size = 0;  // m; NaN: not given
};
CardSettings card_settings(const std::string& format, const std::string& units, const char* datum_keyword,
                           const std::string& datum, std::optional<long long> max_points,
                           std::optional<double> face_size);
std::string card_text(const PressureOverclosureTable& table, const CardSettings& settings,
                      const std::string& description);

}  // namespace asperity::python
