// Periodic self-affine Gaussian surfaces (tests and docs of the exact contact,
// docs/exact-contact.md): the isotropic power spectrum C(q) = C0 for q_r > |q| >= 2 pi / L,
// C0 (|q| / q_r)^(-2(1 + H)) for q_r <= |q| <= q_s and 0 beyond q_s (Hurst exponent H, roll-off
// wavenumber q_r, short-wavelength cutoff q_s), each Fourier coefficient a complex Gaussian of
// that variance; the mean is 0 and the rms height is scaled to `rms_height` exactly. The map
// is periodic (its opposite edges continue each other).
#pragma once
#include <cstddef>
#include <cstdint>

#include "asperity/topography/height_map.hpp"

namespace asperity::topography {

struct SelfAffineSpectrum {
  double hurst = 0.8;               // H, from 0 to 1
  double rolloff_wavelength = 0;    // 2 pi / q_r [m]; 0: the map's size (no roll-off)
  double cutoff_wavelength = 0;     // 2 pi / q_s [m]; 0: two sampling intervals (Nyquist)
  double rms_height = 1e-6;         // [m]
};

// Throws asperity::Error for sizes below 3 x 3 or above max_field_points (synthetic.hpp),
// sampling intervals outside the map limits, H outside [0, 1], wavelengths not finite and >= 0,
// a cutoff wavelength longer than the roll-off one, or an rms height not finite and > 0.
HeightMap self_affine_surface(std::size_t nx, std::size_t ny, double dx, double dy, const SelfAffineSpectrum& spectrum,
                              std::uint64_t seed);

// The rms gradient sqrt(<|grad h|^2>) of a map taken as periodic, from its discrete Fourier
// spectrum (sum of |q|^2 |h_q|^2): the slope the contact solver's Fourier kernel sees, and the
// one in the area-load law A/A0 = kappa p / (E* h'_rms). Throws for missing points.
double spectral_rms_gradient(const HeightMap& map);

}  // namespace asperity::topography
