// tablegen: generate an asperity table file (the generator: asperity/generator/; the command
// line on CLI11: apps/common/command_line.hpp).
//   tablegen --out FILE [--shapes LO:HI:STEP] [--sides tail,bounded] [--gaussian|--no-gaussian]
//            [--tolerance REL] [--density F] [--threads N] [--quiet]
//   tablegen --scene SCENE.toml --out FILE [--threads N] [--quiet]
// Everything that can be checked before the generator runs is checked here, with what is allowed.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "asperity/contact_curves_data.hpp"
#include "asperity/error.hpp"
#include "asperity/output.hpp"
#include "asperity/scene.hpp"
#include "asperity/table_file.hpp"
#include "command_line.hpp"
#include "option_helpers.hpp"
#include "asperity/generator/generate.hpp"
#include "asperity/number_text.hpp"
#include "asperity/generator/law_curves.hpp"
#include "asperity/generator/scene_table.hpp"
#include "asperity/table_writer.hpp"

namespace {

using namespace asperity;
using cli::approximately;
using cli::usage;


// The generator's reach (checked here so that a request beyond it is refused with what is
// allowed, not answered by a quadrature error): Weibull shapes, including the interpolation
// nodes past each end of a grid, within the scene limits; at most this many grid shapes; on a
// Weibull tail, s^a (the exponent of exp(-s^a)) at most 1e100, where the quadrature that checks
// every curve still works (measured: it fails from about 1e130 at a = 50).
constexpr int max_grid_shapes = 1000;
constexpr double max_tail_exponent_log = 100 * 2.302585092994046;  // ln(1e100)

struct Options {
  generator::GenerateOptions generate;
  std::string out, scene, shapes, sides;
  double tolerance = NAN, density = NAN;
  long long threads = 0;
  bool gaussian = false, no_gaussian = false, quiet = false, overwrite = false;
};

// --out under the output policy (asperity/output.hpp), checked before any tabulation: a file that
// is not a table of ours of this kind is replaced only with --overwrite; the scene never.
void check_out(const Options& options, const OutputKind& kind) {
  OutputPlan plan(options.overwrite);
  if (!options.scene.empty()) plan.input(options.scene);
  plan.file("--out", options.out, kind);
  plan.check();
}


// Parses and checks --shapes LO:HI:STEP against the generator's reach before it runs.
void apply_shapes(const std::string& spec, generator::GenerateOptions& options) {
  std::vector<std::string> parts;
  std::stringstream stream(spec);
  for (std::string part; std::getline(stream, part, ':');) parts.push_back(part);
  if (parts.size() != 3 || spec.back() == ':') usage("--shapes wants LO:HI:STEP, got '" + quote_text(spec) + "'");
  const double lo = cli::number_from_text(parts[0], "--shapes LO"), hi = cli::number_from_text(parts[1], "--shapes HI");
  const double step = cli::number_from_text(parts[2], "--shapes STEP");
  const std::string limits = "[" + format_double(weibull_shape_min) + ", " + format_double(weibull_shape_max) + "]";
  if (!(lo >= weibull_shape_min && hi <= weibull_shape_max && lo <= hi))
    usage("--shapes needs " + format_double(weibull_shape_min) + " <= LO <= HI <= " + format_double(weibull_shape_max) +
          ", got LO " + format_double(lo) + ", HI " + format_double(hi));
  if (!(step > 0)) usage("--shapes needs STEP > 0");
  // The grid's spacing in q = ln a - 1/a is at most STEP (2/3 of it on the bounded side): bound
  // the node count before making it.
  const double factor = generator::GenerateOptions::bounded_step_factor;
  const double intervals = (shape_grid_variable(hi) - shape_grid_variable(lo)) / (step * factor);
  if (!(intervals <= max_grid_shapes)) {
    usage("--shapes " + quote_text(spec) + " asks for about " + format_double(std::ceil(intervals)) +
          " grid shapes on the bounded side; at most " + std::to_string(max_grid_shapes) + " (STEP >= " +
          approximately(1.001 * (shape_grid_variable(hi) - shape_grid_variable(lo)) / (max_grid_shapes * factor)) +
          " for this range)");
  }
  options.shape_min = lo;
  options.shape_max = hi;
  options.shape_log_step = step;
  const std::vector<double> grid = generator::shape_grid(options);
  if (grid.front() < weibull_shape_min || grid.back() > weibull_shape_max) {
    usage("--shapes " + quote_text(spec) + ": the grid runs " + std::to_string(shape_stencil / 2) +
          " nodes past each end (for the interpolation between shapes), here from " + approximately(grid.front()) +
          " to " + approximately(grid.back()) + "; every node must be within " + limits +
          ": bring LO and HI inside or make STEP smaller");
  }
}

void apply_sides(const std::string& sides, generator::GenerateOptions& options) {
  options.tail = options.bounded = false;
  std::stringstream stream(sides);
  for (std::string side; std::getline(stream, side, ',');) {
    if (side == "tail") options.tail = true;
    else if (side == "bounded") options.bounded = true;
    else if (side == "both") options.tail = options.bounded = true;
    else if (side != "none") usage("--sides: unknown side '" + quote_text(side) + "' (tail, bounded, both, none)");
  }
}

// A scene's requests checked against the generator's reach before it runs.
void check_scene(const Scene& scene) {
  for (const SceneCurve& curve : scene.curves) {
    if (curve.by_load || curve.distribution != Distribution::weibull || curve.side != Side::tail) continue;
    if (!(curve.range_max > 0) || curve.shape * std::log(curve.range_max) <= max_tail_exponent_log) continue;
    const double reach = std::exp(max_tail_exponent_log / curve.shape);
    throw Error(scene.source + ":" + std::to_string(curve.line) + ": " +
                (curve.name.empty() ? std::string("a curve") : "curve '" + curve.name + "'") +
                ": separations up to " + format_double(curve.range_max) + " at shape " + format_double(curve.shape) +
                " reach s^a = 1e" + format_double(std::floor(curve.shape * std::log10(curve.range_max))) +
                "; the generator's quadrature reaches s^a = 1e100, here s <= " + approximately(reach) +
                " (the series of asymptotic.hpp serve beyond)");
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A scene's progress on standard error: the step the generator is at, shown when it changes (at
// most a line a second) and at least every 5 s while it lasts, with the time elapsed, so that a
// log shows which curve a long run is on and that it is alive.
class ProgressLine {
 public:
  ProgressLine(bool enabled, std::chrono::steady_clock::time_point start) : enabled_(enabled), start_(start) {
    if (enabled_) ticker_ = std::thread([this] { tick(); });
  }
  ~ProgressLine() {
    if (!enabled_) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_one();
    ticker_.join();
  }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // From any thread.
  void set(std::string step) {
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    step_ = std::move(step);
    if (std::chrono::steady_clock::now() - shown_ >= std::chrono::seconds(1)) show();
  }

 private:
  void tick() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(500), [this] { return done_; }))
      if (!step_.empty() && std::chrono::steady_clock::now() - shown_ >= std::chrono::seconds(5)) show();
  }
  void show() {  // the mutex held
    shown_ = std::chrono::steady_clock::now();
    std::fprintf(stderr, "tablegen: %s, %.0f s\n", step_.c_str(), std::chrono::duration<double>(shown_ - start_).count());
    std::fflush(stderr);
  }
  const bool enabled_;
  const std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point shown_{};
  std::string step_;
  bool done_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread ticker_;
};

