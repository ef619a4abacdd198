// The synthetic-surface generator's limits (synthetic.hpp): every size checked before it is
// computed or allocated. Sizes whose products wrapped around used to allocate a small buffer and
// write past it; a correlation of 1e300 overflowed the kernel's width.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/topography/synthetic.hpp"

namespace t = asperity::topography;

namespace {
const std::vector<t::SpectrumComponent> unit = {{2.0, 1.0}};

// The message of the asperity::Error that f throws, or "" if it throws none.
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const asperity::Error& error) {
    return error.what();
  }
  return "";
}
}  // namespace

TEST(TopographySynthetic, SizesWhoseProductWrapsAreRefused) {
  constexpr std::size_t max = std::numeric_limits<std::size_t>::max();
  const std::size_t sizes[][2] = {{std::size_t{1} << 62, 4},   // nx ny = 2^64: 0 after wrapping
                                  {4, std::size_t{1} << 62},
                                  {std::size_t{1} << 32, std::size_t{1} << 32},
                                  {max, 3},
                                  {3, max},
                                  {max / 3 + 1, 3},
                                  {(std::size_t{1} << 13) + 1, std::size_t{1} << 13}};
  for (const auto& size : sizes)
    EXPECT_NE(error_of([&] { t::gaussian_random_field(size[0], size[1], 1e-6, 1e-6, unit, 1); })
                  .find("points is more than 67108864"),
              std::string::npos)
        << size[0] << " x " << size[1];
  EXPECT_NE(error_of([&] { t::gaussian_random_field(std::size_t{1} << 63, 1, 1e-6, 1e-6, unit, 1); }).find("3 x 3"),
            std::string::npos);
}

TEST(TopographySynthetic, ComponentsAndIntervalsAreChecked) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (double correlation : {0.0, -1.0, nan, inf, 1e300, t::max_field_correlation * 1.0000001}) {
    const std::vector<t::SpectrumComponent> spectrum = {{correlation, 1.0}};
    EXPECT_NE(error_of([&] { t::gaussian_random_field(8, 8, 1e-6, 1e-6, spectrum, 1); }).find("correlation"),
              std::string::npos)
        << correlation;
    EXPECT_NE(error_of([&] { t::expected_spectral_moments(1e-6, 1e-6, spectrum); }).find("correlation"),
              std::string::npos)
        << correlation;
  }
  for (double variance : {0.0, -1.0, nan, inf}) {
    const std::vector<t::SpectrumComponent> spectrum = {{2.0, variance}};
    EXPECT_NE(error_of([&] { t::gaussian_random_field(8, 8, 1e-6, 1e-6, spectrum, 1); }).find("variance"),
              std::string::npos);
  }
  const std::vector<t::SpectrumComponent> overflowing = {{2.0, 1e308}, {2.0, 1e308}};
  EXPECT_NE(error_of([&] { t::gaussian_random_field(8, 8, 1e-6, 1e-6, overflowing, 1); }).find("total variance"),
            std::string::npos);
  for (double dx : {0.0, -1e-6, nan, inf}) {
    EXPECT_NE(error_of([&] { t::gaussian_random_field(8, 8, dx, 1e-6, unit, 1); }).find("sampling intervals"),
              std::string::npos);
    EXPECT_NE(error_of([&] { t::expected_spectral_moments(1e-6, dx, unit); }).find("sampling intervals"),
              std::string::npos);
  }
  EXPECT_NE(error_of([&] { t::gaussian_random_field(8, 8, 1e-6, 1e-6, {}, 1); }).find("at least one component"),
            std::string::npos);
}

