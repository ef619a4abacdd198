// The batch path's three passes (kernels.hpp: block) written for x86, shared by the AVX2 and
// AVX-512 builds (each compiles its own copy):
//
// - positions: ScalarPasses::positions four queries a step, with AVX2 intrinsics: the
//   compiler's loop narrows the shift counts to 32 bits and back (bench_lookup BM_Batch, this
//   against the compiler's loop: 9-12% of the whole batch path on AMD Zen 4).
// - quintics: the six coefficients of four queries by four row loads (a record is six doubles
//   in a row) and a 4 x 6 transpose in registers, not by six gathers. Gathers are what the
//   compiler's loop spent its time on (AMD Zen 4: a gather of 4 or 8 doubles costs more than
//   the loads and shuffles that replace it; bench_lookup BM_Batch against the former fused
//   loop, which is kept as BM_Record/batch_*/48B).
// - exps, for value output: e^x without a table in memory. AVX2: x = k ln 2 + r, |r| <= ln2/2,
//   e^r by its Taylor polynomial to degree 13 (truncation below 5e-18). AVX-512: x = (16 m + j)
//   ln2 / 16 + r, |r| <= ln2 / 32, 2^(j/16) from a 16-entry table held in four registers
//   (vpermt2pd), e^r to degree 7 (truncation below 2e-18). Where all lanes are surely normal
//   (fast_math.hpp's exp_surely_normal_min/max), 2^m is applied by one exact multiplication;
//   otherwise the vector's lanes go through the masks of fast_exp_lanes: subnormal results made
//   from normal doubles (no assist), 0 below -746, inf above 710, NaN kept.
// Accuracy of both exps (tests/test_kernels.cpp, against a long double exp over [-760, 720] and
// each edge): within 2.3e-16 relative where the result is normal, within 0.75 of the subnormal
// spacing below. They are not bit-identical to fast_exp (a table of 128 entries), which the
// scalar path uses; test_batch bounds the difference.
#pragma once
#include "kernels.hpp"

// GCC 12's AVX-512 headers initialize their placeholder operands from themselves, which
// -Wmaybe-uninitialized reports at every use (GCC bug 105593, fixed in GCC 13)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace asperity::detail {
namespace {

// fast_quintic for the four queries at[0..3] (element offsets of their records), y[0..3]
ASPERITY_ALWAYS_INLINE __m256d quintic_rows4(const double* coefficients, const std::uint64_t* at,
                                             const double* y) noexcept {
  const double *r0 = coefficients + at[0], *r1 = coefficients + at[1];
  const double *r2 = coefficients + at[2], *r3 = coefficients + at[3];
  // c0..c3: rows of four, unpacked in pairs and the 128-bit halves exchanged
  const __m256d a0 = _mm256_loadu_pd(r0), a1 = _mm256_loadu_pd(r1), a2 = _mm256_loadu_pd(r2), a3 = _mm256_loadu_pd(r3);
  const __m256d even01 = _mm256_unpacklo_pd(a0, a1), odd01 = _mm256_unpackhi_pd(a0, a1);  // c0 c0 c2 c2, c1 c1 c3 c3
  const __m256d even23 = _mm256_unpacklo_pd(a2, a3), odd23 = _mm256_unpackhi_pd(a2, a3);
  const __m256d c0 = _mm256_permute2f128_pd(even01, even23, 0x20), c2 = _mm256_permute2f128_pd(even01, even23, 0x31);
  const __m256d c1 = _mm256_permute2f128_pd(odd01, odd23, 0x20), c3 = _mm256_permute2f128_pd(odd01, odd23, 0x31);
  // c4, c5: pairs of two
  const __m256d b02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(r0 + 4)), _mm_loadu_pd(r2 + 4), 1);
  const __m256d b13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(r1 + 4)), _mm_loadu_pd(r3 + 4), 1);
  const __m256d c4 = _mm256_unpacklo_pd(b02, b13), c5 = _mm256_unpackhi_pd(b02, b13);
  // fast_quintic's Estrin scheme
  const __m256d at_y = _mm256_loadu_pd(y), y2 = _mm256_mul_pd(at_y, at_y);
  const __m256d low = _mm256_fmadd_pd(at_y, c1, c0), middle = _mm256_fmadd_pd(at_y, c3, c2);
  const __m256d high = _mm256_fmadd_pd(at_y, c5, c4);
  return _mm256_fmadd_pd(y2, _mm256_fmadd_pd(y2, high, middle), low);
}

