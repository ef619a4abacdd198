#include "asperity/topography/synthetic.hpp"

#include <algorithm>
#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <random>

#include "asperity/error.hpp"
#include "fft.hpp"

namespace asperity::topography {
namespace {

// The kernel's half-width h: ceil(4 correlation) points, at least 1 (correlation checked).
std::size_t kernel_half_width(double correlation) {
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(4 * correlation)));
}

void check_intervals(double dx, double dy) {
  if (!(std::isfinite(dx) && dx > 0 && std::isfinite(dy) && dy > 0))
    throw Error("gaussian_random_field: the sampling intervals dx, dy must be finite and positive");
}

void check_components(const std::vector<SpectrumComponent>& spectrum) {
  if (spectrum.empty()) throw Error("gaussian_random_field: the spectrum needs at least one component");
  double total = 0;
  for (const SpectrumComponent& component : spectrum) {
    if (!(component.correlation > 0 && component.correlation <= max_field_correlation))
      throw Error("gaussian_random_field: a component's correlation must be a number of points in (0, " +
                  std::to_string(static_cast<long>(max_field_correlation)) + "]");
    if (!(std::isfinite(component.variance) && component.variance > 0))
      throw Error("gaussian_random_field: a component's variance must be finite and positive");
    total += component.variance;
  }
  if (!std::isfinite(total)) throw Error("gaussian_random_field: the total variance is not finite");
}

std::vector<double> kernel(double correlation) {
  const int half = static_cast<int>(kernel_half_width(correlation));
  std::vector<double> k(static_cast<std::size_t>(2 * half + 1));
  double squares = 0;
  for (int m = -half; m <= half; ++m) {
    const double v = std::exp(-0.5 * m * m / (correlation * correlation));
    k[static_cast<std::size_t>(m + half)] = v;
    squares += v * v;
  }
  for (double& v : k) v /= std::sqrt(squares);
  return k;
}

// Standard normal deviates from mt19937_64 bits through the quantile (portable).
double normal(std::mt19937_64& engine) {
  const double u = (static_cast<double>(engine() >> 11) + 0.5) * 0x1p-53;
  return -std::sqrt(2.0) * boost::math::erfc_inv(2 * u);
}

}  // namespace

HeightMap gaussian_random_field(std::size_t nx, std::size_t ny, double dx, double dy,
                                const std::vector<SpectrumComponent>& spectrum, std::uint64_t seed) {
  // every size checked before it is computed, so that no product wraps around
  if (nx < 3 || ny < 3) throw Error("gaussian_random_field: needs at least 3 x 3 points");
  if (nx > max_field_points / ny)
    throw Error("gaussian_random_field: " + std::to_string(nx) + " x " + std::to_string(ny) + " points is more than " +
                std::to_string(max_field_points));
  check_intervals(dx, dy);
  check_components(spectrum);
  std::uint64_t work = 0;
  for (const SpectrumComponent& component : spectrum) {
    const std::size_t half = kernel_half_width(component.correlation);  // <= 2^18: no sum below wraps
    const std::size_t wx = nx + 2 * half, wy = ny + 2 * half;
    if (wx > max_field_noise_points / wy)
      throw Error("gaussian_random_field: a component of correlation " + std::to_string(component.correlation) +
                  " needs more than " + std::to_string(max_field_noise_points) + " points of noise");
    work += static_cast<std::uint64_t>(2 * half + 1) * (wy * nx + ny * nx);  // each term < 2^47
    if (work > max_field_work)
      throw Error("gaussian_random_field: the convolutions would take more than " + std::to_string(max_field_work) +
                  " multiply-adds (fewer points or shorter correlations)");
  }
  HeightMap map;
  map.nx = nx;
  map.ny = ny;
  map.dx = dx;
  map.dy = dy;
  map.format = "synthetic";
  map.source = "synthetic Gaussian random field";
  map.heights.assign(nx * ny, 0.0);
  std::mt19937_64 engine(seed);
  for (const SpectrumComponent& component : spectrum) {
    const std::vector<double> k = kernel(component.correlation);
    const std::size_t half = (k.size() - 1) / 2, wx = nx + 2 * half, wy = ny + 2 * half;
    std::vector<double> noise(wx * wy);
    for (double& v : noise) v = normal(engine);
    // along x, then along y (separable)
    std::vector<double> rows(nx * wy, 0.0);
    for (std::size_t j = 0; j < wy; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        double sum = 0;
        for (std::size_t m = 0; m < k.size(); ++m) sum += k[m] * noise[j * wx + i + m];
        rows[j * nx + i] = sum;
      }
    const double amplitude = std::sqrt(component.variance);
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        double sum = 0;
        for (std::size_t m = 0; m < k.size(); ++m) sum += k[m] * rows[(j + m) * nx + i];
        map.heights[j * nx + i] += amplitude * sum;
      }
  }
  return map;
}

