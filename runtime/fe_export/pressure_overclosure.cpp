#include "asperity/pressure_overclosure.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
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

std::string short_number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// The mean summit height as an origin-convention separation [m] (asperity/separation_datum.hpp).
double mean_summit_position(const ContactModel& model) {
  return separation_datum_position(model.surface(), SeparationDatum::mean_summit, NAN);
}

// The separation (in the model's datum) of an overclosure measured from the mean summit height.
double separation_of(const ContactModel& model, double overclosure) {
  return (mean_summit_position(model) - overclosure) - model.datum_position();
}

struct Node {
  double overclosure, pressure;
};

// A law as the tabulation sees it, overclosures from the mean summit height: the nominal
// pressure at an overclosure, the overclosure at a pressure, dp/dh at an overclosure, and where
// the separation's origin is (the overclosure in the origin datum less that from the mean summit).
struct LawFunctions {
  std::function<double(double)> pressure, overclosure, slope;
  double origin_shift = 0;
  double mean_plane_shift = NAN;  // likewise for the mean plane; NaN: not known, no_mean_plane says why
  std::string no_mean_plane;
};

// The law in the card's datum: overclosure h in the datum is h - shift from the mean summit height.
struct DatumLaw {
  const LawFunctions& law;
  double shift;
  double pressure(double overclosure) const { return law.pressure(overclosure - shift); }
};

Node node_at(const DatumLaw& law, double overclosure) {
  const double h = round_to_card(overclosure);
  return {h, round_to_card(law.pressure(h))};
}

// The largest relative error of the chord from a to b against the law, at `count` interior points.
double chord_error(const DatumLaw& law, const Node& a, const Node& b, int count) {
  double worst = 0;
  for (int i = 1; i <= count; ++i) {
    const double fraction = static_cast<double>(i) / (count + 1);
    const double h = a.overclosure + fraction * (b.overclosure - a.overclosure);
    const double chord = a.pressure + fraction * (b.pressure - a.pressure);
    const double exact = law.pressure(h);
    const double error = std::fabs(chord - exact) / exact;
    if (!(error <= worst)) worst = std::isnan(error) ? INFINITY : error;
  }
  return worst;
}

// Splits [a, b] at its middle (as the card rounds it); false if the card's digits cannot.
bool middle(const DatumLaw& law, const Node& a, const Node& b, Node& mid) {
  mid = node_at(law, 0.5 * (a.overclosure + b.overclosure));
  return mid.overclosure > a.overclosure && mid.overclosure < b.overclosure;
}

struct Tabulation {
  std::vector<Node> placed;
  double worst = 0;
  long checked = 0;
};

// The next point after `a` toward `b` by bisection: b halved toward a until the chord is within
// 0.8 of the tolerance at 7 interior points (or the card's digits cannot split it).
Node bisected_next(const DatumLaw& law, const Node& a, Node b, double tolerance) {
  Node mid;
  while (!(chord_error(law, a, b, 7) <= 0.8 * tolerance) && middle(law, a, b, mid)) b = mid;
  return b;
}

// The farthest next point after `a` (toward `high`) whose chord is within 0.8 of the tolerance at 7
// interior points, from a first step `step` (in multiples of `unit`). A chord's error grows as the
// square of its step, so a step is rescaled by the square root of (target / error) until its error
// lies in [0.5, 0.8] of the tolerance; bisection leaves intervals anywhere in [0.2, 0.8] of it and needs about 1.3 times
// the rows (212 against 168 for the README's card at 1e-3). Bisection where 8 tries find no step.
Node next_point(const DatumLaw& law, const Node& a, const Node& high, double step, double unit, double tolerance) {
  Node best{};
  bool found = false;
  for (int attempt = 0; attempt < 8; ++attempt) {
    // no sliver before the range's end (CalculiX moves overclosures closer than 1e-10 apart): a step
    // that would leave less than half of itself there takes half of what is left instead
    const double left = high.overclosure - a.overclosure;
    if (step < left && left - step < 0.5 * step) step = 0.5 * left;
    // Steps are whole multiples of `unit` (2^-20 of the range), so that a law that differs by
    // rounding (the same surface from another separation datum) places the same points, as
    // bisection's did: a continuous step would carry that rounding into every point after.
    step = std::max(unit, std::round(step / unit) * unit);
    const bool last = a.overclosure + step >= high.overclosure;
    const Node b = last ? high : node_at(law, a.overclosure + step);
    if (!(b.overclosure > a.overclosure)) break;  // below the card's digits
    const double error = chord_error(law, a, b, 7);
    if (error <= 0.8 * tolerance) {
      best = b, found = true;
      if (last || error >= 0.5 * tolerance) break;
      step *= std::min(4.0, std::sqrt(0.65 * tolerance / std::max(error, 1e-300)));
    } else {
      if (found) break;  // a shorter step was within: keep it
      step *= std::isfinite(error) ? std::max(0.1, std::sqrt(0.65 * tolerance / error)) : 0.1;
    }
  }
  return found ? best : bisected_next(law, a, high, tolerance);
}