// A law scene: the law's rough-surface curves as a contact-curves table
int generate_law_scene(const Options& options, const Scene& scene, std::chrono::steady_clock::time_point start) {
  const SceneLaw& law = scene.laws.front();
  check_out(options, output_kinds::contact_curves_table);
  if (!options.quiet)
    std::fprintf(stderr, "tablegen: scene %s: the %s law's curves\n", quote_text(options.scene, 200).c_str(),
                 contact_law_name(law.law.kind));
  generator::LawCurvesResult result;
  {
    ProgressLine line(!options.quiet, start);
    const std::string law_name = contact_law_name(law.law.kind);
    result = generator::generate_law_curves(law, "--scene " + quote_text(options.scene, 200),
                                            [&](const generator::LawCurvesProgress& at) {
                                              line.set(law_name + ": pass " + std::to_string(at.pass) + ", " +
                                                       std::to_string(at.nodes) + " nodes, interval " +
                                                       std::to_string(at.checked) + "/" + std::to_string(at.intervals) +
                                                       " checked, " + std::to_string(at.evaluations) +
                                                       " exact evaluations");
                                            });
  }
  if (!options.quiet) std::fprintf(stderr, "tablegen: writing %s\n", quote_text(options.out, 200).c_str());
  write_contact_curves_file(result.data, options.out, options.overwrite);
  const ContactCurvesData& data = result.data;
  std::printf("%-18s %-8s %-8s %7s %-20s %9s %36s %6s %8s\n", "law", "dist", "side", "shape", "separations", "asked",
              "achieved p / k / a / count", "nodes", "evals");
  char range[64], achieved[80];
  std::snprintf(range, sizeof range, "[%.4g, %.4g]", law.range_min, law.range_max);
  std::snprintf(achieved, sizeof achieved, "%.2g / %.2g / %.2g / %.2g", data.max_rel_error[0], data.max_rel_error[1],
                data.max_rel_error[2], data.summit_count_max_rel_error);
  std::printf("%-18s %-8s %-8s %7.4g %-20s %9.2g %36s %6d %8d\n", contact_law_name(law.law.kind),
              to_string(law.distribution), to_string(law.side), law.shape, range, law.max_rel_error, achieved,
              result.nodes, result.evaluations);
  // an adhesive law's bounds on p and k are relative to the gross (compressive + tensile) values
  std::printf("wrote %s: a contact-curves table%s, %d nodes, %.2f s\n", options.out.c_str(),
              data.has_tension() ? " with a tensile part (the approach branch; p and k bounds relative to the gross)" : "",
              result.nodes, seconds_since(start));
  return cli::exit_success;
}

