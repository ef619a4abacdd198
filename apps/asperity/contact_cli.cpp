#include "contact_cli.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/contact_model.hpp"
#include "asperity/error.hpp"

namespace asperity::cli {

const char* contact_usage =
    "usage: asperity contact [--table FILE] SURFACE QUERY\n"
    "  SURFACE (SI units):\n"
    "    --dist weibull|gaussian  --side tail|bounded (default tail)  --shape A (Weibull)\n"
    "    --sigma M          height scale sigma_s (Gaussian: rms summit height)\n"
    "    --radius M         summit radius R\n"
    "    --density PER_M2 | --count N   summits per unit area, or in all\n"
    "    --area M2          nominal area A0\n"
    "    --modulus PA | --e1 PA --nu1 X --e2 PA --nu2 X   contact modulus E*\n"
    "    --moments M0,M2,M4 a Gaussian surface from its profile's spectral moments\n"
    "                       (Nayak-McCool: sets sigma, radius and density)\n"
    "  QUERY (one):\n"
    "    --separation M | --load N | --pressure PA | --real-area M2\n"
    "    --sweep KIND:FROM:TO:COUNT  KIND separation (linear), load, pressure, real-area (log)\n"
    "  Output: CSV, one row per query; separations in the origin convention (from the Weibull\n"
    "  origin or the Gaussian mean) and from the mean summit height.\n";

namespace {

double number(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value))
    throw Error("contact: " + what + " '" + text + "' is not a number");
  return value;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator)) parts.push_back(part);
  return parts;
}

void print(const PhysicalState& state) {
  std::printf("%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", state.separation, state.mean_separation,
              state.count, state.real_area, state.area_fraction, state.load, state.pressure, state.stiffness,
              state.stiffness_over_load);
}

}  // namespace