#if defined(__AVX512F__)
using Wide = __m512d;
constexpr int wide_lanes = 8;
ASPERITY_ALWAYS_INLINE __m512i wide_splat(std::int64_t value) { return _mm512_set1_epi64(value); }

// 2^(j/16), j = 0..15, as hi + lo (the Taylor series in long double, as make_exp2_table)
struct Exp2Table16 {
  alignas(64) double hi[16];
  alignas(64) double lo[16];
};
constexpr Exp2Table16 make_exp2_table16() {
  Exp2Table16 table{};
  constexpr long double ln2 = 0.693147180559945309417232121458176568L;
  for (int j = 0; j < 16; ++j) {
    const long double x = j * ln2 / 16;
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
constexpr Exp2Table16 exp2_table16 = make_exp2_table16();

// The result's bits from scale (in [0.7, 2.1]) and m, every regime (fast_exp_lanes' masks)
ASPERITY_ALWAYS_INLINE __m512d exp_finish_any(__m512d x, __m512i scale, __m512i m) noexcept {
  const __m512i exponent = _mm512_add_epi64(_mm512_srli_epi64(scale, 52), m);
  const __m512i normal = _mm512_add_epi64(scale, _mm512_slli_epi64(m, 52));
  const __m512d two_52 = _mm512_set1_pd(4503599627370496.0);
  const __m512i clamped = _mm512_max_epi64(m, wide_splat(-1100));
  const __m512d power = _mm512_castsi512_pd(_mm512_slli_epi64(_mm512_add_epi64(clamped, wide_splat(1074 + 1023)), 52));
  const __m512i below = _mm512_sub_epi64(
      _mm512_castpd_si512(_mm512_fmadd_pd(_mm512_castsi512_pd(scale), power, two_52)), _mm512_castpd_si512(two_52));
  const __mmask8 is_below = _mm512_cmple_epi64_mask(exponent, _mm512_setzero_si512());
  const __mmask8 is_zero = _mm512_cmp_pd_mask(x, _mm512_set1_pd(-746.0), _CMP_LT_OQ);
  const __mmask8 is_inf =
      (_mm512_cmpge_epi64_mask(exponent, wide_splat(2047)) | _mm512_cmp_pd_mask(x, _mm512_set1_pd(710.0), _CMP_GT_OQ)) &
      static_cast<__mmask8>(~is_zero);
  const __mmask8 is_nan = _mm512_cmp_pd_mask(x, x, _CMP_UNORD_Q);
  __m512i result = _mm512_mask_blend_epi64(is_below, normal, below);
  result = _mm512_mask_mov_epi64(result, is_inf, wide_splat(0x7ff0000000000000ll));
  result = _mm512_mask_mov_epi64(result, is_zero, _mm512_setzero_si512());
  return _mm512_mask_mov_pd(_mm512_castsi512_pd(result), is_nan, x);
}

ASPERITY_ALWAYS_INLINE __m512d exp_wide(__m512d x) noexcept {
  const __m512d shifter = _mm512_set1_pd(round_shifter);
  const __m512d shifted = _mm512_fmadd_pd(x, _mm512_set1_pd(23.083120654223414), shifter);  // 16 / ln 2
  const __m512d k = _mm512_sub_pd(shifted, shifter);
  const __m512i k_bits = _mm512_sub_epi64(_mm512_castpd_si512(shifted), _mm512_castpd_si512(shifter));
  // ln2 / 16 in two parts, the first with 32 significant bits: k ln2_hi / 16 is exact
  __m512d r = _mm512_fnmadd_pd(k, _mm512_set1_pd(6.93147180369123816490e-01 / 16), x);
  r = _mm512_fnmadd_pd(k, _mm512_set1_pd(1.90821492927058770002e-10 / 16), r);
  const __m512d r2 = _mm512_mul_pd(r, r), r4 = _mm512_mul_pd(r2, r2);
  const __m512d p01 = _mm512_fmadd_pd(r, _mm512_set1_pd(1.0 / 6), _mm512_set1_pd(0.5));
  const __m512d p23 = _mm512_fmadd_pd(r, _mm512_set1_pd(1.0 / 120), _mm512_set1_pd(1.0 / 24));
  const __m512d p45 = _mm512_fmadd_pd(r, _mm512_set1_pd(1.0 / 5040), _mm512_set1_pd(1.0 / 720));
  const __m512d expm1 = _mm512_fmadd_pd(r2, _mm512_fmadd_pd(r4, p45, _mm512_fmadd_pd(r2, p23, p01)), r);
  // the low four bits of k pick the entry (vpermt2pd reads only those)
  const __m512d hi = _mm512_permutex2var_pd(_mm512_load_pd(exp2_table16.hi), k_bits, _mm512_load_pd(exp2_table16.hi + 8));
  const __m512d lo = _mm512_permutex2var_pd(_mm512_load_pd(exp2_table16.lo), k_bits, _mm512_load_pd(exp2_table16.lo + 8));
  const __m512d scale = _mm512_add_pd(hi, _mm512_fmadd_pd(hi, expm1, lo));
  const __m512i m = _mm512_srai_epi64(k_bits, 4);  // floor(k / 16)
  const __mmask8 surely_normal = _mm512_cmp_pd_mask(x, _mm512_set1_pd(exp_surely_normal_min), _CMP_GE_OQ) &
                                 _mm512_cmp_pd_mask(x, _mm512_set1_pd(exp_surely_normal_max), _CMP_LE_OQ);
  if (__builtin_expect(surely_normal == 0xff, 1))
    return _mm512_mul_pd(scale, _mm512_castsi512_pd(_mm512_slli_epi64(_mm512_add_epi64(m, wide_splat(1023)), 52)));
  return exp_finish_any(x, _mm512_castpd_si512(scale), m);
}
ASPERITY_ALWAYS_INLINE __m512d load_wide(const double* from) noexcept { return _mm512_loadu_pd(from); }
ASPERITY_ALWAYS_INLINE void store_wide(double* to, __m512d value) noexcept { _mm512_storeu_pd(to, value); }
ASPERITY_ALWAYS_INLINE void store_wide_first(double* to, __m512d value, int count) noexcept {
  _mm512_mask_storeu_pd(to, static_cast<__mmask8>((1u << count) - 1), value);
}
#else
using Wide = __m256d;
constexpr int wide_lanes = 4;
ASPERITY_ALWAYS_INLINE __m256i wide_splat(std::int64_t value) { return _mm256_set1_epi64x(value); }

// The result's bits from scale (in [0.7, 1.5]) and m = k, every regime (fast_exp_lanes' masks,
// with compares and blends: AVX2 has no mask registers and no 64-bit max)
ASPERITY_ALWAYS_INLINE __m256d exp_finish_any(__m256d x, __m256i scale, __m256i m) noexcept {
  const __m256i exponent = _mm256_add_epi64(_mm256_srli_epi64(scale, 52), m);
  const __m256i normal = _mm256_add_epi64(scale, _mm256_slli_epi64(m, 52));
  const __m256d two_52 = _mm256_set1_pd(4503599627370496.0);
  const __m256i floor = wide_splat(-1100);
  const __m256i clamped = _mm256_blendv_epi8(m, floor, _mm256_cmpgt_epi64(floor, m));
  const __m256d power = _mm256_castsi256_pd(_mm256_slli_epi64(_mm256_add_epi64(clamped, wide_splat(1074 + 1023)), 52));
  const __m256i below = _mm256_sub_epi64(
      _mm256_castpd_si256(_mm256_fmadd_pd(_mm256_castsi256_pd(scale), power, two_52)), _mm256_castpd_si256(two_52));
  const __m256i is_below = _mm256_cmpgt_epi64(wide_splat(1), exponent);
  const __m256i is_zero = _mm256_castpd_si256(_mm256_cmp_pd(x, _mm256_set1_pd(-746.0), _CMP_LT_OQ));
  const __m256i is_inf = _mm256_andnot_si256(
      is_zero, _mm256_or_si256(_mm256_cmpgt_epi64(exponent, wide_splat(2046)),
                               _mm256_castpd_si256(_mm256_cmp_pd(x, _mm256_set1_pd(710.0), _CMP_GT_OQ))));
  const __m256d is_nan = _mm256_cmp_pd(x, x, _CMP_UNORD_Q);
  __m256i result = _mm256_blendv_epi8(normal, below, is_below);
  result = _mm256_blendv_epi8(result, wide_splat(0x7ff0000000000000ll), is_inf);
  result = _mm256_andnot_si256(is_zero, result);
  return _mm256_blendv_pd(_mm256_castsi256_pd(result), x, is_nan);
}

ASPERITY_ALWAYS_INLINE __m256d exp_wide(__m256d x) noexcept {
  const __m256d shifter = _mm256_set1_pd(round_shifter);
  const __m256d shifted = _mm256_fmadd_pd(x, _mm256_set1_pd(1.4426950408889634), shifter);  // 1 / ln 2
  const __m256d k = _mm256_sub_pd(shifted, shifter);
  const __m256i k_bits = _mm256_sub_epi64(_mm256_castpd_si256(shifted), _mm256_castpd_si256(shifter));
  // ln2 in two parts, the first with 32 significant bits: k ln2_hi is exact
  __m256d r = _mm256_fnmadd_pd(k, _mm256_set1_pd(6.93147180369123816490e-01), x);
  r = _mm256_fnmadd_pd(k, _mm256_set1_pd(1.90821492927058770002e-10), r);
  // e^r - 1 = r + r^2 P(r), P(r) = sum of r^(i-2) / i!, i = 2..13 (Estrin's scheme)
  const __m256d r2 = _mm256_mul_pd(r, r), r4 = _mm256_mul_pd(r2, r2);
  const auto pair = [r](double c0, double c1) { return _mm256_fmadd_pd(r, _mm256_set1_pd(c1), _mm256_set1_pd(c0)); };
  const __m256d p23 = pair(1.0 / 2, 1.0 / 6), p45 = pair(1.0 / 24, 1.0 / 120);
  const __m256d p67 = pair(1.0 / 720, 1.0 / 5040), p89 = pair(1.0 / 40320, 1.0 / 362880);
  const __m256d p1011 = pair(1.0 / 3628800, 1.0 / 39916800), p1213 = pair(1.0 / 479001600, 1.0 / 6227020800.0);
  const __m256d q2 = _mm256_fmadd_pd(r2, p45, p23), q6 = _mm256_fmadd_pd(r2, p89, p67);
  const __m256d q10 = _mm256_fmadd_pd(r2, p1213, p1011);
  const __m256d poly = _mm256_fmadd_pd(r4, _mm256_fmadd_pd(r4, q10, q6), q2);
  const __m256d scale = _mm256_add_pd(_mm256_set1_pd(1.0), _mm256_fmadd_pd(r2, poly, r));
  const __m256d surely_normal = _mm256_and_pd(_mm256_cmp_pd(x, _mm256_set1_pd(exp_surely_normal_min), _CMP_GE_OQ),
                                              _mm256_cmp_pd(x, _mm256_set1_pd(exp_surely_normal_max), _CMP_LE_OQ));
  if (__builtin_expect(_mm256_movemask_pd(surely_normal) == 0xf, 1))
    return _mm256_mul_pd(scale, _mm256_castsi256_pd(_mm256_slli_epi64(_mm256_add_epi64(k_bits, wide_splat(1023)), 52)));
  return exp_finish_any(x, _mm256_castpd_si256(scale), k_bits);
}
ASPERITY_ALWAYS_INLINE __m256d load_wide(const double* from) noexcept { return _mm256_loadu_pd(from); }
ASPERITY_ALWAYS_INLINE void store_wide(double* to, __m256d value) noexcept { _mm256_storeu_pd(to, value); }
ASPERITY_ALWAYS_INLINE void store_wide_first(double* to, __m256d value, int count) noexcept {
  alignas(32) double lanes[4];
  _mm256_store_pd(lanes, value);
  for (int lane = 0; lane < count; ++lane) to[lane] = lanes[lane];
}
#endif

struct X86Passes {
  // ScalarPasses::positions (kernels.hpp), four queries a step; the last few one at a time
  static std::uint64_t positions(const FastGrid& grid, const double* separations, std::uint64_t* at, double* y,
                                 int count) noexcept {
    const __m256d lower0 = _mm256_set1_pd(grid.sides[0].lower), lower1 = _mm256_set1_pd(grid.sides[1].lower);
    const __m256d upper0 = _mm256_set1_pd(grid.sides[0].upper), upper1 = _mm256_set1_pd(grid.sides[1].upper);
    const __m256d offset0 = _mm256_castsi256_pd(_mm256_set1_epi64x(grid.sides[0].offset));
    const __m256d offset1 = _mm256_castsi256_pd(_mm256_set1_epi64x(grid.sides[1].offset));
    const __m256i magnitude_mask = _mm256_set1_epi64x(0x7fffffffffffffffll);
    const __m256i mantissa_mask = _mm256_set1_epi64x(0x000fffffffffffffll), exponent_mask = _mm256_set1_epi64x(0x7ff);
    const __m256i knots_mask = _mm256_set1_epi64x(63), fifty_two = _mm256_set1_epi64x(52);
    const __m256i one_bits = _mm256_set1_epi64x(0x3ff0000000000000ll);
    const __m256i first_bias = _mm256_set1_epi64x(FastBinade::first_bias);
    const long long* directory = reinterpret_cast<const long long*>(grid.directory.data());
    std::uint64_t inside_count = 0;
    int j = 0;
    for (; j + 4 <= count; j += 4) {
      const __m256d separation = _mm256_loadu_pd(separations + j);
      const __m256i bits = _mm256_castpd_si256(separation);
      const __m256d magnitude = _mm256_castsi256_pd(_mm256_and_si256(bits, magnitude_mask));
      // the sign's grid: blendv picks by the sign bit, the separation's own
      const __m256d lower = _mm256_blendv_pd(lower0, lower1, separation);
      const __m256d upper = _mm256_blendv_pd(upper0, upper1, separation);
      const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(magnitude, lower, _CMP_GE_OQ),
                                           _mm256_cmp_pd(magnitude, upper, _CMP_LE_OQ));  // NaN fails too
      inside_count += static_cast<std::uint64_t>(__builtin_popcount(static_cast<unsigned>(_mm256_movemask_pd(inside))));
      const __m256i keep = _mm256_castpd_si256(inside);  // off the grid: entry 0, record 0 (valid loads)
      const __m256i offset = _mm256_castpd_si256(_mm256_blendv_pd(offset0, offset1, separation));
      const __m256i entry =
          _mm256_and_si256(_mm256_add_epi64(offset, _mm256_and_si256(_mm256_srli_epi64(bits, 52), exponent_mask)), keep);
      const __m256i packed = _mm256_i64gather_epi64(directory, entry, 8);
      const __m256i knots = _mm256_and_si256(packed, knots_mask), mantissa = _mm256_and_si256(bits, mantissa_mask);
      const __m256i cell = _mm256_srlv_epi64(mantissa, _mm256_sub_epi64(fifty_two, knots));
      const __m256d fraction = _mm256_castsi256_pd(
          _mm256_or_si256(_mm256_and_si256(_mm256_sllv_epi64(mantissa, knots), mantissa_mask), one_bits));
      const __m256i index =
          _mm256_and_si256(_mm256_add_epi64(_mm256_sub_epi64(_mm256_srli_epi64(packed, 6), first_bias), cell), keep);
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(at + j),
                          _mm256_add_epi64(_mm256_slli_epi64(index, 2), _mm256_slli_epi64(index, 1)));  // 6 index
      _mm256_storeu_pd(y + j, _mm256_sub_pd(fraction, _mm256_set1_pd(1.5)));
    }
    std::uint64_t outside = static_cast<std::uint64_t>(j) - inside_count;
    for (; j < count; ++j) {
      FastPosition position;
      const bool inside = fast_position(grid, separations[j], position);
      at[j] = inside ? position.interval * fast_stride : 0;
      y[j] = inside ? position.y : 0;
      outside += inside ? 0 : 1;
    }
    return outside;
  }
  // logs[j] for j < count (a multiple of batch_pad, the records at[j] valid)
  static void quintics(const double* __restrict coefficients, const std::uint64_t* __restrict at,
                       const double* __restrict y, double* __restrict logs, int count) noexcept {
    for (int j = 0; j < count; j += 4) _mm256_storeu_pd(logs + j, quintic_rows4(coefficients, at + j, y + j));
  }
  // out[j] = e^logs[j] for j < count (logs readable up to the next multiple of batch_pad)
  static void exps(const double* logs, double* out, int count) noexcept {
    int j = 0;
    for (; j + wide_lanes <= count; j += wide_lanes) store_wide(out + j, exp_wide(load_wide(logs + j)));
    if (j < count) store_wide_first(out + j, exp_wide(load_wide(logs + j)), count - j);
  }
};

}  // namespace
}  // namespace asperity::detail
