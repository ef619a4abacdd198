// FE export: a rough surface's contact-pressure law as the tabular pressure-overclosure card of
// CalculiX and Abaqus (*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR), or as CSV.
//
// Overclosure, as both codes define it, is the interpenetration of the two contact surfaces
// (positive when they overlap; a clearance is a negative overclosure). The flat's surface and a
// datum of the rough surface are the FE surfaces: in the interfaces by default the card's own first point (zero
// pressure: the whole card lies at overclosure >= 0, so a mesh whose surfaces start touching sees
// all of it, whatever its faces' size: CalculiX's contact-spring cut-off below); or its mean
// summit height (GW's and McCool's datum), overclosure h = -(separation of the flat from the mean
// summit height); or the origin of the separation (docs/model.md section 2). The nominal pressure
// at h is the model's at that separation.
//
// Points are placed by bisection in h until linear interpolation between neighbours is within
// `tolerance` (relative, in pressure) of the law at every checked point, from pressure_min to
// pressure_max; then every interval is checked again at 32 interior points. Below pressure_min
// the table follows the law's tangent at pressure_min down to zero pressure (its first point):
// the law itself falls off smoothly there and never reaches zero on the tail side. Beyond the
// last point Abaqus continues the last slope and CalculiX keeps the last pressure: give a
// pressure_max above what the analysis reaches.
#pragma once
#include <cmath>
#include <iosfwd>
#include <string>
#include <vector>

#include "asperity/contact_curves.hpp"
#include "asperity/contact_model.hpp"