SpectralMoments expected_spectral_moments(double dx, double dy, const std::vector<SpectrumComponent>& spectrum) {
  check_intervals(dx, dy);
  check_components(spectrum);
  SpectralMoments m;
  for (const SpectrumComponent& component : spectrum) {
    const std::vector<double> k = kernel(component.correlation);
    // E[(forward difference)^2] = sum_m (k[m+1] - k[m])^2 (per unit step), likewise the second
    // difference; the other direction's kernel has unit sum of squares.
    double first = 0, second = 0;
    const auto at = [&](long m) { return m >= 0 && m < static_cast<long>(k.size()) ? k[static_cast<std::size_t>(m)] : 0.0; };
    for (long n = -1; n <= static_cast<long>(k.size()); ++n) {
      const double d1 = at(n + 1) - at(n), d2 = at(n - 1) - 2 * at(n) + at(n + 1);
      first += d1 * d1;
      second += d2 * d2;
    }
    m.m0 += component.variance;
    m.m2x += component.variance * first / (dx * dx);
    m.m2y += component.variance * first / (dy * dy);
    m.m4x += component.variance * second / (dx * dx * dx * dx);
    m.m4y += component.variance * second / (dy * dy * dy * dy);
  }
  // separable kernels: no cross term; the principal axes are x and y
  const bool x_steeper = m.m2x >= m.m2y;
  m.principal_angle = x_steeper ? 0 : 1.5707963267948966;
  m.m2_principal[0] = x_steeper ? m.m2x : m.m2y;
  m.m2_principal[1] = x_steeper ? m.m2y : m.m2x;
  m.m4_principal[0] = x_steeper ? m.m4x : m.m4y;
  m.m4_principal[1] = x_steeper ? m.m4y : m.m4x;
  m.anisotropy = m.m2_principal[0] / m.m2_principal[1];
  m.m2 = std::sqrt(m.m2x * m.m2y);
  m.m4 = std::sqrt(m.m4x * m.m4y);
  m.alpha = m.m0 * m.m4 / (m.m2 * m.m2);
  return m;
}

void to_weibull_marginal(HeightMap& map, double shape, bool bounded) {
  if (!(shape > 0)) throw Error("to_weibull_marginal: shape must be positive");
  for (double& h : map.heights) {
    if (std::isnan(h)) continue;
    // W = (-ln(1 - Phi(h)))^(1/a) = (-ln Phi(-h))^(1/a), computed from the upper tail
    const double log_sf = std::log(0.5 * boost::math::erfc(h / std::sqrt(2.0)));
    const double w = std::pow(-log_sf, 1 / shape);
    h = bounded ? -w : w;
  }
  map.notes.push_back(std::string("heights mapped to a unit Weibull marginal, shape ") + std::to_string(shape) +
                      (bounded ? ", mirrored (bounded above)" : ", tail up"));
}

