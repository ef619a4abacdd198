#include "exact_contact_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/output.hpp"
#include "asperity/surface.hpp"
#include "asperity/topography/exact_contact.hpp"
#include "asperity/topography/exact_contact_report.hpp"
#include "asperity/topography/exact_contact_table.hpp"
#include "asperity/contact_curves_data.hpp"
#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/surface_formats.hpp"
#include "asperity/topography/leveling.hpp"
#include "asperity/topography/units.hpp"
#include "command_line.hpp"
#include "fe_card_options.hpp"
#include "map_options.hpp"
#include "option_helpers.hpp"
#include "asperity/number_text.hpp"
#include "asperity/pressure_overclosure.hpp"

namespace asperity::cli {
namespace {
namespace topo = asperity::topography;

constexpr double not_given = NAN;  // add_number only ever stores finite numbers
constexpr long max_steps = 10000;

struct Options {
  std::string file, pressures, gaps, sweep, boundary, kernel, method, fields, card, card_format, units, table,
      overclosure_datum;
  MapOptions map;             // how the map is read (map_options.hpp)
  MaterialOptions material;   // --modulus, or --e1 --nu1 --e2 --nu2
  double tolerance = not_given, hardness = not_given, work_of_adhesion = not_given, adhesive_stress = not_given, table_safety = not_given, face_size = not_given, card_tolerance = not_given;
  long long max_iterations = 20000, max_points = 0;  // max_points 0: not given
  long long table_max_checks = 0;                    // 0: not given (topo::default_table_max_checks)
  std::string max_memory;  // empty: the memory available (topo::memory_limit_option)
  bool json = false, no_level = false, no_stiffness = false, no_coarse_start = false, quiet = false, overwrite = false;
};

// A list of steps: positive numbers, at most max_steps of them.
std::vector<double> step_values(const std::string& text, const std::string& name) {
  std::vector<double> values = positive_numbers(text, name);
  if (values.size() > static_cast<std::size_t>(max_steps)) usage(name + ": more than 10000 values");
  return values;
}

// The steps asked: by pressure (true) or by mean gap, in the order given.
struct Steps {
  bool by_pressure = true;
  std::vector<double> values;
};

Steps steps_from(const Options& o) {
  const int asked = !o.pressures.empty() + !o.gaps.empty() + !o.sweep.empty();
  if (asked != 1)
    usage(asked == 0 ? "the load steps are required: --pressure, --gap or --sweep"
                     : "give one of --pressure, --gap, --sweep");
  Steps steps;
  if (!o.pressures.empty()) {
    steps.values = step_values(o.pressures, "--pressure");
  } else if (!o.gaps.empty()) {
    steps.by_pressure = false;
    steps.values = step_values(o.gaps, "--gap");
  } else {
    const std::vector<std::string> parts = split(o.sweep, ':');
    if (parts.size() != 4) usage("--sweep wants KIND:FROM:TO:COUNT, got '" + quote_text(o.sweep) + "'");
    if (parts[0] != "pressure" && parts[0] != "gap")
      usage("--sweep: unknown KIND '" + quote_text(parts[0]) + "' (pressure, gap)");
    steps.by_pressure = parts[0] == "pressure";
    const double from = number_from_text(parts[1], "--sweep FROM"), to = number_from_text(parts[2], "--sweep TO");
    const double count = number_from_text(parts[3], "--sweep COUNT");
    if (!(count >= 2 && count <= max_steps && count == std::floor(count)))
      usage("--sweep COUNT must be a whole number from 2 to 10000, got '" + quote_text(parts[3]) + "'");
    if (!(from > 0 && to > 0)) usage("--sweep needs FROM, TO > 0");
    const long n = static_cast<long>(count);
    for (long k = 0; k < n; ++k) {
      const double fraction = static_cast<double>(k) / static_cast<double>(n - 1);
      // pressures logarithmic, gaps linear; the ends exactly as given
      const double value = k == 0       ? from
                           : k == n - 1 ? to
                           : steps.by_pressure
                               ? std::pow(10.0, std::log10(from) + fraction * (std::log10(to) - std::log10(from)))
                               : from + fraction * (to - from);
      steps.values.push_back(value);
    }
  }
  return steps;
}

// A field as a 16-bit binary PGM (P5), black at 0 and white at `top`; rows in the map's order
// (the first row, y = 0, at the top); NaN (a missing point) black. The comment line marks it as
// ours (the output policy replaces only images of ours).
std::string pgm_bytes(const std::vector<double>& field, std::size_t nx, std::size_t ny, double top,
                      const std::string& what) {
  std::string bytes = "P5\n# asperity exact-contact " + what + "\n" + std::to_string(nx) + " " + std::to_string(ny) +
                      "\n65535\n";
  bytes.reserve(bytes.size() + 2 * nx * ny);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const double v = field[j * nx + i];
      const double level = std::isnan(v) || !(top > 0) ? 0.0 : std::clamp(v / top, 0.0, 1.0);
      const auto value = static_cast<std::uint16_t>(std::lround(level * 65535));
      bytes += static_cast<char>(value >> 8);
      bytes += static_cast<char>(value & 0xff);
    }
  return bytes;
}

std::string field_name(std::size_t step, const char* field) {
  return "step-" + std::to_string(step + 1) + "-" + field + ".pgm";
}

// The run's outputs, checked before the map is read (docs/reliability.md, "Outputs"): nothing
// is solved for outputs that cannot be written.
OutputPlan output_plan(const Options& o, std::size_t steps) {
  OutputPlan plan(o.overwrite);
  plan.input(o.file);
  if (!o.fields.empty()) {
    std::vector<FolderEntry> images;
    for (std::size_t k = 0; k < steps; ++k)
      for (const char* field : {"pressure", "gap"}) images.push_back({field_name(k, field), &output_kinds::field_image});
    plan.folder("--fields", o.fields, std::move(images));
  }
  if (!o.card.empty() && o.card != "-") plan.file("--card", o.card, output_kinds::card);  // "-": standard output
  if (!o.table.empty()) plan.file("--table", o.table, output_kinds::contact_curves_table);
  plan.check();
  return plan;
}

void stage_fields(OutputTransaction& outputs, const Options& o, const topo::ExactContact& solver,
                  const topo::HeightMap& map, std::size_t step, double max_pressure) {
  const std::vector<double> pressure = solver.pressure_field(), gap = solver.gap_field();
  double top_gap = 0;
  for (double g : gap)
    if (g > top_gap) top_gap = g;
  const std::string label = "step " + std::to_string(step + 1);
  outputs.stage(o.fields, field_name(step, "pressure"), pgm_bytes(pressure, map.nx, map.ny, max_pressure, label + " pressure"));
  outputs.stage(o.fields, field_name(step, "gap"), pgm_bytes(gap, map.nx, map.ny, top_gap, label + " gap"));
}

// What was solved, for the outputs' descriptions: "elastic", or with the hardness, or the adhesion.
std::string contact_model_words(const topo::ExactContactOptions& options) {
  if (topo::is_adhesive(options))
    return "adhesive (Maugis-Dugdale: work of adhesion " + format_double(options.work_of_adhesion) +
           " J/m^2, adhesive stress " + format_double(options.adhesive_stress) + " Pa, range " +
           format_double(options.work_of_adhesion / options.adhesive_stress) + " m)";
  return topo::is_plastic(options) ? "elastic-perfectly-plastic (hardness " + format_double(options.hardness) + " Pa)"
                                   : "elastic";
}

// --work-of-adhesion and --adhesive-stress: both or neither, and what adhesion is solved with.
void adhesion_options(const Options& o, topo::ExactContactOptions& options, bool by_pressure) {
  if (!given(o.work_of_adhesion) && !given(o.adhesive_stress)) return;
  if (!given(o.work_of_adhesion) || !given(o.adhesive_stress))
    usage("adhesion needs both --work-of-adhesion [J/m^2] and --adhesive-stress [Pa] (its range is their ratio)");
  if (!(o.work_of_adhesion > 0) || !(o.adhesive_stress > 0))
    usage("--work-of-adhesion and --adhesive-stress must be positive");
  if (given(o.hardness)) usage("adhesion with --hardness is not solved: give one of them");
  if (by_pressure)
    usage("adhesive contact is solved at mean gaps (--gap or --sweep gap:FROM:TO:COUNT, loading then unloading in "
          "the order given): its load is not monotone in the gap (pull-off), so a pressure can have two solutions "
          "or none");
  if (options.boundary != topo::ContactBoundary::periodic)
    usage("adhesive contact by mean gap is solved on the periodic boundary (where the mean gap is the flat's "
          "position); leave out --boundary padded");
  if (!o.table.empty() || !o.card.empty())
    usage("--table and --card hold the elastic contact's curves (no tension, one branch): leave them out with "
          "adhesion");
  options.work_of_adhesion = o.work_of_adhesion;
  options.adhesive_stress = o.adhesive_stress;
}

// The contact-curves table of the solved nodes (with the solves between them that measure its
// error), staged; returns the line that says what it states.
std::string stage_table(OutputTransaction& outputs, const Options& o, topo::ExactContact& solver,
                        const topo::HeightMap& map, const std::vector<topo::ContactStep>& results,
                        const std::vector<double>& pressures, const topo::ExactContactOptions& options) {
  const std::string boundary = topo::contact_boundary_name(options.boundary);
  const std::string kernel = topo::contact_kernel_name(options.kernel);
  std::ostringstream description, generator_options;
  description << "the exact elastic contact of a measured surface with a flat (boundary elements, " << boundary
              << " boundary, " << kernel << " kernel, " << topo::contact_solver_name(options.solver)
              << " solver, E* " << format_double(options.contact_modulus) << " Pa, tolerance "
              << format_double(options.tolerance) << ")\nmap: " << map.source << " (" << map.nx << " x " << map.ny
              << " points, dx " << format_double(map.dx) << " m, dy " << format_double(map.dy) << " m"
              << (o.no_level ? "" : ", leveled") << ")";
  generator_options << topo::exact_contact_table_generator_options("", pressures);  // within the text limit
  const topo::ExactContactTable table = topo::measure_exact_contact_table(
      solver, results, description.str(), generator_options.str(),
      given(o.table_safety) ? o.table_safety : topo::default_table_safety_factor,
      o.table_max_checks == 0 ? topo::default_table_max_checks : static_cast<std::size_t>(o.table_max_checks));
  const std::vector<unsigned char> bytes = contact_curves_file_bytes(table.data);
  outputs.stage(o.table, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
  std::ostringstream line;
  line << "table " << printable_path(o.table) << ": " << table.nodes.size() << " nodes, separations "
       << format_double(table.data.separation.front()) << " to " << format_double(table.data.separation.back())
       << " m; measured at " << table.checks.size() << " solves between them (finer until settled: "
       << table.unsettled_intervals << " intervals not settled at the cap), largest relative errors: pressure "
       << table.data.measured_rel_error[0] << ", stiffness " << table.data.measured_rel_error[1]
       << ", area fraction " << table.data.measured_rel_error[2] << " (stored bounds " << table.data.safety_factor
       << " times these)";
  if (table.limited_intervals > 0)
    line << "; " << table.limited_intervals << " intervals limited to keep the pressure monotone";
  return line.str();
}

// --card-tolerance: solves added where the card's curve bends. Between neighbouring solved
// points (from the lowest pressure solved up) one more solve at the middle mean gap measures
// linear interpolation's error there (relative, in pressure); where it exceeds `tolerance` both
// halves are split again. Every such solve becomes a point. At most `budget` solves; returns the
// note for the card's header (the solves, the largest error measured where it ended within it).
std::string refine_for_card(topo::ExactContact& solver, std::vector<topo::ContactStep>& results, double tolerance,
                            std::size_t budget, const CLI::App& command) {
  std::vector<topo::ContactStep> sorted = results;  // by mean gap, descending: overclosure ascending
  std::sort(sorted.begin(), sorted.end(),
            [](const topo::ContactStep& a, const topo::ContactStep& b) { return a.mean_gap > b.mean_gap; });
  std::vector<std::pair<topo::ContactStep, topo::ContactStep>> pending;
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i - 1].pressure > 0 && sorted[i].mean_gap < sorted[i - 1].mean_gap)
      pending.push_back({sorted[i - 1], sorted[i]});
  std::size_t solves = 0, within = 0, beyond = 0;
  double worst_within = 0, worst_left = 0;
  while (!pending.empty()) {
    const auto [a, b] = pending.back();
    pending.pop_back();
    if (solves >= budget) {
      ++beyond;
      continue;
    }
    const topo::ContactStep mid = solver.at_mean_gap(0.5 * (a.mean_gap + b.mean_gap));
    ++solves;
    results.push_back(mid);
    const double chord = 0.5 * (a.pressure + b.pressure);
    const double error = mid.pressure > 0 ? std::fabs(chord - mid.pressure) / mid.pressure : INFINITY;
    if (error > tolerance) {
      worst_left = std::max(worst_left, error);
      pending.push_back({mid, b});
      pending.push_back({a, mid});
    } else {
      ++within;
      worst_within = std::max(worst_within, error);
    }
  }
  std::ostringstream note;
  note << "--card-tolerance " << tolerance << ": " << solves
       << " solves added at the middle of intervals (in mean gap) where linear interpolation\n"
       << "  between solved points missed the middle's solve by more than that; at the " << within
       << " middles where it ended,\n  the error measured was " << worst_within
       << " at most (before the middle became a row)";
  if (beyond > 0) {
    note << "\n  WARNING: " << beyond << " intervals left unchecked after " << budget
         << " solves (the largest error measured there: " << worst_left << ")";
    warn(command, "--card-tolerance: " + std::to_string(beyond) + " intervals left unchecked after " +
                      std::to_string(budget) + " added solves; give more pressures or a larger tolerance");
  }
  return note.str();
}