// Places points from low to high for `tolerance` and verifies them; false as soon as more than
// `limit` points would be needed.
bool tabulate_once(const DatumLaw& law, const Node& low, const Node& high, double tolerance, std::size_t limit,
                   Tabulation& result) {
  // Place (the verification below splits what exceeds 0.9 of the tolerance: 0.8 here leaves it
  // little to do)
  std::vector<Node> placed{low};
  const double unit = (high.overclosure - low.overclosure) / 1048576;
  double step = (high.overclosure - low.overclosure) / 16;
  while (placed.back().overclosure < high.overclosure) {
    const Node& a = placed.back();
    const Node b = next_point(law, a, high, step, unit, tolerance);
    step = b.overclosure - a.overclosure;
    placed.push_back(b);
    if (placed.size() > limit) return false;
  }
  // Verify every interval at 32 interior points; split and check again where it fails.
  double worst = 0;
  long checked = 0;
  for (bool again = true; again;) {
    again = false;
    worst = 0;
    checked = 0;
    std::vector<Node> verified{placed.front()};
    for (std::size_t i = 1; i < placed.size(); ++i) {
      const Node& a = verified.back();
      const double error = chord_error(law, a, placed[i], 32);
      checked += 32;
      Node mid;
      if (error > 0.9 * tolerance && middle(law, a, placed[i], mid)) {
        verified.push_back(mid);
        again = true;
      }
      worst = std::max(worst, error);
      verified.push_back(placed[i]);
    }
    placed.swap(verified);
    if (placed.size() > limit) return false;
  }
  result.placed = std::move(placed);
  result.worst = worst;
  result.checked = checked;
  return true;
}

// x rounded up to two significant digits (0.00231 -> 0.0024): a loosened tolerance to state.
double round_up_two_digits(double x) {
  const double scale = std::pow(10.0, std::floor(std::log10(x)) - 1);
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", std::ceil(x / scale * (1 - 1e-12)) * scale);
  return std::strtod(text, nullptr);  // 0.0012, not 0.0012000000000000001
}

