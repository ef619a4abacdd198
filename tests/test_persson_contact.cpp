// Persson's theory for a map (topography/persson_contact.hpp): the radial power spectrum against
// the spectrum a self-affine surface was drawn from, the theory's evaluation against nested
// adaptive quadrature of the same formulas (an independent code path: q as the variable,
// tanh-sinh and exp-sinh), its stiffness against a finite difference of its own gap, the
// small-pressure area slope sqrt(8/pi), and the theory against the exact solution of the same
// surface (boundary elements) at small and moderate pressures.
#include <gtest/gtest.h>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/topography/exact_contact.hpp"
#include "asperity/topography/persson_contact.hpp"
#include "asperity/topography/self_affine.hpp"

namespace {
using namespace asperity::topography;
constexpr double pi = 3.14159265358979323846;

// F(x) = integral x..inf dt/t [gamma + 3 (1 - gamma) erf(t)^2] exp(-t^2), directly (exp-sinh).
double gap_kernel_reference(double x, double gamma) {
  if (x > 30) return 0;
  boost::math::quadrature::exp_sinh<double> integrator;
  const auto f = [gamma](double t) {
    const double e = boost::math::erf(t);
    return (gamma + 3 * (1 - gamma) * e * e) * std::exp(-t * t) / t;
  };
  return integrator.integrate(f, x, std::numeric_limits<double>::infinity(), 1e-13);
}

// u(p) and -dp/du by the formulas in q (persson_contact.hpp), annulus by annulus with tanh-sinh.
struct Reference {
  double gap, stiffness;
};
Reference persson_reference(const RadialPowerSpectrum& s, double modulus, double gamma, double p) {
  boost::math::quadrature::tanh_sinh<double> integrator;
  double gap = 0, compliance = 0, below = 0;
  for (std::size_t k = 0; k < s.density.size(); ++k) {
    const double a = s.edges[k], b = s.edges[k + 1], c = s.density[k];
    const auto w = [&](double q) { return 1 / std::sqrt(pi * (below + c * (q * q * q * q - a * a * a * a) / 4)); };
    gap += integrator.integrate(
        [&](double q) {
          const double x = w(q) * p / modulus;
          return x > 30 ? 0.0 : std::sqrt(pi) * q * q * c * w(q) * gap_kernel_reference(x, gamma);
        },
        a, b, 1e-12);
    compliance += integrator.integrate(
        [&](double q) {
          const double x = w(q) * p / modulus;
          if (x > 30) return 0.0;
          const double e = boost::math::erf(x);
          return std::sqrt(pi) * q * q * c * w(q) * (gamma + 3 * (1 - gamma) * e * e) * std::exp(-x * x);
        },
        a, b, 1e-12);
    below += c * (b * b * b * b - a * a * a * a) / 4;
  }
  return {gap, p / compliance};
}

// A power-law spectrum on a few uneven annuli (units of a micrometre-scale surface).
RadialPowerSpectrum power_law_spectrum() {
  RadialPowerSpectrum s;
  s.edges = {1e4, 2e4, 3.5e4, 7e4, 1.5e5, 4e5, 1e6};
  for (std::size_t k = 0; k + 1 < s.edges.size(); ++k) {
    const double q = 0.5 * (s.edges[k] + s.edges[k + 1]);
    s.density.push_back(2.5e-23 * std::pow(q / 1e4, -3.6));  // rms height about 0.1 um
    s.points.push_back(1);
  }
  return s;
}

}  // namespace

TEST(PerssonContact, GapKernelAgainstDirectQuadrature) {
  for (double gamma : {0.0, 0.42, 1.0})
    for (double x : {1e-6, 1e-3, 0.05, 0.3, 1.0, 2.5, 5.0, 9.0}) {
      const double reference = gap_kernel_reference(x, gamma);
      EXPECT_NEAR(persson_gap_kernel(x, gamma), reference, 1e-11 * std::fabs(reference) + 1e-300)
          << "x " << x << " gamma " << gamma;
    }
  EXPECT_TRUE(std::isnan(persson_gap_kernel(-1, 0.42)));
  EXPECT_TRUE(std::isnan(persson_gap_kernel(NAN, 0.42)));
}

