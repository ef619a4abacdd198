#include "fft.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

// numpy's and scipy's FFT, header-only, as Debian's python3-pythran ships it; no threads of its
// own (the analysis runs its own).
#define POCKETFFT_NO_MULTITHREADING
#include <pythran/pythonic/numpy/fft/pocketfft.hpp>

namespace asperity {
namespace topography {
namespace detail {
namespace {
using Shape = pocketfft::shape_t;
using Stride = pocketfft::stride_t;
constexpr std::ptrdiff_t real_size = sizeof(double), complex_size = sizeof(Complex);
}  // namespace

void forward_rows(const double* in, Complex* out, std::size_t rows, std::size_t n) {
  const std::size_t half = n / 2 + 1;
  pocketfft::r2c(Shape{rows, n}, Stride{static_cast<std::ptrdiff_t>(n) * real_size, real_size},
                 Stride{static_cast<std::ptrdiff_t>(half) * complex_size, complex_size}, std::size_t{1},
                 pocketfft::FORWARD, in, out, 1.0);
}

void inverse_rows(const Complex* in, double* out, std::size_t rows, std::size_t n) {
  const std::size_t half = n / 2 + 1;
  pocketfft::c2r(Shape{rows, n}, Stride{static_cast<std::ptrdiff_t>(half) * complex_size, complex_size},
                 Stride{static_cast<std::ptrdiff_t>(n) * real_size, real_size}, std::size_t{1}, pocketfft::BACKWARD,
                 in, out, 1.0 / static_cast<double>(n));
}

void forward_2d(const double* in, Complex* out, std::size_t ny, std::size_t nx) {
  const std::size_t half = nx / 2 + 1;
  pocketfft::r2c(Shape{ny, nx}, Stride{static_cast<std::ptrdiff_t>(nx) * real_size, real_size},
                 Stride{static_cast<std::ptrdiff_t>(half) * complex_size, complex_size}, Shape{0, 1},
                 pocketfft::FORWARD, in, out, 1.0);
}

void inverse_2d(const Complex* in, double* out, std::size_t ny, std::size_t nx) {
  const std::size_t half = nx / 2 + 1;
  pocketfft::c2r(Shape{ny, nx}, Stride{static_cast<std::ptrdiff_t>(half) * complex_size, complex_size},
                 Stride{static_cast<std::ptrdiff_t>(nx) * real_size, real_size}, Shape{0, 1}, pocketfft::BACKWARD, in,
                 out, 1.0 / (static_cast<double>(nx) * static_cast<double>(ny)));
}

void make_hermitian_columns(Complex* coefficients, std::size_t py, std::size_t px) {
  const std::size_t half = px / 2 + 1;
  const std::size_t columns = px % 2 == 0 && half > 1 ? 2 : 1;  // kx = 0, and the Nyquist column
  for (std::size_t c = 0; c < columns; ++c) {
    const std::size_t i = c == 0 ? 0 : half - 1;
    for (std::size_t j = 1; j < (py + 1) / 2; ++j)
      coefficients[(py - j) * half + i] = std::conj(coefficients[j * half + i]);
    // sqrt(2) Re z: a real normal of the complex draw's variance
    coefficients[i] = std::sqrt(2.0) * coefficients[i].real();
    if (py % 2 == 0) coefficients[(py / 2) * half + i] = std::sqrt(2.0) * coefficients[(py / 2) * half + i].real();
  }
}

void transform_columns(Complex* data, std::size_t ny, std::size_t width, std::size_t first, std::size_t count,
                       bool forward) {
  if (count == 0) return;
  const Stride stride{static_cast<std::ptrdiff_t>(width) * complex_size, complex_size};
  pocketfft::c2c(Shape{ny, count}, stride, stride, Shape{0}, forward, data + first, data + first,
                 forward ? 1.0 : 1.0 / static_cast<double>(ny));
}

std::vector<double> mean_line_autocovariance(const double* field, std::size_t lines, std::size_t n,
                                             std::size_t line_stride, std::size_t point_stride, double mean,
                                             std::size_t max_lag) {
  const std::size_t rows = lines;
  max_lag = std::min(max_lag, n == 0 ? 0 : n - 1);
  // zero-padded to at least 2n - 1: the circular correlation is then the linear one
  const std::size_t padded = 2 * n, half = padded / 2 + 1;
  const std::size_t block = std::max<std::size_t>(1, std::min<std::size_t>(rows, (std::size_t{1} << 22) / padded));
  std::vector<double> values(block * padded), valid(block * padded);
  std::vector<Complex> value_spectrum(block * half), valid_spectrum(block * half);
  std::vector<double> value_power(half, 0.0), valid_power(half, 0.0);
  for (std::size_t first = 0; first < rows; first += block) {
    const std::size_t count = std::min(block, rows - first);
    std::fill(values.begin(), values.end(), 0.0);
    std::fill(valid.begin(), valid.end(), 0.0);
    for (std::size_t r = 0; r < count; ++r)
      for (std::size_t k = 0; k < n; ++k) {
        const double h = field[(first + r) * line_stride + k * point_stride];
        if (std::isnan(h)) continue;
        values[r * padded + k] = h - mean;
        valid[r * padded + k] = 1;
      }
    forward_rows(values.data(), value_spectrum.data(), count, padded);
    forward_rows(valid.data(), valid_spectrum.data(), count, padded);
    for (std::size_t r = 0; r < count; ++r)
      for (std::size_t k = 0; k < half; ++k) {
        value_power[k] += std::norm(value_spectrum[r * half + k]);
        valid_power[k] += std::norm(valid_spectrum[r * half + k]);
      }
  }
  std::vector<Complex> spectrum(half);
  std::vector<double> sums(padded), pairs(padded);
  for (std::size_t k = 0; k < half; ++k) spectrum[k] = value_power[k];
  inverse_rows(spectrum.data(), sums.data(), 1, padded);
  for (std::size_t k = 0; k < half; ++k) spectrum[k] = valid_power[k];
  inverse_rows(spectrum.data(), pairs.data(), 1, padded);
  std::vector<double> covariance(max_lag + 1);
  for (std::size_t lag = 0; lag <= max_lag; ++lag) {
    const double count = std::round(pairs[lag]);  // an integer up to rounding
    covariance[lag] = count >= 1 ? sums[lag] / count : std::numeric_limits<double>::quiet_NaN();
  }
  return covariance;
}

}  // namespace detail
}  // namespace topography
}  // namespace asperity