// The noise each component convolves and the convolutions' work, refused before any allocation.
TEST(TopographySynthetic, NoiseAndWorkAreBounded) {
  // a kernel of half-width 4 x 65536 around 8 x 8 points: 2.7e11 points of noise
  const std::vector<t::SpectrumComponent> widest = {{t::max_field_correlation, 1.0}};
  EXPECT_NE(error_of([&] { t::gaussian_random_field(8, 8, 1e-6, 1e-6, widest, 1); }).find("points of noise"),
            std::string::npos);
  // 4096^2 points with a kernel of 4001 points: 2.0e11 multiply-adds
  const std::vector<t::SpectrumComponent> wide = {{500.0, 1.0}};
  EXPECT_NE(error_of([&] { t::gaussian_random_field(4096, 4096, 1e-6, 1e-6, wide, 1); }).find("multiply-adds"),
            std::string::npos);
  // several components add up their work (40 x 4.8e9)
  const std::vector<t::SpectrumComponent> many(40, t::SpectrumComponent{64.0, 1.0});
  EXPECT_NE(error_of([&] { t::gaussian_random_field(2048, 2048, 1e-6, 1e-6, many, 1); }).find("multiply-adds"),
            std::string::npos);
  // within the limits: the smallest map, and a kernel wider than the map
  const t::HeightMap smallest = t::gaussian_random_field(3, 3, 1e-6, 1e-6, unit, 1);
  EXPECT_EQ(smallest.heights.size(), 9u);
  const std::vector<t::SpectrumComponent> broad = {{40.0, 1.0}};
  const t::HeightMap field = t::gaussian_random_field(16, 8, 1e-6, 1e-6, broad, 1);
  EXPECT_EQ(field.heights.size(), 128u);
  for (double h : field.heights) EXPECT_TRUE(std::isfinite(h));
}

// ---- The self-affine field without roll-off (issue 40, item 1), against its spectrum computed
// here by direct sums, independent of the generator's FFT ----

namespace {
constexpr double pi = 3.14159265358979323846;

// |sum_x h(x) e^(-i q.x)|^2 / N at the integer wavevector (kx, ky) of an n x n map, by a direct sum
double periodogram_at(const t::HeightMap& map, int kx, int ky) {
  double re = 0, im = 0;
  const double n = static_cast<double>(map.nx);
  for (std::size_t j = 0; j < map.ny; ++j)
    for (std::size_t i = 0; i < map.nx; ++i) {
      const double phase = -2 * pi * (kx * static_cast<double>(i) + ky * static_cast<double>(j)) / n;
      re += map.at(i, j) * std::cos(phase);
      im += map.at(i, j) * std::sin(phase);
    }
  return (re * re + im * im) / (n * n);
}
}  // namespace

// Drawn whole (oversize 1: the draw is the map, periodic), the periodogram's mean over rings of
// wavenumber follows q^(-2(1 + H)): its slope relative to that power law, fitted over k = 2 ... 16
// of a 64^2 map, is 0 within 0.12, for a shallow (H 0.3) and a steep (H 0.8) spectrum.
TEST(TopographySynthetic, SelfAffineFieldSpectrumHasItsSlope) {
  for (const double hurst : {0.3, 0.8}) {
    const std::vector<int> rings = {2, 3, 4, 6, 8, 11, 16};
    std::vector<double> ratio(rings.size(), 0.0);
    for (int m = 0; m < 12; ++m) {
      const t::HeightMap map = t::self_affine_random_field(64, 64, 1e-7, 1e-7, hurst, 300 + m, 1);
      for (std::size_t r = 0; r < rings.size(); ++r) {
        double sum = 0;
        int count = 0;
        for (int kx = 0; kx <= rings[r]; ++kx)  // a half ring (the other half: conjugates)
          for (int ky = -rings[r]; ky <= rings[r]; ++ky) {
            const double k = std::hypot(kx, ky);
            if (std::lround(k) != rings[r] || (kx == 0 && ky < 0)) continue;
            sum += periodogram_at(map, kx, ky) / std::pow(k, -2 * (1 + hurst));
            ++count;
          }
        ratio[r] += sum / count;
      }
    }
    // least-squares slope of ln(ratio) against ln k: 0 when the spectrum is the power law
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = static_cast<double>(rings.size());
    for (std::size_t r = 0; r < rings.size(); ++r) {
      const double x = std::log(rings[r]), y = std::log(ratio[r]);
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
    }
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    EXPECT_NEAR(slope, 0, 0.12) << "H " << hurst << ": the spectrum's slope is " << -2 * (1 + hurst) + slope;
  }
}