// The pressure-overclosure card of the solved curve, staged (warnings on standard error);
// returns its text.
std::string stage_card(OutputTransaction& outputs, const Options& o, const CLI::App& command, const topo::ExactContact& solver,
                const topo::HeightMap& map, const std::vector<topo::ContactStep>& results,
                const topo::ExactContactOptions& options, CardFormat card_format, CardUnits card_units,
                OverclosureDatum card_datum, const std::string& refinement) {
  const std::string boundary = topo::contact_boundary_name(options.boundary);
  const std::string kernel = topo::contact_kernel_name(options.kernel);
  // overclosure in the card's datum: -(mean gap) from the map's mean plane, shifted
  const double summit = solver.mean_summit_height();
  if (card_datum == OverclosureDatum::mean_summit && !std::isfinite(summit))
    throw Error("the map has no summits: the card's datum (the mean summit height) does not exist; give "
                "--overclosure-datum mean-plane or zero-pressure");
  const double shift = card_datum == OverclosureDatum::mean_summit   ? summit
                       : card_datum == OverclosureDatum::zero_pressure ? solver.max_height()
                                                                       : 0.0;
  std::vector<PressureOverclosurePoint> points;
  points.push_back({0.0, shift - solver.max_height()});  // first contact
  std::vector<topo::ContactStep> sorted = results;
  std::sort(sorted.begin(), sorted.end(),
            [](const topo::ContactStep& a, const topo::ContactStep& b) { return a.pressure < b.pressure; });
  for (const topo::ContactStep& s : sorted) {
    const double overclosure = card_datum == OverclosureDatum::mean_summit ? -s.separation_from_mean_summit
                                                                           : shift - s.mean_gap;
    if (s.pressure > 0 && overclosure > points.back().overclosure) points.push_back({s.pressure, overclosure});
  }
  const TabulatedCard card = tabulate_points(points, card_max_points(o.max_points, card_format), card_datum,
                                             shift - summit);  // the flat at the mean summit height
  std::ostringstream description, notes;
  description << "asperity " ASPERITY_VERSION_STRING ": the exact " << contact_model_words(options)
              << " contact of a measured surface with a flat\n"
              << "(boundary elements, " << boundary << " boundary, " << kernel << " kernel, E* "
              << format_double(options.contact_modulus) << " Pa)\n"
              << "map: " << map.source << " (" << map.nx << " x " << map.ny << " points)";
  notes << "points: " << points.size() - 1 << " solutions of the contact problem (relative residual at most "
        << options.tolerance << ");\n"
        << "  the card interpolates linearly between them: give as many pressures as the analysis needs\n"
        << "first point: zero pressure at first contact (the flat at the map's highest point)";
  if (!refinement.empty()) notes << "\n" << refinement;
  std::ostringstream out;
  write_tabulated_pressure_overclosure(out, card, card_format, card_units, description.str(), notes.str(),
                                       face_size_option(o.face_size, card_format, card_units, "--card-format"));
  if (o.card != "-") outputs.stage(o.card, out.str());
  if (card.points.size() < card.given_points)
    warn(command, "the card keeps " + std::to_string(card.points.size()) + " of the curve's " +
                      std::to_string(card.given_points) + " points (--max-points " +
                      std::to_string(card.max_points) + "): linear interpolation between its rows is within " +
                      format_double(card.tolerance) + " of the points dropped (relative, in pressure)");
  if (card_format == CardFormat::calculix)
    check_spring_cutoff(command, card.points, face_size_option(o.face_size, card_format, card_units, "--card-format"),
                        card_units,
                        "use --overclosure-datum zero-pressure (and start the model with the surfaces touching) "
                        "or larger faces");
  return out.str();
}

