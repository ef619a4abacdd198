// Fast Fourier transforms of real data in double precision (internal): the one place that
// names the FFT library. pocketfft (BSD-3-Clause, header-only; numpy's and scipy's FFT), from
// Debian's python3-pythran, which python3-scipy already brings; chosen over kissfft (BSD,
// slower) and FFTW (GPL, no faster): scripts/fft-candidates.sh measures them (docs/surfaces.md).
// Any length: pocketfft factors it (Bluestein for large primes), O(n log n) for every n.
#pragma once
#include <complex>
#include <cstddef>
#include <vector>

namespace asperity {
namespace topography {
namespace detail {

using Complex = std::complex<double>;

// Each of `rows` rows of `n` reals (row r at in + r * n) to its n/2 + 1 Fourier coefficients
// (row r at out + r * (n/2 + 1)); unnormalized, e^{-2 pi i k m / n}.
void forward_rows(const double* in, Complex* out, std::size_t rows, std::size_t n);
// The inverse, scaled by 1/n (forward then inverse gives the input back).
void inverse_rows(const Complex* in, double* out, std::size_t rows, std::size_t n);

// A ny x nx real field (x fastest) to its ny x (nx/2 + 1) coefficients, and back (scaled by
// 1/(nx ny)).
void forward_2d(const double* in, Complex* out, std::size_t ny, std::size_t nx);
void inverse_2d(const Complex* in, double* out, std::size_t ny, std::size_t nx);

// Random Fourier coefficients of a real field, drawn independently over the half plane (py x
// (px/2 + 1)), made consistent: in the columns kx = 0 and kx = px/2 (px even) a coefficient and
// the one at -ky are conjugates (row ky takes the conjugate of row py - ky's, each pair then
// standing for a full complex normal of the drawn variance), and the self-conjugate points
// (ky = 0, py/2) real with the pair's variance. Without it the inverse transform keeps only the
// Hermitian part of those columns and halves their variance (the field's mean among them).
void make_hermitian_columns(Complex* coefficients, std::size_t py, std::size_t px);

// Columns first ... first + count - 1 of a ny x width complex array (row r at data + r * width),
// each transformed along y in place: forward (e^{-2 pi i k m / ny}) unscaled, or backward scaled
// by 1/ny. With forward_rows / inverse_rows, a 2-D transform in parts that threads can share
// (forward_rows on all rows, then the columns, gives forward_2d).
void transform_columns(Complex* data, std::size_t ny, std::size_t width, std::size_t first, std::size_t count,
                       bool forward);

// The mean autocovariance of the lines of a field, with missing points (NaN) left out: line r's
// point k is field[r * line_stride + k * point_stride] (rows: line_stride n, point_stride 1;
// columns of a row-major nx-wide field: line_stride 1, point_stride nx): C(lag) = sum of (h[k] - mean)(h[k + lag] - mean) over every line and
// every pair of valid points `lag` apart, divided by the number of such pairs, for lags
// 0 ... max_lag (NaN where no pair exists). O(N log n) by FFT (zero-padded: no wrap-around),
// in blocks of lines so memory stays O(n x block).
std::vector<double> mean_line_autocovariance(const double* field, std::size_t lines, std::size_t n,
                                             std::size_t line_stride, std::size_t point_stride, double mean,
                                             std::size_t max_lag);

}  // namespace detail
}  // namespace topography
}  // namespace asperity
