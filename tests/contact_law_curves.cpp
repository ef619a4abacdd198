// The data behind docs/contact-laws.md (scripts/contact-laws-report.sh): each law's single-asperity
// curves and switch-point jumps, Maugis-Dugdale between DMT and JKR, and the rough-surface curves
// of the papers (Kogut-Etsion 2003, Jackson-Green 2006, Fuller-Tabor 1975) by the independent
// reference (contact_law_reference.hpp).
//   contact_law_curves OUTPUT_DIR
#include <cmath>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <locale>
#include <string>
#include <vector>

#include "asperity/contact_law.hpp"
#include "asperity/number_text.hpp"
#include "contact_law_reference.hpp"

namespace {

using namespace asperity;
using asperity::test::ContactHistory;
using asperity::test::law_integrals;
using asperity::test::SummitHeights;

constexpr double pi = 3.14159265358979323846;
// A steel asperity: R = 100 um, E* = 115 GPa (E = 210 GPa, nu = 0.3 on both sides), Y = 1 GPa
constexpr double R = 1e-4, E = 1.15e11, Y = 1e9, NU = 0.3, H = 2.8 * Y;

struct Law {
  std::string name;
  ContactLaw law;
};

std::vector<Law> elastic_plastic() {
  return {{"hertz", hertz_law(R, E)},
          {"chang-etsion-bogy", chang_etsion_bogy_law(R, E, H, NU)},
          {"zhao-maietta-chang", zhao_maietta_chang_law(R, E, H)},
          {"kogut-etsion", kogut_etsion_law(R, E, Y, NU)},
          {"jackson-green-cosine", jackson_green_law(R, E, Y, NU, JacksonGreenHardness::cosine)},
          {"jackson-green-exponential", jackson_green_law(R, E, Y, NU, JacksonGreenHardness::exponential)}};
}

// Every double a stream writes in the shortest text that reads back to it (format_double, as the
// commands and Python's repr write them; it was 10 digits)
class ShortestDoubles : public std::num_put<char> {
 protected:
  iter_type do_put(iter_type out, std::ios_base&, char, double value) const override {
    const std::string text = format_double(value);
    return std::copy(text.begin(), text.end(), out);
  }
};

std::ofstream open(const std::string& dir, const std::string& name) {
  std::ofstream out(dir + "/" + name);
  if (!out) {
    std::cerr << "contact_law_curves: cannot write " << dir << "/" << name << "\n";
    std::exit(2);
  }
  out.imbue(std::locale(out.getloc(), new ShortestDoubles));
  return out;
}

// P/Pc, A/Ac, stiffness/(Pc/wc) against w/wc, all in Kogut-Etsion's omega_c and P_c
void single_asperity(const std::string& dir) {
  auto out = open(dir, "single_laws.csv");
  const ContactLaw ke = kogut_etsion_law(R, E, Y, NU);
  const double wc = ke.critical_interference, pc = ke.critical_load, ac = ke.critical_area;
  out << "law,x,load,area,stiffness\n";
  for (const Law& l : elastic_plastic()) {
    for (double x = 0.1; x <= 1000; x *= std::pow(10.0, 1.0 / 100)) {
      const AsperityResponse r = asperity_response(l.law, x * wc);
      out << l.name << "," << x << "," << r.load / pc << "," << r.area / ac << "," << r.stiffness / (pc / wc) << "\n";
    }
  }
}

// each law's switch points: omega/omega_c (its own), and the ratios right/left of P, A, dP/domega
void jumps(const std::string& dir) {
  auto out = open(dir, "switch_jumps.csv");
  out << "law,x,load_ratio,area_ratio,stiffness_ratio\n";
  for (const Law& l : elastic_plastic()) {
    const SwitchPoints points = switch_points(l.law);
    for (int k = 0; k < points.count; ++k) {
      const double w = points.interference[k];
      const AsperityResponse left = asperity_response(l.law, std::nextafter(w, 0.0));
      const AsperityResponse right = asperity_response(l.law, std::nextafter(w, 1.0));
      out << l.name << "," << w / l.law.critical_interference << "," << right.load / left.load << ","
          << right.area / left.area << "," << right.stiffness / left.stiffness << "\n";
    }
  }
}

// Maugis-Dugdale's Pbar against D for several lambda, with DMT and JKR
void maugis_dugdale(const std::string& dir) {
  auto out = open(dir, "maugis_dugdale.csv");
  const double gamma = 0.05;
  out << "law,lambda,interference,load,area\n";
  std::vector<Law> laws{{"dmt", dmt_law(R, E, gamma)}, {"jkr", jkr_law(R, E, gamma)}};
  for (double lambda : {0.1, 0.5, 1.0, 2.0, 5.0})
    laws.push_back({"maugis-dugdale", maugis_dugdale_law(R, E, gamma, lambda)});
  for (const Law& l : laws) {
    const double ds = l.law.critical_interference, lowest = l.law.lowest_interference / ds;
    for (int i = 0; i <= 400; ++i) {
      const double d = lowest + (2.0 - lowest) * std::pow(i / 400.0, 2);
      const AsperityResponse r = asperity_response(l.law, d * ds);
      out << l.name << "," << l.law.maugis_parameter << "," << d << "," << r.load / l.law.critical_load << ","
          << r.area / l.law.critical_area << "\n";
    }
  }
}

// Kogut & Etsion 2003: a Gaussian surface of height rms sigma, summits of rms sigma_s =
// sigma sqrt(1 - 3.717e-4 / beta^2) (McCool), beta = eta R sigma; h = separation from the mean of
// the surface heights, d = h - y_s from the summits' mean, y_s = 0.045944 / beta (in sigma);
// psi = (2 E*/(pi K H)) sqrt(sigma_s / R). P/(A_n H) and A/A_n against h/sigma.
struct RoughGeometry {
  double beta, sigma_ratio, offset;  // beta, sigma_s/sigma, y_s/sigma
};
RoughGeometry ke2003_geometry(double beta) {
  return {beta, std::sqrt(1 - 3.717e-4 / (beta * beta)), 0.045944 / beta};
}

// the law's per-summit load and area at h (in sigma), as P/(A_n norm) and A/A_n
struct Pair {
  double load, area;
};
Pair rough_point(const ContactLaw& law, const RoughGeometry& g, double sigma_s, double h, double norm) {
  const double sigma = sigma_s / g.sigma_ratio;
  const double s = (h - g.offset) * sigma / sigma_s;  // from the summits' mean in sigma_s
  const auto v = law_integrals(law, {Distribution::gaussian, Side::tail, 2, sigma_s}, s);
  const double eta = g.beta / (R * sigma);  // summits per area
  return {eta * v.load / norm, eta * v.area};
}

void kogut_etsion_2003(const std::string& dir) {
  auto out = open(dir, "kogut_etsion_2003.csv");
  const RoughGeometry g = ke2003_geometry(0.04);
  out << "psi,h,load,area,elastic_load\n";
  const ContactLaw ke = kogut_etsion_law(R, E, Y, NU), hertz = hertz_law(R, E);
  for (double psi : {0.5, 1.0, 2.0, 4.0, 8.0}) {
    const double sigma_s = psi * psi * ke.critical_interference;
    for (double h = 0; h <= 4.0001; h += 0.1) {
      const Pair p = rough_point(ke, g, sigma_s, h, H), e = rough_point(hertz, g, sigma_s, h, H);
      out << psi << "," << h << "," << p.load << "," << p.area << "," << e.load << "\n";
    }
  }
}

// Area against load for every elastic-plastic law on the same surface (beta = 0.04), for two
// plasticity indices (Kogut-Etsion's psi: each law then has its own omega_c).
void area_load(const std::string& dir) {
  auto out = open(dir, "area_load.csv");
  const RoughGeometry g = ke2003_geometry(0.04);
  const ContactLaw ke = kogut_etsion_law(R, E, Y, NU);
  out << "law,psi,h,load,area\n";
  for (double psi : {1.0, 4.0}) {
    const double sigma_s = psi * psi * ke.critical_interference;
    for (const Law& l : elastic_plastic()) {
      for (double h = 0; h <= 4.0001; h += 0.1) {
        const Pair p = rough_point(l.law, g, sigma_s, h, Y);
        out << l.name << "," << psi << "," << h << "," << p.load << "," << p.area << "\n";
      }
    }
  }
}

// Fuller & Tabor 1975: JKR asperities on Gaussian summits, loaded to separation s0 and pulled
// off under fixed grips; the greatest tension against Delta_c = sigma/delta_c, delta_c =
// (3/4)(pi^2 dgamma^2 R / E*^2)^(1/3) the approach at which one JKR asperity separates, as a
// fraction of what the asperities that touched would carry on a smooth surface (each its law's
// greatest tension, (3/2) pi dgamma R for JKR): 1 as Delta_c -> 0.
void fuller_tabor(const std::string& dir) {
  auto out = open(dir, "fuller_tabor.csv");
  const double gamma = 0.05;
  out << "law,lambda,s0,delta_c,fraction\n";
  std::vector<Law> laws{{"jkr", jkr_law(R, E, gamma)}};
  for (double lambda : {1.0, 3.0}) laws.push_back({"maugis-dugdale", maugis_dugdale_law(R, E, gamma, lambda)});
  const double delta_c = 0.75 * std::cbrt(pi * pi * gamma * gamma * R / (E * E));
  for (const Law& l : laws) {
    double smooth = 0;  // the law's greatest tension on its branch
    for (int i = 0; i <= 20000; ++i) {
      const double w = l.law.lowest_interference * (1 - i / 10000.0);
      smooth = std::min(smooth, asperity_response(l.law, w).load);
    }
    for (double s0 : {0.0, -2.0}) {
      const double touched = 0.5 * std::erfc(s0 / std::sqrt(2.0));
      if (l.name != "jkr" && s0 != 0) continue;
      for (double dc : {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0}) {
        const double fraction = asperity::test::pull_off(l.law, {Distribution::gaussian, Side::tail, 2, dc * delta_c}, s0) / (-smooth * touched);
        out << l.name << "," << l.law.maugis_parameter << "," << s0 << "," << dc << "," << fraction << "\n";
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: contact_law_curves OUTPUT_DIR\n";
    return 2;
  }
  const std::string dir = argv[1];
  single_asperity(dir);
  jumps(dir);
  maugis_dugdale(dir);
  kogut_etsion_2003(dir);
  area_load(dir);
  fuller_tabor(dir);
  return 0;
}
