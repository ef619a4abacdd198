#include "asperity/topography/persson_contact.hpp"

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <boost/math/special_functions/expint.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "asperity/error.hpp"
#include "statistics/fft.hpp"

namespace asperity::topography {
namespace {

constexpr double pi = 3.14159265358979323846;

// Past this x, exp(-x^2) underflows: the annulus carries neither gap nor stiffness.
constexpr double max_kernel_argument = 27;

double signed_index(std::size_t k, std::size_t n) {
  return k <= n / 2 ? static_cast<double>(k) : static_cast<double>(k) - static_cast<double>(n);
}

// A height about the mean, missing points at the mean.
double field_at(const HeightMap& map, std::size_t i, std::size_t j, double mean) {
  const double h = map.heights[j * map.nx + i];
  return std::isnan(h) ? 0.0 : h - mean;
}

}  // namespace

RadialPowerSpectrum radial_power_spectrum(const HeightMap& map, SpectrumEdges edges) {
  map.validate();
  if (map.nx < 8 || map.ny < 8) throw Error(map.source + ": a power spectrum needs at least 8 x 8 points");
  const std::size_t nx = map.nx, ny = map.ny, n = map.size();
  double mean = 0, valid = 0, lowest = INFINITY, highest = -INFINITY;
  for (double h : map.heights)
    if (!std::isnan(h)) {
      mean += h;
      ++valid;
      lowest = std::min(lowest, h);
      highest = std::max(highest, h);
    }
  if (!(highest > lowest)) throw Error(map.source + ": all heights are equal: no spectrum");
  mean /= valid;
  double variance = 0;
  for (double h : map.heights)
    if (!std::isnan(h)) variance += (h - mean) * (h - mean);
  variance /= valid;

  const bool window = edges == SpectrumEdges::hann;
  // Hann in each direction, its mean square restored so the variance is kept
  const auto hann = [window](std::size_t i, std::size_t m) {
    if (!window) return 1.0;
    const double s = std::sin(pi * (static_cast<double>(i) + 0.5) / static_cast<double>(m));
    return s * s;
  };
  std::vector<double> wx(nx), wy(ny);
  double mean_square_x = 0, mean_square_y = 0;
  for (std::size_t i = 0; i < nx; ++i) mean_square_x += (wx[i] = hann(i, nx)) * wx[i];
  for (std::size_t j = 0; j < ny; ++j) mean_square_y += (wy[j] = hann(j, ny)) * wy[j];
  const double window_power = mean_square_x / static_cast<double>(nx) * mean_square_y / static_cast<double>(ny);
  // about the window-weighted mean, so the windowed field has no mean (the q = 0 term, left out,
  // then holds no power)
  double weighted = 0, weights = 0;
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const double h = map.heights[j * nx + i];
      if (std::isnan(h)) continue;
      weighted += (h - mean) * wx[i] * wy[j];
      weights += wx[i] * wy[j];
    }
  const double centre = mean + weighted / weights;
  std::vector<double> field(n);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const double h = map.heights[j * nx + i];
      field[j * nx + i] = std::isnan(h) ? 0.0 : (h - centre) * wx[i] * wy[j];
    }
  const std::size_t half = nx / 2 + 1;
  std::vector<detail::Complex> spectrum(ny * half);
  detail::forward_2d(field.data(), spectrum.data(), ny, nx);
  if (edges == SpectrumEdges::periodic_component) {
    // Moisan's (2011) periodic plus smooth decomposition: the smooth part s solves the discrete
    // Laplace equation whose sources are the jumps between opposite edges; u - s is periodic
    // without those jumps and keeps the interior's differences
    std::fill(field.begin(), field.end(), 0.0);
    for (std::size_t i = 0; i < nx; ++i) {
      const double jump = field_at(map, i, ny - 1, mean) - field_at(map, i, 0, mean);
      field[i] += jump;
      field[(ny - 1) * nx + i] -= jump;
    }
    for (std::size_t j = 0; j < ny; ++j) {
      const double jump = field_at(map, nx - 1, j, mean) - field_at(map, 0, j, mean);
      field[j * nx] += jump;
      field[j * nx + nx - 1] -= jump;
    }
    std::vector<detail::Complex> boundary(ny * half);
    detail::forward_2d(field.data(), boundary.data(), ny, nx);
    for (std::size_t ky = 0; ky < ny; ++ky)
      for (std::size_t kx = 0; kx < half; ++kx) {
        if (kx == 0 && ky == 0) continue;
        const double denominator = 2 * std::cos(2 * pi * static_cast<double>(kx) / static_cast<double>(nx)) +
                                   2 * std::cos(2 * pi * static_cast<double>(ky) / static_cast<double>(ny)) - 4;
        spectrum[ky * half + kx] -= boundary[ky * half + kx] / denominator;
      }
  }
  field.clear();
  field.shrink_to_fit();

  // C(q) = dx dy / (4 pi^2 N) |H(q)|^2 (sum over the grid's q of C (2 pi/Lx)(2 pi/Ly) = variance)
  const double lx = map.width(), ly = map.length();
  const double step = std::max(2 * pi / lx, 2 * pi / ly);
  const double nyquist = std::min(pi / map.dx, pi / map.dy);
  const std::size_t annuli = static_cast<std::size_t>(std::floor(nyquist / step - 0.5));
  if (annuli < 2) throw Error(map.source + ": too few wavenumbers for a power spectrum");
  RadialPowerSpectrum result;
  result.edges_treatment = edges;
  result.map_variance = variance;
  result.edges.resize(annuli + 1);
  for (std::size_t k = 0; k <= annuli; ++k) result.edges[k] = (static_cast<double>(k) + 0.5) * step;
  std::vector<double> sums(annuli, 0.0);
  result.points.assign(annuli, 0);
  const double scale = map.dx * map.dy / (4 * pi * pi * static_cast<double>(n)) / window_power;
  for (std::size_t ky = 0; ky < ny; ++ky)
    for (std::size_t kx = 0; kx < half; ++kx) {
      const double q = std::hypot(2 * pi * static_cast<double>(kx) / lx, 2 * pi * signed_index(ky, ny) / ly);
      const double position = q / step - 0.5;
      if (!(position >= 0)) continue;
      const std::size_t k = static_cast<std::size_t>(position);
      if (k >= annuli) continue;
      // the half plane stands for the whole: each point but those of the self-conjugate columns twice
      const bool self_conjugate = kx == 0 || (nx % 2 == 0 && kx == nx / 2);
      sums[k] += (self_conjugate ? 1.0 : 2.0) * scale * std::norm(spectrum[ky * half + kx]);
      result.points[k] += self_conjugate ? 1 : 2;
    }
  result.density.resize(annuli);
  for (std::size_t k = 0; k < annuli; ++k) {
    if (result.points[k] == 0) throw Error(map.source + ": an empty annulus in the power spectrum");
    // the annulus' power (sum of C over its grid points times the cell 2 pi/Lx x 2 pi/Ly) spread over
    // its area: C's integral over each annulus is the periodogram's sum there, so the variance and
    // (to the annulus' width) the mean square gradient are kept
    const double a = result.edges[k], b = result.edges[k + 1];
    result.density[k] = sums[k] * (2 * pi / lx) * (2 * pi / ly) / (pi * (b * b - a * a));
    result.variance += 2 * pi * result.density[k] * (b * b - a * a) / 2;
    result.mean_square_gradient += 2 * pi * result.density[k] * (b * b * b * b - a * a * a * a) / 4;
  }
  return result;
}