// The smallest tolerance above `fails` (which does not fit) for which fits(tolerance), true at
// card_tolerance_max: by bisection in its logarithm, stated with two digits where those fit too.
// fits was last called with the tolerance returned.
template <class Fits>
double smallest_fitting_tolerance(double fails, Fits fits) {
  double fits_at = card_tolerance_max;
  while (fits_at / fails > 1.01) {
    const double mid = std::sqrt(fails * fits_at);
    if (fits(mid)) fits_at = mid;
    else fails = mid;
  }
  const double stated = std::min(round_up_two_digits(fits_at), card_tolerance_max);
  if (fits(stated)) return stated;
  fits(fits_at);
  return fits_at;
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

namespace {

PressureOverclosureTable tabulate_law(const LawFunctions& functions, double pressure_min, double pressure_max,
                                      double tolerance, OverclosureDatum datum, std::size_t max_points) {
  if (!(std::isfinite(pressure_min) && std::isfinite(pressure_max) && pressure_min > 0 && pressure_max > pressure_min))
    throw Error("the pressure range needs 0 < PMIN < PMAX, finite");
  if (!(tolerance >= card_tolerance_min && tolerance <= card_tolerance_max)) {
    std::ostringstream message;
    message << "the tolerance must be between " << card_tolerance_min << " and " << card_tolerance_max << ", got "
            << tolerance;
    throw Error(message.str());
  }
  if (!(max_points >= card_points_min && max_points <= card_points_max)) {
    std::ostringstream message;
    message << "the cap on the card's points must be from " << card_points_min << " to " << card_points_max
            << ", got " << max_points;
    throw Error(message.str());
  }
  const double low_mean = functions.overclosure(pressure_min), high_mean = functions.overclosure(pressure_max);
  if (!(std::isfinite(low_mean) && std::isfinite(high_mean) && high_mean > low_mean))
    throw Error("the model gives no finite overclosure over this pressure range");
  // Below pressure_min the card follows the law's tangent there down to zero pressure.
  const auto tangent_zero = [&](double overclosure_mean, double pressure) {
    return overclosure_mean - pressure / functions.slope(overclosure_mean);
  };
  double shift = 0;  // overclosure in the datum minus overclosure from the mean summit height
  if (datum == OverclosureDatum::origin) shift = functions.origin_shift;
  if (datum == OverclosureDatum::mean_plane) {
    if (std::isnan(functions.mean_plane_shift)) throw Error(functions.no_mean_plane);
    shift = functions.mean_plane_shift;
  }
  if (datum == OverclosureDatum::zero_pressure) shift = -tangent_zero(low_mean, pressure_min);
  if (!std::isfinite(shift)) throw Error("the model gives no finite datum for the overclosure");
  const DatumLaw law{functions, shift};
  // The range's ends: the pressures asked, at the law's overclosures.
  const Node low{round_to_card(low_mean + shift), round_to_card(pressure_min)};
  const Node high{round_to_card(high_mean + shift), round_to_card(pressure_max)};
  if (!(std::isfinite(low.overclosure) && std::isfinite(high.overclosure) && high.overclosure > low.overclosure))
    throw Error("the model gives no finite overclosure over this pressure range");

  const std::size_t limit = max_points - 1;  // the zero-pressure point is a row too
  Tabulation result;
  double met = tolerance;
  if (!tabulate_once(law, low, high, tolerance, limit, result)) {
    if (max_points == card_points_max) too_many_points(tolerance);
    if (!tabulate_once(law, low, high, card_tolerance_max, limit, result)) {
      std::ostringstream message;
      message << "the law needs more than " << max_points << " points even for a tolerance of " << card_tolerance_max
              << ": allow more points or give a narrower pressure range";
      throw Error(message.str());
    }
    met = smallest_fitting_tolerance(tolerance, [&](double trial) {
      return tabulate_once(law, low, high, trial, limit, result);
    });
  }
  if (!(result.worst <= met)) {
    std::ostringstream message;
    message << "linear interpolation reaches a relative error of " << result.worst << " (asked " << met
            << ") where 13 digits cannot place points closer";
    throw Error(message.str());
  }
  const double zero = datum == OverclosureDatum::zero_pressure
                          ? 0.0
                          : round_to_card(tangent_zero(low.overclosure - shift, low.pressure) + shift);
  if (!(std::isfinite(zero) && zero < low.overclosure))
    throw Error("the law's tangent at the lowest pressure does not reach zero pressure");
  PressureOverclosureTable table;
  table.points.push_back({0.0, zero});
  for (const Node& node : result.placed) table.points.push_back({node.pressure, node.overclosure});
  table.pressure_min = low.pressure;
  table.pressure_max = high.pressure;
  table.tolerance = met;
  table.asked_tolerance = tolerance;
  table.max_points = max_points;
  table.max_error = result.worst;
  table.checked_points = result.checked;
  table.datum = datum;
  table.mean_summit_overclosure = shift;
  return table;
}

}  // namespace

PressureOverclosureTable tabulate_pressure_overclosure(const ContactModel& model, double pressure_min,
                                                       double pressure_max, double tolerance, OverclosureDatum datum,
                                                       std::size_t max_points) {
  LawFunctions law;
  law.pressure = [&](double overclosure) { return law_pressure(model, overclosure); };
  law.overclosure = [&](double pressure) { return law_overclosure(model, pressure); };
  law.slope = [&](double overclosure) {  // dp/dh
    return model.at_separation(separation_of(model, overclosure)).stiffness / model.surface().nominal_area;
  };
  law.origin_shift = -mean_summit_position(model);  // the separation's origin, whatever the model's datum
  if (model.datum() == SeparationDatum::mean_plane)
    law.mean_plane_shift = -model.mean_summit_height();  // the flat at the mean summit is that far from the mean plane
  law.no_mean_plane =
      "the mean-plane overclosure datum needs the mean summit height above the mean plane: make the model with the "
      "mean-plane separation datum and that height";
  return tabulate_law(law, pressure_min, pressure_max, tolerance, datum, max_points);
}

PressureOverclosureTable tabulate_pressure_overclosure(const ContactCurves& curves, double pressure_min,
                                                       double pressure_max, double tolerance, OverclosureDatum datum,
                                                       std::size_t max_points) {
  if (curves.has_tension())
    throw Error("adhesive contact curves carry tension, which a pressure-overclosure card cannot hold");
  const double summit = curves.data().mean_summit_height;
  if (std::isnan(summit) && datum == OverclosureDatum::mean_summit)
    throw Error("the contact curves state no mean summit height: give the overclosure datum origin or zero-pressure");
  const double from = std::isnan(summit) ? 0.0 : summit;  // overclosure from here: -(u - from)
  if (!(pressure_min >= curves.min_pressure() && pressure_max <= curves.max_pressure())) {
    std::ostringstream message;
    message << "the contact curves serve pressures from " << curves.min_pressure() << " to " << curves.max_pressure()
            << " Pa: the card's range must lie within them";
    throw Error(message.str());
  }
  // The card's 13 digits may put the range's ends a hair outside the curves: those are their ends.
  const double low_u = curves.min_separation(), high_u = curves.max_separation(), hair = 1e-9 * (high_u - low_u);
  const auto separation = [=](double overclosure) {
    const double u = from - overclosure;
    return u < low_u && u > low_u - hair ? low_u : u > high_u && u < high_u + hair ? high_u : u;
  };
  LawFunctions law;
  law.pressure = [&](double overclosure) { return curves.pressure(separation(overclosure)); };
  law.overclosure = [&](double pressure) { return from - curves.separation_at_pressure(pressure); };
  law.slope = [&](double overclosure) { return curves.stiffness(separation(overclosure)); };  // dp/dh = -dp/du
  law.origin_shift = -from;  // the origin datum: overclosure -u, from the separation's datum
  // The curves name their separation's datum in words only: overclosure from it is the origin datum.
  law.no_mean_plane = "contact curves take the overclosure datums mean-summit, origin (their separation's datum: " +
                      curves.data().separation_datum + ") and zero-pressure, not mean-plane";
  PressureOverclosureTable table = tabulate_law(law, pressure_min, pressure_max, tolerance, datum, max_points);
  table.origin = curves.data().separation_datum;
  return table;
}

std::string card_number(double value) {
  const double rounded = round_to_card(value);
  // Fixed ("1000000", "0.0002") where that takes at most 20 characters with 13 digits, else
  // scientific ("1e-07"); either way the fewest digits that read back to `rounded`.
  const double magnitude = std::fabs(rounded);
  const bool fixed = rounded == 0 || (magnitude >= 1e-5 && magnitude < 1e15);
  char text[64];
  const std::to_chars_result result = std::to_chars(
      text, text + sizeof text, rounded, fixed ? std::chars_format::fixed : std::chars_format::scientific);
  return std::string(text, result.ptr);
}

double card_length_unit(CardUnits units) { return units == CardUnits::mm ? 1e-3 : 1.0; }

std::string calculix_cutoff_warning(const std::vector<PressureOverclosurePoint>& points, double face_size,
                                    CardUnits units) {
  if (!std::isfinite(face_size) || points.empty()) return std::string();
  const double clearance = -points.front().overclosure, cutoff = calculix_spring_cutoff_per_root_area * face_size;
  if (!(clearance > cutoff)) return std::string();
  // the card's pressure at overclosure -cutoff: its linear interpolation, as CalculiX reads it
  double at_cutoff = points.back().pressure;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (-cutoff <= points[i].overclosure) {
      const PressureOverclosurePoint &a = points[i - 1], &b = points[i];
      at_cutoff = a.pressure + (-cutoff - a.overclosure) / (b.overclosure - a.overclosure) * (b.pressure - a.pressure);
      break;
    }
  const double length = 1.0 / card_length_unit(units), pressure = units == CardUnits::mm ? 1e6 : 1.0;
  const std::string length_unit = units == CardUnits::mm ? " mm" : " m";
  std::ostringstream text;
  text << "the card reaches a clearance of " << short_number(clearance * length) << length_unit
       << ", but CalculiX's node-to-surface\n  contact makes a contact spring only within a clearance of 1e-3 sqrt(A)\n"
          "  (A the slave node's area) = " << short_number(cutoff * length) << length_unit << " for faces of "
       << short_number(face_size * length) << length_unit << " (less at the mesh's edges):\n  below "
       << short_number(at_cutoff / pressure) << (units == CardUnits::mm ? " MPa" : " Pa")
       << " the card never acts and contact starts at that pressure in one increment";
  return text.str();
}

namespace {

// The card (or CSV) of `points` (SI); `datum` (lines without the "** ") says where overclosure
// is measured from; `notes` go after it, where each kind of table states where its points come
// from.
void write_card(std::ostream& out, const std::vector<PressureOverclosurePoint>& points, CardFormat format,
                CardUnits units, const std::string& description, const std::string& datum, const std::string& notes,
                double face_size) {
  const double length = units == CardUnits::mm ? 1e3 : 1.0;     // m -> mm
  const double pressure = units == CardUnits::mm ? 1e6 : 1.0;   // Pa -> MPa = N/mm^2 (divided: 1e8 Pa is 100 MPa)
  const char* length_unit = units == CardUnits::mm ? "mm" : "m";
  const char* pressure_unit = units == CardUnits::mm ? "MPa" : "Pa";
  if (format == CardFormat::calculix)
    for (std::size_t i = 1; i < points.size(); ++i)
      if ((points[i].overclosure - points[i - 1].overclosure) * length < 1e-10)
        throw Error(std::string("two overclosures are closer than 1e-10 ") + length_unit +
                    ", which CalculiX moves apart: write the card in mm (--units mm) or give a larger tolerance");
  const auto row = [&](const PressureOverclosurePoint& point) {
    out << card_number(point.pressure / pressure) << "," << card_number(point.overclosure * length) << "\n";
  };
  if (format == CardFormat::csv) {
    out << "pressure_" << pressure_unit << ",overclosure_" << length_unit << "\n";
    for (const PressureOverclosurePoint& point : points) row(point);
    return;
  }
  const auto comment = [&](const std::string& text) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) out << "** " << line << "\n";
  };
  comment(description);
  out << "** units: overclosure in " << length_unit << ", pressure in " << pressure_unit << "\n"
      << "** overclosure: interpenetration of the contact surfaces (a clearance is negative), measured\n";
  comment(datum);
  comment(notes);
  if (format == CardFormat::calculix) {
    const double clearance = points.empty() ? 0.0 : -points.front().overclosure * length;
    out << "** CalculiX: use this card with node-to-surface contact (*CONTACT PAIR, TYPE=NODE TO SURFACE),\n"
        << "**   which holds at most 200 points. Face-to-face contact (ccx 2.20) does not work with it: above\n"
        << "**   41 points ccx crashes, and it starts contact only at positive overclosure, so clearances give\n"
        << "**   zero force, silently.\n"
        << "** node-to-surface contact makes a contact spring only where the clearance is below 1e-3 sqrt(A),\n"
        << "**   A the slave node's area (1e-3 L for faces of edge L);\n";
    if (clearance > 0)
      out << "**   this card reaches a clearance of " << card_number(clearance) << " " << length_unit
          << ": beyond the cut-off its pressures never act\n";
    else
      out << "**   this card has no clearance (every overclosure >= 0): the cut-off never matters\n";
    const std::string cutoff = calculix_cutoff_warning(points, face_size, units);
    if (!cutoff.empty()) comment("  WARNING: " + cutoff);
    else if (clearance > 0 && std::isfinite(face_size))
      out << "**   for faces of edge " << card_number(face_size * length) << " " << length_unit << " (cut-off "
          << card_number(calculix_spring_cutoff_per_root_area * face_size * length) << " " << length_unit
          << " at interior nodes) the whole card acts\n";
    out << "** beyond the last point CalculiX keeps the last pressure\n";
  } else {
    out << "** beyond the last point Abaqus continues the last slope\n";
  }
  out << "*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=TABULAR\n";
  for (const PressureOverclosurePoint& point : points) row(point);
}

