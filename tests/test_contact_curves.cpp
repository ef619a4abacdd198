// Contact curves against separation (asperity/contact_curves.hpp, contact_curves_data.hpp) and a
// measured surface as a table (topography/exact_contact_table.hpp): the interpolants against
// closed forms, the served curves against independent exact solves of a synthetic map (at the
// nodes to rounding, between them within the stored bound), the inverse, the file's round trip,
// and files damaged or forged in every way the reader must refuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/contact_curves.hpp"
#include "asperity/contact_curves_data.hpp"
#include "asperity/error.hpp"
#include "asperity/pressure_overclosure.hpp"
#include "asperity/table.hpp"
#include "asperity/table_file.hpp"
#include "asperity/table_writer.hpp"
#include "asperity/topography/exact_contact.hpp"
#include "asperity/topography/exact_contact_table.hpp"
#include "asperity/topography/self_affine.hpp"

namespace {
using namespace asperity;
namespace topo = asperity::topography;

std::string temp_path(const std::string& name) { return std::string(ASPERITY_TEST_BINARY_DIR) + "/" + name; }

// Curves from a closed form: ln p(u) = -u/lambda - (u/mu)^power, k = -dp/du, a = p/(E* slope)
// (any decreasing positive area will do for the tests of the pressure).
ContactCurvesData closed_form(int nodes, double power, double u0 = 0.1e-6, double u1 = 1.1e-6) {
  ContactCurvesData data;
  data.source = "closed form";
  data.separation_datum = "u";
  const double lambda = 0.2e-6, mu = 0.5e-6, p0 = 1e8;
  for (int i = 0; i < nodes; ++i) {
    const double u = u0 + (u1 - u0) * i / (nodes - 1);
    const double log_p = -u / lambda - std::pow(u / mu, power);
    const double slope = -1 / lambda - power / mu * std::pow(u / mu, power - 1);  // d ln p / du
    data.separation.push_back(u);
    data.pressure.push_back(p0 * std::exp(log_p));
    data.stiffness.push_back(-p0 * std::exp(log_p) * slope);
    data.area_fraction.push_back(0.5 * std::exp(log_p));
  }
  data.contact_modulus = 1e11;
  data.nominal_area = 1e-6;
  data.safety_factor = 2;
  return data;
}

double closed_form_pressure(double u, double power) {
  return 1e8 * std::exp(-u / 0.2e-6 - std::pow(u / 0.5e-6, power));
}

// Adhesive curves of closed form: p_c = 1e8 exp(-u/a), p_t = 3e7 exp(-u/b), a = 0.2 um, b = 0.4
// um (ln of each linear: the Hermite interpolants are exact), the net stiffness 0 at
// u* = ln(A b / (B a)) / (1/a - 1/b); a summit count 1e9 exp(-u/c)
constexpr double adhesive_a = 0.2e-6, adhesive_b = 0.4e-6;
ContactCurvesData adhesive_closed_form(int nodes) {
  ContactCurvesData data = closed_form(nodes, 3, 0.1e-6, 2.1e-6);
  for (int i = 0; i < nodes; ++i) {
    const double u = data.separation[i], p = 1e8 * std::exp(-u / adhesive_a), q = 3e7 * std::exp(-u / adhesive_b);
    data.pressure[i] = p;
    data.stiffness[i] = p / adhesive_a;
    data.tensile_pressure.push_back(q);
    data.tensile_stiffness.push_back(q / adhesive_b);
    data.summit_count.push_back(1e9 * std::exp(-u / 0.3e-6));
  }
  data.summit_count_max_rel_error = 1e-9;
  return data;
}
double adhesive_net(double u) { return 1e8 * std::exp(-u / adhesive_a) - 3e7 * std::exp(-u / adhesive_b); }

TEST(ContactCurvesInterpolant, AdhesiveCurvesServeTheNetAndThePullOff) {
  const ContactCurves curves(adhesive_closed_form(41));
  ASSERT_TRUE(curves.has_tension());
  const double pull_off = std::log(1e8 * adhesive_b / (3e7 * adhesive_a)) / (1 / adhesive_a - 1 / adhesive_b);
  EXPECT_NEAR(curves.pull_off_separation() / pull_off, 1, 1e-9);
  EXPECT_NEAR(curves.pull_off_pressure() / adhesive_net(pull_off), 1, 1e-12);
  EXPECT_LT(curves.pull_off_pressure(), 0);
  EXPECT_EQ(curves.stable_branch_end(), curves.pull_off_separation());
  EXPECT_EQ(curves.min_pressure(), curves.pull_off_pressure());
  EXPECT_NEAR(curves.max_pressure() / adhesive_net(curves.min_separation()), 1, 1e-13);
  for (int i = 0; i <= 200; ++i) {
    const double u = curves.min_separation() + (curves.max_separation() - curves.min_separation()) * i / 200;
    const double gross = 1e8 * std::exp(-u / adhesive_a) + 3e7 * std::exp(-u / adhesive_b);
    const double gross_k = 1e8 / adhesive_a * std::exp(-u / adhesive_a) + 3e7 / adhesive_b * std::exp(-u / adhesive_b);
    const double net_k = 1e8 / adhesive_a * std::exp(-u / adhesive_a) - 3e7 / adhesive_b * std::exp(-u / adhesive_b);
    EXPECT_NEAR(curves.pressure(u), adhesive_net(u), 1e-13 * gross) << u;
    EXPECT_NEAR(curves.stiffness(u), net_k, 1e-12 * gross_k) << u;
    EXPECT_NEAR(curves.at_separation(u).pressure, curves.pressure(u), 1e-15 * gross);
    EXPECT_NEAR(curves.tensile_part(u).pressure, 3e7 * std::exp(-u / adhesive_b), 1e-13 * gross);
    EXPECT_NEAR(curves.summit_count(u) / (1e9 * std::exp(-u / 0.3e-6)), 1, 1e-13);
    // the inverse on the stable branch, NaN beyond it
    const double back = curves.separation_at_pressure(curves.pressure(u));
    if (u < 0.999 * pull_off) {
      EXPECT_NEAR(back / u, 1, 1e-9) << u;
    }
  }
  EXPECT_TRUE(std::isnan(curves.separation_at_pressure(curves.pull_off_pressure() * 1.0001)));
  EXPECT_TRUE(std::isnan(curves.separation_at_pressure(curves.max_pressure() * 1.0001)));
  EXPECT_EQ(curves.separation_at_pressure(curves.pull_off_pressure()), curves.pull_off_separation());
  // without tension: the pull-off is NaN, the count NaN where not stored
  const ContactCurves plain(closed_form(5, 3));
  EXPECT_FALSE(plain.has_tension());
  EXPECT_TRUE(std::isnan(plain.pull_off_pressure()));
  EXPECT_TRUE(std::isnan(plain.pull_off_separation()));
  EXPECT_TRUE(std::isnan(plain.summit_count(0.5e-6)));
  EXPECT_EQ(plain.tensile_part(0.5e-6).pressure, 0);
  // a range that ends before the pull-off: the whole range is the stable branch
  ContactCurvesData short_range = adhesive_closed_form(41);
  for (auto* v : {&short_range.separation, &short_range.pressure, &short_range.stiffness, &short_range.area_fraction,
                  &short_range.tensile_pressure, &short_range.tensile_stiffness, &short_range.summit_count})
    v->resize(5);
  const ContactCurves early(short_range);
  EXPECT_TRUE(std::isnan(early.pull_off_pressure()));
  EXPECT_EQ(early.stable_branch_end(), early.max_separation());
  EXPECT_EQ(early.min_pressure(), early.pressure(early.max_separation()));
}

// The fuzzer's adhesive table (fuzz/corpus/table_contents/adhesive-pressure-grid-end): the net
// pressures straddle 0 Pa, so min + (max - min) * 1 rounds an ulp above max_pressure(); the
// inverse serves it as the first node, not NaN, and a pressure clearly past stays NaN.
TEST(ContactCurvesInterpolant, AdhesivePressureGridEndsStayOnTheStableBranch) {
  ContactCurvesData data;
  data.source = "contact-law jkr";
  data.separation_datum = "the mean plane";
  data.separation = {1e-7, 2e-7, 3e-7, 4e-7, 5e-7};
  data.pressure = {1e8, 3e7, 1e7, 3e6, 1e6};
  data.stiffness = {1e15, 3e14, 1e14, 3e13, 1e13};
  data.area_fraction = {0.1, 0.04, 0.01, 0.004, 0.001};
  data.tensile_pressure = {36856299.242500149, 2e7, 1e7, 9e6, 6e6};
  data.tensile_stiffness = {1e14, 7e13, 4.5e13, 3e13, 2e13};
  for (int i = 0; i < 3; ++i) {
    data.measured_rel_error[i] = 0.01;
    data.max_rel_error[i] = 0.02;
  }
  data.check_points = 4;
  data.safety_factor = 2;
  data.solver_tolerance = 1e-8;
  data.contact_modulus = 1e11;
  data.nominal_area = 1e-10;
  data.mean_summit_height = 2e-8;
  data.max_height = 6e-7;
  const ContactCurves curves(data);
  ASSERT_TRUE(curves.has_tension());
  const double low = curves.min_pressure(), high = curves.max_pressure(), end = curves.stable_branch_end();
  ASSERT_LT(low, 0);
  for (int i = 0; i <= 64; ++i) {
    const double back = curves.separation_at_pressure(low + (high - low) * i / 64);
    EXPECT_TRUE(back >= curves.min_separation() && back <= end) << i << " " << back;
  }
  EXPECT_GT(low + (high - low) * 64 / 64, high);  // the case: the grid's end past the range
  EXPECT_EQ(curves.separation_at_pressure(std::nextafter(high, INFINITY)), curves.min_separation());
  EXPECT_EQ(curves.separation_at_pressure(std::nextafter(low, -INFINITY)), end);
  EXPECT_TRUE(std::isnan(curves.separation_at_pressure(high + 1e-6 * (high - low))));
  EXPECT_TRUE(std::isnan(curves.separation_at_pressure(low - 1e-6 * (high - low))));
}

TEST(ContactCurvesInterpolant, ReproducesACubicLogPressureExactly) {
  const ContactCurves curves(closed_form(5, 3));  // ln p a cubic: Hermite on exact slopes is exact
  EXPECT_EQ(curves.limited_intervals(), 0u);
  for (int i = 0; i <= 1000; ++i) {
    const double u = 0.1e-6 + 1e-6 * i / 1000;
    EXPECT_NEAR(curves.pressure(u) / closed_form_pressure(u, 3), 1, 1e-13) << u;
  }
}

TEST(ContactCurvesInterpolant, ConvergesAtFourthOrder) {
  // ln p with a quartic term: the cubic Hermite's error falls 16 times as the nodes halve
  double previous = 0;
  for (int nodes : {9, 17, 33}) {
    const ContactCurves curves(closed_form(nodes, 4));
    double worst = 0;
    for (int i = 0; i <= 4000; ++i) {
      const double u = 0.1e-6 + 1e-6 * i / 4000;
      worst = std::max(worst, std::fabs(curves.pressure(u) / closed_form_pressure(u, 4) - 1));
    }
    if (previous > 0) {
      EXPECT_GT(previous / worst, 12) << nodes;
      EXPECT_LT(previous / worst, 20) << nodes;
    }
    previous = worst;
  }
}

TEST(ContactCurvesInterpolant, StaysMonotoneWithInconsistentSlopes) {
  ContactCurvesData data = closed_form(6, 3);
  data.stiffness[2] *= 50;  // a slope far steeper than its neighbours' secants
  data.stiffness[3] *= 0.01;
  data.area_fraction = {0.5, 0.5, 0.2, 0.2, 0.19, 0.01};  // flat stretches: Steffen keeps them flat
  const ContactCurves curves(data);
  EXPECT_GT(curves.limited_intervals(), 0u);
  double last_p = INFINITY, last_a = INFINITY;
  for (int i = 0; i <= 10000; ++i) {
    const double u = curves.min_separation() + (curves.max_separation() - curves.min_separation()) * i / 10000;
    const ContactCurvesState s = curves.at_separation(u);
    EXPECT_LE(s.pressure, last_p);
    EXPECT_LE(s.area_fraction, last_a * (1 + 1e-15));
    EXPECT_GE(s.stiffness, 0);
    last_p = s.pressure;
    last_a = s.area_fraction;
  }
  EXPECT_EQ(curves.area_fraction(data.separation[0] + 0.5 * (data.separation[1] - data.separation[0])), 0.5);
}

TEST(ContactCurvesInterpolant, UnevenNodesFindTheirIntervals) {
  // nodes crowded at one end (a bin of the lookup's directory spans many intervals) and far
  // apart at the other: every query lands in its own interval (between its nodes' values)
  ContactCurvesData data = closed_form(200, 3);
  for (std::size_t i = 0; i < data.separation.size(); ++i) {
    const double f = static_cast<double>(i) / 199, u = 0.1e-6 + 1e-6 * f * f * f * f;
    const double log_p = -u / 0.2e-6 - std::pow(u / 0.5e-6, 3);
    data.separation[i] = u;
    data.pressure[i] = 1e8 * std::exp(log_p);
    data.stiffness[i] = data.pressure[i] * (1 / 0.2e-6 + 3 / 0.5e-6 * std::pow(u / 0.5e-6, 2));
    data.area_fraction[i] = 0.5 * std::exp(log_p);
  }
  const ContactCurves curves(data);
  for (std::size_t i = 0; i + 1 < data.separation.size(); ++i) {
    for (double f : {0.0, 1e-9, 0.5, 1 - 1e-9}) {
      const double u = data.separation[i] + f * (data.separation[i + 1] - data.separation[i]);
      const double p = curves.pressure(u);
      EXPECT_LE(p, data.pressure[i] * (1 + 1e-14)) << i;  // exp(ln p) rounds
      EXPECT_GE(p, data.pressure[i + 1] * (1 - 1e-14)) << i;
      EXPECT_NEAR(p / closed_form_pressure(u, 3), 1, 1e-12) << i;
    }
    EXPECT_NEAR(curves.pressure(data.separation[i]) / data.pressure[i], 1, 1e-14);
  }
}

TEST(ContactCurvesInterpolant, PressuresAFewUlpApartStayFinite) {
  // strictly falling pressures whose logarithms round to the same double: a flat interval
  ContactCurvesData data = closed_form(5, 3);
  data.pressure[2] = std::nextafter(data.pressure[1], 0.0);
  data.pressure[3] = std::nextafter(data.pressure[2], 0.0);
  ASSERT_EQ(std::log(data.pressure[2]), std::log(data.pressure[3]));
  const ContactCurves curves(data);
  for (int i = 0; i <= 1000; ++i) {
    const double u = curves.min_separation() + (curves.max_separation() - curves.min_separation()) * i / 1000;
    const ContactCurvesState s = curves.at_separation(u);
    EXPECT_TRUE(std::isfinite(s.pressure) && std::isfinite(s.stiffness) && std::isfinite(s.area_fraction)) << u;
    EXPECT_GE(curves.separation_at_pressure(s.pressure), curves.min_separation());
  }
  EXPECT_TRUE(std::isfinite(curves.separation_at_pressure(data.pressure[2])));
}

TEST(ContactCurvesInterpolant, OutsideTheRangeIsNaN) {
  const ContactCurves curves(closed_form(5, 3));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double u : {curves.min_separation() * (1 - 1e-15), curves.max_separation() * (1 + 1e-15), nan, double(INFINITY)}) {
    EXPECT_TRUE(std::isnan(curves.pressure(u)));
    EXPECT_TRUE(std::isnan(curves.stiffness(u)));
    EXPECT_TRUE(std::isnan(curves.area_fraction(u)));
    EXPECT_TRUE(std::isnan(curves.at_separation(u).pressure));
  }
  for (double p : {curves.min_pressure() * (1 - 1e-15), curves.max_pressure() * (1 + 1e-15), nan, 0.0, -1.0})
    EXPECT_TRUE(std::isnan(curves.separation_at_pressure(p)));
  EXPECT_EQ(curves.separation_at_pressure(curves.max_pressure()), curves.min_separation());
  EXPECT_EQ(curves.separation_at_pressure(curves.min_pressure()), curves.max_separation());
}

