// The adhesive exact contact (topography/exact_contact.hpp, work_of_adhesion and adhesive_stress:
// the Maugis-Dugdale cohesive zone on every pixel) against Maugis' closed form of the sphere,
// solved here on its own (Maugis 1992, in Johnson and Greenwood's 1997 notation): the load against
// the approach on loading and unloading (the hysteresis: out of contact on loading where
// unloading is still in contact) and the pull-off force, at Maugis parameters near the DMT limit
// (lambda 0.1), at lambda 1 and towards the JKR limit (lambda 3), and the mesh criterion: the
// error against the cohesive zone's width in pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/topography/exact_contact.hpp"
#include "exact_contact_shapes.hpp"
#include "test_subsample.hpp"

namespace {
using namespace asperity::topography;
constexpr double pi = 3.14159265358979323846;
constexpr double modulus = 1e9, radius = 1e-2, side = 1e-3;

// Maugis' sphere in his units (K = 4 E*/3): a = A a_s, a_s = (pi w R^2 / K)^(1/3); approach
// delta = D d_s, d_s = a_s^2 / R; load P = Pbar pi w R; lambda = 2 sigma0 (R / (pi w K^2))^(1/3).
// For a contact radius A the cohesive zone's outer radius c = m a solves
//   (lambda A^2 / 2) [t + (m^2 - 2) atan t] + (4 lambda^2 A / 3) [t atan t - m + 1] = 1,  t = sqrt(m^2 - 1),
// and Pbar = A^3 - lambda A^2 [t + m^2 atan t], D = A^2 - (4/3) A lambda t. The left side grows
// with t (both brackets do), so t is found by bisection.
struct MaugisState {
  double contact_radius = 0, zone_ratio = 0, load = 0, approach = 0;  // A, m, Pbar, D
};

MaugisState maugis(double lambda, double A) {
  auto excess = [&](double t) {
    const double m2 = 1 + t * t, m = std::sqrt(m2), at = std::atan(t);
    return lambda * A * A / 2 * (t + (m2 - 2) * at) + 4 * lambda * lambda * A / 3 * (t * at - m + 1) - 1;
  };
  double low = 0, high = 1;
  while (excess(high) < 0) high *= 2;
  for (int i = 0; i < 200 && high - low > 1e-15 * high; ++i) {
    const double mid = 0.5 * (low + high);
    (excess(mid) < 0 ? low : high) = mid;
  }
  const double t = 0.5 * (low + high), m2 = 1 + t * t, at = std::atan(t);
  MaugisState s;
  s.contact_radius = A;
  s.zone_ratio = std::sqrt(m2);
  s.load = A * A * A - lambda * A * A * (t + m2 * at);
  s.approach = A * A - 4.0 / 3.0 * A * lambda * t;
  return s;
}

// The stable branch under fixed grips (D rising with A, from the branch's end A_end, where D is
// least, upwards), the pull-off (the least load, Pbar) and the branch's end, found by a scan in A
// refined by golden sections.
struct MaugisBranch {
  double lambda = 0, end_radius = 0, end_approach = 0, pull_off = 0, pull_off_approach = 0;
  // the state on the branch at approach D; contact_radius 0 below the branch's end
  MaugisState at_approach(double D) const {
    if (D < end_approach) return MaugisState{};
    double low = end_radius, high = std::max(2 * end_radius, 1.0);
    while (maugis(lambda, high).approach < D) high *= 1.5;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (low + high);
      (maugis(lambda, mid).approach < D ? low : high) = mid;
    }
    return maugis(lambda, 0.5 * (low + high));
  }
};

MaugisBranch maugis_branch(double lambda) {
  MaugisBranch b;
  b.lambda = lambda;
  auto least = [&](auto value) {
    double best = 1e-3, least_value = INFINITY;
    for (double A = 1e-3; A < 4; A += 1e-3)
      if (value(A) < least_value) {
        least_value = value(A);
        best = A;
      }
    double a = std::max(best - 1e-3, 1e-4), d = best + 1e-3;
    for (int i = 0; i < 80; ++i) {
      const double c1 = d - 0.618033988749895 * (d - a), c2 = a + 0.618033988749895 * (d - a);
      if (value(c1) < value(c2)) d = c2;
      else a = c1;
    }
    return 0.5 * (a + d);
  };
  const double A_load = least([&](double A) { return maugis(lambda, A).load; });
  b.pull_off = maugis(lambda, A_load).load;
  b.pull_off_approach = maugis(lambda, A_load).approach;
  b.end_radius = least([&](double A) { return maugis(lambda, A).approach; });
  b.end_approach = maugis(lambda, b.end_radius).approach;
  return b;
}