// The evaluation (Gauss-Legendre in y = 1/w) against nested adaptive quadrature in q, from the
// first contacts (area fraction 1e-5) to near full contact (0.9).
TEST(PerssonContact, EvaluationAgainstNestedQuadrature) {
  const RadialPowerSpectrum s = power_law_spectrum();
  const double modulus = 1e11;
  const PerssonContact persson(s, modulus);
  double worst_gap = 0, worst_stiffness = 0;
  for (double area : {1e-5, 1e-3, 0.03, 0.3, 0.9}) {
    const double p = boost::math::erf_inv(area) * modulus / (persson.area_slope() * std::sqrt(pi) / 2);
    const PerssonState state = persson.at_pressure(p);
    EXPECT_NEAR(state.area_fraction, area, 1e-12 * area);
    const Reference reference = persson_reference(s, modulus, yang_persson_gamma, p);
    worst_gap = std::max(worst_gap, std::fabs(state.mean_gap / reference.gap - 1));
    worst_stiffness = std::max(worst_stiffness, std::fabs(state.stiffness_per_area / reference.stiffness - 1));
  }
  std::printf("largest relative difference to nested quadrature: gap %.2e, stiffness %.2e\n", worst_gap, worst_stiffness);
  EXPECT_LT(worst_gap, 1e-6);
  EXPECT_LT(worst_stiffness, 1e-6);
}

TEST(PerssonContact, StiffnessIsMinusTheGapsDerivative) {
  const PerssonContact persson(power_law_spectrum(), 1e11);
  for (double p : {1e4, 1e6, 1e8}) {
    const double h = 1e-4 * p;
    const double derivative = (persson.at_pressure(p + h).mean_gap - persson.at_pressure(p - h).mean_gap) / (2 * h);
    EXPECT_NEAR(-1 / derivative, persson.at_pressure(p).stiffness_per_area,
                1e-6 * persson.at_pressure(p).stiffness_per_area);
  }
}

// A/A0 -> sqrt(8/pi) p / (E* h'_rms) as p -> 0, h'_rms^2 = 2 pi integral q^3 C dq.
TEST(PerssonContact, SmallPressureAreaSlope) {
  const RadialPowerSpectrum s = power_law_spectrum();
  double gradient = 0;
  for (std::size_t k = 0; k < s.density.size(); ++k)
    gradient += 2 * pi * s.density[k] * (std::pow(s.edges[k + 1], 4) - std::pow(s.edges[k], 4)) / 4;
  const PerssonContact persson(s, 1e11);
  const double p = 1e-9 * 1e11 * std::sqrt(gradient);
  EXPECT_NEAR(persson.at_pressure(p).area_fraction / (p / (1e11 * std::sqrt(gradient))), std::sqrt(8 / pi), 1e-9);
}

TEST(PerssonContact, BadInput) {
  RadialPowerSpectrum s = power_law_spectrum();
  EXPECT_THROW(PerssonContact(s, 0), asperity::Error);
  EXPECT_THROW(PerssonContact(s, NAN), asperity::Error);
  EXPECT_THROW(PerssonContact(s, 1e11, 1.5), asperity::Error);
  RadialPowerSpectrum unordered = s;
  std::swap(unordered.edges[1], unordered.edges[2]);
  EXPECT_THROW(PerssonContact(unordered, 1e11), asperity::Error);
  RadialPowerSpectrum negative = s;
  negative.density[2] = -1;
  EXPECT_THROW(PerssonContact(negative, 1e11), asperity::Error);
  EXPECT_THROW(PerssonContact(RadialPowerSpectrum{}, 1e11), asperity::Error);
  const PerssonContact persson(s, 1e11);
  for (double p : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const PerssonState state = persson.at_pressure(p);
    EXPECT_TRUE(std::isnan(state.mean_gap) && std::isnan(state.area_fraction) && std::isnan(state.stiffness_per_area));
  }
}