// Cut from a draw four times the map (the default), the map's structure function
// E[(h(x + r) - h(x))^2] is the draw's: 2 sum_q C(q) (1 - cos(q r)) / sum_q C(q) over the draw's
// wavevectors, summed here directly (within 12% at lags 1 to 16 of a 128^2 map, 25% at 32,
// averaged over 16 maps), and its log-slope between lags 4 and 16 is near 2H (the power law; within 0.15: the
// pixel's cutoff bends it).
TEST(TopographySynthetic, SelfAffineFieldCutFromALargerDrawHasItsStructureFunction) {
  for (const double hurst : {0.3, 0.8}) {
    const std::size_t n = 128, draw = 4 * n;
    const std::vector<std::size_t> lags = {1, 2, 4, 8, 16, 32};
    // the expectation, along x, by a direct sum over the draw's half plane
    std::vector<double> expected(lags.size(), 0.0);
    double total = 0;
    for (std::size_t j = 0; j < draw; ++j)
      for (std::size_t i = 0; i <= draw / 2; ++i) {
        if (i == 0 && j == 0) continue;
        const double kx = static_cast<double>(i), ky = j <= draw / 2 ? static_cast<double>(j) : static_cast<double>(j) - draw;
        const double weight = (i == 0 || i == draw / 2) ? 1.0 : 2.0;
        const double power = weight * std::pow(kx * kx + ky * ky, -(1 + hurst));
        total += power;
        for (std::size_t l = 0; l < lags.size(); ++l)
          expected[l] += power * 2 * (1 - std::cos(2 * pi * kx * static_cast<double>(lags[l]) / draw));
      }
    for (double& e : expected) e /= total;
    std::vector<double> measured(lags.size(), 0.0);
    const int maps = 16;
    for (int m = 0; m < maps; ++m) {
      const t::HeightMap map = t::self_affine_random_field(n, n, 1e-7, 1e-7, hurst, 900 + m);
      ASSERT_EQ(map.heights.size(), n * n);
      for (std::size_t l = 0; l < lags.size(); ++l) {
        double sum = 0;
        for (std::size_t j = 0; j < n; ++j)
          for (std::size_t i = 0; i + lags[l] < n; ++i) sum += std::pow(map.at(i + lags[l], j) - map.at(i, j), 2);
        measured[l] += sum / static_cast<double>(n * (n - lags[l])) / maps;
      }
    }
    for (std::size_t l = 0; l < lags.size(); ++l)  // the longest lag the noisiest: fewer wavelengths behind it
      EXPECT_NEAR(measured[l] / expected[l], 1, lags[l] < 32 ? 0.12 : 0.25) << "H " << hurst << ", lag " << lags[l];
    const double slope = std::log(expected[4] / expected[2]) / std::log(4.0);
    EXPECT_NEAR(slope, 2 * hurst, 0.15) << "H " << hurst;
    const double measured_slope = std::log(measured[4] / measured[2]) / std::log(4.0);
    EXPECT_NEAR(measured_slope, slope, 0.1) << "H " << hurst;
  }
  // the limits
  EXPECT_NE(error_of([] { t::self_affine_random_field(64, 64, 1e-7, 1e-7, 0, 1); }).find("Hurst"), std::string::npos);
  EXPECT_NE(error_of([] { t::self_affine_random_field(64, 64, 1e-7, 1e-7, 1.2, 1); }).find("Hurst"), std::string::npos);
  EXPECT_NE(error_of([] { t::self_affine_random_field(64, 64, 1e-7, 1e-7, 0.5, 1, 0); }).find("oversize"), std::string::npos);
  EXPECT_NE(error_of([] { t::self_affine_random_field(2, 64, 1e-7, 1e-7, 0.5, 1); }).find("3 x 3"), std::string::npos);
  EXPECT_NE(error_of([] { t::self_affine_random_field(8192, 16, 1e-7, 1e-7, 0.5, 1, 16); }).find("more than"),
            std::string::npos);
  const t::HeightMap strip = t::self_affine_random_field(64, 8, 1e-7, 1e-7, 0.5, 3);
  EXPECT_EQ(strip.nx, 64u);
  EXPECT_EQ(strip.ny, 8u);
}
