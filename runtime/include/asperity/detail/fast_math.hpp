// exp and log for the hot path: inlinable, and fast_exp_lanes written so that a compiler
// vectorizes a loop of it (only double arithmetic, selects, and 64-bit integer add, and, or
// and logical shifts on the bit patterns: no int64 <-> double conversions, which SSE2 and AVX2
// lack). The library versions (std::exp, std::log) are the baseline they are benchmarked
// against (bench/bench_lookup.cpp) and tested against (tests/test_fast_math.cpp). The runtime's
// scalar lookups call fast_exp; its x86 vector kernels have their own exps without a table in
// memory (runtime/core/kernel/exp_x86.hpp), with fast_exp_lanes' handling of special values.
//
// Accuracy (measured in the test against long double references): exp within 1 ulp on
// [-708.39, 709.78] and within 1 ulp of the subnormal spacing below; log within 1 ulp on all
// positive normal and subnormal doubles.
// Special values: exp(NaN) = NaN, exp(-inf) = 0, exp(x > 709.78) = inf, and results below
// the normal range are subnormal or 0; log(0) = -inf, log(x < 0) = NaN, log(inf) = inf,
// log(NaN) = NaN.
//
// The functions are `static` on purpose: the batch kernel is compiled once per instruction
// set (runtime/core/kernel/kernels_*.cpp), and internal linkage keeps each copy in its own translation
// unit (an inline function with external linkage would be merged by the linker, and an
// AVX-512 copy could then be called on a machine without AVX-512).
#pragma once
#include <cstdint>
#include <cstring>
#if defined(__AVX512F__)
#include "asperity/detail/intrinsics.hpp"
#endif

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
static constexpr double ln_2 = 0.69314718055994530942;  // rounded to double (3.4e-17 relative)

// 2^(j/N), j = 0..N-1, as a double and the rest (hi + lo carries ~64 bits), computed at
// compile time by the Taylor series of e^(j ln2 / N) in long double (N = 128 here; the x86
// kernels' AVX-512 exp holds N = 16 in registers, runtime/core/kernel/exp_x86.hpp).
template <int entries>
struct Exp2Table {
  double hi[entries];
  double lo[entries];
};
template <int entries>
constexpr Exp2Table<entries> make_exp2_table() {
  Exp2Table<entries> table{};
  constexpr long double ln2 = 0.693147180559945309417232121458176568L;
  for (int j = 0; j < entries; ++j) {
    const long double x = j * ln2 / entries;
    long double term = 1, sum = 1;
    for (int k = 1; k < 30; ++k) {
      term *= x / k;
      sum += term;
    }
    table.hi[j] = static_cast<double>(sum);
    table.lo[j] = static_cast<double>(sum - table.hi[j]);
  }
  return table;
}
static constexpr Exp2Table<128> exp2_table = make_exp2_table<128>();