// The radial spectrum of a periodic self-affine surface: the variance and mean square gradient
// it carries, and its slope -2(1 + H) between roll-off and cutoff.
TEST(RadialPowerSpectrum, SelfAffineSurface) {
  SelfAffineSpectrum spectrum;
  spectrum.hurst = 0.8;
  const double dx = 1e-7;
  const std::size_t n = 512;
  spectrum.rolloff_wavelength = n * dx / 4;
  spectrum.cutoff_wavelength = 8 * dx;  // inside the Nyquist circle: nothing in the corners
  spectrum.rms_height = 1e-8;
  const double q_r = 2 * pi / spectrum.rolloff_wavelength, q_s = 2 * pi / spectrum.cutoff_wavelength;
  double mean_slope = 0, windowed_variance = 0;
  const int maps = 8;
  for (int seed = 1; seed <= maps; ++seed) {
    const HeightMap map = self_affine_surface(n, n, dx, dx, spectrum, static_cast<std::uint64_t>(seed));
    const RadialPowerSpectrum s = radial_power_spectrum(map, SpectrumEdges::none);
    // the annuli hold the power of the grid points inside them, and every point lies inside
    EXPECT_NEAR(s.variance / s.map_variance, 1, 1e-9);
    const double gradient = spectral_rms_gradient(map);
    EXPECT_NEAR(s.mean_square_gradient / (gradient * gradient), 1, 0.01);
    // least-squares slope of ln C against ln q over the self-affine annuli
    double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
    for (std::size_t k = 0; k < s.density.size(); ++k) {
      if (s.edges[k] < 1.5 * q_r || s.edges[k + 1] > 0.9 * q_s) continue;
      const double x = std::log(0.5 * (s.edges[k] + s.edges[k + 1])), y = std::log(s.density[k]);
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
      ++m;
    }
    mean_slope += (m * sxy - sx * sy) / (m * sxx - sx * sx) / maps;
    const RadialPowerSpectrum windowed = radial_power_spectrum(map, SpectrumEdges::hann);
    windowed_variance += windowed.variance / windowed.map_variance / maps;
    // on a periodic map the periodic component is nearly the map
    const RadialPowerSpectrum component = radial_power_spectrum(map, SpectrumEdges::periodic_component);
    EXPECT_NEAR(component.variance / component.map_variance, 1, 0.01);
    EXPECT_NEAR(component.mean_square_gradient / s.mean_square_gradient, 1, 0.01);
  }
  // the Hann window loses the power its main lobe moves to q = 0 from the lowest wavenumbers
  // (here a tenth: the spectrum's plateau reaches down to 2 pi / L)
  std::printf("windowed variance / map variance, mean over %d maps: %.4f\n", maps, windowed_variance);
  EXPECT_GT(windowed_variance, 0.85);
  EXPECT_LT(windowed_variance, 1.0);
  std::printf("mean slope of ln C over %d maps: %.4f (drawn: %.4f)\n", maps, mean_slope, -2 * (1 + spectrum.hurst));
  EXPECT_NEAR(mean_slope, -2 * (1 + spectrum.hurst), 0.05);
}