TEST(ContactCurvesData, ValidateRefusesWhatTheSchemaForbids) {
  const ContactCurvesData good = closed_form(5, 3);
  EXPECT_NO_THROW(good.validate("good"));
  const auto refused = [&](auto change) {
    ContactCurvesData data = good;
    change(data);
    EXPECT_THROW(data.validate("bad"), Error);
    EXPECT_THROW(ContactCurves{data}, Error);
  };
  refused([](ContactCurvesData& d) { d.separation.resize(2); d.pressure.resize(2); d.stiffness.resize(2); d.area_fraction.resize(2); });
  refused([](ContactCurvesData& d) { d.pressure.pop_back(); });
  refused([](ContactCurvesData& d) { d.separation[2] = d.separation[1]; });
  refused([](ContactCurvesData& d) { d.separation[2] = NAN; });
  refused([](ContactCurvesData& d) { d.pressure[2] = d.pressure[1]; });
  refused([](ContactCurvesData& d) { d.pressure[2] = -1; });
  refused([](ContactCurvesData& d) { d.pressure[0] = INFINITY; });
  refused([](ContactCurvesData& d) { d.stiffness[1] = 0; });
  refused([](ContactCurvesData& d) { d.area_fraction[3] = d.area_fraction[2] * 2; });
  refused([](ContactCurvesData& d) { d.area_fraction[0] = 1.5; });
  refused([](ContactCurvesData& d) { d.max_rel_error[1] = NAN; });
  refused([](ContactCurvesData& d) { d.safety_factor = 0.5; });
  refused([](ContactCurvesData& d) { d.contact_modulus = 0; });
  refused([](ContactCurvesData& d) { d.source.clear(); });
  refused([](ContactCurvesData& d) { d.mean_summit_height = INFINITY; });
  // the optional tensile part and summit count
  const ContactCurvesData adhesive = adhesive_closed_form(5);
  EXPECT_NO_THROW(adhesive.validate("good"));
  const auto refused_adhesive = [&](auto change) {
    ContactCurvesData data = adhesive;
    change(data);
    EXPECT_THROW(data.validate("bad"), Error);
    EXPECT_THROW(ContactCurves{data}, Error);
  };
  refused_adhesive([](ContactCurvesData& d) { d.tensile_stiffness.clear(); });
  refused_adhesive([](ContactCurvesData& d) { d.tensile_pressure.pop_back(); d.tensile_stiffness.pop_back(); });
  refused_adhesive([](ContactCurvesData& d) { d.tensile_pressure[2] = 0; });
  refused_adhesive([](ContactCurvesData& d) { d.tensile_pressure[2] = NAN; });
  refused_adhesive([](ContactCurvesData& d) { d.tensile_pressure[3] = 2 * d.tensile_pressure[2]; });
  refused_adhesive([](ContactCurvesData& d) { d.tensile_stiffness[1] = -1; });
  refused_adhesive([](ContactCurvesData& d) { d.tensile_stiffness[1] = INFINITY; });
  refused_adhesive([](ContactCurvesData& d) { d.summit_count.pop_back(); });
  refused_adhesive([](ContactCurvesData& d) { d.summit_count[4] = 2 * d.summit_count[3]; });
  refused_adhesive([](ContactCurvesData& d) { d.summit_count[0] = 0; });
  refused_adhesive([](ContactCurvesData& d) { d.summit_count_max_rel_error = NAN; });
  // flat tension (every summit in contact: DMT on a Weibull tail below its origin) is taken
  ContactCurvesData flat = adhesive;
  for (std::size_t i = 0; i < 3; ++i) flat.tensile_pressure[i] = flat.tensile_pressure[3], flat.tensile_stiffness[i] = 0;
  EXPECT_NO_THROW(ContactCurves{flat});
}

