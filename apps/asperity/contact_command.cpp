#include "contact_command.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/contact_curves.hpp"
#include "asperity/contact_law.hpp"
#include "asperity/contact_law_registry.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/generator/law_curves.hpp"
#include "asperity/scene.hpp"
#include "asperity/table_file.hpp"
#include "asperity/error.hpp"
#include "command_line.hpp"
#include "option_helpers.hpp"
#include "fe_card_options.hpp"
#include "law_options.hpp"
#include "asperity/number_text.hpp"
#include "asperity/plausibility.hpp"
#include "asperity/pressure_overclosure.hpp"
#include "asperity/separation_datum.hpp"

namespace asperity::cli {
namespace {

constexpr double not_given = NAN;  // add_number only ever stores finite numbers

struct Options {
  std::string table, dist, side, moments, sweep, export_format, pressure_range, units, overclosure_datum, datum;
  LawOptions law;         // a contact law's curves, tabulated on the fly (docs/contact-laws.md section 8)
  std::string law_range;  // the separations they are tabulated over
  double shape = not_given, sigma = not_given, rms = not_given, radius = not_given, density = not_given,
         count = not_given, area = not_given;
  MaterialOptions material;  // --modulus, or --e1 --nu1 --e2 --nu2
  std::vector<double> separations, loads, pressures, real_areas;  // the queries (lists); empty: not given
  double export_tolerance = not_given, face_size = not_given, mean_summit_height = not_given;
  long long max_points = 0;  // 0: not given
};

std::string number(double value) { return format_double(value); }

// What a card from `--export` states on standard error: a tolerance loosened to fit --max-points
// (a warning), then its points, how closely they follow `what` (the law, the served curve) over
// [low, high] Pa, and the datum.
void state_card(const CLI::App& command, const PressureOverclosureTable& table, double tolerance,
                std::size_t max_points, double low, double high, OverclosureDatum datum, const std::string& what) {
  if (table.tolerance != tolerance)
    warn(command, "the tolerance " + number(tolerance) + " needs more than " + std::to_string(max_points) +
                      " points: the card is within " + number(table.tolerance) + " of " + what +
                      " instead (--max-points)");
  note(command, std::to_string(table.points.size()) + " points; linear interpolation within " +
                    number(table.tolerance) + " of " + what + " from " + number(low) + " to " + number(high) +
                    " Pa (measured at most " + approximately(table.max_error) + " at " +
                    std::to_string(table.checked_points) + " points); overclosure from the " + datum_name(datum) +
                    " datum");
}

// The surface from the options; `given_scale` says which height scale was given and the other.
RoughSurface surface_from(const Options& options, std::string& given_scale) {
  RoughSurface surface;
  if (options.dist.empty()) throw CLI::RequiredError("--dist");
  if (!parse_distribution(options.dist, surface.distribution))
    usage("--dist: '" + quote_text(options.dist) + "' is not weibull or gaussian");
  if (!options.side.empty() && !parse_side(options.side, surface.side))
    usage("--side: '" + quote_text(options.side) + "' is not tail or bounded");
  const bool weibull = surface.distribution == Distribution::weibull;
  if (weibull && !given(options.shape))
    usage("--shape A is required for a Weibull surface (" + format_double(weibull_shape_min) + " <= A <= " +
          format_double(weibull_shape_max) + ")");
  if (!weibull && given(options.shape)) usage("--shape is the Weibull shape: a Gaussian surface has none");
  if (weibull) surface.shape = options.shape;

  if (!given(options.area)) throw CLI::RequiredError("--area");
  surface.nominal_area = options.area;
  surface.contact_modulus = options.material.contact_modulus();
  if (!given(surface.contact_modulus)) usage("give the contact modulus: --modulus, or --e1 --nu1 --e2 --nu2");

  if (!options.moments.empty()) {
    if (weibull) usage("--moments describe a Gaussian surface (--dist gaussian)");
    if (given(options.sigma) || given(options.rms) || given(options.radius) || given(options.density) ||
        given(options.count))
      usage("--moments set sigma, the radius and the density: give none of --sigma --rms --radius --density --count");
    const std::vector<std::string> parts = split(options.moments, ',');
    if (parts.size() != 3) usage("--moments wants M0,M2,M4, got '" + quote_text(options.moments) + "'");
    const RoughSurface from = gaussian_surface_from_moments(
        number_from_text(parts[0], "--moments M0"), number_from_text(parts[1], "--moments M2"),
        number_from_text(parts[2], "--moments M4"), surface.nominal_area, surface.contact_modulus);
    surface.height_scale = from.height_scale;
    surface.summit_radius = from.summit_radius;
    surface.summit_density = from.summit_density;
    surface.validate();
    given_scale = "--moments (Nayak-McCool): rms summit height sigma " + approximately(surface.height_scale) +
                  " m, summit radius " + approximately(surface.summit_radius) + " m, summit density " +
                  approximately(surface.summit_density) + " per m^2";
    return surface;
  }
  if (given(options.sigma) == given(options.rms))
    usage("give the height scale once: --sigma (Weibull: its scale; Gaussian: the rms summit height) or --rms");
  if (!given(options.radius)) throw CLI::RequiredError("--radius");
  if (given(options.density) == given(options.count)) usage("give the summit density once: --density or --count");
  // (named here: the surface's own check would name the Weibull scale it converts to)
  if (given(options.rms) && !(options.rms > 0)) usage("--rms must be a positive length [m], got " + number(options.rms));
  surface.summit_radius = options.radius;
  if (given(options.density)) surface.summit_density = options.density;
  else if (!(options.count > 0)) usage("--count must be positive, got " + number(options.count));
  else surface.summit_density = options.count / surface.nominal_area;
  // The rms summit height of a Weibull surface is weibull_rms(shape) times its scale.
  const double rms_per_scale = weibull ? weibull_rms(surface.shape) : 1.0;
  surface.height_scale = given(options.sigma) ? options.sigma : options.rms / rms_per_scale;
  surface.validate();
  if (!weibull)
    given_scale = "sigma " + number(surface.height_scale) + " m is the Gaussian's rms summit height";
  else if (given(options.sigma))
    given_scale = "--sigma " + number(options.sigma) + " m given (the Weibull scale); rms summit height " +
                  approximately(surface.height_scale * rms_per_scale) + " m (rms = " + approximately(rms_per_scale) +
                  " sigma for shape " + number(surface.shape) + ")";
  else
    given_scale = "--rms " + number(options.rms) + " m given (the rms summit height); Weibull scale sigma " +
                  approximately(surface.height_scale) + " m (rms = " + approximately(rms_per_scale) +
                  " sigma for shape " + number(surface.shape) + ")";
  return surface;
}

struct Sweep {
  std::string kind;
  double from = 0, to = 0;
  long count = 0;
};

Sweep sweep_from(const std::string& text) {
  const std::vector<std::string> parts = split(text, ':');
  if (parts.size() != 4) usage("--sweep wants KIND:FROM:TO:COUNT, got '" + quote_text(text) + "'");
  Sweep sweep;
  sweep.kind = parts[0];
  if (sweep.kind != "separation" && sweep.kind != "load" && sweep.kind != "pressure" && sweep.kind != "real-area")
    usage("--sweep: unknown KIND '" + quote_text(sweep.kind) + "' (separation, load, pressure, real-area)");
  sweep.from = number_from_text(parts[1], "--sweep FROM");
  sweep.to = number_from_text(parts[2], "--sweep TO");
  const double count = number_from_text(parts[3], "--sweep COUNT");
  if (!(count >= 2 && count <= 1e6 && count == std::floor(count)))
    usage("--sweep COUNT must be a whole number from 2 to 1000000, got '" + quote_text(parts[3]) + "'");
  sweep.count = static_cast<long>(count);
  if (sweep.kind != "separation" && !(sweep.from > 0 && sweep.to > 0))
    usage("--sweep: a load, pressure or real-area sweep is logarithmic and needs FROM, TO > 0");
  return sweep;
}

// The k-th of `count` values from `from` to `to`, linear or logarithmic (in logs, so that no
// ratio of the ends overflows), the ends exact.
double sweep_value(const Sweep& sweep, long k) {
  if (k == 0) return sweep.from;
  if (k == sweep.count - 1) return sweep.to;
  const double fraction = static_cast<double>(k) / static_cast<double>(sweep.count - 1);
  if (sweep.kind == "separation") return sweep.from + (sweep.to - sweep.from) * fraction;
  // in decimal logarithms: a sweep over decades lands on its powers of ten exactly (1e3:1e6:4 gives
  // 1e4 and 1e5, where natural logarithms give 9999.99999999999)
  const double log_from = std::log10(sweep.from), log_to = std::log10(sweep.to);
  return std::pow(10.0, log_from + (log_to - log_from) * fraction);
}

// The queries asked: one kind (separation, load, pressure or real-area) and its values, from that
// kind's list option or from --sweep (whose values are computed as they are asked for: a sweep
// may have a million)
struct Queries {
  std::string kind;
  std::vector<double> values;  // a list's
  Sweep sweep;
  bool swept = false;
  long size() const { return swept ? sweep.count : static_cast<long>(values.size()); }
  double at(long k) const { return swept ? sweep_value(sweep, k) : values[static_cast<std::size_t>(k)]; }
  // the k-th value's name in a message
  std::string option(long k) const {
    const std::string place = "(query " + std::to_string(k + 1) + " of " + std::to_string(size()) + ")";
    if (swept) return "--sweep " + kind + " " + place;
    return "--" + kind + (size() > 1 ? " " + place : "");
  }
};

// How many of the query options are given (--export not counted)
int queries_given(const Options& options) {
  return !options.separations.empty() + !options.loads.empty() + !options.pressures.empty() +
         !options.real_areas.empty() + !options.sweep.empty();
}

// The one query option given (queries_given is 1)
Queries queries_from(const Options& options) {
  Queries queries;
  if (!options.sweep.empty()) {
    queries.sweep = sweep_from(options.sweep);
    queries.kind = queries.sweep.kind;
    queries.swept = true;
    return queries;
  }
  const std::pair<const char*, const std::vector<double>*> lists[] = {
      {"separation", &options.separations}, {"load", &options.loads},
      {"pressure", &options.pressures}, {"real-area", &options.real_areas}};
  for (const auto& [kind, values] : lists)
    if (!values->empty()) queries.kind = kind, queries.values = *values;
  return queries;
}

// The state at a query (the model's inverses give the quantity asked back as asked)
PhysicalState query(const ContactModel& model, const std::string& kind, double value) {
  if (kind == "separation") return model.at_separation(value);
  if (kind == "load") return model.at_load(value);
  if (kind == "pressure") return model.at_pressure(value);
  return model.at_real_area(value);
}

// A load, pressure or real area asked of a Greenwood-Williamson surface: positive (at 0 or below
// there is no contact, which no finite separation answers: the tail side's is infinite).
void require_positive_query(const char* name, const std::vector<double>& values, const char* unit) {
  for (const double value : values)
    if (!(value > 0))
      usage(std::string(name) + " must be positive, got " + number(value) + " " + unit +
            " (no contact: no finite separation carries it)");
}

const char* query_unit(const std::string& kind) {
  return kind == "separation" ? "m" : kind == "load" ? "N" : kind == "pressure" ? "Pa" : "m^2";
}

// The range the model answers (a scene table's: outside, NaN), in the unit of a `kind` query
std::string model_range(const ContactModel& model, const std::string& kind) {
  const double area = model.surface().nominal_area;
  if (kind == "separation")
    return "separations " + number(model.min_separation()) + " to " + number(model.max_separation()) + " m" +
           (model.surface().side == Side::bounded ? " (and from 0 on: no contact)" : "");
  if (kind == "load") return "loads " + number(model.min_load()) + " to " + number(model.max_load()) + " N";
  if (kind == "pressure")
    return "nominal pressures " + number(model.min_load() / area) + " to " + number(model.max_load() / area) + " Pa";
  return "real areas " + number(model.min_real_area()) + " to " + number(model.max_real_area()) + " m^2";
}

// A query the model answers NaN (outside a scene table's range): refused with the range it covers
void check_answered(const ContactModel& model, const std::string& option, const std::string& kind, double value,
                    const PhysicalState& state) {
  if (!std::isnan(state.load) || std::isnan(value)) return;
  throw Error(option + " " + number(value) + " " + query_unit(kind) +
              " is outside the range the table serves for this surface: " + model_range(model, kind) +
              " (a scene table serves its scene's range: a full table, such as the default, serves every one)");
}


// the CSV's columns: the physical state's fields (physical_state_fields.hpp), in their order
void print_header() { std::printf("%s\n", csv_header<PhysicalState>().c_str()); }
void print(const PhysicalState& state) { std::printf("%s\n", csv_row(state).c_str()); }

void warn_past_gw(const CLI::App& command, double area_fraction) {
  const std::string warning = gw_area_fraction_warning(area_fraction);
  if (!warning.empty()) warn(command, warning);
}

std::string describe(const RoughSurface& surface) {
  std::ostringstream text;
  text << to_string(surface.distribution) << " " << to_string(surface.side) << " summit heights";
  if (surface.distribution == Distribution::weibull)
    text << ", shape " << number(surface.shape) << ", scale sigma " << number(surface.height_scale)
         << " m (rms summit height " << approximately(surface.height_scale * weibull_rms(surface.shape)) << " m)";
  else
    text << ", rms summit height sigma " << number(surface.height_scale) << " m";
  text << "\nsummit radius " << number(surface.summit_radius) << " m, summit density "
       << number(surface.summit_density) << " per m^2, nominal area " << number(surface.nominal_area)
       << " m^2, contact modulus E* " << number(surface.contact_modulus) << " Pa";
  return text.str();
}

int export_law(const Options& options, const ContactModel& model, const CLI::App& command, CardFormat format,
               CardUnits units, OverclosureDatum datum) {
  const std::vector<std::string> range = split(options.pressure_range, ':');
  if (range.size() != 2) usage("--pressure-range wants PMIN:PMAX (Pa), got '" + quote_text(options.pressure_range) + "'");
  const double low = number_from_text(range[0], "--pressure-range PMIN");
  const double high = number_from_text(range[1], "--pressure-range PMAX");
  if (!(low > 0 && high > low)) usage("--pressure-range needs 0 < PMIN < PMAX");
  const double area = model.surface().nominal_area;
  if (low < model.min_load() / area || high > model.max_load() / area)
    throw Error("--pressure-range " + number(low) + ":" + number(high) +
                " Pa reaches outside the range the table serves for this surface: " + model_range(model, "pressure"));
  const double tolerance = given(options.export_tolerance) ? options.export_tolerance : 1e-3;
  const std::size_t max_points = card_max_points(options.max_points, format);
  const double face_size = face_size_option(options.face_size, format, units, "--export");  // m
  const PressureOverclosureTable table = tabulate_pressure_overclosure(model, low, high, tolerance, datum, max_points);
  write_pressure_overclosure(std::cout, table, format, units,
                             "asperity " ASPERITY_VERSION_STRING
                             ": the pressure-overclosure law of a rough surface against a flat "
                             "(Greenwood-Williamson)\n" +
                                 describe(model.surface()),
                             face_size);
  state_card(command, table, tolerance, max_points, low, high, datum, "the law");
  if (format == CardFormat::calculix)
    check_spring_cutoff(
        command, table.points, face_size, units,
        "use --overclosure-datum zero-pressure (and start the model with the surfaces touching), larger faces, or a "
        "higher PMIN");
  warn_past_gw(command, model.at_pressure(high).area_fraction);
  return exit_success;
}

int serve_contact_curves(const Options& options, const CLI::App& command, const ContactCurves& curves);

// The queries contact curves answer: one of --separation, --pressure, --sweep, --export
void check_curve_queries(const Options& options, const std::string& what) {
  // Contact curves carry their own separation datum (a law's: the origin convention; a measured
  // surface's: its mean plane), stated on standard error; their CSV also gives the separation from
  // the mean summit height.
  if (!options.datum.empty() || given(options.mean_summit_height))
    usage(what + " are served from their own separation datum (standard error names it; the CSV's "
                 "separation_from_mean_summit_m is from the mean summit height): --datum and --mean-summit-height "
                 "go with a Greenwood-Williamson surface (--dist ...)");
  if (!options.loads.empty() || !options.real_areas.empty())
    usage(what + " are served at a separation or a nominal pressure: --separation, --pressure, --sweep "
                 "separation|pressure, or --export");
  const int queries = queries_given(options) + !options.export_format.empty();
  if (queries != 1)
    usage(queries == 0 ? "a query is required: --separation, --pressure, --sweep or --export"
                       : "give one query: --separation, --pressure, --sweep or --export");
}

// `asperity contact --law NAME ...`: the law's rough-surface curves on the surface the options
// describe, tabulated now by the generator (as tablegen does a law scene: the scene is made of
// the options, so that its checks and messages are the scene file's) and served as contact curves.
int run_contact_law(const Options& options, const CLI::App& command) {
  if (!options.table.empty()) usage("--law tabulates the law's curves itself: give no --table");
  law_values(options.law);
  if (options.law_range.empty()) throw CLI::RequiredError("--law-range (with --law)");
  const std::vector<std::string> range = split(options.law_range, ':');
  if (range.size() != 2) usage("--law-range wants SMIN:SMAX (dimensionless separations), got '" +
                               quote_text(options.law_range) + "'");
  const double lo = number_from_text(range[0], "--law-range SMIN"), hi = number_from_text(range[1], "--law-range SMAX");
  check_curve_queries(options, "a law's curves");
  std::string given_scale;
  const RoughSurface surface = surface_from(options, given_scale);
  const SceneLaw law =
      law_scene(options.law, surface, lo, hi, "asperity contact --law", options.law.approach_separation);
  if (!given_scale.empty()) note(command, given_scale);
  const std::string name = contact_law_name(law.law.kind);
  switch (find_contact_law(law.law.kind)->family) {  // the regime's figure (contact_law_registry.hpp)
    case LawFamily::adhesive:
      note(command, name + ": " +
                        (law.withdrawal() ? "the withdrawal (unloading) branch after an approach to s0 = " +
                                                number(law.approach_separation) + " (summits leave at omega_min = " +
                                                number(law.law.lowest_interference) + " m)"
                                          : std::string("the approach (loading) branch")) +
                        "; Maugis' length d_s = " +
                        approximately(law.law.critical_interference) + " m, Fuller-Tabor's adhesion parameter " +
                        "sigma_s / delta_c = " + approximately(adhesion_parameter(law.law, surface.height_scale)));
      break;
    case LawFamily::elastic_plastic:
      note(command, name + ": omega_c = " + approximately(law.law.critical_interference) +
                        " m, plasticity index psi = (sigma_s / omega_c)^1/2 = " +
                        approximately(plasticity_index(law.law, surface.height_scale)));
      break;
    case LawFamily::elastic: break;
  }
  const generator::LawCurvesResult result = generator::generate_law_curves(law, "asperity contact --law");
  return serve_contact_curves(options, command, ContactCurves(result.data));
}

// `asperity contact --table FILE` with a contact-curves table (a measured surface's exact
// contact, asperity exact-contact --table, or a law scene's, tablegen): its served curves at
// separations or pressures, or their card.
int run_contact_curves(const Options& options, const CLI::App& command) {
  if (!options.side.empty() || given(options.shape) || given(options.sigma) ||
      given(options.rms) || given(options.radius) || given(options.density) || given(options.count) ||
      given(options.area) || options.material.any_given() || !options.moments.empty())
    usage("the table '" + quote_text(options.table) +
          "' holds a measured surface's contact curves: it is the surface (give no --side, --shape, --sigma, "
          "--rms, --radius, --density, --count, --area, --modulus, --e1..--nu2, --moments)");
  check_curve_queries(options, "a table's contact curves");
  return serve_contact_curves(options, command, ContactCurves::open(options.table));
}

// Contact curves (a contact-curves table's, or a law's made by --law) at separations or
// pressures, or their card
int serve_contact_curves(const Options& options, const CLI::App& command, const ContactCurves& curves) {
  Queries queries;
  if (options.export_format.empty()) {
    queries = queries_from(options);
    if (queries.swept && queries.kind != "separation" && queries.kind != "pressure")
      usage("--sweep: contact curves sweep separation or pressure, not " + queries.kind);
  }
  const ContactCurvesData& data = curves.data();
  note(command, "contact curves of " + data.source + ": " + data.description);
  note(command, "separation: " + data.separation_datum + "; served from " + number(curves.min_separation()) +
                    " to " + number(curves.max_separation()) + " m (" + approximately(curves.max_pressure()) + " to " +
                    approximately(curves.min_pressure()) + " Pa); stored error bound (relative): pressure " +
                    approximately(data.max_rel_error[0]) + ", stiffness " + approximately(data.max_rel_error[1]) +
                    ", area fraction " + approximately(data.max_rel_error[2]) +
                    (data.summit_count.empty() ? std::string()
                                               : ", summit count " + approximately(data.summit_count_max_rel_error)) +
                    (curves.has_tension() ? " (pressure and stiffness relative to the gross, compressive + tensile; " : " (") +
                    approximately(data.safety_factor) + " x the largest measured at " +
                    std::to_string(data.check_points) + " exact solves between the nodes, method " +
                    to_string(data.bound_method) + "; solver tolerance " +
                    approximately(data.solver_tolerance) + ")");
  if (curves.has_tension()) {
    // the branch, as the table states it (its approach_separation)
    const std::string branch = data.withdrawal()
                                   ? "withdrawal branch after an approach to " + number(data.approach_separation) + " m"
                                   : "approach branch";
    if (std::isnan(curves.pull_off_pressure()))
      note(command, "adhesive curves (" + branch + "): the pull-off (greatest tension) is not inside their range; "
                    "--pressure is served from " + number(curves.min_pressure()) + " to " +
                        number(curves.max_pressure()) + " Pa");
    else
      note(command, "adhesive curves (" + branch + "): pull-off (greatest tension) " +
                        number(curves.pull_off_pressure()) + " Pa at separation " +
                        number(curves.pull_off_separation()) +
                        " m; --pressure is served on the stable branch, up to that separation");
    if (!options.export_format.empty())
      usage("--export: adhesive curves carry tension, which a pressure-overclosure card cannot hold");
  }
  if (!options.export_format.empty()) {
    CardFormat format = CardFormat::csv;
    CardUnits units = CardUnits::si;
    OverclosureDatum datum = OverclosureDatum::zero_pressure;
    if (!parse_card_format(options.export_format, format))
      usage("--export: '" + quote_text(options.export_format) + "' is not calculix, abaqus or csv");
    if (!options.units.empty() && !parse_card_units(options.units, units))
      usage("--units: '" + quote_text(options.units) + "' is not si or mm");
    if (!options.overclosure_datum.empty() && !parse_overclosure_datum(options.overclosure_datum, datum))
      usage("--overclosure-datum: '" + quote_text(options.overclosure_datum) +
            "' is not zero-pressure, mean-summit or origin");
    if (datum == OverclosureDatum::mean_plane)
      usage("--overclosure-datum mean-plane is a Greenwood-Williamson surface's: contact curves take mean-summit, "
            "origin (their separation's datum: " + data.separation_datum + ") or zero-pressure");
    double low = curves.min_pressure(), high = curves.max_pressure();
    if (!options.pressure_range.empty()) {
      const std::vector<std::string> range = split(options.pressure_range, ':');
      if (range.size() != 2) usage("--pressure-range wants PMIN:PMAX (Pa), got '" + quote_text(options.pressure_range) + "'");
      low = number_from_text(range[0], "--pressure-range PMIN");
      high = number_from_text(range[1], "--pressure-range PMAX");
      if (!(low > 0 && high > low)) usage("--pressure-range needs 0 < PMIN < PMAX");
    }
    const double tolerance = given(options.export_tolerance) ? options.export_tolerance : 1e-3;
    const std::size_t max_points = options.max_points > 0        ? static_cast<std::size_t>(options.max_points)
                                   : format == CardFormat::calculix ? calculix_points_max
                                                                    : card_points_max;
    const double face_size = face_size_option(options.face_size, format, units, "--export");  // m
    const PressureOverclosureTable table = tabulate_pressure_overclosure(curves, low, high, tolerance, datum, max_points);
    write_pressure_overclosure(std::cout, table, format, units,
                               std::string("asperity " ASPERITY_VERSION_STRING ": the pressure-overclosure law of a ") +
                                   (data.source.rfind("contact-law", 0) == 0 ? "rough surface under a contact law"
                                                                             : "measured surface") +
                                   " against a flat, from its contact-curves table (" + data.source + ")\n" +
                                   data.description + "\nthe table's own error bound (relative, in pressure): " +
                                   approximately(data.max_rel_error[0]) + " (measured at " +
                                   std::to_string(data.check_points) + " exact solves between its nodes, times " +
                                   approximately(data.safety_factor) + ")",
                               face_size);
    if (format == CardFormat::calculix)
      check_spring_cutoff(command, table.points, face_size, units,
                          "use --overclosure-datum zero-pressure (and start the model with the surfaces touching), "
                          "larger faces, or a higher PMIN");
    state_card(command, table, tolerance, max_points, low, high, datum, "the served curve");
    return exit_success;
  }
  if (!options.pressure_range.empty() || !options.units.empty() || given(options.export_tolerance) ||
      options.max_points > 0 || !options.overclosure_datum.empty() || given(options.face_size))
    usage("--pressure-range, --units, --export-tolerance, --max-points, --overclosure-datum and --face-size go "
          "with --export");
  // the columns of ContactCurvesRow (contact_curves.hpp); a law's table counts the summits in
  // contact (a measured surface's has no such column: the last left out)
  const std::size_t columns = RecordFields<ContactCurvesRow>::count - (curves.counts_summits() ? 0 : 1);
  std::printf("%s\n", csv_header<ContactCurvesRow>(columns).c_str());
  const auto row = [&](const ContactCurvesState& state) {
    std::printf("%s\n", csv_row(curves.row(state), [](double value) { return format_double(value); }, columns).c_str());
  };
  const auto at = [&](const std::string& kind, double value) {
    if (kind == "separation") return curves.at_separation(value);
    ContactCurvesState state = curves.at_pressure(value);
    state.pressure = value;
    if (std::isnan(state.separation)) state.stiffness = state.area_fraction = NAN;
    return state;
  };
  // every query checked before any row is written: one outside the range served is refused whole
  // (nothing is extrapolated), with the range in its unit
  const auto check = [&](const std::string& option, const std::string& kind, double value) {
    const bool separation = kind == "separation";
    const double lo = separation ? curves.min_separation() : curves.min_pressure();
    const double hi = separation ? curves.max_separation() : curves.max_pressure();
    const ContactCurvesState state = at(kind, value);
    if (value >= lo && value <= hi && !std::isnan(separation ? state.pressure : state.separation)) return;
    throw Error(option + " " + number(value) + (separation ? " m" : " Pa") +
                " is outside the range the contact curves serve (nothing is extrapolated): " +
                (separation ? "separations " : "nominal pressures ") + number(lo) + " to " + number(hi) +
                (separation ? " m" : " Pa") +
                (curves.has_tension() && !separation ? " (the stable branch, up to the pull-off)" : ""));
  };
  for (long k = 0; k < queries.size(); ++k) check(queries.option(k), queries.kind, queries.at(k));
  for (long k = 0; k < queries.size(); ++k) row(at(queries.kind, queries.at(k)));
  return exit_success;
}

int run_contact(const Options& options, const CLI::App& command) {
  if (!options.law.law.empty()) return run_contact_law(options, command);
  check_no_law_options(options.law, options.law_range.empty() ? "" : "--law-range, ");
  if (!options.law_range.empty()) usage("--law-range goes with --law");
  // A table alone, no surface: it may be a measured surface's or a law scene's (its kind read only
  // then, so that a GW table is not read twice); with a surface, a contact-curves table is refused
  // on opening.
  if (!options.table.empty() && options.dist.empty() && read_table_kind(options.table) == TableKind::contact_curves)
    return run_contact_curves(options, command);
  std::string given_scale;
  const RoughSurface surface = surface_from(options, given_scale);
  const int asked = queries_given(options) + !options.export_format.empty();
  if (asked != 1)
    usage(asked == 0 ? "a query is required: --separation, --load, --pressure, --real-area, --sweep or --export"
                       : "give one query: --separation, --load, --pressure, --real-area, --sweep or --export");
  CardFormat format = CardFormat::csv;
  CardUnits units = CardUnits::si;
  OverclosureDatum datum = OverclosureDatum::zero_pressure;
  SeparationDatum separation_datum = default_separation_datum;
  if (!options.datum.empty() && !parse_separation_datum(options.datum, separation_datum))
    usage("--datum: '" + quote_text(options.datum) + "' is not origin, mean-summit or mean-plane");
  if (!options.datum.empty() && !options.export_format.empty())
    usage("--datum is the queries' separation datum: the card's is --overclosure-datum");
  if (!options.export_format.empty()) {
    if (!parse_card_format(options.export_format, format))
      usage("--export: '" + quote_text(options.export_format) + "' is not calculix, abaqus or csv");
    if (!options.units.empty() && !parse_card_units(options.units, units))
      usage("--units: '" + quote_text(options.units) + "' is not si or mm");
    datum = overclosure_datum_option(options.overclosure_datum);
    face_size_option(options.face_size, format, units, "--export");  // checked before any work
    if (options.pressure_range.empty()) throw CLI::RequiredError("--pressure-range (with --export)");
  } else if (!options.pressure_range.empty() || !options.units.empty() || given(options.export_tolerance) ||
             options.max_points > 0 || !options.overclosure_datum.empty() || given(options.face_size)) {
    usage("--pressure-range, --units, --export-tolerance, --max-points, --overclosure-datum and --face-size go "
          "with --export");
  }
  // the mean plane is where the user says it is: the summit heights do not fix it
  const bool mean_plane = separation_datum == SeparationDatum::mean_plane ||
                          (!options.export_format.empty() && datum == OverclosureDatum::mean_plane);
  if (mean_plane && !given(options.mean_summit_height))
    usage("the mean-plane datum needs --mean-summit-height M: the mean summit height above the mean plane (`asperity "
          "surface` reports it for a measured map); the summit heights alone do not fix the mean plane");
  if (!mean_plane && given(options.mean_summit_height))
    usage("--mean-summit-height goes with --datum mean-plane (or --overclosure-datum mean-plane)");
  if (mean_plane) separation_datum = SeparationDatum::mean_plane;
  require_positive_query("--load", options.loads, "N");
  require_positive_query("--pressure", options.pressures, "Pa");
  require_positive_query("--real-area", options.real_areas, "m^2");
  Queries queries;
  if (options.export_format.empty()) queries = queries_from(options);

  const Table table = open_table(options.table);
  const ContactModel model(table, surface, separation_datum, options.mean_summit_height);
  for (const std::string& line : implausible_values(surface)) warn(command, line);
  if (mean_plane)
    for (const std::string& line : implausible_mean_summit_height(surface, options.mean_summit_height))
      warn(command, line);
  if (!given_scale.empty()) note(command, given_scale);
  if (!options.export_format.empty()) return export_law(options, model, command, format, units, datum);

  // every query answered before any row is written: one outside the range is refused whole (a
  // full table's model answers every finite query: its sweep needs no pass of checks)
  const bool everything = model.min_separation() == -HUGE_VAL && model.max_separation() == HUGE_VAL;
  if (!(queries.swept && everything))
    for (long k = 0; k < queries.size(); ++k)
      check_answered(model, queries.option(k), queries.kind, queries.at(k), query(model, queries.kind, queries.at(k)));

  note(command, "separation_m (and --separation, --sweep separation): " +
                    describe_separation_datum(separation_datum, options.mean_summit_height) +
                    "; mean_separation_m: from the mean summit height");
  print_header();
  double largest_fraction = 0;
  auto row = [&](const PhysicalState& state) {
    print(state);
    if (state.area_fraction > largest_fraction) largest_fraction = state.area_fraction;
  };
  for (long k = 0; k < queries.size(); ++k) row(query(model, queries.kind, queries.at(k)));
  warn_past_gw(command, largest_fraction);
  return exit_success;
}

}  // namespace

void add_contact_command(CLI::App& app) {
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "contact", "a physical rough surface against a flat: count, real area, load, pressure and stiffness at a "
                 "separation, a load, a pressure or a real area (CSV), or its pressure-overclosure law for FE codes");
  Options& o = *options;
  add_table_option(*command, o.table);
  add_quiet_option(*command);
  add_text(*command, "--dist", o.dist, "summit heights: weibull or gaussian (required)")->type_name("NAME")->group("Surface (SI units)");
  add_text(*command, "--side", o.side, "tail (default; GW's approach) or bounded (Weibull only: worn surfaces)")->type_name("SIDE")->group("Surface (SI units)");
  add_number(*command, "--shape", o.shape, "Weibull shape a, " + format_double(weibull_shape_min) + " to " + format_double(weibull_shape_max) + " (required for the Weibull)")->type_name("A")->group("Surface (SI units)");
  add_number(*command, "--sigma", o.sigma,
             "height scale [m]: the Weibull scale sigma_s (not its rms), or the Gaussian's rms summit height")
      ->type_name("M")->group("Surface (SI units)");
  add_number(*command, "--rms", o.rms,
             "rms summit height [m], what GW users measure (Weibull: sigma = rms / weibull_rms(a); "
             "for a = 1.6, rms = 0.574 sigma); give --sigma or --rms")
      ->type_name("M")->group("Surface (SI units)");
  add_number(*command, "--radius", o.radius, "summit radius R [m]")->type_name("M")->group("Surface (SI units)");
  add_number(*command, "--density", o.density, "summits per unit nominal area [1/m^2]")->type_name("PER_M2")->group("Surface (SI units)");
  add_number(*command, "--count", o.count, "summits in all (instead of --density)")->type_name("N")->group("Surface (SI units)");
  add_number(*command, "--area", o.area, "nominal area A0 [m^2] (required)")->type_name("M2")->group("Surface (SI units)");
  add_material_options(*command, o.material, "contact modulus E* [Pa] (or --e1 --nu1 --e2 --nu2)", "Surface (SI units)");
  add_text(*command, "--moments", o.moments,
           "a Gaussian surface from its profile's spectral moments (Nayak-McCool: sets sigma, radius, density)")
      ->type_name("M0,M2,M4")->group("Surface (SI units)");
  add_law_options(*command, o.law, "a contact law's curves instead of Hertz's",
                  " (an adhesive law's approach branch, or its withdrawal with --approach-separation), tabulated now "
                  "on the surface given (docs/contact-laws.md section 8); queries --separation, --pressure, --sweep "
                  "separation|pressure, --export",
                  "at or below --law-range's SMIN");
  add_text(*command, "--law-range", o.law_range,
           "with --law: the dimensionless separations s tabulated (origin convention; required)")
      ->type_name("SMIN:SMAX")->group("Contact law");
  add_numbers(*command, "--separation", o.separations, "at separations [m] from the datum (--datum), comma-separated")
      ->type_name("M[,M...]")->group("Query (one)");
  add_numbers(*command, "--load", o.loads, "at loads [N], comma-separated")->type_name("N[,N...]")->group("Query (one)");
  add_numbers(*command, "--pressure", o.pressures, "at nominal pressures [Pa], comma-separated")
      ->type_name("PA[,PA...]")->group("Query (one)");
  add_numbers(*command, "--real-area", o.real_areas, "at real contact areas [m^2], comma-separated")
      ->type_name("M2[,M2...]")->group("Query (one)");
  add_text(*command, "--sweep", o.sweep,
           "COUNT queries from FROM to TO: KIND separation (linear), load, pressure or real-area (logarithmic)")
      ->type_name("KIND:FROM:TO:COUNT")->group("Query (one)");
  add_text(*command, "--datum", o.datum,
           "where separations (--separation, --sweep separation, separation_m) are measured from: origin (default, "
           "kept for existing scripts: the Weibull origin, the Gaussian's mean), mean-summit (the mean summit height, "
           "GW's datum) or mean-plane (the mean plane of the heights: give --mean-summit-height)")
      ->type_name("DATUM")->group("Query (one)");
  add_number(*command, "--mean-summit-height", o.mean_summit_height,
             "the mean summit height above the mean plane [m] (asperity surface reports it), for --datum mean-plane "
             "or --overclosure-datum mean-plane")
      ->type_name("M")->group("Query (one)");
  add_text(*command, "--export", o.export_format,
           "the pressure-overclosure law as a *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR card "
           "(calculix, abaqus) or CSV, on standard output")
      ->type_name("FORMAT")->group("Query (one)");
  add_text(*command, "--pressure-range", o.pressure_range, "with --export: nominal pressures covered [Pa]")
      ->type_name("PMIN:PMAX")->group("FE export");
  add_number(*command, "--export-tolerance", o.export_tolerance,
             "with --export: largest relative error of linear interpolation between the points (default 1e-3)")
      ->type_name("REL")->group("FE export");
  add_text(*command, "--units", o.units, "with --export: si (m, Pa; default) or mm (mm, MPa = N/mm^2)")
      ->type_name("UNITS")->group("FE export");
  add_whole_number(*command, "--max-points", o.max_points, static_cast<long long>(card_points_min),
                   static_cast<long long>(card_points_max),
                   "with --export: at most N rows in the card (default: 200 for calculix, what its node-to-surface "
                   "contact holds; no cap for abaqus and csv); a tolerance that needs more is loosened to the "
                   "smallest that fits (a warning says which)")
      ->group("FE export");
  add_text(*command, "--overclosure-datum", o.overclosure_datum,
           "with --export: where overclosure is zero: zero-pressure (default; the card's first point: every "
           "overclosure >= 0, start the model with the surfaces touching), mean-summit (the flat at the mean summit "
           "height), origin (the separation's origin: the Weibull origin, the Gaussian's mean) or mean-plane (give "
           "--mean-summit-height)")
      ->type_name("DATUM")->group("FE export");
  add_face_size_option(*command, o.face_size, "with --export calculix", "FE export");
  command->footer(
      "Output: CSV, one row per query (a list's values in order): separation_m (from the datum, --datum: by default the origin\n"
      "convention, from the Weibull origin or the Gaussian's mean; standard error names the datum),\n"
      "mean_separation_m (from the mean summit height), count, real_area_m2, area_fraction, load_N,\n"
      "nominal_pressure_Pa, stiffness_N_per_m, stiffness_over_load_per_m.\n"
      "Standard error says which height scale was given and the other's value, names the datum, warns\n"
      "of implausible values (a unit slip: a summit radius over 1 mm, E* under 1 MPa, ...), and warns when\n"
      "the real-area fraction exceeds 0.1: GW's asperities are independent Hertz contacts, which holds only\n"
      "while the contacts are sparse (above 1 the answer is impossible).\n"
      "FE export: overclosure is the interpenetration of the surfaces (a clearance is negative),\n"
      "measured from where the card's pressure reaches zero (--overclosure-datum; start the model with\n"
      "the surfaces touching); the card's header\n"
      "states the units, the datum, the range and the measured interpolation error. CalculiX needs\n"
      "NODE TO SURFACE contact with this card (at most 200 points: the default --max-points; face-to-face,\n"
      "ccx 2.20: crashes above 41 points and gives zero force at clearances, silently), and makes a\n"
      "contact spring only within a clearance of 1e-3 sqrt(slave node area): --face-size L warns when\n"
      "the card reaches beyond 1e-3 L (L in the card's units).\n"
      "A measured surface: --table FILE of contact curves (asperity exact-contact --table) is the surface\n"
      "itself (no --dist ...): --separation (from the table's datum, the map's mean plane), --pressure,\n"
      "--sweep separation|pressure or --export; CSV separation_m, separation_from_mean_summit_m,\n"
      "nominal_pressure_Pa, stiffness_per_area_N_per_m3, area_fraction. A query outside the range a table\n"
      "serves (a contact-curves table's, or a scene table's for a surface) is refused with that range.\n"
      "--load, --pressure and --real-area of a surface (--dist) must be positive.\n" +
      std::string(exit_status_help));
  CLI::App* self = command;
  set_action(*command, [options, self] { return run_contact(*options, *self); });
}

}  // namespace asperity::cli
