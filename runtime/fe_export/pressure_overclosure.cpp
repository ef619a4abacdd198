#include "asperity/pressure_overclosure.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <sstream>

#include "asperity/error.hpp"

namespace asperity {
namespace {

// The cards carry 13 significant digits: CalculiX reads each field as 20 characters (f20.0),
// and "-1.234567890123e-05" is 19.
constexpr int card_digits = 13;

double round_to_card(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*e", card_digits - 1, value);
  return std::strtod(text, nullptr);
}

std::string card_number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", card_digits, value);
  return text;
}

std::string short_number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// The separation (origin convention) of an overclosure measured from the mean summit height.
double separation_of(const ContactModel& model, double overclosure) {
  const double origin_to_mean = -model.at_separation(0).mean_separation;
  return origin_to_mean - overclosure;
}

struct Node {
  double overclosure, pressure;
};

Node node_at(const ContactModel& model, double overclosure) {
  const double h = round_to_card(overclosure);
  return {h, round_to_card(law_pressure(model, h))};
}

// The largest relative error of the chord from a to b against the law, at `count` interior points.
double chord_error(const ContactModel& model, const Node& a, const Node& b, int count) {
  double worst = 0;
  for (int i = 1; i <= count; ++i) {
    const double fraction = static_cast<double>(i) / (count + 1);
    const double h = a.overclosure + fraction * (b.overclosure - a.overclosure);
    const double chord = a.pressure + fraction * (b.pressure - a.pressure);
    const double law = law_pressure(model, h);
    const double error = std::fabs(chord - law) / law;
    if (!(error <= worst)) worst = std::isnan(error) ? INFINITY : error;
  }
  return worst;
}

// Splits [a, b] at its middle (as the card rounds it); false if the card's digits cannot.
bool middle(const ContactModel& model, const Node& a, const Node& b, Node& mid) {
  mid = node_at(model, 0.5 * (a.overclosure + b.overclosure));
  return mid.overclosure > a.overclosure && mid.overclosure < b.overclosure;
}

[[noreturn]] void too_many_points(double tolerance) {
  std::ostringstream message;
  message << "the law needs more than " << card_points_max << " points for a tolerance of " << tolerance
          << ": give a larger tolerance or a narrower pressure range";
  throw Error(message.str());
}

}  // namespace

double law_pressure(const ContactModel& model, double overclosure) {
  return model.at_separation(separation_of(model, overclosure)).pressure;
}

double law_overclosure(const ContactModel& model, double pressure) {
  return -model.at_pressure(pressure).mean_separation;
}

PressureOverclosureTable tabulate_pressure_overclosure(const ContactModel& model, double pressure_min,
                                                       double pressure_max, double tolerance) {
  if (!(std::isfinite(pressure_min) && std::isfinite(pressure_max) && pressure_min > 0 && pressure_max > pressure_min))
    throw Error("the pressure range needs 0 < PMIN < PMAX, finite");
  if (!(tolerance >= card_tolerance_min && tolerance <= card_tolerance_max)) {
    std::ostringstream message;
    message << "the tolerance must be between " << card_tolerance_min << " and " << card_tolerance_max << ", got "
            << tolerance;
    throw Error(message.str());
  }
  const Node low = node_at(model, law_overclosure(model, pressure_min));
  const Node high = node_at(model, law_overclosure(model, pressure_max));
  if (!(std::isfinite(low.overclosure) && std::isfinite(high.overclosure) && low.pressure > 0 &&
        std::isfinite(high.pressure) && high.overclosure > low.overclosure))
    throw Error("the model gives no finite overclosure over this pressure range");

  // Place: bisect until the chord is within half the tolerance at 7 interior points.
  std::vector<Node> placed{low}, pending{high};  // pending: right ends still to reach, nearest last
  while (!pending.empty()) {
    const Node& a = placed.back();
    const Node b = pending.back();
    Node mid;
    if (chord_error(model, a, b, 7) <= 0.5 * tolerance || !middle(model, a, b, mid)) {
      placed.push_back(b);
      pending.pop_back();
    } else {
      pending.push_back(mid);
    }
    if (placed.size() + pending.size() > card_points_max) too_many_points(tolerance);
  }
  // Verify every interval at 32 interior points; split and check again where it fails.
  PressureOverclosureTable table;
  double worst = 0;
  long checked = 0;
  for (bool again = true; again;) {
    again = false;
    worst = 0;
    checked = 0;
    std::vector<Node> verified{placed.front()};
    for (std::size_t i = 1; i < placed.size(); ++i) {
      const Node& a = verified.back();
      const double error = chord_error(model, a, placed[i], 32);
      checked += 32;
      Node mid;
      if (error > 0.9 * tolerance && middle(model, a, placed[i], mid)) {
        verified.push_back(mid);
        again = true;
      }
      worst = std::max(worst, error);
      verified.push_back(placed[i]);
    }
    placed.swap(verified);
    if (placed.size() > card_points_max) too_many_points(tolerance);
  }
  if (!(worst <= tolerance)) {
    std::ostringstream message;
    message << "linear interpolation reaches a relative error of " << worst << " (asked " << tolerance
            << ") where 13 digits cannot place points closer";
    throw Error(message.str());
  }
  // Below pressure_min: the tangent at the first point, down to zero pressure.
  const PhysicalState first = model.at_separation(separation_of(model, low.overclosure));
  const double slope = first.stiffness / model.surface().nominal_area;  // dp/dh
  const double zero = round_to_card(low.overclosure - low.pressure / slope);
  if (!(std::isfinite(zero) && zero < low.overclosure))
    throw Error("the law's tangent at the lowest pressure does not reach zero pressure");
  table.points.push_back({0.0, zero});
  for (const Node& node : placed) table.points.push_back({node.pressure, node.overclosure});
  table.pressure_min = low.pressure;
  table.pressure_max = placed.back().pressure;
  table.tolerance = tolerance;
  table.max_error = worst;
  table.checked_points = checked;
  return table;
}