// ---- a synthetic measured map, solved ----

topo::HeightMap rough_map() {
  topo::SelfAffineSpectrum spectrum;
  spectrum.hurst = 0.8;
  const double side = 1e-3;
  const std::size_t n = 64;
  spectrum.rolloff_wavelength = side * 0.5;
  spectrum.cutoff_wavelength = 4 * side / static_cast<double>(n);
  spectrum.rms_height = 1e-6;
  return topo::self_affine_surface(n, n, side / n, side / n, spectrum, 11);
}

topo::ExactContactOptions solver_options() {
  topo::ExactContactOptions options;
  options.contact_modulus = 1e11;
  options.tolerance = 1e-10;
  options.threads = 1;
  return options;
}

// 17 nodes from 1e6 to 1e8 Pa (area fractions of about 1% to 30% on this map)
struct Solved {
  topo::ExactContactTable table;
  ContactCurves curves;
};

const Solved& solved() {
  static const Solved result = [] {
    const topo::HeightMap map = rough_map();
    topo::ExactContact solver(map, solver_options());
    std::vector<topo::ContactStep> nodes;
    for (int i = 0; i < 17; ++i) nodes.push_back(solver.at_pressure(1e6 * std::pow(10.0, 2.0 * i / 16)));
    topo::ExactContactTable table = topo::measure_exact_contact_table(solver, nodes, "synthetic", "17 nodes");
    ContactCurves curves(table.data);
    return Solved{std::move(table), std::move(curves)};
  }();
  return result;
}