// e^x: x = (128 m + j) ln2 / 128 + r with |r| <= ln2 / 256 (Cody-Waite, ln2 / 128 split so
// that k ln2_hi / 128 is exact), e^x = 2^m 2^(j/128) e^r, e^r by its degree-5 Taylor polynomial
// (truncation below 6e-19). The table is what keeps the dependency chain short (a scalar call
// is latency-bound). 2^m goes into the result's bits by integer arithmetic (fast_exp: by one
// exact multiplication where the result is surely normal), and subnormal
// results are made from normal doubles (exp_below_normal): a floating-point operation that makes
// a subnormal costs a microcode assist on x86, and the tails reach X < 1e-308 (bench_lookup:
// BM_StdExp/subnormal_results against BM_FastExp/subnormal_results).
// Two forms of the same arithmetic: fast_exp_lanes for loops that vectorize (the special
// values by bit masks, every load unconditional) and fast_exp for one call at a time (the
// special values by branches, which predict well and are cheaper there: bench_lookup's
// BM_FastExp against BM_FastExpLanes and BM_StdExp, one call at a time). Same bits for every x.
struct ExpParts {
  std::uint64_t scale;     // 2^(j/128) e^r, in [0.99, 2.01]
  std::uint64_t exponent;  // the result's biased exponent: that of scale + m (two's complement)
  std::uint64_t m;         // floor(k / 128) (two's complement; garbage where x is beyond +-2^44)
};
// The parts from k in the shifted sum's bits (k = 128 m + j) and r, the rest of the reduction
static ASPERITY_ALWAYS_INLINE ExpParts exp_parts_reduced(double shifted, double r) noexcept {
  const std::uint64_t k_bits = bits_of(shifted) - bits_of(round_shifter);  // k, two's complement
  const std::int64_t index = static_cast<std::int64_t>(k_bits & 127);     // signed: what gathers take
  const double r2 = r * r;
  // e^r - 1 = r + r^2 (1/2 + r/6 + r^2 (1/24 + r/120)); 2^(j/128) e^r = hi + (hi (e^r - 1) + lo)
  const double expm1 = r + r2 * ((0.5 + r * (1.0 / 6)) + r2 * (1.0 / 24 + r * (1.0 / 120)));
  const double hi = exp2_table.hi[index];
  const std::uint64_t scale = bits_of(hi + (hi * expm1 + exp2_table.lo[index]));
  // m = floor(k / 128) by a logical shift of k + 2^20 (AVX2 has no 64-bit arithmetic shift;
  // |k| < 2^18 where the result is used)
  const std::uint64_t m = ((k_bits + (std::uint64_t(1) << 20)) >> 7) - (std::uint64_t(1) << 13);
  return {scale, (scale >> 52) + m, m};
}
// e^x
static ASPERITY_ALWAYS_INLINE ExpParts exp_parts(double x) noexcept {
  constexpr double scaled_log2e = 184.66496523378731;          // 128 / ln 2
  constexpr double ln2_hi = 6.93147180369123816490e-01 / 128;  // 32 significant bits: k ln2_hi exact
  constexpr double ln2_lo = 1.90821492927058770002e-10 / 128;
  const double shifted = x * scaled_log2e + round_shifter;
  const double k = shifted - round_shifter;  // an integer for |x| < 2^44 (garbage beyond)
  return exp_parts_reduced(shifted, (x - k * ln2_hi) - k * ln2_lo);
}
// 2^t: k = round(128 t); 128 t - k is exact (128 t is, and k lies within a factor 2 of it or
// is 0), so the one rounding is r's (|r| <= ln2 / 256: below 1e-18 of the result)
static ASPERITY_ALWAYS_INLINE ExpParts exp2_parts(double t) noexcept {
  const double scaled = t * 128;
  const double shifted = scaled + round_shifter;
  const double k = shifted - round_shifter;  // an integer for |t| < 2^44 (garbage beyond)
  return exp_parts_reduced(shifted, (scaled - k) * (ln_2 / 128));
}
// The two bases, for the arithmetic shared by fast_exp and fast_exp2 (and the x86 kernels'
// exp4, exp_x86.hpp): `lowest` and `highest` bound the range where the parts are not garbage
// (e^-746 and 2^-1076 are below half the smallest subnormal, e^710 and 2^1025 above DBL_MAX);
// in [surely_normal_min, surely_normal_max] the result is surely a normal double (k in
// [-1021, 1023] for exp4's reduction to |r| <= ln2 / 2); within exact_k_max of 0 exp4's k is
// exactly round(x / ln 2) (|k| <= 2^50). In an unnamed namespace, as the functions here are
// static: each instruction set's build keeps its own copy.
namespace {
struct NaturalExp {
  static ASPERITY_ALWAYS_INLINE ExpParts parts(double x) noexcept { return exp_parts(x); }
  static constexpr double lowest = -746.0, highest = 710.0;
  static constexpr double surely_normal_min = -708.0, surely_normal_max = 709.0;
  static constexpr double exact_k_max = 0x1.62e42fefa39efp+49;  // 2^50 ln 2
};
struct BinaryExp {
  static ASPERITY_ALWAYS_INLINE ExpParts parts(double t) noexcept { return exp2_parts(t); }
  static constexpr double lowest = -1076.0, highest = 1025.0;
  static constexpr double surely_normal_min = -1021.0, surely_normal_max = 1023.0;
  static constexpr double exact_k_max = 0x1p+50;
};
}  // namespace

// The result in the normal range: m added to the exponent field.
static ASPERITY_ALWAYS_INLINE std::uint64_t exp_normal(ExpParts parts) noexcept {
  return parts.scale + ((parts.exponent - (parts.scale >> 52)) << 52);
}
// Below it (exponent <= 0): the subnormal's bit pattern is the integer nearest
// e^x 2^1074 = scale 2^(m + 1074) < 2^52, which adding 2^52 rounds to (once, to nearest even)
// and puts in the low bits. Every operand and result is a normal double (2^(m + 1074) is made in
// the exponent field, m clamped at -1100 where the result is 0 anyway), so there is no assist.
static ASPERITY_ALWAYS_INLINE std::uint64_t exp_below_normal(ExpParts parts) noexcept {
  constexpr double two_52 = 4503599627370496.0;
  const std::int64_t m = static_cast<std::int64_t>(parts.exponent - (parts.scale >> 52));
  const std::uint64_t scaled_exponent = static_cast<std::uint64_t>((m < -1100 ? -1100 : m) + 1074 + 1023);
  return bits_of(double_of(parts.scale) * double_of(scaled_exponent << 52) + two_52) - bits_of(two_52);
}

