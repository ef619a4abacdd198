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
#pragma once
#include <cstdint>
#include <vector>

#include "asperity/topography/height_map.hpp"
#include "asperity/topography/statistics.hpp"

namespace asperity::topography {

struct SpectrumComponent {
  double correlation = 4;  // kernel standard deviation [points]
  double variance = 1;     // [m^2]
};

HeightMap gaussian_random_field(std::size_t nx, std::size_t ny, double dx, double dy,
                                const std::vector<SpectrumComponent>& spectrum, std::uint64_t seed);

// m0, m2x, m2y, m4x, m4y, m2, m4, alpha of the field in expectation (sampling counts 0).
SpectralMoments expected_spectral_moments(double dx, double dy, const std::vector<SpectrumComponent>& spectrum);

// Requires unit-variance Gaussian heights (a field of total variance 1).
void to_weibull_marginal(HeightMap& map, double shape, bool bounded);

}  // namespace asperity::topography
