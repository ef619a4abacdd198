// The elastic-perfectly-plastic exact contact (topography/exact_contact.hpp, hardness: the
// pressure capped at H on every pixel) against closed forms: Hertz below the onset of yield (the
// elastic limit), the onset where Hertz's peak pressure p0 reaches H, the fully plastic limit
// (load -> H times the plastic area), the flat punch (elastic below the cap, H times the punch's
// area at most), and the complementarity conditions of the solution checked with displacements
// summed directly from Love's coefficients (not the solver's FFTs).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/topography/exact_contact.hpp"
#include "exact_contact_shapes.hpp"
#include "asperity/topography/self_affine.hpp"

namespace {
using namespace asperity::topography;
constexpr double pi = 3.14159265358979323846;
constexpr double modulus = 1e11, radius = 1e-2, side = 1e-3;

// A paraboloid of radius R centred on the map: the gap of a sphere over a flat.
HeightMap sphere(std::size_t n) { return asperity::test::sphere_map(n, side, radius); }

// A flat-ended punch of radius a (the points whose centres are within it at 0, the rest `depth`
// below): its contact never leaves the punch's face.
HeightMap punch(std::size_t n, double a, double depth, std::size_t& face_points) {
  HeightMap map = sphere(n);
  map.source = "punch";
  face_points = 0;
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const double x = (static_cast<double>(i) + 0.5 - n / 2.0) * map.dx;
      const double y = (static_cast<double>(j) + 0.5 - n / 2.0) * map.dy;
      const bool face = x * x + y * y < a * a;
      map.heights[j * n + i] = face ? 0.0 : -depth;
      face_points += face;
    }
  return map;
}

ExactContactOptions plastic_options(double hardness) {
  ExactContactOptions options;
  options.contact_modulus = modulus;
  options.boundary = ContactBoundary::padded;
  options.kernel = ContactKernel::love;
  options.hardness = hardness;
  return options;
}

// Hertz: the load at which the peak pressure p0 = 2 E* a / (pi R) reaches H, P_y = pi^3 R^2 H^3 / (6 E*^2).
double hertz_yield_load(double hardness) { return pi * pi * pi * radius * radius * std::pow(hardness, 3) / (6 * modulus * modulus); }

// Below the onset the capped solve is the elastic one (the cap never reached) and Hertz's.
TEST(ExactContactPlastic, BelowTheOnsetIsHertz) {
  const double a = side / 5, load = 4 * modulus * a * a * a / (3 * radius), peak = 2 * modulus * a / (pi * radius);
  const HeightMap map = sphere(128);  // contact radius 25.6 pixels
  ExactContact elastic(map, plastic_options(0)), capped(map, plastic_options(1.1 * peak));
  const ContactStep e = elastic.at_pressure(load / (side * side)), c = capped.at_pressure(load / (side * side));
  EXPECT_EQ(c.plastic_points, 0u);
  EXPECT_EQ(c.contact_points, e.contact_points);
  EXPECT_NEAR(c.approach / e.approach, 1, 1e-7);
  EXPECT_NEAR(c.max_pressure / e.max_pressure, 1, 1e-6);
  EXPECT_NEAR(c.approach_stiffness / e.approach_stiffness, 1, 1e-6);
  std::printf("below the onset: radius %+.5f peak %+.5f stiffness %+.5f against Hertz\n",
              std::sqrt(c.real_area / pi) / a - 1, c.max_pressure / peak - 1, c.approach_stiffness / (2 * modulus * a) - 1);
  EXPECT_NEAR(std::sqrt(c.real_area / pi) / a, 1, 1e-2);
  EXPECT_NEAR(c.max_pressure / peak, 1, 2e-3);
  EXPECT_NEAR(c.approach_stiffness / (2 * modulus * a), 1, 5e-3);
  // the elastic answer as it was: hardness 0 and +inf are the same solver, bit for bit
  ExactContact infinite(map, plastic_options(INFINITY));
  const ContactStep i = infinite.at_pressure(load / (side * side));
  EXPECT_EQ(i.approach, e.approach);
  EXPECT_EQ(i.max_pressure, e.max_pressure);
  EXPECT_EQ(i.plastic_area_fraction, 0.0);
}