int generate_scene(const Options& options, int threads) {
  const auto start = std::chrono::steady_clock::now();
  const Scene scene = read_scene_file(options.scene);
  if (!scene.laws.empty()) return generate_law_scene(options, scene, start);
  check_scene(scene);
  check_out(options, output_kinds::gw_table);
  if (!options.quiet)
    std::fprintf(stderr, "tablegen: scene %s: %zu curves\n", quote_text(options.scene, 200).c_str(), scene.curves.size());
  generator::SceneResult result;
  {
    ProgressLine line(!options.quiet, start);
    result = generator::generate_scene_table(scene, threads, [&](const std::string& step) { line.set(step); });
  }
  if (!options.quiet) std::fprintf(stderr, "tablegen: writing %s\n", quote_text(options.out, 200).c_str());
  write_table_file(result.table, options.out, options.overwrite);
  std::printf("%-16s %-8s %-8s %7s %-14s %-24s %9s %9s %6s %8s\n", "curve", "dist", "side", "shape", "orders",
              "separations", "asked", "achieved", "knots", "memory");
  std::size_t bytes = 0;
  for (const generator::SceneCurveReport& report : result.curves) {
    std::string orders;
    for (int twice_order : report.curve.twice_orders)
      orders += (orders.empty() ? "" : ",") + std::string(twice_order % 2 ? std::to_string(twice_order) + "/2"
                                                                          : std::to_string(twice_order / 2));
    char range[64];
    std::snprintf(range, sizeof range, "[%.4g, %.4g]", report.separation_min, report.separation_max);
    std::printf("%-16s %-8s %-8s %7.4g %-14s %-24s %9.2g %9.2g %6d %5.1f KiB\n",
                report.curve.name.empty() ? "-" : report.curve.name.c_str(), to_string(report.curve.distribution),
                to_string(report.curve.side), report.curve.shape, orders.c_str(), range, report.curve.max_rel_error,
                report.achieved_error, report.knots, report.memory_bytes / 1024.0);
    bytes += report.memory_bytes;
  }
  std::printf("wrote %s: %zu curves, %.1f KiB in memory, %.2f s\n", options.out.c_str(), result.curves.size(),
              bytes / 1024.0, seconds_since(start));
  return cli::exit_success;
}