// A sphere of radius R on an n x n map of side `side`, padded, Love's kernel (the free half-space),
// with a work of adhesion whose a_s spans `scale_pixels` pixels at n and the adhesive stress of
// Maugis parameter lambda.
struct Sphere {
  double w = 0, sigma0 = 0, a_s = 0, d_s = 0, force = 0, tip = 0;  // tip: above the mean plane
  ExactContactOptions options;
  HeightMap map;
};

Sphere adhesive_sphere(std::size_t n, double a_s, double lambda) {
  Sphere s;
  const double K = 4 * modulus / 3;
  s.a_s = a_s;
  s.w = a_s * a_s * a_s * K / (pi * radius * radius);
  s.d_s = a_s * a_s / radius;
  s.force = pi * s.w * radius;
  s.sigma0 = lambda / (2 * std::cbrt(radius / (pi * s.w * K * K)));
  s.map = asperity::test::sphere_map(n, side, radius);
  double mean = 0;
  for (double h : s.map.heights) mean += h;
  s.tip = -mean / static_cast<double>(n * n);  // the sphere's apex (height 0) above the mean plane
  s.options.contact_modulus = modulus;
  s.options.boundary = ContactBoundary::padded;
  s.options.kernel = ContactKernel::love;
  s.options.work_of_adhesion = s.w;
  s.options.adhesive_stress = s.sigma0;
  s.options.stiffness = false;
  return s;
}

// One loading-unloading cycle: D from `from` up to `top` and back down to `to` (steps of `step`,
// in d_s), each from the last; the load (Pbar), contact points, D and the cohesive zone's points.
struct CyclePoint {
  double D = 0, load = 0;
  std::size_t contact = 0, zone = 0;
  bool unloading = false;
  int passes = 0, iterations = 0;  // the fixed point's passes, the constrained iterations of all of them
};
std::vector<CyclePoint> cycle(const Sphere& s, double from, double top, double to, double load_step,
                              double unload_step) {
  ExactContact solver(s.map, s.options);
  std::vector<CyclePoint> points;
  auto solve_at = [&](double D, bool unloading) {
    const ContactStep r = solver.at_approach(s.tip - D * s.d_s);
    points.push_back({D, r.load / s.force, r.contact_points, r.adhesive_points, unloading, r.solves, r.iterations});
  };
  // loading on the unloading's grid (a multiple of its step), so that both pass the same approaches
  const int up = static_cast<int>(std::ceil((top - from) / load_step - 1e-9));
  const int down = static_cast<int>(std::lround((top - to) / unload_step));
  for (int k = up; k >= 0; --k) solve_at(top - k * load_step, false);
  for (int k = 1; k <= down; ++k) solve_at(top - k * unload_step, true);
  return points;
}

// A cycle set against Maugis' branch: the largest error of the load on unloading where both are in
// contact (in pi w R), the pull-off (the least load on unloading) and its error relative to
// Maugis', and whether loading and unloading differ (out of contact on loading, in on unloading).
struct CycleErrors {
  double load = 0, pull_off = INFINITY, pull_off_error = 0;
  bool hysteresis = false;
};
CycleErrors against_maugis(const std::vector<CyclePoint>& points, const MaugisBranch& branch, bool print) {
  CycleErrors e;
  for (const CyclePoint& p : points) {
    const MaugisState m = branch.at_approach(p.D);
    if (print)
      std::printf("  %s D %+.3f load %+.4f (Maugis %+.4f, A %.3f) contact %zu zone %zu passes %d iterations %d\n",
                  p.unloading ? "un" : "lo", p.D, p.load, m.contact_radius > 0 ? m.load : NAN, m.contact_radius, p.contact,
                  p.zone, p.passes, p.iterations);
    if (!p.unloading) continue;
    e.pull_off = std::min(e.pull_off, p.load);
    if (p.contact > 0 && m.contact_radius > 0) e.load = std::max(e.load, std::fabs(p.load - m.load));
    for (const CyclePoint& q : points)
      if (!q.unloading && std::fabs(q.D - p.D) < 1e-9 && q.contact == 0 && p.contact > 0) e.hysteresis = true;
  }
  e.pull_off_error = e.pull_off / branch.pull_off - 1;
  return e;
}