namespace asperity {

enum class CardFormat { calculix, abaqus, csv };
enum class CardUnits { si, mm };  // overclosure in m and pressure in Pa, or mm and MPa (N/mm^2)
// Where zero overclosure is: the flat at the mean summit height (these functions' default, kept
// for existing callers), at the separation's origin (the Weibull origin, the Gaussian's mean),
// where the card's pressure reaches zero (the interfaces' default: the command line, Python's
// and the C API's *_card_options functions), or at
// the mean plane (a model made with SeparationDatum::mean_plane: it knows the mean summit height
// above the plane). The first, second and last are asperity/separation_datum.hpp's datums.
enum class OverclosureDatum { mean_summit, origin, zero_pressure, mean_plane };

struct PressureOverclosurePoint {
  double pressure;     // Pa
  double overclosure;  // m
};

struct PressureOverclosureTable {
  std::vector<PressureOverclosurePoint> points;  // ascending in overclosure; points[0] at zero pressure
  double pressure_min = 0, pressure_max = 0;     // Pa: the range within tolerance
  double tolerance = 0;                          // the one met: asked, or loosened to fit max_points
  double asked_tolerance = 0;                    // asked
  std::size_t max_points = 0;                    // the cap on the rows asked
  double max_error = 0;                          // measured, relative in pressure
  long checked_points = 0;                       // where it was measured
  OverclosureDatum datum = OverclosureDatum::zero_pressure;
  double mean_summit_overclosure = 0;  // m: the overclosure (in this datum) of the flat at the mean summit height
  std::string origin;  // the separation's origin in words, where it is not the model's (contact curves')
};

// The law the table follows: the nominal pressure [Pa] at overclosure h [m] from the mean summit height.
double law_pressure(const ContactModel& model, double overclosure);
// The overclosure [m] from the mean summit height at a nominal pressure [Pa] > 0.
double law_overclosure(const ContactModel& model, double pressure);

inline constexpr double card_tolerance_min = 1e-6, card_tolerance_max = 0.1;
inline constexpr std::size_t card_points_max = 100000, card_points_min = 3;

// Throws asperity::Error for a bad range or tolerance, or when more than card_points_max
// points would be needed. Points are rounded to the 13 significant digits the card carries
// before they are checked. The range's ends are the pressures asked (their overclosures the
// law's). With max_points (card_points_min to card_points_max) the card has at most that many
// rows (the zero-pressure point counted): when the tolerance asked needs more, the tolerance is
// loosened to the smallest that fits (table.tolerance; found by bisection in its logarithm);
// Error when even card_tolerance_max does not fit.
PressureOverclosureTable tabulate_pressure_overclosure(const ContactModel& model, double pressure_min,
                                                       double pressure_max, double tolerance,
                                                       OverclosureDatum datum = OverclosureDatum::mean_summit,
                                                       std::size_t max_points = card_points_max);

// The same card from contact curves against separation (a measured surface's table,
// contact_curves.hpp): the law is the curves' served pressure, overclosure from the mean summit
// height (ContactCurvesData::mean_summit_height; without one only the origin and zero-pressure
// datums), origin: the separation's datum. Throws Error as above, for a pressure range
// beyond the one the curves serve, and for adhesive curves (tension: ContactCurves::has_tension).
PressureOverclosureTable tabulate_pressure_overclosure(const ContactCurves& curves, double pressure_min,
                                                       double pressure_max, double tolerance,
                                                       OverclosureDatum datum = OverclosureDatum::mean_summit,
                                                       std::size_t max_points = card_points_max);

// CalculiX's node-to-surface contact makes a contact spring at a slave node only where its
// clearance is below 1e-3 sqrt(A), A the slave node's area (ccx 2.20, gencontelem_n2f.f, for
// linear and tabular pressure-overclosure; measured: tests/fe_export_calculix.py). For faces
// of edge L an interior node's area is L^2: the cut-off is 1e-3 L (at the mesh's edges and
// corners 1e-3 L / sqrt(2) and 1e-3 L / 2).
inline constexpr double calculix_spring_cutoff_per_root_area = 1e-3;
// CalculiX's node-to-surface spring reads a tabular law into arrays of 200 points (ccx source,
// springforc_n2f.f: xiso(200), yiso(200)): a longer card runs past them. Face-to-face contact
// reads 41 (springforc_f2f.f: an 82-entry plconloc) and crashes beyond.
inline constexpr std::size_t calculix_points_max = 200;
// The cap on a card's rows where none is asked (every interface's default): calculix_points_max
// for CalculiX, card_points_max for Abaqus and CSV.
inline std::size_t default_card_points(CardFormat format) {
  return format == CardFormat::calculix ? calculix_points_max : card_points_max;
}

// The card's length unit in metres: 1 (si) or 1e-3 (mm). Lengths given with a card (face_size)
// are in its unit.
double card_length_unit(CardUnits units);

// For CalculiX: what of a card (rows in SI, ascending) never acts in node-to-surface contact with
// slave faces of edge face_size [m] (interior nodes: cut-off 1e-3 face_size): empty when the
// card's clearance is within the cut-off, else one sentence with the lengths and pressures in
// the card's units (the clearance, the cut-off, and the card's pressure at the cut-off, below
// which it never acts). face_size NaN: empty.
std::string calculix_cutoff_warning(const std::vector<PressureOverclosurePoint>& points, double face_size,
                                    CardUnits units);

// The card (or CSV), `description` (one line per '\n') as its comment header. Throws
// asperity::Error for a CalculiX card whose overclosures are closer than CalculiX keeps them
// (1e-10 in the card's length unit). face_size [m] (NaN: not given): a CalculiX card's header
// states calculix_cutoff_warning for it, or that the cut-off covers the card.
void write_pressure_overclosure(std::ostream& out, const PressureOverclosureTable& table, CardFormat format,
                                CardUnits units, const std::string& description, double face_size = NAN);

// A curve given by its points (a tabulated law: the exact contact of a measured map, `asperity
// exact-contact`), in the same card: ascending in overclosure, the pressure never falling
// (points[0] may be the zero pressure at first contact); `notes` (one line per '\n') in the
// header where a law's card states its interpolation error. Points are rounded to the card's
// 13 digits. Throws asperity::Error for fewer than two points, a point not finite or of
// negative pressure, points out of order, or as write_pressure_overclosure does.
void write_tabulated_pressure_overclosure(std::ostream& out, const std::vector<PressureOverclosurePoint>& points,
                                          CardFormat format, CardUnits units, const std::string& description,
                                          const std::string& notes);

// A tabulated curve's card with the law's card options (`asperity exact-contact`): the points
// in the card's datum, of which at most max_points are kept. When the curve has more, points are
// dropped (greedily, from the first) where linear interpolation between the kept neighbours is
// within a tolerance (relative, in pressure) of them; the tolerance is the smallest that fits,
// found as tabulate_pressure_overclosure loosens the law's. The first and last points are kept.
struct TabulatedCard {
  std::vector<PressureOverclosurePoint> points;  // the card's rows (rounded to its 13 digits), in `datum`
  std::size_t given_points = 0;                  // the curve's points
  std::size_t max_points = 0;                    // the cap asked
  double tolerance = 0;                          // 0: every point kept; else the dropped points are within it
  double max_error = 0;                          // measured at the dropped points (relative, in pressure)
  OverclosureDatum datum = OverclosureDatum::mean_summit;
  double mean_summit_overclosure = 0;  // m: the flat at the mean summit height, in this datum (NaN: none)
};

// Throws asperity::Error as write_tabulated_pressure_overclosure does for the points, for a cap
// outside [card_points_min, card_points_max], or when even card_tolerance_max needs more rows.
TabulatedCard tabulate_points(const std::vector<PressureOverclosurePoint>& points, std::size_t max_points,
                              OverclosureDatum datum, double mean_summit_overclosure);
// Its card: the header states the datum as the law's card does, `notes`, and the points dropped.
void write_tabulated_pressure_overclosure(std::ostream& out, const TabulatedCard& card, CardFormat format,
                                          CardUnits units, const std::string& description, const std::string& notes,
                                          double face_size = NAN);

bool parse_card_format(const std::string& name, CardFormat& format);
bool parse_card_units(const std::string& name, CardUnits& units);
bool parse_overclosure_datum(const std::string& name, OverclosureDatum& datum);
const char* datum_name(OverclosureDatum datum);  // "mean-summit", "origin", "zero-pressure", "mean-plane"

// A card's number: rounded to the card's 13 significant digits, then the shortest text that
// reads back to that double ("1000000", "0.0002", "-1.5e-07"; never "999999.9999996" for the 1e6
// asked); fixed from 1e-5 to 1e15, scientific beyond: at most 20 characters, what CalculiX reads
// a field.
std::string card_number(double value);

}  // namespace asperity