int generate(Options options) {
  generator::GenerateOptions& generate = options.generate;
  if (!options.shapes.empty()) apply_shapes(options.shapes, generate);
  if (!options.sides.empty()) apply_sides(options.sides, generate);
  if (options.gaussian && options.no_gaussian) usage("give --gaussian or --no-gaussian, not both");
  if (options.no_gaussian) generate.gaussian = false;
  if (!std::isnan(options.tolerance)) {
    if (!(options.tolerance >= 1e-15 && options.tolerance <= 1e-3)) usage("--tolerance must be between 1e-15 and 1e-3");
    generate.tolerance = options.tolerance;
  }
  if (!std::isnan(options.density)) {
    if (!(options.density >= 0.05 && options.density <= 8)) usage("--density must be between 0.05 and 8");
    generate.knot_density = options.density;
  }
  generate.threads = static_cast<int>(options.threads);
  if (!options.scene.empty()) {
    if (!options.shapes.empty() || !options.sides.empty() || options.gaussian || options.no_gaussian ||
        !std::isnan(options.tolerance) || !std::isnan(options.density))
      usage("--shapes, --sides, --gaussian, --tolerance and --density do not apply to --scene (its file says what to make)");
    // Writing the table over its own scene file would lose the scene.
    std::error_code code;
    if (std::filesystem::equivalent(options.out, options.scene, code))
      usage("--out names the scene file itself ('" + quote_text(options.out, 200) + "'): give another file");
    return generate_scene(options, generate.threads);
  }
  if (!generate.tail && !generate.bounded && !generate.gaussian)
    usage("nothing to generate: choose at least one of --sides tail/bounded or --gaussian");

  check_out(options, output_kinds::gw_table);
  const auto start = std::chrono::steady_clock::now();
  const bool terminal = isatty(STDERR_FILENO);
  const bool quiet = options.quiet;
  int reported = 0;
  // A bar on a terminal; otherwise a line per tenth of the curves, so a log shows it is alive.
  auto progress = [&](int done, int total) {
    if (quiet) return;
    if (terminal) {
      const int width = 40, filled = width * done / total;
      std::fprintf(stderr, "\r[%s%s] %d/%d curves", std::string(filled, '#').c_str(),
                   std::string(width - filled, ' ').c_str(), done, total);
      if (done == total) std::fprintf(stderr, "\n");
    } else if (done == total || done * 10 / total > reported) {
      reported = done * 10 / total;
      std::fprintf(stderr, "tablegen: %d/%d curves integrated and checked, %.1f s\n", done, total, seconds_since(start));
    }
  };
  if (!quiet)
    std::fprintf(stderr, "tablegen: Weibull %s%s%s on %zu%s grid shapes (%s to %s served)%s\n",
                 generate.tail ? "tail" : "", generate.tail && generate.bounded ? " and " : "",
                 generate.bounded ? "bounded side" : (generate.tail ? " side" : "no side"),
                 generator::shape_grid(generate, generate.tail ? Side::tail : Side::bounded).size(),
                 generate.tail && generate.bounded
                     ? (" and " + std::to_string(generator::shape_grid(generate, Side::bounded).size())).c_str()
                     : "",
                 format_double(generate.shape_min).c_str(), format_double(generate.shape_max).c_str(),
                 generate.gaussian ? ", and the Gaussian" : "");
  const TableData table = generator::generate_table(generate, progress);
  if (!quiet) std::fprintf(stderr, "tablegen: writing %s\n", quote_text(options.out, 200).c_str());
  write_table_file(table, options.out, options.overwrite);
  double worst = 0;
  std::size_t curves = 0;
  for (const CurveSet& set : table.sets) {
    curves += set.shapes.size();
    for (std::size_t i = 0; i < set.shapes.size(); ++i)
      if (set.shapes[i] >= set.shape_min && set.shapes[i] <= set.shape_max)
        for (int k = 0; k < order_count; ++k) worst = std::max(worst, set.max_rel_error[i * order_count + k]);
  }
  std::printf("wrote %s: %zu curve sets, %zu curves of 6 orders, max relative error against quadrature "
              "(served shapes) %.3g, %.1f s\n",
              options.out.c_str(), table.sets.size(), curves, worst, seconds_since(start));
  return cli::exit_success;
}

