// Persson's theory of contact (Persson 2001, 2007; Yang and Persson 2008) for a measured map:
// the mean gap, real area and normal stiffness of an elastic half-space (contact modulus E*)
// pressed on the map, computed from the map's power spectrum alone. Unlike a Greenwood-
// Williamson model it has no summits: every wavelength carries load, and the elastic coupling
// between scales is kept; it is exact in full contact and an approximation in partial contact
// (against boundary elements: Almqvist et al. 2011; Müser et al. 2017). docs/exact-contact.md
// compares it with the exact solution of the same map.
//
// Spectrum: the isotropic power spectral density C(q) [m^4] with h_rms^2 = integral d^2q C(q)
// (q the wavenumber [1/m]), the radial average of the map's periodogram over annuli one
// wavenumber step 2 pi / L wide (the map's longer side L), up to the largest circle inside the
// grid's Nyquist limits (pi / dx, pi / dy; the corners beyond it are left out and their share of
// the variance reported). A measured map is not periodic: its periodogram is taken through a
// Hann window in each direction (scaled to keep the variance), which keeps the edges' jump out
// of the spectrum; a periodic map (synthetic) may be taken without it.
//
// Theory, with I(q) = integral from q0 to q of q'^3 C(q') dq', w(q) = (pi I(q))^(-1/2) and
// x = w(q) p / E* (p the nominal pressure):
//   area fraction     A/A0 = erf(p w(q1) / E*)
//   mean gap          u(p) = sqrt(pi) integral q0..q1 dq q^2 C(q) w(q) F(x),
//                     F(x) = integral x..inf dt/t [gamma + 3 (1 - gamma) erf(t)^2] exp(-t^2)
//   stiffness/area    -dp/du = p / (sqrt(pi) integral dq q^2 C w [gamma + 3 (1 - gamma) erf(x)^2] exp(-x^2))
// (Persson 2007, PRL 99 125502; Yang and Persson 2008, J. Phys. Condens. Matter 20 215214, with
// the ratio gamma of the elastic energy stored in the non-contact area, 0.42 as fitted there and
// used by Almqvist et al. 2011). q0 is the lowest wavenumber of the map (the first annulus' inner
// edge), q1 the Nyquist circle's. The mean gap is measured from the mean plane of the map, as the
// exact solver's (exact_contact.hpp).
//
// Accuracy of the evaluation (not of the theory): C piecewise constant over each annulus, the
// wavenumber integrals by Gauss-Legendre in y = sqrt(pi I) = 1/w (smooth within an annulus), F by
// adaptive Gauss-Kronrod and E1 (Boost.Math); the tests measure the result against nested
// adaptive quadrature of the same piecewise-constant spectrum (test_persson_contact.cpp).
#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

#include "asperity/record_fields.hpp"
#include "asperity/topography/height_map.hpp"

namespace asperity::topography {

inline constexpr double yang_persson_gamma = 0.42;

// How the periodogram treats a map's edges: `none` takes the map as periodic (a synthetic periodic
// map); `hann` weights it by a Hann window each way; `periodic_component` takes Moisan's (2011)
// periodic component (the map less the smooth field that carries the jumps between opposite
// edges).
enum class SpectrumEdges { none, hann, periodic_component };

// Its name (Python's edges_treatment, the option's value): "none", "hann", "periodic_component"
inline const char* to_string(SpectrumEdges edges) noexcept {
  return edges == SpectrumEdges::none ? "none" : edges == SpectrumEdges::hann ? "hann" : "periodic_component";
}

// The isotropic power spectrum: annulus k covers [edges[k], edges[k + 1]), density[k] is C there
// [m^4], the periodogram's power in the annulus over the annulus' area (its integral of C is the
// power on the grid); its fields defined once (a record's list, record_fields.hpp; not written)
#define ASPERITY_RADIAL_POWER_SPECTRUM_FIELDS(X)                                                          \
  X(std::vector<double>, edges, nullptr, "[1/m], ascending, one more than density")                     \
  X(std::vector<double>, density, nullptr, "[m^4]")                                                      \
  X(std::vector<std::size_t>, points, nullptr, "periodogram points (whole plane) in each annulus")       \
  X(SpectrumEdges, edges_treatment, nullptr, "how the periodogram treated the edges: none, hann or periodic_component", \
    SpectrumEdges::none)                                                                                 \
  X(double, map_variance, nullptr, "the heights' variance (valid points) [m^2]")                        \
  X(double, variance, nullptr, "2 pi integral q C dq over the annuli [m^2]")                            \
  X(double, mean_square_gradient, nullptr, "2 pi integral q^3 C dq: <|grad h|^2> of the spectrum")

struct RadialPowerSpectrum {
  ASPERITY_RADIAL_POWER_SPECTRUM_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

// The radial power spectrum of a map about its mean (missing points set to the mean). Throws
// asperity::Error for a bad map (HeightMap::validate), a map under 8 x 8 points, or all heights
// equal.
RadialPowerSpectrum radial_power_spectrum(const HeightMap& map, SpectrumEdges edges);

// Persson's theory at one nominal pressure; its fields, defined once (a record's list,
// record_fields.hpp)
#define ASPERITY_PERSSON_STATE_FIELDS(X)                                       \
  X(double, pressure, "pressure_Pa", "nominal [Pa]")                           \
  X(double, mean_gap, "mean_gap_m", "from the mean plane [m]")                 \
  X(double, area_fraction, "area_fraction", "A / A0")                          \
  X(double, stiffness_per_area, "stiffness_per_area_N_per_m3", "-dp/du [N/m^3]")

struct PerssonState {
  ASPERITY_PERSSON_STATE_FIELDS(ASPERITY_RECORD_MEMBER_ZERO)
};

class PerssonContact {
 public:
  // Throws asperity::Error for a spectrum without annuli, edges not ascending from > 0, a density
  // negative or not finite, a modulus not finite and > 0, or gamma outside [0, 1].
  PerssonContact(const RadialPowerSpectrum& spectrum, double contact_modulus, double gamma = yang_persson_gamma);

  // p > 0 and finite; NaN in every field otherwise (p = 0: the mean gap is infinite).
  PerssonState at_pressure(double pressure) const noexcept;

  double contact_modulus() const noexcept { return modulus_; }
  double gamma() const noexcept { return gamma_; }
  // the small-pressure area slope: A/A0 -> area_slope() p / E*  (= sqrt(8/pi) / h'_rms)
  double area_slope() const noexcept { return 2 / std::sqrt(3.14159265358979323846) * w_top_; }

 private:
  double modulus_ = 0, gamma_ = 0, w_top_ = 0;
  // the wavenumber quadrature: at node i, (2/sqrt(pi)) / q x its weight (dy), and 1 / (E* y)
  std::vector<double> factor_, scale_;
};

// F(x) above (x >= 0; +inf at 0 when gamma > 0), exposed for the tests.
double persson_gap_kernel(double x, double gamma) noexcept;

}  // namespace asperity::topography

namespace asperity {
ASPERITY_DEFINE_RECORD(topography::PerssonState, ASPERITY_PERSSON_STATE_FIELDS)
ASPERITY_DEFINE_RECORD(topography::RadialPowerSpectrum, ASPERITY_RADIAL_POWER_SPECTRUM_FIELDS)
}  // namespace asperity
