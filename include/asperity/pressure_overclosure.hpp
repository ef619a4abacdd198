// FE export: a rough surface's contact-pressure law as the tabular pressure-overclosure card of
// CalculiX and Abaqus (*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR), or as CSV.
//
// Overclosure, as both codes define it, is the interpenetration of the two contact surfaces
// (positive when they overlap; a clearance is a negative overclosure). Here the flat's surface
// and the rough surface's mean summit height (GW's and McCool's datum) are the FE surfaces:
// overclosure h = -(separation of the flat from the mean summit height), and the nominal
// pressure at h is the model's at that separation.
//
// Points are placed by bisection in h until linear interpolation between neighbours is within
// `tolerance` (relative, in pressure) of the law at every checked point, from pressure_min to
// pressure_max; then every interval is checked again at 32 interior points. Below pressure_min
// the table follows the law's tangent at pressure_min down to zero pressure (its first point):
// the law itself falls off smoothly there and never reaches zero on the tail side. Beyond the
// last point Abaqus continues the last slope and CalculiX keeps the last pressure: give a
// pressure_max above what the analysis reaches.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "asperity/contact_model.hpp"

namespace asperity {

enum class CardFormat { calculix, abaqus, csv };
enum class CardUnits { si, mm };  // overclosure in m and pressure in Pa, or mm and MPa (N/mm^2)

struct PressureOverclosurePoint {
  double pressure;     // Pa
  double overclosure;  // m
};

struct PressureOverclosureTable {
  std::vector<PressureOverclosurePoint> points;  // ascending in overclosure; points[0] at zero pressure
  double pressure_min = 0, pressure_max = 0;     // Pa: the range within tolerance
  double tolerance = 0;                          // asked
  double max_error = 0;                          // measured, relative in pressure
  long checked_points = 0;                       // where it was measured
};

// The law the table follows: the nominal pressure [Pa] at overclosure h [m].
double law_pressure(const ContactModel& model, double overclosure);
// The overclosure [m] at a nominal pressure [Pa] > 0.
double law_overclosure(const ContactModel& model, double pressure);

inline constexpr double card_tolerance_min = 1e-6, card_tolerance_max = 0.1;
inline constexpr std::size_t card_points_max = 100000;

// Throws asperity::Error for a bad range or tolerance, or when more than card_points_max
// points would be needed. Points are rounded to the 13 significant digits the card carries
// before they are checked.
PressureOverclosureTable tabulate_pressure_overclosure(const ContactModel& model, double pressure_min,
                                                       double pressure_max, double tolerance);

// The card (or CSV), `description` (one line per '\n') as its comment header. Throws
// asperity::Error for a CalculiX card whose overclosures are closer than CalculiX keeps them
// (1e-10 in the card's length unit).
void write_pressure_overclosure(std::ostream& out, const PressureOverclosureTable& table, CardFormat format,
                                CardUnits units, const std::string& description);

// A curve given by its points (a tabulated law: the exact contact of a measured map, `asperity
// exact-contact`), in the same card: ascending in overclosure, the pressure never falling
// (points[0] may be the zero pressure at first contact); `notes` (one line per '\n') in the
// header where a law's card states its interpolation error. Points are rounded to the card's
// 13 digits. Throws asperity::Error for fewer than two points, a point not finite or of
// negative pressure, points out of order, or as write_pressure_overclosure does.
void write_tabulated_pressure_overclosure(std::ostream& out, const std::vector<PressureOverclosurePoint>& points,
                                          CardFormat format, CardUnits units, const std::string& description,
                                          const std::string& notes);

bool parse_card_format(const std::string& name, CardFormat& format);
bool parse_card_units(const std::string& name, CardUnits& units);

}  // namespace asperity