const char* mean_summit_datum = "  from the rough surface's mean summit height to the flat";

// A curve given by its points, checked (see write_tabulated_pressure_overclosure) and rounded to
// the card's 13 digits.
std::vector<PressureOverclosurePoint> rounded_curve(const std::vector<PressureOverclosurePoint>& points) {
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
  return rounded;
}

// Where the card's overclosure is zero, as its header says; the flat at the mean summit height
// is at mean_summit_overclosure in it (NaN: no mean summit height, nothing said).
// `origin`: the separation's origin in words where it is not the model's (contact curves'), or empty.
std::string datum_text(OverclosureDatum datum_kind, double mean_summit_overclosure, CardUnits units,
                       const std::string& origin = std::string()) {
  const double length = units == CardUnits::mm ? 1e3 : 1.0;
  const char* length_unit = units == CardUnits::mm ? "mm" : "m";
  std::ostringstream datum;
  const bool known = std::isfinite(mean_summit_overclosure);
  const std::string mean_at =
      known ? "  (the flat at the mean summit height is at overclosure " +
                  card_number(mean_summit_overclosure * length) + " " + length_unit + ")"
            : std::string();
  if (datum_kind == OverclosureDatum::mean_summit)
    datum << mean_summit_datum << " (--overclosure-datum mean-summit)";
  else if (datum_kind == OverclosureDatum::mean_plane) {
    datum << "  from the mean plane of the surface heights to the flat (--overclosure-datum mean-plane";
    if (known)
      datum << "; the mean\n  summit height is " << card_number(-mean_summit_overclosure * length) << " " << length_unit
            << " above it)\n"
            << mean_at;
    else
      datum << ")";
  } else if (datum_kind == OverclosureDatum::origin && !origin.empty())
    datum << "  from the origin of the separation (" << origin << ") to the flat\n"
          << "  (--overclosure-datum origin)\n"
          << mean_at;
  else if (datum_kind == OverclosureDatum::origin)
    datum << "  from the origin of the separation (the Weibull origin: its lowest summit on the tail side, its\n"
          << "  highest on the bounded side; the Gaussian's mean) to the flat (--overclosure-datum origin)\n"
          << mean_at;
  else
    datum << "  from where the card's pressure reaches zero, its first point (--overclosure-datum zero-pressure,\n"
          << "  the default): start the FE model with the surfaces touching\n"
          << mean_at;
  return datum.str();
}

}  // namespace

