// A rough surface (docs/model.md sections 1, 3 and 6), in SI units: what the contact of a
// flat against it depends on. Either Weibull summit heights of shape a and scale sigma_s, or
// Gaussian summit heights (rms sigma), possibly from the profile's spectral moments through
// Nayak and McCool.
#pragma once
#include <limits>

#include "asperity/integrals.hpp"

namespace asperity {

// The physical values have no default (NaN: not given): validate() names the first left out, so a
// surface is never silently the example one (issue 39; Python's RoughSurface requires them too).
struct RoughSurface {
  static constexpr double not_given = std::numeric_limits<double>::quiet_NaN();
  Distribution distribution = Distribution::weibull;
  Side side = Side::tail;        // GW's approach: the flat meets the upper tail
  double shape = not_given;            // Weibull a (the Gaussian: unused)
  double height_scale = not_given;     // sigma_s [m] (Gaussian: sigma, the rms summit height)
  double summit_radius = not_given;    // R [m]
  double summit_density = not_given;   // summits per unit nominal area [1/m^2]
  double nominal_area = not_given;     // A0 [m^2]
  double contact_modulus = not_given;  // E* [Pa], plane strain: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2

  double summit_count() const noexcept { return summit_density * nominal_area; }
  // Throws asperity::Error naming the first bad parameter (not given, not finite, or <= 0; a Weibull shape
  // outside 0.3..50; a bounded side for the Gaussian), or the first factor of docs/model.md section 3
  // (N, pi N R sigma_s, (4/3) N E* R^1/2 sigma_s^3/2, 2 N E* R^1/2 sigma_s^1/2) that falls outside
  // [1e-250, 1e250], where its products would underflow or overflow.
  void validate() const;
};
// The former name, kept for existing code (deprecated: to be removed; use RoughSurface).
using PhysicalSurface = RoughSurface;

// The Weibull scale sigma_s that gives an rms summit height `rms` (about the mean):
// sigma_s = rms / c_a, c_a = sqrt(Gamma(1 + 2/a) - Gamma(1 + 1/a)^2) (docs/model.md section 1); GW
// users measure the rms (for a = 1.6, rms = 0.574 sigma_s). The Gaussian's sigma is the rms.
// Throws for rms or shape <= 0.
double height_scale_from_rms(Distribution distribution, double shape, double rms);

// E* from the two bodies' Young's moduli and Poisson's ratios; throws for E <= 0 or nu outside
// (-1, 0.5].
double contact_modulus_from(double young1, double poisson1, double young2, double poisson2);

// The input checks every interface shares (the commands, C, Python): the contact modulus from
// what a user gave, E* itself or the four E1, nu1, E2, nu2 together, a value not given being
// NaN. Returns NaN where none is given (the caller says whether it needs one). Throws
// asperity::Error for both given, the four incomplete, an E* not positive and finite, or as
// contact_modulus_from.
double contact_modulus_given(double contact_modulus, double young1, double poisson1, double young2, double poisson2);

// A total load [N] as the nominal pressure [Pa] over the nominal area A0 [m^2]; throws for a load
// or an area not positive and finite.
double nominal_pressure_from_load(double load, double nominal_area);

// A Gaussian surface from the spectral moments of its profile (Nayak's bandwidth alpha =
// m0 m4 / m2^2, McCool's summit statistics):
//   summit density D = m4 / (6 pi sqrt(3) m2), summit radius 1/R = (8/3) sqrt(m4 / pi),
//   rms summit height sigma = sqrt(m0 (1 - 0.8968 / alpha)).
// The paper prints sigma = sqrt(m0)(1 - 0.9/alpha), which is not what its own product
// R sigma D = (1/48) sqrt((3/pi)(alpha - 0.9)) needs (that product follows from the square root
// form). Throws for moments <= 0 or alpha <= 0.9 (McCool's formulas need a broad band).
RoughSurface gaussian_surface_from_moments(double m0, double m2, double m4, double nominal_area,
                                              double contact_modulus);
double bandwidth_alpha(double m0, double m2, double m4);

}  // namespace asperity
