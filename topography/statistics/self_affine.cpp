#include "asperity/topography/self_affine.hpp"

#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/topography/synthetic.hpp"
#include "fft.hpp"

namespace asperity::topography {
namespace {

constexpr double pi = 3.14159265358979323846;

// Standard normal deviates from mt19937_64 bits through the quantile (portable, as synthetic.cpp).
double normal(std::mt19937_64& engine) {
  const double u = (static_cast<double>(engine() >> 11) + 0.5) * 0x1p-53;
  return -std::sqrt(2.0) * boost::math::erfc_inv(2 * u);
}

double wavenumber(std::size_t k, std::size_t n, double h) {
  const double signed_k = k <= n / 2 ? static_cast<double>(k) : static_cast<double>(k) - static_cast<double>(n);
  return 2 * pi * signed_k / (static_cast<double>(n) * h);
}

}  // namespace

HeightMap self_affine_surface(std::size_t nx, std::size_t ny, double dx, double dy, const SelfAffineSpectrum& spectrum,
                              std::uint64_t seed) {
  if (nx < 3 || ny < 3) throw Error("self_affine_surface: needs at least 3 x 3 points");
  if (nx > max_field_points / ny) throw Error("self_affine_surface: more than max_field_points points");
  for (double h : {dx, dy})
    if (!(h >= min_sampling_interval && h <= max_sampling_interval))
      throw Error("self_affine_surface: the sampling intervals must lie within the map limits");
  if (!(spectrum.hurst >= 0 && spectrum.hurst <= 1)) throw Error("self_affine_surface: H must lie in [0, 1]");
  if (!(std::isfinite(spectrum.rolloff_wavelength) && spectrum.rolloff_wavelength >= 0 &&
        std::isfinite(spectrum.cutoff_wavelength) && spectrum.cutoff_wavelength >= 0))
    throw Error("self_affine_surface: the wavelengths must be finite and non-negative");
  if (spectrum.rolloff_wavelength > 0 && spectrum.cutoff_wavelength > spectrum.rolloff_wavelength)
    throw Error("self_affine_surface: the cutoff wavelength is longer than the roll-off wavelength");
  if (!(std::isfinite(spectrum.rms_height) && spectrum.rms_height > 0 && spectrum.rms_height <= max_height))
    throw Error("self_affine_surface: the rms height must be finite and positive");
  const double q_r = spectrum.rolloff_wavelength > 0 ? 2 * pi / spectrum.rolloff_wavelength : 0.0;
  const double q_s = spectrum.cutoff_wavelength > 0 ? 2 * pi / spectrum.cutoff_wavelength : INFINITY;
  const std::size_t half = nx / 2 + 1;
  std::vector<detail::Complex> coefficients(ny * half);
  std::mt19937_64 engine(seed);
  for (std::size_t ky = 0; ky < ny; ++ky)
    for (std::size_t kx = 0; kx < half; ++kx) {
      const double q = std::hypot(wavenumber(kx, nx, dx), wavenumber(ky, ny, dy));
      const double re = normal(engine), im = normal(engine);
      if (q == 0 || q > q_s) continue;
      const double amplitude = std::pow(std::max(q, q_r), -(1 + spectrum.hurst));
      coefficients[ky * half + kx] = {amplitude * re, amplitude * im};
    }
  HeightMap map;
  map.nx = nx;
  map.ny = ny;
  map.dx = dx;
  map.dy = dy;
  map.heights.assign(nx * ny, 0.0);
  detail::inverse_2d(coefficients.data(), map.heights.data(), ny, nx);
  double mean = 0;
  for (double h : map.heights) mean += h;
  mean /= static_cast<double>(nx * ny);
  double squares = 0;
  for (double& h : map.heights) {
    h -= mean;
    squares += h * h;
  }
  const double scale = spectrum.rms_height / std::sqrt(squares / static_cast<double>(nx * ny));
  if (!std::isfinite(scale)) throw Error("self_affine_surface: no wavelength between the cutoffs fits the map");
  for (double& h : map.heights) h *= scale;
  map.source = "self-affine";
  map.format = "synthetic";
  map.notes.push_back("self-affine, H " + std::to_string(spectrum.hurst) + ", seed " + std::to_string(seed));
  return map;
}

double spectral_rms_gradient(const HeightMap& map) {
  map.validate();
  if (map.missing_points() > 0) throw Error("spectral_rms_gradient: the map has missing points");
  const std::size_t nx = map.nx, ny = map.ny, half = nx / 2 + 1;
  std::vector<detail::Complex> spectrum(ny * half);
  detail::forward_2d(map.heights.data(), spectrum.data(), ny, nx);
  double sum = 0;
  for (std::size_t ky = 0; ky < ny; ++ky)
    for (std::size_t kx = 0; kx < half; ++kx) {
      const double qx = wavenumber(kx, nx, map.dx), qy = wavenumber(ky, ny, map.dy);
      const bool single = kx == 0 || (nx % 2 == 0 && kx == nx / 2);
      sum += (single ? 1.0 : 2.0) * (qx * qx + qy * qy) * std::norm(spectrum[ky * half + kx]);
    }
  const double points = static_cast<double>(nx * ny);
  return std::sqrt(sum / (points * points));
}

}  // namespace asperity::topography