void write_pressure_overclosure(std::ostream& out, const PressureOverclosureTable& table, CardFormat format,
                                CardUnits units, const std::string& description, double face_size) {
  const double pressure = units == CardUnits::mm ? 1e6 : 1.0;
  const char* pressure_unit = units == CardUnits::mm ? "MPa" : "Pa";
  const std::string datum = datum_text(table.datum, table.mean_summit_overclosure, units, table.origin);
  std::ostringstream notes;
  notes << "from " << short_number(table.pressure_min / pressure) << " to " << short_number(table.pressure_max / pressure)
        << " " << pressure_unit << " linear interpolation between the points is within " << table.tolerance << "\n"
        << "  (relative, in pressure) of the law: measured " << table.max_error << " at most, at "
        << table.checked_points << " points\n";
  if (table.tolerance != table.asked_tolerance)
    notes << "  (tolerance " << table.asked_tolerance << " asked, loosened to fit at most " << table.max_points
          << " points)\n";
  notes << "first point: zero pressure where the law's tangent at the lowest pressure reaches zero\n";
  write_card(out, table.points, format, units, description, datum, notes.str(), face_size);
}

void write_tabulated_pressure_overclosure(std::ostream& out, const std::vector<PressureOverclosurePoint>& points,
                                          CardFormat format, CardUnits units, const std::string& description,
                                          const std::string& notes) {
  write_card(out, rounded_curve(points), format, units, description, mean_summit_datum, notes, NAN);
}