namespace {

// The card (or CSV) of `points`; `notes` (lines without the "** ") go after the units and the
// datum, where each kind of table states where its points come from.
void write_card(std::ostream& out, const std::vector<PressureOverclosurePoint>& points, CardFormat format,
                CardUnits units, const std::string& description, const std::string& notes) {
  const double length = units == CardUnits::mm ? 1e3 : 1.0;     // m -> mm
  const double pressure = units == CardUnits::mm ? 1e-6 : 1.0;  // Pa -> MPa = N/mm^2
  const char* length_unit = units == CardUnits::mm ? "mm" : "m";
  const char* pressure_unit = units == CardUnits::mm ? "MPa" : "Pa";
  if (format == CardFormat::calculix)
    for (std::size_t i = 1; i < points.size(); ++i)
      if ((points[i].overclosure - points[i - 1].overclosure) * length < 1e-10)
        throw Error(std::string("two overclosures are closer than 1e-10 ") + length_unit +
                    ", which CalculiX moves apart: write the card in mm (--units mm) or give a larger tolerance");
  if (format == CardFormat::csv) {
    out << "pressure_" << pressure_unit << ",overclosure_" << length_unit << "\n";
    for (const PressureOverclosurePoint& point : points)
      out << card_number(point.pressure * pressure) << "," << card_number(point.overclosure * length) << "\n";
    return;
  }
  std::istringstream lines(description);
  for (std::string line; std::getline(lines, line);) out << "** " << line << "\n";
  out << "** units: overclosure in " << length_unit << ", pressure in " << pressure_unit << "\n"
      << "** overclosure: interpenetration of the contact surfaces (a clearance is negative), measured\n"
      << "**   from the rough surface's mean summit height to the flat\n";
  std::istringstream note_lines(notes);
  for (std::string line; std::getline(note_lines, line);) out << "** " << line << "\n";
  if (format == CardFormat::calculix)
    out << "** beyond the last point CalculiX keeps the last pressure; node-to-face contact makes a contact\n"
        << "**   spring only within a clearance of 1e-3 sqrt(spring area) (ccx manual, *SURFACE BEHAVIOR)\n";
  else
    out << "** beyond the last point Abaqus continues the last slope\n";
  out << "*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=TABULAR\n";
  for (const PressureOverclosurePoint& point : points)
    out << card_number(point.pressure * pressure) << "," << card_number(point.overclosure * length) << "\n";
}

}  // namespace

void write_pressure_overclosure(std::ostream& out, const PressureOverclosureTable& table, CardFormat format,
                                CardUnits units, const std::string& description) {
  const double pressure = units == CardUnits::mm ? 1e-6 : 1.0;
  const char* pressure_unit = units == CardUnits::mm ? "MPa" : "Pa";
  std::ostringstream notes;
  notes << "from " << short_number(table.pressure_min * pressure) << " to "
        << short_number(table.pressure_max * pressure) << " " << pressure_unit
        << " linear interpolation between the points is within " << table.tolerance << "\n"
        << "  (relative, in pressure) of the law: measured " << table.max_error << " at most, at "
        << table.checked_points << " points\n"
        << "first point: zero pressure where the law's tangent at the lowest pressure reaches zero\n";
  write_card(out, table.points, format, units, description, notes.str());
}

void write_tabulated_pressure_overclosure(std::ostream& out, const std::vector<PressureOverclosurePoint>& points,
                                          CardFormat format, CardUnits units, const std::string& description,
                                          const std::string& notes) {
  if (points.size() < 2) throw Error("a tabulated pressure-overclosure curve needs at least two points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const PressureOverclosurePoint& point = points[i];
    if (!(std::isfinite(point.pressure) && std::isfinite(point.overclosure) && point.pressure >= 0))
      throw Error("a point of the pressure-overclosure curve is not finite, or its pressure is negative");
    if (i > 0 && !(point.overclosure > points[i - 1].overclosure && point.pressure >= points[i - 1].pressure))
      throw Error("the pressure-overclosure curve must rise in overclosure, its pressure never falling");
  }
  std::vector<PressureOverclosurePoint> rounded;
  for (const PressureOverclosurePoint& point : points)
    rounded.push_back({round_to_card(point.pressure), round_to_card(point.overclosure)});
  write_card(out, rounded, format, units, description, notes);
}

bool parse_card_format(const std::string& name, CardFormat& format) {
  if (name == "calculix") format = CardFormat::calculix;
  else if (name == "abaqus") format = CardFormat::abaqus;
  else if (name == "csv") format = CardFormat::csv;
  else return false;
  return true;
}

bool parse_card_units(const std::string& name, CardUnits& units) {
  if (name == "si") units = CardUnits::si;
  else if (name == "mm") units = CardUnits::mm;
  else return false;
  return true;
}

}  // namespace asperity
