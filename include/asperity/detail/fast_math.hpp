// exp and log for the hot path: branch-free, inlinable, and written so that a compiler
// vectorizes a loop of them (only double arithmetic, selects, and 64-bit integer add, and,
// or and logical shifts on the bit patterns: no int64 <-> double conversions, which SSE2
// and AVX2 lack). The library versions (std::exp, std::log) are the baseline they are
// benchmarked against (bench/bench_lookup.cpp) and tested against (tests/test_fast_math.cpp).
//
// Accuracy (measured in the test against 50-digit references): exp within 1 ulp on
// [-708, 709.7]; log within 1 ulp on all positive normal and subnormal doubles.
// Special values: exp(NaN) = NaN, exp(-inf) = 0, exp(x > 709.78) = inf, and results below
// the normal range are subnormal or 0; log(0) = -inf, log(x < 0) = NaN, log(inf) = inf,
// log(NaN) = NaN.
//
// The functions are `static` on purpose: the batch kernel is compiled once per instruction
// set (runtime/kernel/kernels_*.cpp), and internal linkage keeps each copy in its own translation
// unit (an inline function with external linkage would be merged by the linker, and an
// AVX-512 copy could then be called on a machine without AVX-512).
#pragma once
#include <cstdint>
#include <cstring>

#if defined(__GNUC__) || defined(__clang__)
#define ASPERITY_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define ASPERITY_ALWAYS_INLINE inline
#endif

namespace asperity::detail {

static ASPERITY_ALWAYS_INLINE std::uint64_t bits_of(double value) noexcept {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}
static ASPERITY_ALWAYS_INLINE double double_of(std::uint64_t bits) noexcept {
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// 1.5 * 2^52: adding it rounds a double of magnitude < 2^51 to an integer, which then sits
// in the low bits of the pattern.
static constexpr double round_shifter = 6755399441055744.0;

// 2^n for an integer-valued double n in [-1022, 1023], built in the exponent field.
static ASPERITY_ALWAYS_INLINE double exp2_of_integer(double integer) noexcept {
  const std::uint64_t biased = bits_of(integer + round_shifter) - bits_of(round_shifter) + 1023;
  return double_of(biased << 52);
}

// e^x: x = n ln2 + r with |r| <= ln2 / 2 (Cody-Waite, ln2 split so n ln2_hi is exact),
// e^r by its degree-13 Taylor polynomial (truncation below 1e-17 of e^r) in Estrin form,
// 2^n applied as two factors so that subnormal results need no branch.
static ASPERITY_ALWAYS_INLINE double fast_exp(double x) noexcept {
  constexpr double log2e = 1.4426950408889634;
  constexpr double ln2_hi = 6.93147180369123816490e-01;  // 32 significant bits (fdlibm's split)
  constexpr double ln2_lo = 1.90821492927058770002e-10;
  const double clamped = x < -746.0 ? -746.0 : (x > 710.0 ? 710.0 : x);
  const double n = (clamped * log2e + round_shifter) - round_shifter;
  const double r = (clamped - n * ln2_hi) - n * ln2_lo;
  const double r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
  // 1 + (r + r^2 q(r)): the large terms added last, so the roundings stay near 1 ulp
  const double p23 = 1.0 / 2 + r * (1.0 / 6), p45 = 1.0 / 24 + r * (1.0 / 120);
  const double p67 = 1.0 / 720 + r * (1.0 / 5040), p89 = 1.0 / 40320 + r * (1.0 / 362880);
  const double p1011 = 1.0 / 3628800 + r * (1.0 / 39916800);
  const double p1213 = 1.0 / 479001600 + r * (1.0 / 6227020800);
  const double tail = r2 * ((p23 + r2 * p45) + r4 * (p67 + r2 * p89) + r8 * (p1011 + r2 * p1213));
  const double poly = 1.0 + (r + tail);
  const double half = (n * 0.5 + round_shifter) - round_shifter;  // n = half + (n - half)
  const double result = poly * exp2_of_integer(half) * exp2_of_integer(n - half);
  return x != x ? x : result;
}

// ln x: x = 2^e m with m in [sqrt(1/2), sqrt(2)), ln m = f - (f^2/2 - s (f^2/2 + R(s^2)))
// with f = m - 1, s = f / (2 + f) and fdlibm's minimax R (error below 2^-58.45).
static ASPERITY_ALWAYS_INLINE double fast_log(double x) noexcept {
  constexpr double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
  constexpr double lg1 = 6.666666666666735130e-01, lg2 = 3.999999999940941908e-01;
  constexpr double lg3 = 2.857142874366239149e-01, lg4 = 2.222219843214978396e-01;
  constexpr double lg5 = 1.818357216161805012e-01, lg6 = 1.531383769920937332e-01;
  constexpr double lg7 = 1.479819860511658591e-01;
  constexpr double smallest_normal = 2.2250738585072014e-308, two_54 = 18014398509481984.0;
  const bool subnormal = x < smallest_normal;
  const double scaled = subnormal ? x * two_54 : x;
  const std::uint64_t bits = bits_of(scaled);
  // Adding 1 - sqrt(1/2) in the pattern moves the exponent boundary to m = sqrt(1/2), so the
  // biased exponent of `shifted` is e + 1023 (positive finite x only: no overflow).
  const std::uint64_t shifted = bits + (0x3ff0000000000000ULL - 0x3fe6a09e667f3bcdULL);
  const std::uint64_t exponent_field = shifted & 0xfff0000000000000ULL;
  const double m = double_of(bits - exponent_field + 0x3ff0000000000000ULL);
  const double e = (double_of((shifted >> 52) | 0x4330000000000000ULL) - 4503599627370496.0) - 1023.0 -
                   (subnormal ? 54.0 : 0.0);
  const double f = m - 1.0, s = f / (2.0 + f), z = s * s, w = z * z;
  const double t1 = w * (lg2 + w * (lg4 + w * lg6)), t2 = z * (lg1 + w * (lg3 + w * (lg5 + w * lg7)));
  const double half_f2 = 0.5 * f * f;
  const double result = e * ln2_hi - ((half_f2 - (s * (half_f2 + (t1 + t2)) + e * ln2_lo)) - f);
  constexpr double inf = __builtin_inf();
  // x = inf -> inf; x = 0 -> -inf; x < 0 or NaN -> NaN. One select each: nested ones leave
  // a many-way join that stops if-conversion, and with it vectorization.
  double special = x == inf ? inf : result;
  special = x == 0 ? -inf : special;
  return x >= 0 ? special : __builtin_nan("");
}

}  // namespace asperity::detail