// The onset of yield: no plastic point below Hertz's P_y (p0 = H), some above it.
TEST(ExactContactPlastic, OnsetOfYieldWherePeakReachesHardness) {
  const HeightMap map = sphere(128);
  // the hardness that Hertz's peak reaches at a contact radius of side / 5 (25.6 pixels)
  const double a = side / 5, onset_hardness = 2 * modulus * a / (pi * radius);
  ExactContact solver(map, plastic_options(onset_hardness));
  const double yield = hertz_yield_load(onset_hardness) / (side * side);
  const ContactStep below = solver.at_pressure(0.97 * yield), above = solver.at_pressure(1.03 * yield);
  std::printf("onset: at 0.97 P_y peak/H %.5f, plastic points %zu; at 1.03 P_y %zu plastic of %zu\n",
              below.max_pressure / onset_hardness, below.plastic_points, above.plastic_points, above.contact_points);
  EXPECT_EQ(below.plastic_points, 0u);
  EXPECT_LT(below.max_pressure, onset_hardness);
  EXPECT_GT(above.plastic_points, 0u);
  EXPECT_EQ(above.max_pressure, onset_hardness);
  // the plastic points are the middle of the contact: within the radius where Hertz's pressure exceeds H
  EXPECT_LT(above.plastic_points, above.contact_points / 10);
}

// Pressed far past the onset the load is carried at the hardness: P / (H A) -> 1 and the plastic
// area nears the contact area.
TEST(ExactContactPlastic, FullyPlasticLimit) {
  // P_y at a contact radius of 10 um (1.3 pixels); at 1000 P_y about 260 um (33 pixels)
  const double a = side / 5, hardness = 2 * modulus * a / (pi * radius) / 20;
  const HeightMap map = sphere(128);
  ExactContact solver(map, plastic_options(hardness));
  double last_ratio = 0, plastic_share = 0;
  for (double times : {10.0, 100.0, 1000.0}) {
    const ContactStep s = solver.at_pressure(times * hertz_yield_load(hardness) / (side * side));
    const double load_ratio = s.load / (hardness * s.real_area);
    const double plastic_ratio = s.plastic_area_fraction / s.area_fraction;
    std::printf("fully plastic: P = %6.0f P_y: P/(H A) %.4f, A_plastic/A %.4f, P/(H A_plastic) %.4f, %zu points\n", times,
                load_ratio, plastic_ratio, s.load / (hardness * s.plastic_area_fraction * solver.nominal_area()),
                s.contact_points);
    EXPECT_LE(load_ratio, 1.0);
    EXPECT_GT(load_ratio, last_ratio);  // nearer the limit the further past the onset
    last_ratio = load_ratio;
    plastic_share = plastic_ratio;
    EXPECT_LE(s.max_pressure, hardness);
  }
  // the incremental stiffness (the free points held, the plastic ones carrying no increment)
  // against a finite difference of two solves, at 100 P_y and 1e-3 apart
  const double base = 100 * hertz_yield_load(hardness) / (side * side);
  const ContactStep a0 = solver.at_pressure(base), a1 = solver.at_pressure(base * (1 + 1e-3));
  const double difference = (a1.load - a0.load) / (a0.approach - a1.approach);
  std::printf("fully plastic: stiffness %.6g against a finite difference %.6g\n", a0.approach_stiffness, difference);
  EXPECT_NEAR(a0.approach_stiffness / difference, 1, 0.05);
  for (double f : {1.01, 1.1, 1.3}) {  // the tangent of a pixelated curve: see docs/exact-contact.md
    const ContactStep b0 = solver.at_pressure(base), b1 = solver.at_pressure(base * f);
    std::printf("fully plastic: secant over a load %.2f times the step: %.6g\n", f, (b1.load - b0.load) / (b0.approach - b1.approach));
  }
  // measured at 1000 P_y (3436 points in contact): P/(H A) 0.9987, A_plastic/A 0.9953
  EXPECT_GT(last_ratio, 0.995);
  EXPECT_GT(plastic_share, 0.99);
}