void print_results(const Options& o, const topo::HeightMap& map, const topo::ExactContact& solver,
                   const topo::ExactContactOptions& options, bool by_pressure,
                   const std::vector<topo::ContactStep>& results);

int run_exact_contact(const Options& o, const CLI::App& command) {
  const double modulus = o.material.contact_modulus();
  if (!given(modulus)) usage("the contact modulus is required: --modulus E* [Pa] or --e1 --nu1 --e2 --nu2");
  topo::ExactContactOptions options;
  options.contact_modulus = modulus;
  if (!o.boundary.empty() && !topo::parse_contact_boundary(o.boundary, options.boundary))
    usage("--boundary: '" + quote_text(o.boundary) + "' is not periodic or padded");
  if (!o.kernel.empty() && !topo::parse_contact_kernel(o.kernel, options.kernel))
    usage("--kernel: '" + quote_text(o.kernel) + "' is not fourier or love");
  if (!o.method.empty() && !topo::parse_contact_solver(o.method, options.solver))
    usage("--solver: '" + quote_text(o.method) + "' is not preconditioned or polonsky-keer");
  options.coarse_start = !o.no_coarse_start;
  if (given(o.tolerance)) {
    if (!(o.tolerance >= topo::min_contact_tolerance && o.tolerance <= topo::max_contact_tolerance))
      usage("--tolerance must be from 1e-14 to 0.01");
    options.tolerance = o.tolerance;
  }
  options.max_iterations = static_cast<int>(o.max_iterations);
  options.stiffness = !o.no_stiffness;
  options.max_memory = topo::memory_limit_option(o.max_memory, "--max-memory");
  if (given(o.hardness)) {
    if (!(o.hardness > 0)) usage("--hardness must be positive [Pa]");
    options.hardness = o.hardness;
  }
  CardFormat card_format = CardFormat::calculix;
  CardUnits card_units = CardUnits::si;
  if (!o.card_format.empty() && !parse_card_format(o.card_format, card_format))
    usage("--card-format: '" + quote_text(o.card_format) + "' is not calculix, abaqus or csv");
  if (!o.units.empty() && !parse_card_units(o.units, card_units)) usage("--units: '" + quote_text(o.units) + "' is not si or mm");
  if (o.card.empty() && (!o.card_format.empty() || !o.units.empty() || o.max_points > 0 ||
                         !o.overclosure_datum.empty() || given(o.face_size) || given(o.card_tolerance)))
    usage("--card-format, --units, --max-points, --overclosure-datum, --face-size and --card-tolerance go with --card");
  if (given(o.card_tolerance) && !(o.card_tolerance >= card_tolerance_min && o.card_tolerance <= card_tolerance_max))
    usage("--card-tolerance must be from 1e-06 to 0.1");
  const OverclosureDatum card_datum = overclosure_datum_option(o.overclosure_datum);
  // a measured map has no fitted distribution: no origin (the Weibull origin, the Gaussian's mean)
  if (card_datum == OverclosureDatum::origin)
    usage("--overclosure-datum origin is a fitted distribution's (the Weibull origin, the Gaussian's mean): a "
          "measured map's exact curve has none; give zero-pressure (first contact: the flat at the map's highest "
          "point, the default), mean-summit (the map's mean summit height) or mean-plane (the map's mean plane)");
  face_size_option(o.face_size, card_format, card_units, "--card-format");  // checked before any work
  const Steps steps = steps_from(o);
  adhesion_options(o, options, steps.by_pressure);
  if (o.table.empty() && given(o.table_safety)) usage("--table-safety goes with --table");
  if (o.table.empty() && o.table_max_checks != 0) usage("--table-max-checks goes with --table");
  if (!o.table.empty()) {
    if (!steps.by_pressure) usage("--table needs the nodes as pressures: --pressure or --sweep pressure:FROM:TO:COUNT");
    if (steps.values.size() < 3) usage("--table needs at least 3 pressures");
    for (std::size_t i = 1; i < steps.values.size(); ++i)
      if (!(steps.values[i] > steps.values[i - 1])) usage("--table needs the pressures in ascending order");
    topo::check_exact_contact_table_nodes(steps.values);
    if (o.no_stiffness) usage("--table needs the stiffness: leave out --no-stiffness");
    if (given(o.hardness))
      usage("--table is the elastic contact's (a contact-curves table serves loading and unloading alike): leave out "
            "--hardness");
    if (given(o.table_safety) && !(o.table_safety >= 1 && o.table_safety <= 1000))
      usage("--table-safety must be from 1 to 1000");
  }

  const OutputPlan plan = output_plan(o, steps.values.size());  // before any work
  topo::HeightMap map = topo::read_height_map(o.file, read_options(o.map));
  if (!o.no_level) topo::subtract_plane(map, topo::fit_plane(map));

  // progress on standard error once a solve has run for 2 s, then every 2 s
  using clock = std::chrono::steady_clock;
  clock::time_point step_start = clock::now(), last_line = step_start;
  std::size_t step_index = 0;
  if (!o.quiet)
    options.progress = [&](const topo::ContactProgress& progress) {
      const clock::time_point now = clock::now();
      if (now - step_start < std::chrono::seconds(2) || now - last_line < std::chrono::seconds(2)) return;
      last_line = now;
      std::ostringstream line;
      if (step_index < steps.values.size()) line << "step " << step_index + 1 << "/" << steps.values.size() << ": ";
      else line << "the table's checks between the nodes: ";
      line << progress.stage << " iteration "
           << progress.iteration << ", residual " << progress.residual << ", " << progress.contact_points
           << " points in contact";
      note(command, line.str());
    };
  topo::ExactContact solver(map, options);
  if (steps.by_pressure) for (double p : steps.values) solver.check_pressure(p);  // every step, before the first solve
  OutputTransaction outputs(plan);  // each output staged; renamed into place only when all are done

  std::vector<topo::ContactStep> results;
  for (step_index = 0; step_index < steps.values.size(); ++step_index) {
    step_start = clock::now();
    const double value = steps.values[step_index];
    results.push_back(steps.by_pressure ? solver.at_pressure(value) : solver.at_mean_gap(value));
    if (!o.fields.empty()) stage_fields(outputs, o, solver, map, step_index, results.back().max_pressure);
  }

  std::string table_note;
  if (!o.table.empty()) {
    step_index = steps.values.size();  // the checks: no step number in the progress lines
    step_start = clock::now();
    table_note = stage_table(outputs, o, solver, map, results, steps.values, options);
  }
  std::string card;
  if (!o.card.empty()) {
    std::vector<topo::ContactStep> card_points = results;
    std::string refinement;
    if (given(o.card_tolerance))
      refinement = refine_for_card(solver, card_points, o.card_tolerance,
                                   card_max_points(o.max_points, card_format) > results.size() + 1
                                       ? card_max_points(o.max_points, card_format) - 1 - results.size()
                                       : 0,
                                   command);
    card = stage_card(outputs, o, command, solver, map, card_points, options, card_format, card_units, card_datum,
                      refinement);
  }
  outputs.commit();
  if (!table_note.empty()) note(command, table_note);  // what the table states, not progress: also with --quiet
  if (o.card == "-") std::cout << card;

  print_results(o, map, solver, options, steps.by_pressure, results);
  return exit_success;
}