namespace {
// The indices of the points kept for `tolerance`: from each kept point, the farthest point whose
// chord is within it of every point between (greedy); the largest error of a dropped point in `worst`.
std::vector<std::size_t> kept_points(const std::vector<PressureOverclosurePoint>& points, double tolerance,
                                     double& worst) {
  const auto error = [&](std::size_t a, std::size_t b, std::size_t k) {
    const PressureOverclosurePoint &p = points[a], &q = points[b];
    const double fraction = (points[k].overclosure - p.overclosure) / (q.overclosure - p.overclosure);
    const double chord = p.pressure + fraction * (q.pressure - p.pressure);
    return std::fabs(chord - points[k].pressure) / points[k].pressure;  // k > 0: a positive pressure
  };
  std::vector<std::size_t> kept{0};
  worst = 0;
  while (kept.back() + 1 < points.size()) {
    const std::size_t a = kept.back();
    std::size_t b = a + 1;
    double b_worst = 0;
    for (std::size_t next = a + 2; next < points.size(); ++next) {
      double next_worst = 0;
      for (std::size_t k = a + 1; k < next && next_worst <= tolerance; ++k)
        next_worst = std::max(next_worst, error(a, next, k));
      if (!(next_worst <= tolerance)) break;
      b = next;
      b_worst = next_worst;
    }
    kept.push_back(b);
    worst = std::max(worst, b_worst);
  }
  return kept;
}
}  // namespace

