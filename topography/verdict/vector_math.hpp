// ln, exp and expm1 over arrays, a vector of lanes at a time (Highway's contrib/math, Debian
// libhwy-dev), the best instruction set of the CPU chosen at the first call (internal to the
// topography library). The surrogate ensembles spend a third of their time in these three
// functions, one point at a time through glibc (the spacing objective of every refit, the
// normal deviates of every surrogate).
//
// Accuracy (Highway's documented bounds, checked against the standard library in
// tests/test_topography_fit.cpp): log within 4 ulp on (0, DBL_MAX], exp within 1 ulp on
// [-DBL_MAX, 706], expm1 within 4 ulp on [-DBL_MAX, 706]. Outside those ranges (and for
// subnormal or non-finite arguments) the result is unspecified: a caller whose arguments may
// leave them recomputes those points with <cmath> (spacing_fit.cpp does).
#pragma once
#include <cstddef>

namespace asperity::topography::detail {

void vector_log(const double* x, double* out, std::size_t n) noexcept;
void vector_exp(const double* x, double* out, std::size_t n) noexcept;
void vector_expm1(const double* x, double* out, std::size_t n) noexcept;

// Bounds of the arguments within which the functions above hold their accuracy.
inline constexpr double vector_exp_max = 706;

}  // namespace asperity::topography::detail
