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