TEST(ExactContactTable, ServedValuesAreTheNodesToRounding) {
  const Solved& s = solved();
  for (const topo::ContactStep& node : s.table.nodes) {
    const ContactCurvesState state = s.curves.at_separation(node.mean_gap);
    EXPECT_NEAR(state.pressure / node.pressure, 1, 1e-14);
    EXPECT_NEAR(state.stiffness / node.stiffness_per_area, 1, 1e-13);
    EXPECT_NEAR(state.area_fraction / node.area_fraction, 1, 1e-14);
  }
  // 5 checks an interval at least, finer where the estimate had not settled; the method stored
  EXPECT_GE(s.table.data.check_points, 16 * 5);
  EXPECT_EQ(s.table.data.check_points, static_cast<int>(s.table.checks.size()));
  EXPECT_EQ(s.table.data.bound_method, ContactBoundMethod::checks_until_settled);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(s.table.data.measured_rel_error[k], 0);
    EXPECT_EQ(s.table.data.max_rel_error[k], 2 * s.table.data.measured_rel_error[k]);
  }
  EXPECT_EQ(s.table.data.solver_tolerance, 1e-10);
}

TEST(ExactContactTable, IndependentSolvesBetweenTheNodesLieWithinTheStoredBound) {
  // new solves, by mean gap, at the middle of each interval in separation (the table's own
  // checks were by pressure, at the geometric means): a fresh solver, nothing shared
  const Solved& s = solved();
  const topo::HeightMap map = rough_map();
  topo::ExactContact solver(map, solver_options());
  const ContactCurvesData& data = s.table.data;
  double worst[3] = {0, 0, 0};
  for (std::size_t i = 0; i + 1 < data.separation.size(); ++i) {
    const double u = 0.5 * (data.separation[i] + data.separation[i + 1]);
    const topo::ContactStep exact = solver.at_mean_gap(u);
    const ContactCurvesState served = s.curves.at_separation(exact.mean_gap);
    const double errors[3] = {std::fabs(served.pressure / exact.pressure - 1),
                              std::fabs(served.stiffness / exact.stiffness_per_area - 1),
                              std::fabs(served.area_fraction / exact.area_fraction - 1)};
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(errors[k], data.max_rel_error[k]) << "quantity " << k << " at " << u;
      worst[k] = std::max(worst[k], errors[k]);
    }
  }
  std::printf("measured at the table's checks: %.3g %.3g %.3g; at independent mid-separation solves: %.3g %.3g %.3g\n",
              data.measured_rel_error[0], data.measured_rel_error[1], data.measured_rel_error[2], worst[0], worst[1],
              worst[2]);
}