double persson_gap_kernel(double x, double gamma) noexcept {
  if (!(x >= 0)) return std::numeric_limits<double>::quiet_NaN();
  if (x > max_kernel_argument) return 0;
  const double elastic = x > 0 ? 0.5 * boost::math::expint(1, x * x) : std::numeric_limits<double>::infinity();
  // erf(t)^2 exp(-t^2) / t: smooth, ~ (4/pi) t at 0, negligible past x + 8
  const auto integrand = [](double t) {
    if (t == 0) return 0.0;
    const double e = boost::math::erf(t);
    return e * e * std::exp(-t * t) / t;
  };
  const double coupled = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(integrand, x, x + 8, 15, 1e-12);
  return (gamma > 0 ? gamma * elastic : 0.0) + 3 * (1 - gamma) * coupled;
}

PerssonContact::PerssonContact(const RadialPowerSpectrum& spectrum, double contact_modulus, double gamma)
    : modulus_(contact_modulus), gamma_(gamma) {
  if (!(contact_modulus > 0) || !std::isfinite(contact_modulus))
    throw Error("Persson contact: the contact modulus must be a positive number");
  if (!(gamma >= 0 && gamma <= 1)) throw Error("Persson contact: gamma must lie in [0, 1]");
  const std::size_t annuli = spectrum.density.size();
  if (annuli == 0 || spectrum.edges.size() != annuli + 1) throw Error("Persson contact: a spectrum without annuli");
  if (!(spectrum.edges.front() > 0) || !std::isfinite(spectrum.edges.back()))
    throw Error("Persson contact: the spectrum's wavenumbers must be positive and finite");
  for (std::size_t k = 0; k < annuli; ++k) {
    if (!(spectrum.edges[k + 1] > spectrum.edges[k])) throw Error("Persson contact: the annuli must ascend");
    if (!(spectrum.density[k] >= 0) || !std::isfinite(spectrum.density[k]))
      throw Error("Persson contact: a power spectral density negative or not finite");
  }
  // The integrals in y = sqrt(pi I(q)) = 1/w: both integrands are (2/sqrt(pi)) dy / q(y) times
  // a function of x = p / (E* y), smooth in y within an annulus (C constant there, so
  // I = below + C (q^4 - a^4) / 4 inverts to q(y)). 4-point Gauss-Legendre on pieces at most
  // `piece` long in ln y (the error falls about as its fifth power: 1.4e-5 at 0.05, 5e-9 at 0.01,
  // measured by the test against nested quadrature); the first annulus (y from 0) graded
  // geometrically down to 1e-13 of its end, below which x is past max_kernel_argument for every
  // pressure above 1e-12 E*.
  static constexpr std::array<double, 4> node = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                                  0.8611363115940526};
  static constexpr std::array<double, 4> weight = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                                    0.3478548451374538};
  constexpr double piece = 0.02;  // in ln y
  double below = 0;  // I at the annulus' inner edge
  const auto add_piece = [&](double y0, double y1, double a, double b, double c, double base) {
    for (std::size_t g = 0; g < node.size(); ++g) {
      const double y = 0.5 * (y0 + y1) + 0.5 * (y1 - y0) * node[g];
      // q^4 = a^4 + 4 (I - below) / C, kept within the annulus against rounding when C is tiny
      const double fourth = std::clamp(a * a * a * a + 4 * (y * y / pi - base) / c, a * a * a * a, b * b * b * b);
      const double q = std::sqrt(std::sqrt(fourth));
      factor_.push_back(2 / std::sqrt(pi) / q * 0.5 * (y1 - y0) * weight[g]);
      scale_.push_back(1 / (y * contact_modulus));
    }
  };
  for (std::size_t k = 0; k < annuli; ++k) {
    const double a = spectrum.edges[k], b = spectrum.edges[k + 1], c = spectrum.density[k];
    const double above = below + c * (b * b * b * b - a * a * a * a) / 4;
    if (c > 0) {
      const double y_end = std::sqrt(pi * above);
      if (below == 0) {
        for (double y = y_end; y > 1e-13 * y_end; y *= std::exp(-piece)) add_piece(y * std::exp(-piece), y, a, b, c, below);
      } else {
        const double y_start = std::sqrt(pi * below);
        const int pieces = std::max(1, static_cast<int>(std::ceil(std::log(y_end / y_start) / piece)));
        for (int m = 0; m < pieces; ++m)
          add_piece(y_start * std::pow(y_end / y_start, static_cast<double>(m) / pieces),
                    y_start * std::pow(y_end / y_start, static_cast<double>(m + 1) / pieces), a, b, c, below);
      }
    }
    below = above;
  }
  if (!(below > 0)) throw Error("Persson contact: the spectrum carries no slope");
  w_top_ = 1 / std::sqrt(pi * below);
}

PerssonState PerssonContact::at_pressure(double pressure) const noexcept {
  PerssonState state;
  state.pressure = pressure;
  if (!(pressure > 0) || !std::isfinite(pressure)) {
    state.mean_gap = state.area_fraction = state.stiffness_per_area = std::numeric_limits<double>::quiet_NaN();
    return state;
  }
  double gap = 0, compliance = 0;
  for (std::size_t i = 0; i < factor_.size(); ++i) {
    const double x = scale_[i] * pressure;
    if (x > max_kernel_argument) continue;
    const double e = boost::math::erf(x);
    gap += factor_[i] * persson_gap_kernel(x, gamma_);
    compliance += factor_[i] * (gamma_ + 3 * (1 - gamma_) * e * e) * std::exp(-x * x);
  }
  state.mean_gap = gap;
  state.area_fraction = boost::math::erf(w_top_ * pressure / modulus_);
  state.stiffness_per_area = compliance > 0 ? pressure / compliance : std::numeric_limits<double>::infinity();
  return state;
}

}  // namespace asperity::topography