int contact_command(int argc, char** argv) {
  std::string table_path, query_kind, sweep;
  double query_value = NAN;
  PhysicalSurface surface;
  double count = NAN, e1 = NAN, nu1 = NAN, e2 = NAN, nu2 = NAN;
  std::string moments;
  bool have[6] = {};  // sigma, radius, density-or-count, area, modulus, dist
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Error("contact: " + argument + " needs a value");
      return argv[++i];
    };
    if (argument == "--table") table_path = value();
    else if (argument == "--dist") {
      if (!parse_distribution(value(), surface.distribution)) throw Error("contact: --dist is weibull or gaussian");
      have[5] = true;
    } else if (argument == "--side") {
      if (!parse_side(value(), surface.side)) throw Error("contact: --side is tail or bounded");
    } else if (argument == "--shape") surface.shape = number(value(), "--shape");
    else if (argument == "--sigma") { surface.height_scale = number(value(), "--sigma"); have[0] = true; }
    else if (argument == "--radius") { surface.summit_radius = number(value(), "--radius"); have[1] = true; }
    else if (argument == "--density") { surface.summit_density = number(value(), "--density"); have[2] = true; }
    else if (argument == "--count") { count = number(value(), "--count"); have[2] = true; }
    else if (argument == "--area") { surface.nominal_area = number(value(), "--area"); have[3] = true; }
    else if (argument == "--modulus") { surface.contact_modulus = number(value(), "--modulus"); have[4] = true; }
    else if (argument == "--e1") e1 = number(value(), "--e1");
    else if (argument == "--nu1") nu1 = number(value(), "--nu1");
    else if (argument == "--e2") e2 = number(value(), "--e2");
    else if (argument == "--nu2") nu2 = number(value(), "--nu2");
    else if (argument == "--moments") moments = value();
    else if (argument == "--separation" || argument == "--load" || argument == "--pressure" || argument == "--real-area") {
      if (!query_kind.empty() || !sweep.empty()) throw Error("contact: give one query");
      query_kind = argument.substr(2);
      query_value = number(value(), argument);
    } else if (argument == "--sweep") {
      if (!query_kind.empty() || !sweep.empty()) throw Error("contact: give one query");
      sweep = value();
    } else if (argument == "--help" || argument == "-h") {
      std::fputs(contact_usage, stdout);
      return 0;
    } else {
      throw Error("contact: unknown argument '" + argument + "'\n" + contact_usage);
    }
  }
  if (!have[5]) throw Error(std::string("contact: --dist is required\n") + contact_usage);
  if (!std::isnan(e1) || !std::isnan(e2) || !std::isnan(nu1) || !std::isnan(nu2)) {
    if (std::isnan(e1) || std::isnan(e2) || std::isnan(nu1) || std::isnan(nu2))
      throw Error("contact: --e1 --nu1 --e2 --nu2 go together");
    surface.contact_modulus = contact_modulus_from(e1, nu1, e2, nu2);
    have[4] = true;
  }
  if (!moments.empty()) {
    if (surface.distribution != Distribution::gaussian) throw Error("contact: --moments describe a Gaussian surface");
    const std::vector<std::string> parts = split(moments, ',');
    if (parts.size() != 3) throw Error("contact: --moments wants M0,M2,M4");
    if (!have[3]) throw Error("contact: --area is required");
    const PhysicalSurface from = gaussian_surface_from_moments(number(parts[0], "m0"), number(parts[1], "m2"),
                                                               number(parts[2], "m4"), surface.nominal_area,
                                                               surface.contact_modulus);
    surface.height_scale = from.height_scale;
    surface.summit_radius = from.summit_radius;
    surface.summit_density = from.summit_density;
    have[0] = have[1] = have[2] = true;
  }
  const char* names[] = {"--sigma", "--radius", "--density or --count", "--area", "--modulus (or --e1 ...)"};
  for (int k = 0; k < 5; ++k)
    if (!have[k]) throw Error(std::string("contact: ") + names[k] + " is required\n" + contact_usage);
  if (!std::isnan(count)) {
    if (!(count > 0)) throw Error("contact: --count must be positive");
    surface.summit_density = count / surface.nominal_area;
  }
  if (query_kind.empty() && sweep.empty()) throw Error(std::string("contact: a query is required\n") + contact_usage);

  const Table table = table_path.empty() ? Table::open_default() : Table::open(table_path);
  const ContactModel model(table, surface);
  std::printf("separation_m,mean_separation_m,count,real_area_m2,area_fraction,load_N,nominal_pressure_Pa,"
              "stiffness_N_per_m,stiffness_over_load_per_m\n");
  auto query = [&](const std::string& kind, double value) {
    if (kind == "separation") print(model.at_separation(value));
    else if (kind == "load") print(model.at_load(value));
    else if (kind == "pressure") print(model.at_pressure(value));
    else if (kind == "real-area") print(model.at_real_area(value));
    else throw Error("contact: unknown sweep kind '" + kind + "' (separation, load, pressure, real-area)");
  };
  if (!sweep.empty()) {
    const std::vector<std::string> parts = split(sweep, ':');
    if (parts.size() != 4) throw Error("contact: --sweep wants KIND:FROM:TO:COUNT");
    const double from = number(parts[1], "sweep FROM"), to = number(parts[2], "sweep TO");
    const int points = static_cast<int>(number(parts[3], "sweep COUNT"));
    if (points < 2 || points > 1000000) throw Error("contact: sweep COUNT must be 2 to 1e6");
    const bool logarithmic = parts[0] != "separation";
    if (logarithmic && !(from > 0 && to > 0)) throw Error("contact: a load, pressure or area sweep needs FROM, TO > 0");
    for (int k = 0; k < points; ++k) {
      const double fraction = static_cast<double>(k) / (points - 1);
      query(parts[0], logarithmic ? from * std::pow(to / from, fraction) : from + (to - from) * fraction);
    }
  } else {
    query(query_kind, query_value);
  }
  return 0;
}

}  // namespace asperity::cli