namespace {

constexpr double pi = 3.14159265358979323846;

// A Gaussian field drawn on a periodic px x py grid and cut to its first nx x ny points, of unit
// variance in expectation: each half-plane Fourier coefficient a complex normal (one mt19937_64, in
// row order) of variance power(kx, ky), kx = 2 pi i / px and ky = 2 pi j / py radians a point (ky
// signed: j above py / 2 is j - py), the origin's power 0. What spectral_random_field and
// self_affine_random_field share; their spectra are the `power` they pass.
template <class Power>
HeightMap field_from_spectrum(std::size_t nx, std::size_t ny, double dx, double dy, std::size_t px, std::size_t py,
                              Power power_at, std::uint64_t seed, std::string source) {
  const std::size_t half = px / 2 + 1;
  std::vector<detail::Complex> coefficients(py * half);
  std::mt19937_64 engine(seed);
  double total = 0;  // the spectrum's sum over the full plane: the field's variance before scaling
  for (std::size_t j = 0; j < py; ++j)
    for (std::size_t i = 0; i < half; ++i) {
      const double kx = 2 * pi * static_cast<double>(i) / static_cast<double>(px);
      const double ky = 2 * pi * static_cast<double>(j <= py / 2 ? j : py - j) / static_cast<double>(py) *
                        (j <= py / 2 ? 1.0 : -1.0);
      const double power = (i == 0 && j == 0) ? 0 : power_at(kx, ky);
      // each half-plane coefficient stands for itself and its conjugate (but for the self-conjugate columns)
      const bool self_conjugate = i == 0 || (px % 2 == 0 && i == px / 2);
      total += self_conjugate ? power : 2 * power;
      const double a = normal(engine), b = normal(engine);
      coefficients[j * half + i] = std::sqrt(power / 2) * detail::Complex(a, b);
    }
  detail::make_hermitian_columns(coefficients.data(), py, px);
  std::vector<double> padded(px * py);
  detail::inverse_2d(coefficients.data(), padded.data(), py, px);
  // inverse_2d divides by px py: the field's variance is total / (px py)^2 in expectation
  const double scale = static_cast<double>(px) * static_cast<double>(py) / std::sqrt(total);
  HeightMap map;
  map.nx = nx;
  map.ny = ny;
  map.dx = dx;
  map.dy = dy;
  map.format = "synthetic";
  map.source = std::move(source);
  map.heights.resize(nx * ny);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) map.heights[j * nx + i] = scale * padded[j * px + i];
  return map;
}

}  // namespace

HeightMap spectral_random_field(std::size_t nx, std::size_t ny, double dx, double dy, CorrelationFunction function,
                                double correlation_length, std::uint64_t seed) {
  check_intervals(dx, dy);
  if (nx < 3 || ny < 3 || nx > max_field_points / ny)
    throw Error("spectral_random_field: needs 3 x 3 points and at most " + std::to_string(max_field_points));
  if (!(correlation_length > 0 && correlation_length <= max_field_correlation))
    throw Error("spectral_random_field: the correlation length must lie in (0, 65536] points");
  const double xi = correlation_length;
  const auto power = [&](double kx, double ky) {
    const double q2 = kx * kx + ky * ky;
    return function == CorrelationFunction::gaussian ? std::exp(-q2 * xi * xi / 4) : std::pow(1 + q2 * xi * xi, -1.5);
  };
  return field_from_spectrum(nx, ny, dx, dy, 2 * nx, 2 * ny, power, seed,
                             std::string("synthetic ") +
                                 (function == CorrelationFunction::gaussian ? "Gaussian" : "exponential") +
                                 "-correlated field");
}

HeightMap self_affine_random_field(std::size_t nx, std::size_t ny, double dx, double dy, double hurst,
                                   std::uint64_t seed, std::size_t oversize) {
  check_intervals(dx, dy);
  if (nx < 3 || ny < 3) throw Error("self_affine_random_field: needs at least 3 x 3 points");
  if (!(hurst > 0 && hurst <= 1)) throw Error("self_affine_random_field: the Hurst exponent must lie in (0, 1]");
  if (oversize < 1 || oversize > 16) throw Error("self_affine_random_field: the draw's oversize must lie in [1, 16]");
  const std::size_t side = oversize * std::max(nx, ny);
  if (side > max_field_noise_points / side)
    throw Error("self_affine_random_field: a draw of " + std::to_string(side) + " x " + std::to_string(side) +
                " points is more than " + std::to_string(max_field_noise_points));
  // C(q) = q^(-2(1 + H)), q in units of 1/dx (its scale is the normalization's): no power overflows
  const double aspect = dx / dy;
  const auto power = [&](double kx, double ky) {
    const double ky_dx = ky * aspect;  // the y wavenumber in radians per dx
    return std::pow(kx * kx + ky_dx * ky_dx, -(1 + hurst));
  };
  return field_from_spectrum(nx, ny, dx, dy, side, side, power, seed,
                             "synthetic self-affine field (H " + std::to_string(hurst) +
                                 ", no roll-off, cut from a draw " + std::to_string(oversize) + " times the map)");
}

}  // namespace asperity::topography