// The flat punch: below the cap the elastic punch (P = 2 a E* delta for the punch's equivalent
// radius; the discrete edge carries a large but finite pressure), with a cap the edge plastic and
// the middle not, and the load never above H times the face's area.
TEST(ExactContactPlastic, FlatPunchEdgeCappedLoadBoundedByHardnessTimesArea) {
  const std::size_t n = 96;
  std::size_t face = 0;
  const HeightMap map = punch(n, side / 6, 1e-5, face);
  const double pixel = (side / n) * (side / n), face_area = static_cast<double>(face) * pixel;
  const double a = std::sqrt(face_area / pi);
  ExactContact elastic(map, plastic_options(0));
  const double pressure = 1e8;  // nominal: 1e8 * side^2 / face_area on the face
  const ContactStep e = elastic.at_pressure(pressure);
  EXPECT_EQ(e.contact_points, face);
  // the rigid-body approach: the flat's position below the face (the map's highest point)
  const double stiffness = e.load / (elastic.max_height() - e.approach);
  std::printf("punch: %zu face points, elastic P/delta / (2 a E*) %.4f; edge pressure / mean %.2f\n", face,
              stiffness / (2 * a * modulus), e.max_pressure / (e.load / face_area));
  EXPECT_NEAR(stiffness / (2 * a * modulus), 1, 0.03);
  // a cap above the largest elastic pressure changes nothing
  ExactContact loose(map, plastic_options(1.01 * e.max_pressure));
  const ContactStep l = loose.at_pressure(pressure);
  EXPECT_EQ(l.plastic_points, 0u);
  EXPECT_NEAR(l.approach / e.approach, 1, 1e-7);
  // a cap at twice the face's mean pressure: the edge plastic, the centre not, the punch deeper
  const double hardness = 2 * e.load / face_area;
  ExactContact capped(map, plastic_options(hardness));
  const ContactStep c = capped.at_pressure(pressure);
  EXPECT_EQ(c.contact_points, face);
  EXPECT_GT(c.plastic_points, 0u);
  EXPECT_LT(c.plastic_points, face);
  EXPECT_LT(c.approach, e.approach);
  const std::vector<double> field = capped.pressure_field();
  EXPECT_LT(field[(n / 2) * n + n / 2], hardness);  // the middle elastic
  // nearly all the face plastic: the load H times the face's area, at most
  const double most = hardness * face_area / (side * side);
  const ContactStep nearly = capped.at_pressure(0.995 * most);
  std::printf("punch at 0.995 H A: %zu of %zu face points plastic\n", nearly.plastic_points, face);
  EXPECT_GT(nearly.plastic_points, face * 9 / 10);
  EXPECT_EQ(nearly.contact_points, face);
  EXPECT_LE(nearly.load, hardness * face_area * (1 + 1e-12));
}

// The pressure on a pixel [-a, a] x [-b, b] moves (x, y) by this times p / (pi E*): Johnson (1985),
// eq. 3.25, in its logarithms.
double johnson_rectangle(double x, double y, double a, double b) {
  const auto r = [](double u, double v) { return std::sqrt(u * u + v * v); };
  return (x + a) * std::log(((y + b) + r(y + b, x + a)) / ((y - b) + r(y - b, x + a))) +
         (y + b) * std::log(((x + a) + r(y + b, x + a)) / ((x - a) + r(y + b, x - a))) +
         (x - a) * std::log(((y - b) + r(y - b, x - a)) / ((y + b) + r(y + b, x - a))) +
         (y - b) * std::log(((x - a) + r(y - b, x - a)) / ((x + a) + r(y - b, x + a)));
}

