#include "surface_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/surface.hpp"
#include "asperity/topography/analysis.hpp"
#include "asperity/topography/surface_report.hpp"
#include "asperity/topography/units.hpp"

namespace asperity::cli {
namespace {
namespace topo = asperity::topography;

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ',')) parts.push_back(part);
  return parts;
}

double positive_number(const std::string& text, const char* what) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value > 0) || !std::isfinite(value))
    throw Error(std::string(what) + ": '" + text + "' is not a positive number");
  return value;
}

}  // namespace

int surface_command(int argc, char** argv, std::ostream& out, std::ostream& err) {
  CLI::App app{
      "asperity surface: a measured height map (X3P, Gwyddion .gsf or ASCII matrix, xyz) to its statistics, "
      "summits, the Gaussian and the two three-parameter Weibulls fitted to its summit heights with their "
      "goodness of fit, and (with --modulus) the contact curves of each fit side by side.",
      "asperity surface"};
  std::string file, format = "auto", pixel_size, unit, height_unit, summit_threshold, pressures, loads, table, report;
  double modulus = 0, area = 0, confidence = 0.95, e1 = 0, nu1 = 0, e2 = 0, nu2 = 0;
  int window = 1, bootstrap = 199, threads = 0;
  std::uint64_t seed = 1;
  bool json = false, no_level = false, no_height_fit = false;
  app.add_option("file", file, "the height map")->required();
  app.add_option("--format", format, "auto (default: by content, then extension), x3p, gsf, matrix, xyz");
  app.add_option("--pixel-size", pixel_size,
                 "sampling interval with its unit, one or x,y (1.5um or 1.5um,2um); required when the file has none, "
                 "else it overrides the file's");
  app.add_option("--unit", unit, "unit of x, y (and of heights unless --height-unit) for files without units (xyz), "
                                 "and of a bare --pixel-size");
  app.add_option("--height-unit", height_unit, "unit of the heights in the file (overrides the file's)");
  app.add_flag("--no-level", no_level, "do not subtract the least-squares plane");
  app.add_option("--summit-window", window, "summits: highest within this many points (1: the 8 neighbours)");
  app.add_option("--summit-threshold", summit_threshold,
                 "summits: at least this high above the mean of their 8 neighbours (a length with its unit, e.g. 2nm)");
  app.add_option("--modulus", modulus, "contact modulus E* [Pa] (plane strain): gives the contact curves");
  app.add_option("--e1", e1, "Young's modulus of body 1 [Pa] (with --nu1 --e2 --nu2, instead of --modulus)");
  app.add_option("--nu1", nu1, "Poisson's ratio of body 1");
  app.add_option("--e2", e2, "Young's modulus of body 2 [Pa]");
  app.add_option("--nu2", nu2, "Poisson's ratio of body 2");
  app.add_option("--pressure", pressures, "nominal pressures of interest [Pa], comma-separated (default E* x 1e-5,1e-4,1e-3)");
  app.add_option("--load", loads, "loads of interest [N], comma-separated (over the nominal area)");
  app.add_option("--area", area, "nominal contact area A0 [m^2] (default: the measured area)");
  app.add_option("--bootstrap", bootstrap, "parametric bootstrap samples for the p-values and intervals (default 199)");
  app.add_option("--confidence", confidence, "of the intervals (default 0.95)");
  app.add_option("--seed", seed, "of the bootstrap (default 1: reproducible)");
  app.add_option("--threads", threads, "for the bootstrap and the scene tables (default: all cores)");
  app.add_flag("--no-height-fit", no_height_fit, "fit the summit heights only");
  app.add_option("--table", table, "a full table for the Weibull curves instead of exact-shape scene tables");
  app.add_option("--report", report, "write a report directory: report.md, report.json, curves.csv, summits.csv, plots");
  app.add_flag("--json", json, "write the JSON to standard output instead of the summary");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    std::ostringstream message, help;
    const int status = app.exit(error, help, message);
    out << help.str();
    err << message.str();
    return status == 0 ? 0 : 2;
  }

  try {
    topo::AnalysisOptions options;
    if (!topo::parse_height_map_format(format, options.read.format)) throw Error("--format: unknown format '" + format + "'");
    options.read.lateral_unit = unit;
    options.read.height_unit = height_unit;
    if (!pixel_size.empty()) {
      const std::vector<std::string> parts = split_commas(pixel_size);
      if (parts.empty() || parts.size() > 2) throw Error("--pixel-size: one length, or two (x,y)");
      options.read.pixel_size_x = topo::parse_length(parts[0], unit);
      options.read.pixel_size_y = parts.size() == 2 ? topo::parse_length(parts[1], unit) : options.read.pixel_size_x;
      if (!(options.read.pixel_size_x > 0 && options.read.pixel_size_y > 0)) throw Error("--pixel-size must be positive");
    }
    options.level = !no_level;
    options.summits.window = window;
    if (!summit_threshold.empty()) options.summits.min_drop = topo::parse_length(summit_threshold);
    options.assessment.bootstrap = bootstrap;
    options.assessment.seed = seed;
    options.assessment.threads = threads;
    options.assessment.confidence = confidence;
    options.fit_heights = !no_height_fit;
    if (bootstrap < 0) throw Error("--bootstrap must be >= 0");
    if (e1 != 0 || e2 != 0) {
      if (modulus != 0) throw Error("give --modulus or --e1 --nu1 --e2 --nu2, not both");
      modulus = contact_modulus_from(e1, nu1, e2, nu2);
    }
    if (modulus != 0 || !pressures.empty() || !loads.empty()) {
      if (!(modulus > 0)) throw Error("the contact curves need the contact modulus: --modulus E* [Pa]");
      topo::ContactOptions contact;
      contact.contact_modulus = modulus;
      contact.nominal_area = area;
      contact.table_path = table;
      contact.threads = threads;
      for (const std::string& p : split_commas(pressures)) contact.pressures.push_back(positive_number(p, "--pressure"));
      if (!loads.empty()) {
        // loads over the nominal area: A0 given, or the measured area (known after reading)
        topo::HeightMap probe = topo::read_height_map(file, options.read);
        const double a0 = area > 0 ? area : probe.width() * probe.length();
        for (const std::string& l : split_commas(loads)) contact.pressures.push_back(positive_number(l, "--load") / a0);
      }
      options.contact = contact;
    }
    const topo::SurfaceAnalysis analysis = topo::analyse_surface_file(file, options);
    if (json) out << topo::analysis_json(analysis);
    else out << topo::analysis_summary(analysis);
    if (!report.empty()) {
      const topo::ReportOutcome outcome = topo::write_report(analysis, report);
      if (!outcome.plots) err << "asperity surface: " << outcome.plot_note << "\n";
      if (!json) out << "  report: " << outcome.files.front() << " (" << outcome.files.size() << " files)\n";
    }
    return 0;
  } catch (const std::exception& error) {
    err << "asperity surface: " << error.what() << "\n";
    return 2;
  }
}

int surface_command(int argc, char** argv) { return surface_command(argc, argv, std::cout, std::cerr); }

}  // namespace asperity::cli