// A measured map is a window cut from a larger surface: not periodic. Its periodic component
// keeps the slope spectrum of the surface it was cut from; taken as periodic, the jumps between
// its opposite edges add slope power.
TEST(RadialPowerSpectrum, CutFromALargerSurface) {
  SelfAffineSpectrum spectrum;
  spectrum.hurst = 0.8;
  const double dx = 1e-7;
  const std::size_t parent_n = 1024, n = 256;
  spectrum.rolloff_wavelength = 64 * dx;
  spectrum.cutoff_wavelength = 4 * dx;
  spectrum.rms_height = 1e-8;
  double component = 0, periodic = 0;
  const int maps = 4;
  for (int seed = 1; seed <= maps; ++seed) {
    const HeightMap parent = self_affine_surface(parent_n, parent_n, dx, dx, spectrum, static_cast<std::uint64_t>(seed));
    const double parent_gradient = radial_power_spectrum(parent, SpectrumEdges::none).mean_square_gradient;
    for (std::size_t corner : {std::size_t{0}, std::size_t{512}}) {
      HeightMap cut;
      cut.nx = cut.ny = n;
      cut.dx = cut.dy = dx;
      cut.source = "cut";
      for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i) cut.heights.push_back(parent.at(corner + i, corner + j));
      component += radial_power_spectrum(cut, SpectrumEdges::periodic_component).mean_square_gradient / parent_gradient /
                   (2 * maps);
      periodic += radial_power_spectrum(cut, SpectrumEdges::none).mean_square_gradient / parent_gradient / (2 * maps);
    }
  }
  std::printf("mean square gradient of a cut over its surface's: periodic component %.4f, taken as periodic %.4f\n",
              component, periodic);
  EXPECT_NEAR(component, 1, 0.05);
  EXPECT_GT(periodic, component);
}

TEST(RadialPowerSpectrum, BadInput) {
  HeightMap map;
  map.nx = map.ny = 6;
  map.dx = map.dy = 1e-6;
  map.heights.assign(36, 1e-9);
  EXPECT_THROW(radial_power_spectrum(map, SpectrumEdges::hann), asperity::Error);  // too small
  map.nx = map.ny = 16;
  map.heights.assign(256, 1e-9);
  EXPECT_THROW(radial_power_spectrum(map, SpectrumEdges::hann), asperity::Error);  // flat
}

// The theory against the exact solution of the same periodic self-affine surface: the mean gap
// and the stiffness at small and moderate pressures (Almqvist et al. 2011 found the theory's
// separation close to boundary elements; its area is known to be low: sqrt(8/pi) = 1.6 against
// the exact slope of about 2).
TEST(PerssonContact, AgainstTheExactSolution) {
  SelfAffineSpectrum spectrum;
  spectrum.hurst = 0.8;
  const double dx = 1e-7;
  const std::size_t n = 256;
  spectrum.rolloff_wavelength = n * dx / 4;
  spectrum.cutoff_wavelength = 4 * dx;
  spectrum.rms_height = 1e-8;
  const HeightMap map = self_affine_surface(n, n, dx, dx, spectrum, 11);
  const double modulus = 1e11;
  const PerssonContact persson(radial_power_spectrum(map, SpectrumEdges::none), modulus);
  ExactContactOptions options;
  options.contact_modulus = modulus;
  ExactContact exact(map, options);
  const double gradient = spectral_rms_gradient(map);
  std::printf("p/(E* h')  gap Persson/exact  stiffness Persson/exact  area Persson/exact\n");
  for (double reduced : {0.005, 0.02, 0.1}) {
    const double p = reduced * modulus * gradient;
    const ContactStep step = exact.at_pressure(p);
    const PerssonState theory = persson.at_pressure(p);
    const double gap = theory.mean_gap / step.mean_gap, stiffness = theory.stiffness_per_area / step.stiffness_per_area,
                 area = theory.area_fraction / step.area_fraction;
    std::printf("%9.3f  %8.3f  %8.3f  %8.3f\n", reduced, gap, stiffness, area);
    EXPECT_NEAR(gap, 1, 0.1) << reduced;
    EXPECT_NEAR(stiffness, 1, 0.3) << reduced;
    EXPECT_GT(area, 0.6);
    EXPECT_LT(area, 1.0);
  }
}
