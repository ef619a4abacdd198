#include "surface_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <thread>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/surface.hpp"
#include "asperity/topography/surface_formats.hpp"
#include "asperity/topography/analysis.hpp"
#include "asperity/topography/exact_contact.hpp"
#include "asperity/topography/surface_report.hpp"
#include "asperity/topography/units.hpp"
#include "asperity/topography/next_steps.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/output.hpp"
#include "asperity/pressure_overclosure.hpp"
#include "asperity/table.hpp"
#include "fe_card_options.hpp"
#include "command_line.hpp"
#include "option_helpers.hpp"
#include "law_options.hpp"
#include "map_options.hpp"
#include "asperity/number_text.hpp"

namespace asperity::cli {
namespace {
namespace topo = asperity::topography;

constexpr double not_given = NAN;  // add_number only ever stores finite numbers

struct Options {
  std::string file, summit_threshold, pressures, loads, table, report, exact_boundary, exact_kernel, card, card_format;
  MapOptions map;             // how the map is read (map_options.hpp)
  MaterialOptions material;   // --modulus, or --e1 --nu1 --e2 --nu2
  double area = not_given, confidence = not_given;
  long long window = 1, ensemble = -1, bootstrap = -1, seed = 1, threads = 0, exact_points = 13;
  double exact_tolerance = not_given;
  std::string max_memory;  // empty: the memory available (topo::memory_limit_option)
  bool json = false, no_level = false, no_height_fit = false, exact = false, no_exact = false, no_persson = false,
       overwrite = false;
  LawOptions law;  // a contact law beside the elastic curves (law_options.hpp)
};

// What the analysis of a map needs [bytes], from the peak resident memory measured on the
// maps of tests/data/surfaces (docs/reliability.md, "Memory"): 13 MB for the process, 78 bytes a
// point for the statistics, summits and fits; with an ensemble 205 bytes a point and 106 more a
// thread (the surrogates' padded transforms); with contact curves 80 MB (the scene tables they
// generate); with --exact the solver's own estimate.
struct SurfaceMemory {
  std::size_t total = 0, ensemble = 0, exact = 0;
  int threads = 1;
};

SurfaceMemory surface_memory(const topo::HeightMap& map, const topo::AnalysisOptions& options) {
  SurfaceMemory memory;
  const double points = static_cast<double>(map.nx) * static_cast<double>(map.ny);
  const int bootstrap = options.assessment.bootstrap;
  memory.threads = options.assessment.threads > 0 ? options.assessment.threads
                                                  : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  memory.threads = std::max(1, std::min(memory.threads, bootstrap));
  double total = 13e6 + 78 * points;
  if (bootstrap > 0) {
    const double ensemble = points * (205 + 106.0 * memory.threads);
    memory.ensemble = static_cast<std::size_t>(std::min(ensemble, 1e18));
    total += ensemble;
  }
  if (options.contact) total += 80e6;
  if (options.contact && topo::exact_contact_wanted(*options.contact, map.nx * map.ny)) {
    topo::ExactContactOptions exact;
    exact.boundary = options.contact->exact_boundary;
    exact.kernel = options.contact->exact_kernel;
    exact.threads = options.contact->threads;
    memory.exact = topo::exact_contact_memory(map.nx, map.ny, exact);
    total += static_cast<double>(memory.exact);
  }
  memory.total = static_cast<std::size_t>(std::min(total, 1.8e19));
  return memory;
}

std::string memory_in_words(const topo::HeightMap& map, const SurfaceMemory& memory) {
  std::string text = "the analysis of '" + quote_text(map.source, 4096) + "' (" + std::to_string(map.nx) + " x " +
                     std::to_string(map.ny) + " points) needs about " + topo::memory_text(memory.total);
  if (memory.ensemble > 0 || memory.exact > 0) {
    text += " (";
    if (memory.ensemble > 0)
      text += "the surrogate surfaces on " + std::to_string(memory.threads) + " threads " + topo::memory_text(memory.ensemble);
    if (memory.exact > 0) text += std::string(memory.ensemble > 0 ? ", " : "") + "the exact contact " + topo::memory_text(memory.exact);
    text += ")";
  }
  return text;
}

const char* const less_memory_advice =
    "crop or decimate the map (half the points each way needs a quarter of the memory), fewer --threads, --ensemble 0, "
    "or --exact-boundary periodic";

// analysis_summary prints the map's source as it is: its control bytes must not reach the terminal
std::string summary_text(topo::SurfaceAnalysis& analysis) {
  const std::string source = analysis.map.source;
  analysis.map.source = terminal_text(quote_text(source, 4096));
  std::string text = topo::analysis_summary(analysis);
  analysis.map.source = source;
  return text;
}

// --card FILE: the pressure-overclosure card of the model the verdict names, what next_steps'
// card command writes (the default table, the card's defaults, the contact's pressure range);
// none named: refused, naming the exact contact's card instead.
void write_named_card(const topo::SurfaceAnalysis& a, const Options& o, const CLI::App& command, CardFormat format) {
  const topo::NextSteps next = topo::next_steps(a);
  const topo::ModelContact* curves = next.model && a.contact ? a.contact->find(*next.model) : nullptr;
  if (!curves || !curves->served)
    throw Error("--card: " + next.why + (next.exact_command.empty() ? "" : "; the map's exact contact has a card: " +
                                                                         next.exact_command));
  const Table table = o.table.empty() ? Table::open_default() : Table::open(o.table);
  const ContactModel model(table, curves->surface);
  const topo::ContactComparison& c = *a.contact;
  const OverclosureDatum datum = cli::overclosure_datum_option("");
  const PressureOverclosureTable card = tabulate_pressure_overclosure(
      model, c.pressure_min, c.pressure_max, 1e-3, datum, cli::card_max_points(0, format));
  std::ostringstream out;
  write_pressure_overclosure(out, card, format, CardUnits::si,
                             "asperity " ASPERITY_VERSION_STRING ": the pressure-overclosure law (Greenwood-Williamson) "
                             "of the model asperity surface names for " + a.map.source + ": " + next.why);
  OutputPlan plan(o.overwrite);
  plan.input(o.file);
  plan.file("--card", o.card, output_kinds::card);
  plan.check();
  OutputTransaction outputs(plan);
  outputs.stage(o.card, out.str());
  outputs.commit();
  note(command, "--card " + o.card + ": " + topo::contact_model_name(next.model) + ", " + std::to_string(card.points.size()) +
                    " points from " + format_double(c.pressure_min) + " to " + format_double(c.pressure_max) +
                    " Pa, overclosure from the " + datum_name(datum) + " datum (the same card: " + next.card_command + ")");
}

int run_surface(const Options& o, const CLI::App& command) {
  topo::AnalysisOptions options;
  options.read = read_options(o.map);
  options.level = !o.no_level;
  options.summits.window = static_cast<int>(o.window);
  if (!o.summit_threshold.empty()) options.summits.min_drop = topo::parse_length(o.summit_threshold);
  if (o.ensemble >= 0 && o.bootstrap >= 0) usage("give --ensemble or --bootstrap (its former name), not both");
  if (o.ensemble >= 0 || o.bootstrap >= 0) options.assessment.bootstrap = static_cast<int>(o.ensemble >= 0 ? o.ensemble : o.bootstrap);
  options.assessment.seed = static_cast<std::uint64_t>(o.seed);
  options.assessment.threads = static_cast<int>(o.threads);
  if (given(o.confidence)) {
    if (!(o.confidence > 0 && o.confidence < 1)) usage("--confidence must lie between 0 and 1");
    options.assessment.confidence = o.confidence;
  }
  options.fit_heights = !o.no_height_fit;
  if (given(o.area) && !(o.area > 0)) usage("--area must be positive");

  const double modulus = o.material.contact_modulus();
  const bool exact_options = !o.exact_boundary.empty() || !o.exact_kernel.empty() || given(o.exact_tolerance);
  if (o.exact && o.no_exact) usage("--exact and --no-exact: give one");
  if (exact_options && o.no_exact)
    usage("--exact-boundary, --exact-kernel and --exact-tolerance set the exact contact: not with --no-exact");
  const bool contact = given(modulus) || !o.pressures.empty() || !o.loads.empty() || !o.table.empty() || given(o.area) ||
                       o.exact || o.no_exact || o.no_persson || !o.law.law.empty() || !o.card.empty();
  if (contact && !given(modulus))
    usage("the contact curves (--pressure, --load, --area, --table, --exact, --law, --card) need the contact modulus: --modulus "
          "E* [Pa] or --e1 --nu1 --e2 --nu2");
  check_no_law_options(o.law);
  if (!o.law.law.empty()) law_values(o.law);  // the law and its material checked before the analysis
  std::vector<double> pressures, loads;
  if (!o.pressures.empty()) pressures = positive_numbers(o.pressures, "--pressure");
  if (!o.loads.empty()) loads = positive_numbers(o.loads, "--load");

  const std::size_t memory_limit = topo::memory_limit_option(o.max_memory, "--max-memory");
  // the report folder checked before any work (the output policy: docs/reliability.md)
  if (!o.report.empty()) topo::report_plan(o.report, o.file, o.overwrite);
  CardFormat card_format = CardFormat::calculix;
  if (!o.card.empty()) {
    if (!o.card_format.empty() && !parse_card_format(o.card_format, card_format))
      usage("--card-format: calculix, abaqus or csv, not '" + quote_text(o.card_format) + "'");
    OutputPlan plan(o.overwrite);  // checked before any work too
    plan.input(o.file);
    plan.file("--card", o.card, output_kinds::card);
    plan.check();
  } else if (!o.card_format.empty()) {
    usage("--card-format goes with --card FILE");
  }
  topo::HeightMap map = topo::read_height_map(o.file, options.read);
  if (contact) {
    topo::ContactOptions curves;
    curves.contact_modulus = modulus;
    curves.nominal_area = given(o.area) ? o.area : 0;
    curves.table_path = o.table;
    curves.threads = options.assessment.threads;
    curves.persson = !o.no_persson;
    curves.exact = o.exact;
    curves.exact_auto = !o.no_exact;
    curves.exact_points = static_cast<int>(o.exact_points);
    if (!o.exact_boundary.empty() && !topo::parse_contact_boundary(o.exact_boundary, curves.exact_boundary))
      usage("--exact-boundary: periodic or padded, not '" + quote_text(o.exact_boundary) + "'");
    if (!o.exact_kernel.empty() && !topo::parse_contact_kernel(o.exact_kernel, curves.exact_kernel))
      usage("--exact-kernel: fourier or love, not '" + quote_text(o.exact_kernel) + "'");
    if (given(o.exact_tolerance)) {
      if (!(o.exact_tolerance >= topo::min_contact_tolerance && o.exact_tolerance <= topo::max_contact_tolerance))
        usage("--exact-tolerance must lie in [1e-14, 1e-2]");
      curves.exact_tolerance = o.exact_tolerance;
    }
    curves.pressures = pressures;
    // loads over the nominal area: A0 given, or the measured area
    const double a0 = given(o.area) ? o.area : map.width() * map.length();
    for (double load : loads) curves.pressures.push_back(nominal_pressure_from_load(load, a0));
    options.contact = curves;
    if (!o.law.law.empty()) {
      options.law = [law = o.law](const RoughSurface& surface, double s_min, double s_max, double approach) {
        return law_scene(law, surface, s_min, s_max, "asperity surface --law", approach);
      };
      options.law_approach_separation = o.law.approach_separation;
    }
  }
  // progress on standard error for an ensemble that takes more than a second: a line that
  // rewrites itself on a terminal, a line every few seconds otherwise
  const auto start = std::chrono::steady_clock::now();
  auto last = start;
  bool printed = false;
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  options.progress = [&](std::size_t done, std::size_t total) {
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    const double since = std::chrono::duration<double>(now - last).count();
    if (quiet() || elapsed < 1 || (since < (terminal ? 0.2 : 5) && done < total)) return;
    last = now;
    const double left = elapsed / static_cast<double>(done) * static_cast<double>(total - done);
    std::fprintf(stderr, "%sasperity surface: ensemble %zu/%zu surrogate surfaces, about %.0f s left%s",
                 terminal ? "\r" : "", done, total, left, terminal ? "  " : "\n");
    printed = true;
  };
  const auto exact_start = std::make_shared<std::chrono::steady_clock::time_point>();
  options.exact_progress = [&, exact_start](std::size_t done, std::size_t total) {
    const auto now = std::chrono::steady_clock::now();
    if (done == 1) *exact_start = now;  // the first step includes setting up the solver
    const double elapsed = std::chrono::duration<double>(now - *exact_start).count();
    const double since = std::chrono::duration<double>(now - last).count();
    if (quiet() || (since < (terminal ? 0.2 : 5) && done < total)) return;
    last = now;
    const double left = done > 1 ? elapsed / static_cast<double>(done - 1) * static_cast<double>(total - done) : 0;
    std::fprintf(stderr, "%sasperity surface: exact contact, load step %zu/%zu, about %.0f s left%s",
                 terminal ? "\r" : "", done, total, left, terminal ? "  " : "\n");
    printed = true;
  };
  const SurfaceMemory memory = surface_memory(map, options);
  if (memory_limit > 0 && memory.total > memory_limit)
    throw Error(memory_in_words(map, memory) + ", more than the " + topo::memory_text(memory_limit) +
                " allowed (--max-memory): " + less_memory_advice + ", or allow more");
  const std::string in_words = memory_in_words(map, memory);
  std::optional<topo::SurfaceAnalysis> analysed;
  try {
    analysed = topo::analyse_height_map(std::move(map), options);
  } catch (const std::bad_alloc&) {
    throw Error("out of memory: " + in_words + " and the system gave less: " + less_memory_advice);
  }
  topo::SurfaceAnalysis& analysis = *analysed;
  if (printed && terminal) std::fputc('\n', stderr);
  std::cout << (o.json ? topo::analysis_json(analysis) : summary_text(analysis));
  if (!o.report.empty()) {
    const topo::ReportOutcome outcome = topo::write_report(analysis, o.report, o.overwrite);
    if (!o.json)
      std::cout << "  report: " << terminal_text(quote_text(outcome.files.front(), 4096)) << " (" << outcome.files.size()
                << " files)\n";
  }
  // statistics only: what was asked beyond them (summits, fits, curves) does not exist
  if (!o.card.empty() && !analysis.noise_floor.reached) write_named_card(analysis, o, command, card_format);
  if (analysis.noise_floor.reached) throw Error(quote_text(analysis.map.source, 4096) + ": " + analysis.noise_floor.text);
  return exit_success;
}

}  // namespace

void add_surface_command(CLI::App& app) {
  auto options = std::make_shared<Options>();
  Options& o = *options;
  CLI::App* command = app.add_subcommand(
      "surface", "a measured height map (" + topo::surface_format_list() + ") to its statistics, summits, the "
                 "Gaussian and two three-parameter Weibulls fitted to its summit heights with their goodness of "
                 "fit, and (with --modulus) the contact curves of each fit side by side");
  command->add_option("FILE", o.file, "the height map")
      ->required()
      ->check(CLI::Validator([](std::string& path) { return path.empty() ? std::string("an empty path") : std::string(); },
                             ""));
  add_map_options(*command, o.map, "Reading");
  const char* analysis = "Analysis";
  command->add_flag("--no-level", o.no_level, "do not subtract the least-squares plane")->group(analysis);
  add_whole_number(*command, "--summit-window", o.window, 1, 1000,
                   "summits: highest within this many points (1: the 8 neighbours; default 1)")
      ->group(analysis);
  add_text(*command, "--summit-threshold", o.summit_threshold,
           "summits: at least this high above the mean of their 8 neighbours (a length with its unit, e.g. 2nm)")
      ->type_name("LENGTH")->group(analysis);
  add_whole_number(*command, "--ensemble", o.ensemble, 0, 100000,
                   "surrogate surfaces of the map's own spectrum for the p-values and intervals (default 99; at "
                   "least 40: the verdict tests at 2.5%; 0: no tests)")
      ->group(analysis);
  add_whole_number(*command, "--bootstrap", o.bootstrap, 0, 100000, "the same as --ensemble (its former name)")
      ->group(analysis);
  add_number(*command, "--confidence", o.confidence, "of the intervals (default 0.95)")->type_name("P")->group(analysis);
  add_whole_number(*command, "--seed", o.seed, 0, 9223372036854775807LL, "of the ensemble (default 1: reproducible)")
      ->group(analysis);
  add_whole_number(*command, "--threads", o.threads, 0, 1024,
                   "for the ensemble and the scene tables (default 0: all cores; fewer if the system refuses more)")
      ->group(analysis);
  command->add_flag("--no-height-fit", o.no_height_fit, "fit the summit heights only")->group(analysis);
  add_text(*command, "--max-memory", o.max_memory, topo::max_memory_help)->type_name("SIZE")->group(analysis);
  const char* contact = "Contact curves (SI units)";
  add_material_options(*command, o.material, "contact modulus E* [Pa] (plane strain): gives the contact curves", contact);
  add_text(*command, "--pressure", o.pressures,
           "nominal pressures of interest [Pa], comma-separated (default E* x 1e-5,1e-4,1e-3)")
      ->type_name("PA[,PA...]")->group(contact);
  add_text(*command, "--load", o.loads, "loads of interest [N], comma-separated (over the nominal area)")
      ->type_name("N[,N...]")->group(contact);
  add_number(*command, "--area", o.area, "nominal contact area A0 [m^2] (default: the measured area)")
      ->type_name("M2")->group(contact);
  add_text(*command, "--table", o.table,
           "a full table for the Weibull curves instead of exact-shape scene tables (default: scene tables made "
           "for the fitted shapes)")
      ->type_name("FILE")->group(contact);
  command->add_flag("--exact", o.exact,
                    "solve the exact elastic contact of the map (boundary elements, docs/exact-contact.md) and "
                    "compare every model with it at any size (by default it is solved for maps of at most " +
                        std::to_string(topo::exact_auto_max_points) + " points: 256 x 256 adds about 2 s; larger "
                        "maps take seconds to minutes)")
      ->group(contact);
  command->add_flag("--no-exact", o.no_exact, "leave out the exact contact even on a small map")->group(contact);
  add_text(*command, "--exact-boundary", o.exact_boundary,
           "padded (default: the map as a patch of a half-space; a measured map is not periodic) or periodic")
      ->type_name("NAME")->group(contact);
  add_text(*command, "--exact-kernel", o.exact_kernel, "love (default: pixel-constant pressure) or fourier")
      ->type_name("NAME")->group(contact);
  add_whole_number(*command, "--exact-points", o.exact_points, 2, 1000,
                   "exact solves along the curves' pressure range, besides the pressures of interest (default 13)")
      ->group(contact);
  add_number(*command, "--exact-tolerance", o.exact_tolerance, "of each exact solve (default 1e-8)")
      ->type_name("TOL")->group(contact);
  command->add_flag("--no-persson", o.no_persson, "leave out Persson's theory of the map's spectrum")->group(contact);
  add_law_options(*command, o.law, "a contact law beside the elastic curves (with --modulus)",
                  " with its material; gives the regime of the measured summits (an elastic-plastic law's "
                  "plasticity index, an adhesive law's adhesion parameter) and the law's curves on the fit the "
                  "verdict names (docs/surfaces.md)",
                  "in the fitted model's height scale, origin convention, as the report's law separations; the "
                  "approach must reach the largest pressure compared");
  const char* output = "Output";
  add_text(*command, "--report", o.report,
           "write a report directory: report.md, report.json, curves.csv, summits.csv, plots")
      ->type_name("DIR")->group(output);
  add_quiet_option(*command)->group(output);
  add_text(*command, "--card", o.card,
           "write the pressure-overclosure card of the model the verdict names for the contact (what the summary's "
           "next steps print as its card command; needs --modulus); none named: refused, naming the exact contact's card")
      ->type_name("FILE")->group(output);
  add_text(*command, "--card-format", o.card_format, "with --card: calculix (default), abaqus or csv")
      ->type_name("FORMAT")->group(output);
  command->add_flag("--json", o.json,
                    std::string("write the JSON (schema ") + topo::surface_json_schema + ") instead of the summary")
      ->group(output);
  command->add_flag("--overwrite", o.overwrite,
                    "with --report: replace files in DIR that are not asperity's report files (a report's own files "
                    "are replaced without it); the map is never written over")
      ->group(output);
  command->footer(
      "Output: a summary on standard output (or the JSON with --json): the map and how it was read,\n"
      "height statistics, spectral moments and Nayak's alpha, summits (density, radius, their\n"
      "dependence on the sampling interval), the three fits of the summit heights with Anderson-Darling\n"
      "and Kolmogorov-Smirnov p-values against surrogate surfaces of the map's spectrum, AIC and a verdict,\n"
      "and with a modulus GW on the measured summits beside\n"
      "the contact curves of each fit and their ratios at the pressures of interest, Persson's theory of\n"
      "the map's spectrum, and with --exact the exact elastic contact of the map, which every curve is\n"
      "then compared with (docs/surfaces.md, docs/exact-contact.md).\n"
      "With --law NAME and its material: the regime of the measured summits (an elastic-plastic law's\n"
      "plasticity index psi, the law's (sigma_s/omega_c)^1/2 and GW's (E*/H)(sigma_s/R)^1/2, sigma_s the\n"
      "summit heights' standard deviation, R the summit radius, GW: psi < 0.6 elastic, > 1 plastic; an\n"
      "adhesive law's Fuller-Tabor adhesion parameter sigma_s/delta_c) and the law's curves\n"
      "(separation, real area, stiffness) on the fit the verdict names, next to its elastic ones, at\n"
      "the pressures of interest (the report's law.svg; curves.csv rows law:NAME).\n" +
      std::string(exit_status_help));
  CLI::App* self = command;
  set_action(*command, [options, self] {
    try {
      return run_surface(*options, *self);
    } catch (const std::bad_alloc&) {  // the analysis's own name its estimate
      throw Error("out of memory reading '" + quote_text(options->file, 4096) + "': give a smaller map");
    }
  });
}

}  // namespace asperity::cli