TabulatedCard tabulate_points(const std::vector<PressureOverclosurePoint>& points, std::size_t max_points,
                              OverclosureDatum datum, double mean_summit_overclosure) {
  if (!(max_points >= card_points_min && max_points <= card_points_max)) {
    std::ostringstream message;
    message << "the card's rows must be capped at " << card_points_min << " to " << card_points_max << ", got "
            << max_points;
    throw Error(message.str());
  }
  const std::vector<PressureOverclosurePoint> rounded = rounded_curve(points);
  TabulatedCard card;
  card.given_points = rounded.size();
  card.max_points = max_points;
  card.datum = datum;
  card.mean_summit_overclosure = mean_summit_overclosure;
  if (rounded.size() <= max_points) {
    card.points = rounded;
    return card;
  }
  std::vector<std::size_t> kept;
  double worst = 0;
  const auto fits = [&](double tolerance) {
    kept = kept_points(rounded, tolerance, worst);
    return kept.size() <= max_points;
  };
  if (!fits(card_tolerance_max)) {
    std::ostringstream message;
    message << "the curve's " << rounded.size() << " points need more than " << max_points
            << " rows even where linear interpolation may miss the dropped ones by " << card_tolerance_max
            << ": allow more rows or give fewer points";
    throw Error(message.str());
  }
  card.tolerance = fits(card_tolerance_min) ? card_tolerance_min : smallest_fitting_tolerance(card_tolerance_min, fits);
  card.max_error = worst;
  for (std::size_t index : kept) card.points.push_back(rounded[index]);
  return card;
}

void write_tabulated_pressure_overclosure(std::ostream& out, const TabulatedCard& card, CardFormat format,
                                          CardUnits units, const std::string& description, const std::string& notes,
                                          double face_size) {
  std::ostringstream all_notes;
  all_notes << notes;
  if (card.points.size() < card.given_points)
    all_notes << (notes.empty() || notes.back() == '\n' ? "" : "\n") << "rows: " << card.points.size()
              << " of the curve's " << card.given_points << " points (at most " << card.max_points
              << "): linear interpolation between\n  the rows is within " << card.tolerance
              << " (relative, in pressure) of the points dropped: measured " << card.max_error << " at most";
  write_card(out, rounded_curve(card.points), format, units, description,
             datum_text(card.datum, card.mean_summit_overclosure, units), all_notes.str(), face_size);
}

// The separation datums' names are separation_datum.hpp's; zero-pressure is the card's own.
bool parse_overclosure_datum(const std::string& name, OverclosureDatum& datum) {
  SeparationDatum separation_datum;
  if (name == "zero-pressure") datum = OverclosureDatum::zero_pressure;
  else if (!parse_separation_datum(name, separation_datum)) return false;
  else if (separation_datum == SeparationDatum::origin) datum = OverclosureDatum::origin;
  else if (separation_datum == SeparationDatum::mean_plane) datum = OverclosureDatum::mean_plane;
  else datum = OverclosureDatum::mean_summit;
  return true;
}

const char* datum_name(OverclosureDatum datum) {
  switch (datum) {
    case OverclosureDatum::origin: return separation_datum_name(SeparationDatum::origin);
    case OverclosureDatum::mean_plane: return separation_datum_name(SeparationDatum::mean_plane);
    case OverclosureDatum::zero_pressure: return "zero-pressure";
    case OverclosureDatum::mean_summit: break;
  }
  return separation_datum_name(SeparationDatum::mean_summit);
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
