// Synthetic surfaces with a known spectrum and a known height distribution (tests, docs).
//
// Gaussian random field: white Gaussian noise convolved with a separable Gaussian kernel of
// standard deviation `correlation` points (truncated at 4 standard deviations, normalized to
// unit sum of squares); several components of given variance are summed (a spectrum that is
// a sum of Gaussian bumps: broader band, larger Nayak alpha). Every height is exactly
// N(0, total variance) in distribution. The discrete field's finite-difference moments are
// known exactly (expected_spectral_moments), which tests the moment estimator.
// Weibull marginals: each height h ~ N(0, 1) is mapped to F_W^-1(Phi(h)) (tail up) or to its
// negative (bounded above): the marginal is then exactly a unit Weibull of the given shape.
//
// Limits, checked before anything is allocated (asperity::Error beyond them): nx, ny >= 3 and
// nx ny <= max_field_points (the readers' default: 512 MiB of heights); dx, dy finite and > 0;
// each component's correlation finite, > 0 and <= max_field_correlation points, its variance
// finite and > 0; the noise each component convolves, (nx + 2h)(ny + 2h) points with
// h = ceil(4 correlation), <= max_field_noise_points (1 GiB); and the multiply-adds of the
// convolutions, (2h + 1)((ny + 2h) nx + ny nx) summed over the components, <= max_field_work.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "asperity/topography/height_map.hpp"
#include "asperity/topography/statistics.hpp"

namespace asperity::topography {

inline constexpr std::size_t max_field_points = std::size_t{1} << 26;
inline constexpr double max_field_correlation = 65536;
inline constexpr std::size_t max_field_noise_points = std::size_t{1} << 27;
inline constexpr std::uint64_t max_field_work = std::uint64_t{1} << 36;

struct SpectrumComponent {
  double correlation = 4;  // kernel standard deviation [points]
  double variance = 1;     // [m^2]
};

HeightMap gaussian_random_field(std::size_t nx, std::size_t ny, double dx, double dy,
                                const std::vector<SpectrumComponent>& spectrum, std::uint64_t seed);

// m0, m2x, m2y, m4x, m4y, m2, m4, alpha of the field in expectation (sampling counts 0). The
// components and intervals are checked as gaussian_random_field checks them.
SpectralMoments expected_spectral_moments(double dx, double dy, const std::vector<SpectrumComponent>& spectrum);

// Requires unit-variance Gaussian heights (a field of total variance 1).
void to_weibull_marginal(HeightMap& map, double shape, bool bounded);

// An isotropic Gaussian random field of unit variance with a named correlation function, made
// by FFT (its power spectrum's square root times complex normals) on a periodic grid twice the
// map's size in each direction, cut to the map (so it is not periodic):
//   gaussian     C(r) = exp(-r^2 / xi^2),  S(q) ~ exp(-q^2 xi^2 / 4): narrow band, Nayak alpha small
//   exponential  C(r) = exp(-r / xi),      S(q) ~ (1 + q^2 xi^2)^(-3/2): broad band, alpha grows
//                                          as xi / dx does (the alpha ~ 30 at xi = 20 dx)
// xi in points. The variance is 1 in expectation (each height is exactly N(0, 1)).
enum class CorrelationFunction { gaussian, exponential };
HeightMap spectral_random_field(std::size_t nx, std::size_t ny, double dx, double dy, CorrelationFunction function,
                                double correlation_length, std::uint64_t seed);

// A self-affine Gaussian random field without roll-off, cut from a larger draw as a measured map
// is cut from a surface: the isotropic spectrum C(q) ~ q^(-2(1 + H)) (Hurst exponent H) at every
// wavevector of a periodic draw `oversize` times the map's longer side along both axes (a square
// draw, so that a strip has the surface's long wavelengths across it too), from the draw's lowest
// wavenumbers, 2 pi / (oversize max(nx, ny) dx) along x (dy along y), to the pixel (Nyquist),
// q = 0 left out; the map is the draw's corner, not periodic, and not leveled (the analysis levels
// it). Unit variance in expectation over the draw (a no-roll-off field's variance grows with the
// draw: the map's own, about its mean, is smaller, the more so the larger H). Wavenumbers are
// physical (dx, dy). Throws asperity::Error for nx or ny < 3, H outside (0, 1], oversize outside
// [1, 16], or a draw of more than max_field_noise_points points.
inline constexpr std::size_t self_affine_default_oversize = 4;
HeightMap self_affine_random_field(std::size_t nx, std::size_t ny, double dx, double dy, double hurst,
                                   std::uint64_t seed, std::size_t oversize = self_affine_default_oversize);

}  // namespace asperity::topography