TEST(ExactContactTable, InverseRoundTrip) {
  const ContactCurves& curves = solved().curves;
  const double span = curves.max_separation() - curves.min_separation();
  for (int i = 0; i <= 2000; ++i) {
    const double u = curves.min_separation() + span * i / 2000;
    const double p = curves.pressure(u);
    EXPECT_NEAR(curves.separation_at_pressure(p), u, 1e-12 * span) << u;
    const ContactCurvesState at_p = curves.at_pressure(p);
    EXPECT_NEAR(at_p.pressure, p, 1e-15 * p);
    EXPECT_NEAR(at_p.stiffness / curves.stiffness(u), 1, 1e-9);
  }
  for (int i = 0; i <= 2000; ++i) {
    const double p = curves.min_pressure() * std::pow(curves.max_pressure() / curves.min_pressure(), i / 2000.0);
    EXPECT_NEAR(curves.pressure(curves.separation_at_pressure(p)) / p, 1, 1e-12) << p;
  }
}

TEST(ExactContactTable, FileRoundTrip) {
  const ContactCurvesData& data = solved().table.data;
  const std::string path = temp_path("contact-curves-round-trip.h5");
  write_contact_curves_file(data, path);
  EXPECT_EQ(read_table_kind(path), TableKind::contact_curves);
  const ContactCurvesData read = read_contact_curves_file(path);
  EXPECT_EQ(read.separation, data.separation);
  EXPECT_EQ(read.pressure, data.pressure);
  EXPECT_EQ(read.stiffness, data.stiffness);
  EXPECT_EQ(read.area_fraction, data.area_fraction);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(read.max_rel_error[k], data.max_rel_error[k]);
    EXPECT_EQ(read.measured_rel_error[k], data.measured_rel_error[k]);
  }
  EXPECT_EQ(read.check_points, data.check_points);
  EXPECT_EQ(read.bound_method, data.bound_method);
  EXPECT_EQ(read.safety_factor, data.safety_factor);
  EXPECT_EQ(read.solver_tolerance, data.solver_tolerance);
  EXPECT_EQ(read.contact_modulus, data.contact_modulus);
  EXPECT_EQ(read.nominal_area, data.nominal_area);
  EXPECT_EQ(read.mean_summit_height, data.mean_summit_height);
  EXPECT_EQ(read.max_height, data.max_height);
  EXPECT_EQ(read.source, data.source);
  EXPECT_EQ(read.description, data.description);
  EXPECT_EQ(read.separation_datum, data.separation_datum);
  EXPECT_EQ(read.generator, data.generator);
  // the same bytes for the same data (no timestamps)
  EXPECT_EQ(contact_curves_file_bytes(read), contact_curves_file_bytes(data));
  const ContactCurves opened = ContactCurves::open(path);
  const ContactCurves& served = solved().curves;
  for (int i = 0; i <= 100; ++i) {
    const double u = served.min_separation() + (served.max_separation() - served.min_separation()) * i / 100;
    EXPECT_EQ(opened.pressure(u), served.pressure(u));
    EXPECT_EQ(opened.stiffness(u), served.stiffness(u));
    EXPECT_EQ(opened.area_fraction(u), served.area_fraction(u));
  }
  // without the optional mean summit height
  ContactCurvesData bare = data;
  bare.mean_summit_height = NAN;
  bare.max_height = NAN;
  write_contact_curves_file(bare, path);
  EXPECT_TRUE(std::isnan(read_contact_curves_file(path).mean_summit_height));
  EXPECT_FALSE(read_contact_curves_file(path).has_tension());
  EXPECT_TRUE(read_contact_curves_file(path).summit_count.empty());
  // with the tensile part and the summit count
  const ContactCurvesData adhesive = adhesive_closed_form(9);
  write_contact_curves_file(adhesive, path);
  const ContactCurvesData back = read_contact_curves_file(path);
  EXPECT_EQ(back.tensile_pressure, adhesive.tensile_pressure);
  EXPECT_EQ(back.tensile_stiffness, adhesive.tensile_stiffness);
  EXPECT_EQ(back.summit_count, adhesive.summit_count);
  EXPECT_EQ(back.summit_count_max_rel_error, adhesive.summit_count_max_rel_error);
  EXPECT_EQ(contact_curves_file_bytes(back), contact_curves_file_bytes(adhesive));
}