// The results on standard output: JSON, or '#' lines saying what was solved and a CSV row a step.
void print_results(const Options& o, const topo::HeightMap& map, const topo::ExactContact& solver,
                   const topo::ExactContactOptions& options, bool by_pressure,
                   const std::vector<topo::ContactStep>& results) {
  const std::string boundary = topo::contact_boundary_name(options.boundary);
  const std::string kernel = topo::contact_kernel_name(options.kernel);
  const double modulus = options.contact_modulus;
  if (o.json) {
    std::cout << topo::exact_contact_json(map, !o.no_level, solver, options, by_pressure, results) << "\n";
  } else {
    std::cout << "# asperity exact-contact: " << terminal_text(quote_text(map.source, 4096)) << ", " << map.nx << " x "
              << map.ny << " points, dx " << format_double(map.dx) << " m, dy " << format_double(map.dy) << " m"
              << (o.no_level ? "" : ", leveled") << "\n"
              << "# " << contact_model_words(options) << ", " << boundary << " boundary, " << kernel
              << " kernel, E* " << format_double(modulus) << " Pa, tolerance " << format_double(options.tolerance) << "\n"
              << "# datum: mean_gap_m is the separation of the flat from the mean plane of the map; the mean summit\n"
              << "# height is " << format_double(solver.mean_summit_height()) << " m above it ("
              << solver.summits() << " summits), the highest point " << format_double(solver.max_height()) << " m\n"
              << csv_header<topo::ContactStep>() << "\n";  // the columns of ContactStep's list (exact_contact.hpp)
    for (const topo::ContactStep& s : results) std::cout << csv_row(s) << "\n";
  }
}

}  // namespace

