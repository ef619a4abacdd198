// tablegen: generate an asperity table file.
//   tablegen --out FILE [--shapes LO:HI:STEP] [--sides tail,bounded] [--gaussian|--no-gaussian]
//            [--tolerance REL] [--density F] [--threads N]
//   tablegen --scene SCENE.toml --out FILE [--threads N]
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

#include "asperity/error.hpp"
#include "asperity/scene.hpp"
#include "generate.hpp"
#include "scene_table.hpp"
#include "table_writer.hpp"

namespace {

const char* usage =
    "usage: tablegen --out FILE [--shapes LO:HI:STEP] [--sides tail,bounded] [--gaussian|--no-gaussian]\n"
    "                [--tolerance REL] [--density F] [--threads N]\n"
    "       tablegen --scene SCENE.toml --out FILE [--threads N]\n"
    "  --scene SCENE        a table for one scene's curves only (docs/scenes.md): exact shapes,\n"
    "                       knots where the scene needs them, each curve's error measured and stored\n"
    "  --shapes LO:HI:STEP  Weibull shapes served, LO to HI: grid nodes at LO, HI and 1, 2, 3, 5,\n"
    "                       uniform in q = ln(a) - 1/a between them with spacing at most STEP,\n"
    "                       six nodes more past each end (default 0.5:20:0.075)\n"
    "  --sides LIST         Weibull sides to tabulate: tail, bounded, both (default) or none\n"
    "  --gaussian           include the Gaussian tail side (default); --no-gaussian leaves it out\n"
    "  --tolerance REL      odeint error tolerance on ln X (default 1e-14)\n"
    "  --density F          knots per segment relative to the default layout (default 1): 0.25 gives\n"
    "                       ~1e-8 worst-case error at a quarter of the memory, 2 gives ~1e-13\n"
    "                       (measured: docs/speed-vs-error.md)\n"
    "  --threads N          worker threads (default: all cores)\n";

double parse_number(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value))
    throw asperity::Error("tablegen: " + what + " '" + text + "' is not a number");
  return value;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace asperity;
  try {
    tablegen::GenerateOptions options;
    std::string out, scene_path;
    for (int i = 1; i < argc; ++i) {
      const std::string argument = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw Error("tablegen: " + argument + " needs a value");
        return argv[++i];
      };
      if (argument == "--out") out = value();
      else if (argument == "--scene") scene_path = value();
      else if (argument == "--shapes") {
        const std::string spec = value();
        std::stringstream stream(spec);
        std::string lo, hi, step;
        if (!std::getline(stream, lo, ':') || !std::getline(stream, hi, ':') || !std::getline(stream, step) )
          throw Error("tablegen: --shapes wants LO:HI:STEP, got '" + spec + "'");
        options.shape_min = parse_number(lo, "shape LO");
        options.shape_max = parse_number(hi, "shape HI");
        options.shape_log_step = parse_number(step, "shape STEP");
        if (!(options.shape_min > 0 && options.shape_max >= options.shape_min && options.shape_log_step > 0))
          throw Error("tablegen: --shapes needs 0 < LO <= HI and STEP > 0");
      } else if (argument == "--sides") {
        const std::string sides = value();
        options.tail = options.bounded = false;
        std::stringstream stream(sides);
        std::string side;
        while (std::getline(stream, side, ',')) {
          if (side == "tail") options.tail = true;
          else if (side == "bounded") options.bounded = true;
          else if (side == "both") options.tail = options.bounded = true;
          else if (side != "none") throw Error("tablegen: unknown side '" + side + "' (tail, bounded, both, none)");
        }
      } else if (argument == "--gaussian") options.gaussian = true;
      else if (argument == "--no-gaussian") options.gaussian = false;
      else if (argument == "--tolerance") {
        options.tolerance = parse_number(value(), "tolerance");
        if (!(options.tolerance >= 1e-15 && options.tolerance <= 1e-3))
          throw Error("tablegen: --tolerance must be between 1e-15 and 1e-3");
      } else if (argument == "--density") {
        options.knot_density = parse_number(value(), "density");
        if (!(options.knot_density >= 0.05 && options.knot_density <= 8))
          throw Error("tablegen: --density must be between 0.05 and 8");
      } else if (argument == "--threads") {
        options.threads = static_cast<int>(parse_number(value(), "threads"));
        if (options.threads < 1) throw Error("tablegen: --threads must be at least 1");
      } else if (argument == "--help" || argument == "-h") {
        std::cout << usage;
        return 0;
      } else throw Error("tablegen: unknown argument '" + argument + "'\n" + usage);
    }
    if (out.empty()) throw Error(std::string("tablegen: --out FILE is required\n") + usage);

    const auto start = std::chrono::steady_clock::now();
    if (!scene_path.empty()) {
      const Scene scene = read_scene_file(scene_path);
      const tablegen::SceneResult result = tablegen::generate_scene_table(scene, options.threads);
      tablegen::write_table_file(result.table, out);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("%-16s %-8s %-8s %7s %-14s %-24s %9s %9s %6s %8s\n", "curve", "dist", "side", "shape", "orders",
                  "separations", "asked", "achieved", "knots", "memory");
      std::size_t bytes = 0;
      for (const tablegen::SceneCurveReport& report : result.curves) {
        std::string orders;
        for (int twice_order : report.curve.twice_orders)
          orders += (orders.empty() ? "" : ",") + std::string(twice_order % 2 ? std::to_string(twice_order) + "/2"
                                                                              : std::to_string(twice_order / 2));
        char range[64];
        std::snprintf(range, sizeof range, "[%.4g, %.4g]", report.separation_min, report.separation_max);
        std::printf("%-16s %-8s %-8s %7.4g %-14s %-24s %9.2g %9.2g %6d %5.1f KiB\n",
                    report.curve.name.empty() ? "-" : report.curve.name.c_str(), to_string(report.curve.distribution),
                    to_string(report.curve.side), report.curve.shape, orders.c_str(), range,
                    report.curve.max_rel_error, report.achieved_error, report.knots, report.memory_bytes / 1024.0);
        bytes += report.memory_bytes;
      }
      std::printf("wrote %s: %zu curves, %.1f KiB in memory, %.2f s\n", out.c_str(), result.curves.size(),
                  bytes / 1024.0, seconds);
      return 0;
    }
    const bool terminal = isatty(STDERR_FILENO);
    auto progress = [&](int done, int total) {
      if (!terminal) return;
      const int width = 40, filled = width * done / total;
      std::fprintf(stderr, "\r[%s%s] %d/%d curves", std::string(filled, '#').c_str(),
                   std::string(width - filled, ' ').c_str(), done, total);
      if (done == total) std::fprintf(stderr, "\n");
    };
    const TableData table = tablegen::generate_table(options, progress);
    tablegen::write_table_file(table, out);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
                out.c_str(), table.sets.size(), curves, worst, seconds);
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 1;
  }
}