TEST(ExactContactTable, CardFromTheCurves) {
  const ContactCurves& curves = solved().curves;
  const double low = curves.min_pressure(), high = curves.max_pressure();
  const PressureOverclosureTable card = tabulate_pressure_overclosure(curves, low, high, 1e-3);
  EXPECT_LE(card.max_error, 1e-3);
  EXPECT_EQ(card.points.front().pressure, 0);
  const double summit = curves.data().mean_summit_height;
  for (std::size_t i = 1; i < card.points.size(); ++i) {
    // each point on the served curve: overclosure -(u - mean summit height)
    const double u = summit - card.points[i].overclosure;
    EXPECT_NEAR(card.points[i].pressure / curves.pressure(std::clamp(u, curves.min_separation(), curves.max_separation())),
                1, 1e-9);
  }
  EXPECT_THROW(tabulate_pressure_overclosure(curves, low * 0.5, high, 1e-3), Error);  // beyond the range served
  std::ostringstream text;
  write_pressure_overclosure(text, tabulate_pressure_overclosure(curves, low, high, 1e-3, OverclosureDatum::origin),
                             CardFormat::abaqus, CardUnits::si, "test");
  EXPECT_NE(text.str().find("the mean gap"), std::string::npos) << text.str();
  // the mean-plane datum is a GW model's (it needs the model's mean summit height above the plane):
  // refused for curves, naming the datums they take
  try {
    tabulate_pressure_overclosure(curves, low, high, 1e-3, OverclosureDatum::mean_plane);
    ADD_FAILURE() << "the mean-plane datum was not refused";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("not mean-plane"), std::string::npos) << error.what();
  }
}