// Between -746 and 710 the arithmetic itself gives the subnormals, 0 and inf; beyond, and for
// NaN, masks replace its garbage. (A select, or clamping x, lets the compiler skip the table
// load under a condition, and a conditional load does not vectorize.)
static ASPERITY_ALWAYS_INLINE double fast_exp_lanes(double x) noexcept {
  const ExpParts parts = exp_parts(x);
  const std::int64_t exponent = static_cast<std::int64_t>(parts.exponent);
  const std::uint64_t is_below = 0 - static_cast<std::uint64_t>(exponent <= 0);
  const std::uint64_t is_zero = 0 - static_cast<std::uint64_t>(x < NaturalExp::lowest);
  const std::uint64_t is_inf =
      (0 - static_cast<std::uint64_t>((exponent >= 2047) | (x > NaturalExp::highest))) & ~is_zero;
  const std::uint64_t is_nan = 0 - static_cast<std::uint64_t>(x != x);
  const std::uint64_t finite = (exp_below_normal(parts) & is_below) | (exp_normal(parts) & ~is_below);
  const std::uint64_t result = (finite & ~(is_inf | is_zero)) | (0x7ff0000000000000ULL & is_inf);
  return double_of((result & ~is_nan) | (bits_of(x) & is_nan));
}

template <class Base>
static ASPERITY_ALWAYS_INLINE double fast_exp_of(double x) noexcept {
  // Where the result is surely normal (m in [-1021, 1022], with scale in [0.99, 2.01]), 2^m is a
  // normal double made from k's bits beside the polynomial, and one exact multiplication
  // applies it: the same bits as exp_normal, without the trip through the integer registers
  // after the polynomial (the latency a lookup waits on). The test is one unsigned compare of
  // m, which NaN, infinities and |x| beyond 2^44 (garbage m, far outside) fail too: two
  // micro-operations fewer than a test of x against two bounds, ~8% of a scalar lookup in a
  // same-binary harness (the lookups overlap in the out-of-order window, which counts them).
  const ExpParts parts = Base::parts(x);
#if defined(__AVX512F__)
  // In the AVX-512 kernels' build, vscalefpd applies 2^m for m in [-1100, 1100]: it rounds a
  // subnormal result once (the same bits as exp_below_normal) and gives 0 and inf beyond the
  // range, so the tails' tiny results take no branch of their own (faster in bench_lookup's
  // BM_ScalarKind rows, whose random queries reach below DBL_MIN). With the default MXCSR:
  // under flush-to-zero those results are 0.
  if (__builtin_expect(parts.m + 1100 <= 1100 + 1100, 1))
    return _mm_cvtsd_f64(_mm_scalef_sd(_mm_set_sd(double_of(parts.scale)),
                                       _mm_set_sd(static_cast<double>(static_cast<std::int64_t>(parts.m)))));
#endif
  if (__builtin_expect(parts.m + 1021 <= 1021 + 1022, 1)) {
    const std::uint64_t power = (parts.m + 1023) << 52;
    return double_of(parts.scale) * double_of(power);
  }
  if (__builtin_expect(!(x >= Base::lowest && x <= Base::highest), 0))
    return x != x ? x : x > 0 ? __builtin_inf() : 0.0;
  const std::int64_t exponent = static_cast<std::int64_t>(parts.exponent);
  if (__builtin_expect(exponent > 0 && exponent < 2047, 1)) return double_of(exp_normal(parts));
  return exponent > 0 ? __builtin_inf() : double_of(exp_below_normal(parts));
}

static ASPERITY_ALWAYS_INLINE double fast_exp(double x) noexcept { return fast_exp_of<NaturalExp>(x); }
// 2^t, as accurate as fast_exp (the contact records hold log2 X: runtime/core/kernel/kernels.hpp)
static ASPERITY_ALWAYS_INLINE double fast_exp2(double t) noexcept { return fast_exp_of<BinaryExp>(t); }

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