void add_exact_contact_command(CLI::App& app) {
  auto options = std::make_shared<Options>();
  Options& o = *options;
  CLI::App* command = app.add_subcommand(
      "exact-contact",
      "the exact elastic contact of a measured height map with a flat (boundary elements on FFTs): real area, "
      "mean gap, load, stiffness and contact patches at each pressure or mean gap (CSV or JSON)");
  command->add_option("FILE", o.file, "the height map")
      ->required()
      ->check(CLI::Validator([](std::string& path) { return path.empty() ? std::string("an empty path") : std::string(); },
                             ""));
  const char* reading = "Reading";
  add_map_options(*command, o.map, reading);
  command->add_flag("--no-level", o.no_level, "do not subtract the least-squares plane")->group(reading);
  add_material_options(*command, o.material, "contact modulus E* [Pa] (plane strain)", "Material (SI units)");
  const char* load = "Load steps (one kind; solved in the order given, each from the last)";
  add_text(*command, "--pressure", o.pressures, "nominal pressures [Pa], comma-separated")
      ->type_name("PA[,PA...]")->group(load);
  add_text(*command, "--gap", o.gaps, "mean gaps [m] (separations from the mean plane), comma-separated")
      ->type_name("M[,M...]")->group(load);
  add_text(*command, "--sweep", o.sweep, "COUNT steps from FROM to TO: KIND pressure (logarithmic) or gap (linear)")
      ->type_name("KIND:FROM:TO:COUNT")->group(load);
  const char* solver = "Solver";
  add_text(*command, "--boundary", o.boundary,
           "periodic (default: the map repeats) or padded (non-periodic: zero padding to twice the map each way)")
      ->type_name("NAME")->group(solver);
  add_text(*command, "--kernel", o.kernel,
           "fourier (default: the point-force Fourier kernel) or love (pixel-constant pressure, Love's coefficients)")
      ->type_name("NAME")->group(solver);
  add_text(*command, "--solver", o.method,
           "preconditioned (default: the constrained conjugate gradient preconditioned by the inverse Green's "
           "function's 3 x 3 stencil) or polonsky-keer (as published)")
      ->type_name("NAME")->group(solver);
  command->add_flag("--no-coarse-start", o.no_coarse_start,
                    "start each step from the last solution, not from the solution on the map coarsened 2 x 2")
      ->group(solver);
  add_number(*command, "--tolerance", o.tolerance,
             "relative residual: pressure-weighted mean |gap| in contact and largest penetration, in rms heights "
             "(default 1e-8)")
      ->type_name("REL")->group(solver);
  add_whole_number(*command, "--max-iterations", o.max_iterations, 1, 1000000,
                   "per solve; beyond them the command fails (default 20000)")
      ->group(solver);
  add_number(*command, "--hardness", o.hardness,
             "cap the contact pressure at H [Pa] on every point: elastic-perfectly-plastic (points at H are plastic; "
             "plastic_area_fraction, plastic_points); default: elastic")
      ->type_name("PA")->group(solver);
  add_number(*command, "--work-of-adhesion", o.work_of_adhesion,
             "with --adhesive-stress: adhesive contact, the Maugis-Dugdale cohesive zone: the tension of "
             "--adhesive-stress on every point whose gap is within the range W / stress (adhesive_pressure_Pa, "
             "adhesive_points); by mean gap, each step from the last (loading then unloading: the order given), "
             "periodic. W [J/m^2]; default: no adhesion")
      ->type_name("J/M2")->group(solver);
  add_number(*command, "--adhesive-stress", o.adhesive_stress,
             "the Dugdale stress sigma0 [Pa] of --work-of-adhesion (the range W / sigma0 should span a few pixels "
             "of the cohesive zone: docs/exact-contact.md)")
      ->type_name("PA")->group(solver);
  command->add_flag("--no-stiffness", o.no_stiffness, "skip the incremental solve (stiffness 0)")->group(solver);
  add_text(*command, "--max-memory", o.max_memory, topo::max_memory_help)->type_name("SIZE")->group(solver);
  add_quiet_option(*command, &o.quiet)->group(solver);
  const char* output = "Output";
  command->add_flag("--json", o.json,
                    std::string("write JSON (schema ") + topo::exact_contact_json_schema + ") instead of CSV")->group(output);
  add_text(*command, "--fields", o.fields,
           "write each step's pressure and gap fields as 16-bit PGM images into DIR (step-K-pressure.pgm, "
           "step-K-gap.pgm: white at the largest value, first row at the top)")
      ->type_name("DIR")->group(output);
  add_text(*command, "--card", o.card,
           "write the solved curve as a *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR card (overclosure from "
           "first contact: --overclosure-datum); - writes it to standard output, before the results")
      ->type_name("FILE")->group(output);
  add_text(*command, "--table", o.table,
           "write the solved curves as a contact-curves table (HDF5, the tables' format): the pressures asked are "
           "its nodes (ascending, at least 3); solves between each two measure the error of the curves as "
           "served, 2 then 5 an interval and finer where the two estimates differ (--table-max-checks) "
           "(asperity contact --table FILE serves it)")
      ->type_name("FILE")->group(output);
  command->add_flag("--overwrite", o.overwrite,
                    "replace an output file that is not asperity's of that kind (a table, card or field image "
                    "of this command is replaced without it); an input is never written over")
      ->group(output);
  add_number(*command, "--table-safety", o.table_safety,
             "with --table: the stored error bound is the measured one times this (default 2)")
      ->type_name("FACTOR")->group(output);
  add_whole_number(*command, "--table-max-checks", o.table_max_checks, 5, 1535,
                   "with --table: at most N checks an interval, where its error estimate has not settled "
                   "(default 47; the levels have 2, 5, 11, 23, 47, 95, ... checks)")
      ->group(output);
  add_text(*command, "--card-format", o.card_format, "calculix (default), abaqus or csv")->type_name("FORMAT")->group(output);
  add_whole_number(*command, "--max-points", o.max_points, static_cast<long long>(card_points_min),
                   static_cast<long long>(card_points_max),
                   "at most N rows in the card (default: 200 for calculix, what its node-to-surface contact holds; "
                   "no cap for abaqus and csv); with more solutions, points are dropped where linear interpolation "
                   "between the rows kept is within the smallest tolerance that fits (a warning says which)")
      ->group(output);
  add_text(*command, "--overclosure-datum", o.overclosure_datum,
           "where the card's overclosure is zero: zero-pressure (default; first contact: the flat at the map's "
           "highest point; every overclosure >= 0), mean-summit (the flat at the map's mean summit height) or "
           "mean-plane (the flat at the map's mean plane: overclosure -mean_gap_m). Not origin: a measured map has no "
           "fitted distribution")
      ->type_name("DATUM")->group(output);
  add_face_size_option(*command, o.face_size, "with a calculix card", output);
  add_number(*command, "--card-tolerance", o.card_tolerance,
             "with --card: solve more where the curve bends: between neighbouring solved points one more solve at "
             "the middle mean gap, split again where linear interpolation misses it by more than REL (relative, in "
             "pressure); the card's header states the solves added and the error measured")
      ->type_name("REL")->group(output);
  add_text(*command, "--units", o.units, "of the card: si (m, Pa; default) or mm (mm, MPa)")->type_name("UNITS")->group(output);
  command->footer(
      "Output: CSV, one row per step: pressure_Pa (nominal: load over the map's area), load_N,\n"
      "mean_gap_m (the separation of the flat from the map's mean plane: the mean gap), \n"
      "separation_from_mean_summit_m (less the mean summit height: the GW curves' datum), approach_m\n"
      "(the flat's rigid-body position), area_fraction, real_area_m2, contact_points, clusters (4-neighbour\n"
      "patches), plastic_area_fraction, plastic_points (at --hardness; 0 elastic),\n"
      "adhesive_pressure_Pa, adhesive_points (the cohesive zone's tension and points; 0 without adhesion),\n"
      "stiffness_N_per_m (-dP/d mean gap, from the incremental solve), stiffness_per_area_N_per_m3,\n"
      "approach_stiffness_N_per_m, max_pressure_Pa, iterations, solves, residual, stiffness_iterations,\n"
      "stiffness_residual; '#' lines first say what was solved (docs/exact-contact.md). A solve that does\n"
      "not converge is an error. Progress goes to standard error once a solve runs for 2 s.\n" +
      std::string(exit_status_help));
  CLI::App* self = command;
  set_action(*command, [options, self] {
    try {
      return run_exact_contact(*options, *self);
    } catch (const std::bad_alloc&) {  // the solver's own are asperity::Errors with its figures
      throw Error("out of memory running on '" + quote_text(options->file, 4096) +
                  "' (the map, or the outputs): give a smaller map, or see --max-memory");
    }
  });
}

}  // namespace asperity::cli