// ---- files from outside ----

std::vector<unsigned char> good_bytes() { return contact_curves_file_bytes(closed_form(5, 3)); }

TableFileStatus status_of(const std::vector<unsigned char>& bytes) {
  try {
    read_contact_curves_bytes(bytes.data(), bytes.size(), "test");
  } catch (const TableFileError& error) {
    return error.status();
  }
  ADD_FAILURE() << "accepted";
  return TableFileStatus::missing;
}

// Replaces the 8 bytes of `from` (a double stored little-endian, as the writer stores every
// float) by those of `to`, at its first occurrence, and seals the header again: a file whose
// integrity header is right and whose contents are forged.
std::vector<unsigned char> forged(std::vector<unsigned char> bytes, double from, double to) {
  unsigned char a[8], b[8];
  std::memcpy(a, &from, 8);
  std::memcpy(b, &to, 8);
  const auto at = std::search(bytes.begin() + 512, bytes.end(), a, a + 8);
  EXPECT_NE(at, bytes.end()) << "no " << from << " in the file";
  if (at != bytes.end()) std::copy(b, b + 8, at);
  seal_table_bytes(bytes.data(), bytes.size());
  return bytes;
}

TEST(ContactCurvesFile, DamagedFilesAreRefused) {
  const std::vector<unsigned char> good = good_bytes();
  EXPECT_NO_THROW(read_contact_curves_bytes(good.data(), good.size(), "good"));
  std::vector<unsigned char> flipped = good;
  flipped[good.size() / 2] ^= 0x10;
  EXPECT_EQ(status_of(flipped), TableFileStatus::damaged);
  EXPECT_EQ(status_of(std::vector<unsigned char>(good.begin(), good.end() - 100)), TableFileStatus::damaged);
  std::vector<unsigned char> longer = good;
  longer.push_back(0);
  EXPECT_EQ(status_of(longer), TableFileStatus::damaged);
  EXPECT_EQ(status_of(std::vector<unsigned char>(good.begin(), good.begin() + 100)), TableFileStatus::damaged);
  EXPECT_EQ(status_of({}), TableFileStatus::not_hdf5);
}

