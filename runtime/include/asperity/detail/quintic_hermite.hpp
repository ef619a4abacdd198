// The interpolation kernel: quintic Hermite on one interval of a uniform grid.
// Data at the two ends: value, first and second derivative, the derivatives already
// multiplied by the step h and h^2. Reproduces polynomials of degree <= 5 exactly.
#pragma once

namespace asperity::detail {

// The same interpolant in the power basis of x: out[j] is the coefficient of x^j. The runtime
// stores these per interval (Horner's rule then needs six loads and five multiply-adds).
inline void quintic_hermite_coefficients(const double* left, const double* right, double out[6]) noexcept {
  const double f0 = left[0], g0 = left[1], k0 = left[2];
  const double a = right[0] - f0 - g0 - 0.5 * k0, b = right[1] - g0 - k0, c = right[2] - k0;
  out[0] = f0;
  out[1] = g0;
  out[2] = 0.5 * k0;
  out[3] = 10 * a - 4 * b + 0.5 * c;
  out[4] = -15 * a + 7 * b - c;
  out[5] = 6 * a - 3 * b + 0.5 * c;
}

// x in [0, 1] is the position inside the interval; left and right point at {f, h f', h^2 f''}.
inline double quintic_hermite(const double* left, const double* right, double x) noexcept {
  const double f0 = left[0], g0 = left[1], k0 = left[2];
  const double f1 = right[0], g1 = right[1], k1 = right[2];
  const double a = f1 - f0 - g0 - 0.5 * k0;  // what the quadratic Taylor part misses at x = 1
  const double b = g1 - g0 - k0;
  const double c = k1 - k0;
  const double c3 = 10 * a - 4 * b + 0.5 * c;
  const double c4 = -15 * a + 7 * b - c;
  const double c5 = 6 * a - 3 * b + 0.5 * c;
  return f0 + x * (g0 + x * (0.5 * k0 + x * (c3 + x * (c4 + x * c5))));
}

// The derivative with respect to x (divide by h for the derivative in u).
inline double quintic_hermite_slope(const double* left, const double* right, double x) noexcept {
  const double f0 = left[0], g0 = left[1], k0 = left[2];
  const double f1 = right[0], g1 = right[1], k1 = right[2];
  const double a = f1 - f0 - g0 - 0.5 * k0, b = g1 - g0 - k0, c = k1 - k0;
  const double c3 = 10 * a - 4 * b + 0.5 * c, c4 = -15 * a + 7 * b - c, c5 = 6 * a - 3 * b + 0.5 * c;
  return g0 + x * (k0 + x * (3 * c3 + x * (4 * c4 + x * 5 * c5)));
}

}  // namespace asperity::detail
