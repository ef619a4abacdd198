// The paper's figures and claims from the engine (docs/paper.md, scripts/paper.sh): curves in
// the paper's normalization (docs/model.md section 6) as CSV, and the quantitative claims as CSV.
//   build/examples/paper_data OUT_DIR
//
// Normalization: A/A0^g = sqrt(2 pi) X_1 / c_a, P/P0^g = sqrt(2 pi) X_3/2 / c_a^(3/2) (the
// Gaussian: c = 1, which is McCool's model normalized the same way). Separations are in rms
// units of the summit heights, t = (s - mu_a)/c_a on the tail side (from the mean summit height,
// the convention that puts Weibull, Gaussian and Persson on one axis) and s/c_a on the bounded
// side (zero at first contact, as in the paper's Fig. 2). The stiffness/load ratio is
// -(dP/dt)/P = (3/2) c_a X_1/2 / X_3/2, in those rms units.
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/output.hpp"
#include "asperity/table.hpp"

namespace {
using namespace asperity;
constexpr double root_two_pi = 2.5066282746310002;

struct Family {
  std::string label;
  Distribution distribution;
  Side side;
  double shape;
};

double rms(const Family& family) { return family.distribution == Distribution::gaussian ? 1.0 : weibull_rms(family.shape); }
double mean(const Family& family) { return family.distribution == Distribution::gaussian ? 0.0 : weibull_mean(family.shape); }

// One row per separation: t, the origin-convention s, A/A0^g, P/P0^g, stiffness/load.
void write_curves(const Table& table, const std::vector<Family>& families, const std::string& path) {
  std::ostringstream out;
  out << "family,side,shape,t,s,area,load,stiffness_over_load\n";
  out.precision(12);
  for (const Family& family : families) {
    const Curve curve = table.curve(family.distribution, family.side, family.shape);
    const double c = rms(family), mu = mean(family);
    const int points = 800;
    for (int i = 0; i <= points; ++i) {
      double t, s;
      if (family.side == Side::tail) {  // t from -1 (deep) to 12 (Fig. 1a needs small loads)
        t = -1.0 + 13.0 * i / points;
        s = mu + c * t;
      } else {  // s/c from -3 (deep) to -1e-6 (first contact), log-spaced toward 0
        t = -std::pow(10.0, 0.5 - 6.5 * i / points);
        s = c * t;
      }
      double logs[order_count];
      curve.log_values(s, logs);
      out << family.label << "," << to_string(family.side) << "," << family.shape << "," << t << "," << s << ","
          << root_two_pi * std::exp(logs[2]) / c << "," << root_two_pi * std::exp(logs[3]) / std::pow(c, 1.5) << ","
          << 1.5 * c * std::exp(logs[1] - logs[3]) << "\n";
    }
  }
  asperity::write_output_file(path, out.str(), asperity::output_kinds::any_file);  // the one output policy
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: paper_data OUT_DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  const Table table = Table::open_default();
  const std::vector<Family> tail = {{"Weibull a = 1", Distribution::weibull, Side::tail, 1},
                                    {"Weibull a = 2", Distribution::weibull, Side::tail, 2},
                                    {"Weibull a = 3", Distribution::weibull, Side::tail, 3},
                                    {"Weibull a = 5", Distribution::weibull, Side::tail, 5},
                                    {"Gaussian (McCool)", Distribution::gaussian, Side::tail, 2}};
  const std::vector<Family> bounded = {{"Weibull a = 1", Distribution::weibull, Side::bounded, 1},
                                       {"Weibull a = 2", Distribution::weibull, Side::bounded, 2},
                                       {"Weibull a = 3", Distribution::weibull, Side::bounded, 3},
                                       {"Weibull a = 5", Distribution::weibull, Side::bounded, 5}};
  write_curves(table, tail, dir + "/paper_tail.csv");
  write_curves(table, bounded, dir + "/paper_bounded.csv");

  // Claims: name, t or parameter, engine value, the paper's approximation.
  std::ostringstream claims;
  claims.precision(12);
  claims << "claim,at,engine,paper\n";
  const Curve gaussian = table.curve(Distribution::gaussian, Side::tail, 2);
  for (double t : {0.5, 1.0, 1.5, 2.0, 2.5, 3.0}) {
    double logs[order_count];
    gaussian.log_values(t, logs);
    claims << "stiffness_load_gaussian," << t << "," << 1.5 * std::exp(logs[1] - logs[3]) << "," << 0.92 * (1 + t) << "\n";
    claims << "area_load_gaussian," << t << "," << std::exp(logs[2] - logs[3]) << "," << 1 + 0.148 * t << "\n";
    claims << "asymptotic_t," << t << "," << 1.5 * std::exp(logs[1] - logs[3]) << "," << t << "\n";
  }
  // the Weibull tail side: the local slope -(d ln P / dt) at t = 0..3, to compare with Persson's 1/beta
  for (double shape : {1.0, 2.0, 3.0, 5.0}) {
    const Curve curve = table.curve(Distribution::weibull, Side::tail, shape);
    const double c = weibull_rms(shape), mu = weibull_mean(shape);
    for (double t : {0.0, 1.0, 2.0, 3.0}) {
      double logs[order_count];
      curve.log_values(mu + c * t, logs);
      claims << "stiffness_load_weibull_a" << shape << "," << t << "," << 1.5 * c * std::exp(logs[1] - logs[3]) << ",\n";
    }
  }
  // area-load independence of a: A/A0^g at fixed P/P0^g, tail and bounded sides
  for (Side side : {Side::tail, Side::bounded})
    for (double target : {1e-4, 1e-3, 1e-2, 1e-1})
      for (double shape : {1.0, 2.0, 3.0, 5.0, 0.0}) {
        if (shape == 0 && side == Side::bounded) continue;
        const Distribution distribution = shape == 0 ? Distribution::gaussian : Distribution::weibull;
        const Curve curve = table.curve(distribution, side, shape == 0 ? 2.0 : shape);
        const double c = shape == 0 ? 1.0 : weibull_rms(shape);
        // P/P0^g = target: bisection on s
        double lo = -50, hi = side == Side::bounded ? -1e-300 : 50;
        for (int i = 0; i < 300; ++i) {
          const double middle = 0.5 * (lo + hi);
          (root_two_pi * curve.value(3, middle) / std::pow(c, 1.5) > target ? lo : hi) = middle;
        }
        const double s = 0.5 * (lo + hi);
        claims << "area_at_load_" << to_string(side) << "_a" << shape << "," << target << ","
               << root_two_pi * curve.value(2, s) / c << ",\n";
      }
  // bounded side: stiffness/load near first contact (in rms units), and its limit (n + a)/|t|
  for (double shape : {1.0, 2.0, 5.0}) {
    const Curve curve = table.curve(Distribution::weibull, Side::bounded, shape);
    const double c = weibull_rms(shape);
    for (double t : {-1e-6, -1e-4, -1e-2, -1.0, -3.0}) {
      double logs[order_count];
      curve.log_values(c * t, logs);
      claims << "bounded_stiffness_load_a" << shape << "," << t << "," << 1.5 * c * std::exp(logs[1] - logs[3]) << ","
             << (1.5 + shape) / std::fabs(t) << "\n";
    }
  }
  asperity::write_output_file(dir + "/paper_claims.csv", claims.str(), asperity::output_kinds::any_file);
  std::printf("wrote %s/paper_tail.csv, paper_bounded.csv, paper_claims.csv\n", dir.c_str());
  return 0;
}