TEST(ContactCurvesFile, ForgedContentsAreRefused) {
  const ContactCurvesData data = closed_form(5, 3);
  const std::vector<unsigned char> good = good_bytes();
  // a pressure that rises, a NaN separation, an area above 1, a negative stiffness, a bound NaN
  EXPECT_EQ(status_of(forged(good, data.pressure[2], data.pressure[0] * 2)), TableFileStatus::invalid);
  EXPECT_EQ(status_of(forged(good, data.separation[3], NAN)), TableFileStatus::invalid);
  EXPECT_EQ(status_of(forged(good, data.separation[3], data.separation[1])), TableFileStatus::invalid);
  EXPECT_EQ(status_of(forged(good, data.area_fraction[0], 2.0)), TableFileStatus::invalid);
  EXPECT_EQ(status_of(forged(good, data.stiffness[4], -data.stiffness[4])), TableFileStatus::invalid);
  EXPECT_EQ(status_of(forged(good, data.contact_modulus, INFINITY)), TableFileStatus::invalid);
}

// How the bound was measured: stored and read back; a table without it (written before it) is
// served as unstated; a method this runtime does not know is refused, naming it.
TEST(ContactCurvesFile, BoundMethodStoredAbsentOrUnknown) {
  ContactCurvesData data = closed_form(5, 3);
  EXPECT_EQ(data.bound_method, ContactBoundMethod::unstated);
  const std::vector<unsigned char> unstated = contact_curves_file_bytes(data);
  EXPECT_EQ(read_contact_curves_bytes(unstated.data(), unstated.size(), "old").bound_method,
            ContactBoundMethod::unstated);
  data.bound_method = ContactBoundMethod::checks_until_settled;
  std::vector<unsigned char> bytes = contact_curves_file_bytes(data);
  EXPECT_EQ(read_contact_curves_bytes(bytes.data(), bytes.size(), "new").bound_method,
            ContactBoundMethod::checks_until_settled);
  const std::string token = to_string(ContactBoundMethod::checks_until_settled), newer = "checks-until-settlez";
  ASSERT_EQ(token.size(), newer.size());
  const auto at = std::search(bytes.begin() + 512, bytes.end(), token.begin(), token.end());
  ASSERT_NE(at, bytes.end());
  std::copy(newer.begin(), newer.end(), at);
  seal_table_bytes(bytes.data(), bytes.size());
  try {
    read_contact_curves_bytes(bytes.data(), bytes.size(), "newer");
    ADD_FAILURE() << "an unknown bound method accepted";
  } catch (const TableFileError& error) {
    EXPECT_EQ(error.status(), TableFileStatus::other_version);
    EXPECT_NE(std::string(error.what()).find("'bound_method' = 'checks-until-settlez'"), std::string::npos)
        << error.what();
  }
  ContactBoundMethod method{};
  for (ContactBoundMethod known : {ContactBoundMethod::unstated, ContactBoundMethod::checks_until_settled,
                                   ContactBoundMethod::checks_split_to_tolerance}) {
    EXPECT_TRUE(parse_contact_bound_method(to_string(known), method));
    EXPECT_EQ(method, known);
    EXPECT_GT(std::strlen(bound_method_meaning(known)), 40u);
  }
  EXPECT_FALSE(parse_contact_bound_method("", method));
}

TEST(ContactCurvesFile, TheOtherKindIsRefusedEitherWay) {
  const std::string curves_path = temp_path("contact-curves-kind.h5");
  write_contact_curves_file(closed_form(5, 3), curves_path);
  try {
    Table::open(curves_path);
    ADD_FAILURE() << "a contact-curves table opened as integrals";
  } catch (const TableFileError& error) {
    EXPECT_EQ(error.status(), TableFileStatus::other_schema);
    EXPECT_NE(std::string(error.what()).find("contact curves"), std::string::npos) << error.what();
  }
  try {
    read_contact_curves_file(ASPERITY_TEST_TABLE);
    ADD_FAILURE() << "a table of integrals opened as contact curves";
  } catch (const TableFileError& error) {
    EXPECT_EQ(error.status(), TableFileStatus::other_schema);
  }
  EXPECT_EQ(read_table_kind(ASPERITY_TEST_TABLE), TableKind::integrals);
  try {
    read_table_kind(temp_path("no-such-table.h5"));
    ADD_FAILURE();
  } catch (const TableFileError& error) {
    EXPECT_EQ(error.status(), TableFileStatus::missing);
  }
}

TEST(ContactCurvesFile, WriterRefusesWhatTheReaderWould) {
  ContactCurvesData data = closed_form(5, 3);
  data.pressure[3] = data.pressure[1];
  EXPECT_THROW(contact_curves_file_bytes(data), Error);
  const std::string path = temp_path("contact-curves-refused.h5");
  std::remove(path.c_str());
  EXPECT_THROW(write_contact_curves_file(data, path), Error);
  EXPECT_FALSE(std::ifstream(path).good());  // nothing written
}

}  // namespace