// One sphere's cycle at Maugis parameter lambda with a_s spanning `a_s_pixels` of an n x n map, set
// against Maugis; prints what it measured (the cohesive zone's width c - a at the pull-off in
// pixels: the mesh criterion's figure).
struct Level {
  double zone_pixels = 0;
  CycleErrors errors;
};
Level run_level(double lambda, std::size_t n, double a_s_pixels) {
  const Sphere s = adhesive_sphere(n, a_s_pixels * side / static_cast<double>(n), lambda);
  const MaugisBranch branch = maugis_branch(lambda);
  const double range = s.w / s.sigma0 / s.d_s;  // h0 in d_s: 2 / (pi lambda)
  const MaugisState at_pull_off = branch.at_approach(branch.pull_off_approach);
  Level level;
  level.zone_pixels = (at_pull_off.zone_ratio - 1) * at_pull_off.contact_radius * a_s_pixels;
  const std::vector<CyclePoint> points =
      cycle(s, std::max(-range - 0.1, -1.2), 1.0, branch.end_approach - 0.2, 0.1, 0.05);
  level.errors = against_maugis(points, branch, std::getenv("ASPERITY_PRINT_CYCLES") != nullptr);
  int passes = 0, iterations = 0;
  for (const CyclePoint& p : points) {
    passes += p.passes;
    iterations += p.iterations;
  }
  std::printf("lambda %.2f (h0 %.3f d_s), a_s %.0f pixels, the zone c - a %.1f pixels at the pull-off: load within "
              "%.4f pi w R of Maugis on unloading; pull-off %.4f against Maugis %.4f (%+.2f%%; DMT -2, JKR -1.5); "
              "hysteresis %d; %zu steps, %d passes, %d iterations\n",
              lambda, range, a_s_pixels, level.zone_pixels, level.errors.load, level.errors.pull_off, branch.pull_off,
              100 * level.errors.pull_off_error, level.errors.hysteresis, points.size(), passes, iterations);
  return level;
}

// Near the DMT limit (lambda 0.1) the zone is wide (27 pixels at a_s 8 pixels): the load and the
// pull-off within a few tenths of a percent of pi w R. No hysteresis (the contact forms and leaves
// without a jump below lambda 0.93).
TEST(ExactContactAdhesive, NearTheDmtLimit) {
  const bool sanitized = asperity::test::subsample_stride() > 1;
  const Level level = run_level(0.1, sanitized ? 64 : 128, sanitized ? 4 : 8);
  EXPECT_LT(level.errors.load, sanitized ? 0.1 : 0.03);
  EXPECT_LT(std::fabs(level.errors.pull_off_error), sanitized ? 0.05 : 0.01);
  EXPECT_FALSE(level.errors.hysteresis);
}

// At lambda 1 and towards the JKR limit (lambda 3, where the zone is 0.08 a_s wide): the pixel's
// error is first order in the spacing over the zone's width (the zone's edge falls on a pixel
// centre), so two levels (a_s doubled in pixels on the same sphere) extrapolate (Richardson) to
// Maugis' pull-off; each level has the hysteresis (jump-in on loading, contact kept on unloading).
TEST(ExactContactAdhesive, MaugisAndTowardsJkrAgainstTheClosedForm) {
  const bool sanitized = asperity::test::subsample_stride() > 1;
  struct Case {
    double lambda, a_s_pixels, coarse_pull_off, fine_pull_off, extrapolated, load;
  };
  for (const Case c : {Case{1.0, 8, 0.15, 0.07, 0.015, 0.15}, Case{3.0, 16, 0.5, 0.25, 0.05, 0.6}}) {
    const Level coarse = run_level(c.lambda, 64, c.a_s_pixels);
    EXPECT_TRUE(coarse.errors.hysteresis) << c.lambda;
    EXPECT_LT(std::fabs(coarse.errors.pull_off_error), c.coarse_pull_off) << c.lambda;
    if (sanitized) continue;
    const Level fine = run_level(c.lambda, 128, 2 * c.a_s_pixels);
    EXPECT_TRUE(fine.errors.hysteresis) << c.lambda;
    EXPECT_LT(std::fabs(fine.errors.pull_off_error), c.fine_pull_off) << c.lambda;
    EXPECT_LT(std::fabs(fine.errors.pull_off_error), std::fabs(coarse.errors.pull_off_error)) << c.lambda;
    EXPECT_LT(fine.errors.load, c.load) << c.lambda;
    const double extrapolated = 2 * fine.errors.pull_off_error - coarse.errors.pull_off_error;
    std::printf("lambda %.2f: pull-off error extrapolated from the two levels %+.2f%%\n", c.lambda, 100 * extrapolated);
    EXPECT_LT(std::fabs(extrapolated), c.extrapolated) << c.lambda;
  }
}

// The mesh criterion's third level (slow: a 256 x 256 map padded): lambda 1 at a_s 32 pixels.
TEST(ExactContactAdhesive, SlowThirdMeshLevel) {
  const Level level = run_level(1.0, 256, 32);
  EXPECT_LT(std::fabs(level.errors.pull_off_error), 0.035);
}

}  // namespace