// The solution's complementarity, with displacements summed directly: 0 <= p <= H; a free point
// (0 < p < H) has no gap, a point out of contact no penetration, a plastic point no gap above
// zero; the mean pressure is the one asked.
TEST(ExactContactPlastic, ComplementarityWithDirectDisplacements) {
  const std::size_t n = 48;
  SelfAffineSpectrum spectrum;
  spectrum.hurst = 0.8;
  spectrum.rolloff_wavelength = side / 2;
  spectrum.cutoff_wavelength = 4 * side / static_cast<double>(n);
  spectrum.rms_height = 1e-6;
  const HeightMap map = self_affine_surface(n, n, side / n, side / n, spectrum, 11);
  const double gradient = spectral_rms_gradient(map), pressure = 0.05 * modulus * gradient;
  const double hardness = 0.5 * modulus * gradient;  // below the elastic contact's largest pressures
  ExactContactOptions options = plastic_options(hardness);
  options.tolerance = 1e-10;
  ExactContact solver(map, options);
  const ContactStep s = solver.at_pressure(pressure);
  ASSERT_GT(s.plastic_points, 0u);
  ASSERT_LT(s.plastic_points, s.contact_points);
  const std::vector<double> p = solver.pressure_field();
  double mean = 0;
  for (double h : map.heights) mean += h / static_cast<double>(n * n);
  const double h = side / n;
  std::vector<double> influence((2 * n - 1) * (2 * n - 1));  // by offset (di, dj) in [-(n-1), n-1]
  for (std::size_t dj = 0; dj < 2 * n - 1; ++dj)
    for (std::size_t di = 0; di < 2 * n - 1; ++di)
      influence[dj * (2 * n - 1) + di] =
          johnson_rectangle((static_cast<double>(di) - (n - 1.0)) * h, (static_cast<double>(dj) - (n - 1.0)) * h, h / 2, h / 2) /
          (pi * modulus);
  double load = 0, worst_free = 0, worst_open = 0, worst_plastic = 0;
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      double u = 0;
      for (std::size_t b = 0; b < n; ++b)
        for (std::size_t a = 0; a < n; ++a)
          u += influence[(b + n - 1 - j) * (2 * n - 1) + (a + n - 1 - i)] * p[b * n + a];
      const double pk = p[j * n + i], gap = u - (map.heights[j * n + i] - mean) + s.approach;
      load += pk;
      ASSERT_GE(pk, 0.0);
      ASSERT_LE(pk, hardness);
      if (pk == hardness) worst_plastic = std::max(worst_plastic, gap);
      else if (pk > 0) worst_free = std::max(worst_free, std::fabs(gap));
      else worst_open = std::max(worst_open, -gap);
    }
  const double rms = solver.rms_height();
  std::printf("complementarity (in rms heights): free |gap| %.2e, open penetration %.2e, plastic gap %.2e; "
              "%zu plastic of %zu in contact\n",
              worst_free / rms, worst_open / rms, worst_plastic / rms, s.plastic_points, s.contact_points);
  // the load as asked: to rounding by the rescaling (measured 1e-12), to 10 times the tolerance by
  // the search on the position that takes over where the rescaling stalls
  EXPECT_NEAR(load / static_cast<double>(n * n) / pressure, 1, 10 * options.tolerance);
  EXPECT_LT(worst_free / rms, 1e-6);
  EXPECT_LT(worst_open / rms, 1e-6);
  EXPECT_LT(worst_plastic / rms, 1e-6);
}

// The loads the cap cannot carry are refused before iterating, with the bound; a bad hardness too.
TEST(ExactContactPlastic, BeyondTheWholeMapPlasticRefused) {
  const HeightMap map = sphere(64);
  EXPECT_THROW(ExactContact(map, plastic_options(-1)), asperity::Error);
  EXPECT_THROW(ExactContact(map, plastic_options(NAN)), asperity::Error);
  int iterations = 0;
  ExactContactOptions options = plastic_options(1e9);
  options.progress = [&iterations](const ContactProgress&) { ++iterations; };
  ExactContact solver(map, options);
  EXPECT_EQ(solver.pressure_range().plastic_limit, 1e9);
  try {
    solver.at_pressure(1e9);
    ADD_FAILURE() << "no error";
  } catch (const asperity::Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("every point plastic carries 1e+09 Pa"), std::string::npos) << message;
  }
  EXPECT_EQ(iterations, 0);
}

}  // namespace