int print_version() {
  std::printf("tablegen %s (writes schema %s, version %d)\n", ASPERITY_VERSION_STRING, table_schema_name(),
              table_schema_version());
  return cli::exit_success;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("tablegen: generate an asperity table file (the integrals on a grid of shapes, or one scene's curves)",
               "tablegen");
  app.get_formatter()->column_width(30);
  auto options = std::make_shared<Options>();
  Options& o = *options;
  cli::add_version_flag(app, print_version, "print the version and the table schema it writes, then exit");
  cli::add_text(app, "--out", o.out, "the table file to write (atomically: a temporary file renamed into place)")
      ->type_name("FILE")
      ->required();
  app.add_flag("--overwrite", o.overwrite,
               "replace --out even if it is not a table of ours of the kind written (a table is replaced without it)");
  cli::add_text(app, "--scene", o.scene,
                "a table for one scene's curves only (docs/scenes.md): exact shapes, knots where the scene "
                "needs them, each curve's error measured and stored")
      ->type_name("SCENE.toml");
  cli::add_text(app, "--shapes", o.shapes,
                "Weibull shapes served, LO to HI: grid nodes at LO, HI and 1, 2, 3, 5, uniform in q = ln(a) - 1/a "
                "between them with spacing at most STEP (2/3 of it on the bounded side; from a = " +
                    format_double(generator::GenerateOptions::large_shape_from) + " on, " +
                    format_double(generator::GenerateOptions::large_shape_step_factor) +
                    " of each), six nodes more past each end; every node within [" + format_double(weibull_shape_min) + ", " + format_double(weibull_shape_max) +
                    "], at most 1000 (default 0.5:20:0.075)")
      ->type_name("LO:HI:STEP");
  cli::add_text(app, "--sides", o.sides, "Weibull sides to tabulate: tail, bounded, both (default) or none")
      ->type_name("LIST");
  app.add_flag("--gaussian", o.gaussian, "include the Gaussian tail side (the default)");
  app.add_flag("--no-gaussian", o.no_gaussian, "leave the Gaussian out");
  cli::add_number(app, "--tolerance", o.tolerance, "odeint error tolerance on ln X, 1e-15 to 1e-3 (default 1e-14)")
      ->type_name("REL");
  cli::add_number(app, "--density", o.density,
                  "knots per segment relative to the default layout, 0.05 to 8 (default 1): 0.25 gives ~1e-8 "
                  "worst-case error at a quarter of the memory, 2 gives ~1e-13 (docs/speed-vs-error.md)")
      ->type_name("F");
  cli::add_whole_number(app, "--threads", o.threads, 1, 4096, "worker threads (default: all cores)");
  app.add_flag("--quiet", o.quiet, "no progress on standard error (errors are still reported)");
  app.footer(
      "Progress goes to standard error: a bar on a terminal, else a line per tenth of the curves; a scene's\n"
      "step (which curve, shape or pass) when it changes and at least every 5 s, with the time elapsed.\n"
      "Exit status: 0 written; 2 bad usage, a bad scene file, a generation that fails its checks, or a\n"
      "file that could not be written.");
  cli::set_action(app, [options] { return generate(*options); });
  return cli::run(app, argc, argv);
}
