// e^x on vectors for the x86 kernels (batch_x86.hpp, contact4_x86.hpp), without a table in
// memory (a table lookup per lane is a gather, which costs more than the arithmetic it saves:
// bench_lookup BM_Batch, BM_ContactOrders):
// - exp4 (AVX2 + FMA, four lanes): x = k ln 2 + r, |r| <= ln2 / 2, e^r by a minimax
//   polynomial of degree 11 (error 6.5e-18); in base 2 too (2^x, exp4_expm1<BinaryExp>: the
//   contact kernels, whose records hold log2 X). Where every lane is surely normal (fast_math.hpp's
//   NaturalExp / BinaryExp ranges), the result is 2^k + 2^k (e^r - 1) in one fused multiply-add,
//   2^k made in the exponent field. Where a lane is below that range but every lane is in
//   [-760, 709] (the tails' X < 1e-308), subnormal results are made from normal doubles (no
//   assist; faster than fast_exp_lanes' masks in BM_BatchTail/avx2/subnormal_results);
//   otherwise exp4_any: fast_exp_lanes' masks
//   (0 below -746, inf above 710, NaN kept), or in the AVX-512 build vscalefpd where k is exact.
// - exp8 (AVX-512, eight lanes): x = (m + j/16) ln2 + r, |r| <= ln2 / 32, 2^(j/16) from a
//   16-entry table held in four registers (vpermt2pd), e^r by a minimax polynomial of degree 6
//   (error 1.2e-17), 2^m applied by vscalefpd, which gives inf beyond the range (x clamped to
//   [-760, 710] first, NaN kept); below ln DBL_MIN the result's bits are made as an integer
//   (exp8_below_normal: a vscalefpd that makes a subnormal takes a microcode assist on Intel
//   cores), the same rounding: bench_lookup's BM_BatchTail/avx512 rows, subnormal_results
//   against normal_results, show what the tails cost.
// The coefficients: scripts/exp_minimax.py (Remez in 50 digits, the errors with the
// coefficients rounded to double); each polynomial is one or two operations shorter than the
// Taylor one of the same accuracy, on a path bound by its vector operations.
// Accuracy (tests/test_kernels.cpp, against a long double exp over [-760, 720] and each edge,
// and exp2 over [-1100, 1040]): within 2.3e-16 relative where the result is normal (measured
// 1.5e-16 exp4, 1.2e-16 exp8, 1.9e-16 exp4 in base 2), 0.75 of the subnormal spacing below.
// Subnormal results assume the default MXCSR (vscalefpd flushes them to 0 under flush-to-zero).
// Not bit-identical to fast_exp (a table of 128 entries), which the scalar path uses.
#pragma once
#include <type_traits>

#include "kernels.hpp"

#include "asperity/detail/intrinsics.hpp"

namespace asperity::detail {
namespace {

// The result's bits from scale (in [0.7, 1.5]) and m = k, every regime (fast_exp_lanes' masks,
// with compares and blends: AVX2 has no mask registers and no 64-bit max), x in Base's units
template <class Base>
ASPERITY_ALWAYS_INLINE __m256d exp4_finish_any(__m256d x, __m256i scale, __m256i m) noexcept {
  const __m256i exponent = _mm256_add_epi64(_mm256_srli_epi64(scale, 52), m);
  const __m256i normal = _mm256_add_epi64(scale, _mm256_slli_epi64(m, 52));
  const __m256d two_52 = _mm256_set1_pd(4503599627370496.0);
  const __m256i floor = _mm256_set1_epi64x(-1100);
  const __m256i clamped = _mm256_blendv_epi8(m, floor, _mm256_cmpgt_epi64(floor, m));
  const __m256d power = _mm256_castsi256_pd(_mm256_slli_epi64(_mm256_add_epi64(clamped, _mm256_set1_epi64x(1074 + 1023)), 52));
  const __m256i below = _mm256_sub_epi64(
      _mm256_castpd_si256(_mm256_fmadd_pd(_mm256_castsi256_pd(scale), power, two_52)), _mm256_castpd_si256(two_52));
  const __m256i is_below = _mm256_cmpgt_epi64(_mm256_set1_epi64x(1), exponent);
  const __m256i is_zero = _mm256_castpd_si256(_mm256_cmp_pd(x, _mm256_set1_pd(Base::lowest), _CMP_LT_OQ));
  const __m256i is_inf = _mm256_andnot_si256(
      is_zero, _mm256_or_si256(_mm256_cmpgt_epi64(exponent, _mm256_set1_epi64x(2046)),
                               _mm256_castpd_si256(_mm256_cmp_pd(x, _mm256_set1_pd(Base::highest), _CMP_GT_OQ))));
  const __m256d is_nan = _mm256_cmp_pd(x, x, _CMP_UNORD_Q);
  __m256i result = _mm256_blendv_epi8(normal, below, is_below);
  result = _mm256_blendv_epi8(result, _mm256_set1_epi64x(0x7ff0000000000000ll), is_inf);
  result = _mm256_andnot_si256(is_zero, result);
  return _mm256_blendv_pd(_mm256_castsi256_pd(result), x, is_nan);
}

// The shifter that rounds x / ln 2 to k, plus 1023: the low bits of the sum are then k + 1023,
// 2^k's exponent field, with no integer addition (exp4_normal)
constexpr double exp4_shifter = round_shifter + 1023;
// e^r - 1 = r + r^2 P(r), P of degree 9, minimax on |r| <= 1.0001 ln2 / 2 (Remez in 50
// digits, scripts/exp_minimax.py: error 6.5e-18 with the coefficients in double; the Taylor
// polynomial of degree 13, 4.3e-18, took two operations more), Estrin's scheme
ASPERITY_ALWAYS_INLINE __m256d exp4_polynomial(__m256d r) noexcept {
  const __m256d r2 = _mm256_mul_pd(r, r), r4 = _mm256_mul_pd(r2, r2);
  const auto pair = [r](double c0, double c1) { return _mm256_fmadd_pd(r, _mm256_set1_pd(c1), _mm256_set1_pd(c0)); };
  const __m256d p23 = pair(0.5000000000000013, 0.166666666666667);
  const __m256d p45 = pair(0.041666666666513204, 0.008333333333307725);
  const __m256d p67 = pair(0.0013888888947499532, 0.00019841269916447693);
  const __m256d p89 = pair(2.4801489508409978e-05, 2.7557217033060023e-06);
  const __m256d p1011 = pair(2.763141794091523e-07, 2.511765148358147e-08);
  const __m256d q2 = _mm256_fmadd_pd(r2, p45, p23), q6 = _mm256_fmadd_pd(r2, p89, p67);
  const __m256d poly = _mm256_fmadd_pd(r4, _mm256_fmadd_pd(r4, p1011, q6), q2);
  return _mm256_fmadd_pd(r2, poly, r);
}
// e^x = e^r 2^k (NaturalExp) or 2^x = e^r 2^k (BinaryExp): returns e^r - 1 (in [-0.3, 0.5])
// and the bits of k + exp4_shifter, whose low 11 bits are k + 1023 (garbage where x is beyond
// Base's [lowest, highest] or NaN, which exp4_finish_any masks).
// - e^x: k = round(x / ln 2), r = x - k ln 2 with ln 2 in two parts, the first with 32
//   significant bits (k ln2_hi is exact): a multiply-add, a subtraction and two multiply-adds;
// - 2^x: k = round(x), x - k exact (Sterbenz), r = (x - k) ln 2 with ln 2 and the product
//   rounded (|r| <= ln2 / 2: at most 4e-17 from the exact r, within exp4's 2.3e-16): an
//   addition, two subtractions and a multiplication, 3 cycles shorter on the lookup's chain
//   (the contact records hold log2 X)
template <class Base = NaturalExp>
ASPERITY_ALWAYS_INLINE __m256d exp4_expm1(__m256d x, __m256i& shifted_bits) noexcept {
  const __m256d shifter = _mm256_set1_pd(exp4_shifter);
  if constexpr (std::is_same_v<Base, BinaryExp>) {
    const __m256d shifted = _mm256_add_pd(x, shifter);
    shifted_bits = _mm256_castpd_si256(shifted);
    const __m256d fraction = _mm256_sub_pd(x, _mm256_sub_pd(shifted, shifter));
    return exp4_polynomial(_mm256_mul_pd(fraction, _mm256_set1_pd(ln_2)));
  } else {
    const __m256d shifted = _mm256_fmadd_pd(x, _mm256_set1_pd(1.4426950408889634), shifter);  // 1 / ln 2
    const __m256d k = _mm256_sub_pd(shifted, shifter);
    shifted_bits = _mm256_castpd_si256(shifted);
    __m256d r = _mm256_fnmadd_pd(k, _mm256_set1_pd(6.93147180369123816490e-01), x);
    r = _mm256_fnmadd_pd(k, _mm256_set1_pd(1.90821492927058770002e-10), r);
    return exp4_polynomial(r);
  }
}
// The lanes (bits 0..3) whose result is surely a normal double (Base's range); with
// AVX-512 in mask registers (two compares, no movemask)
template <class Base = NaturalExp>
ASPERITY_ALWAYS_INLINE int exp4_surely_normal_lanes(__m256d x) noexcept {
#if defined(__AVX512VL__)
  return _mm256_mask_cmp_pd_mask(_mm256_cmp_pd_mask(x, _mm256_set1_pd(Base::surely_normal_min), _CMP_GE_OQ), x,
                                 _mm256_set1_pd(Base::surely_normal_max), _CMP_LE_OQ);
#else
  return _mm256_movemask_pd(_mm256_and_pd(_mm256_cmp_pd(x, _mm256_set1_pd(Base::surely_normal_min), _CMP_GE_OQ),
                                          _mm256_cmp_pd(x, _mm256_set1_pd(Base::surely_normal_max), _CMP_LE_OQ)));
#endif
}
template <class Base = NaturalExp>
ASPERITY_ALWAYS_INLINE bool exp4_surely_normal(__m256d x) noexcept {
  return exp4_surely_normal_lanes<Base>(x) == 0xf;
}
// e^r 2^k = 2^k + 2^k (e^r - 1) where the result is surely normal (k in [-1021, 1023]): 2^k made
// in the exponent field, one fused multiply-add, one rounding (a multiplication and an addition
// after the polynomial were one operation and ~2 cycles more on every lookup's chain)
ASPERITY_ALWAYS_INLINE __m256d exp4_normal(__m256d expm1, __m256i shifted_bits) noexcept {
  const __m256d power = _mm256_castsi256_pd(_mm256_slli_epi64(shifted_bits, 52));
  return _mm256_fmadd_pd(expm1, power, power);
}
// every regime, from exp4_expm1's results. With AVX-512, where every lane's k is exact (|x| <=
// Base::exact_k_max), vscalefpd applies 2^k: it rounds a subnormal result once and gives 0 and
// inf beyond the range, the same bits as the masks (with the default MXCSR: under
// flush-to-zero it gives 0 for a subnormal result, as exp8 does), in two operations for ~25
// (contact_orders' every lane on AVX-512; faster in bench_lookup BM_ContactAllFour when the
// contact kernels' deep tails took this path)
template <class Base = NaturalExp>
ASPERITY_ALWAYS_INLINE __m256d exp4_any(__m256d x, __m256d expm1, __m256i shifted_bits) noexcept {
  const __m256d scale = _mm256_add_pd(_mm256_set1_pd(1.0), expm1);
#if defined(__AVX512VL__)
  const __m256d magnitude = _mm256_andnot_pd(_mm256_set1_pd(-0.0), x);
  if (__builtin_expect(_mm256_cmp_pd_mask(magnitude, _mm256_set1_pd(Base::exact_k_max), _CMP_LE_OQ) == 0xf, 1))
    return _mm256_scalef_pd(scale, _mm256_sub_pd(_mm256_castsi256_pd(shifted_bits), _mm256_set1_pd(exp4_shifter)));
#endif
  const __m256i k_bits = _mm256_sub_epi64(shifted_bits, _mm256_castpd_si256(_mm256_set1_pd(exp4_shifter)));
  return exp4_finish_any<Base>(x, _mm256_castpd_si256(scale), k_bits);
}
// e^x for x in [-760, 709], every lane: where e^x < DBL_MIN (x below ln DBL_MIN), the result's
// bits as an integer, e^x 2^1074 rounded once, by adding 2^52 to it (a normal double: no
// subnormal is made by a floating-point operation); elsewhere exp4_normal (k >= -1022)
ASPERITY_ALWAYS_INLINE __m256d exp4_down_to_subnormal(__m256d x, __m256d expm1, __m256i shifted_bits) noexcept {
  const __m256d two_52 = _mm256_set1_pd(4503599627370496.0);
  // 2^(k + 1074), normal for k >= -1097: the exponent field k + 1023 + 1074
  const __m256d power = _mm256_castsi256_pd(_mm256_slli_epi64(_mm256_add_epi64(shifted_bits, _mm256_set1_epi64x(1074)), 52));
  const __m256d units = _mm256_fmadd_pd(_mm256_add_pd(_mm256_set1_pd(1.0), expm1), power, two_52);  // < 2^53
  const __m256d below = _mm256_castsi256_pd(_mm256_sub_epi64(_mm256_castpd_si256(units), _mm256_castpd_si256(two_52)));
  const __m256d is_below = _mm256_cmp_pd(x, _mm256_set1_pd(-708.3964185322641), _CMP_LT_OQ);  // ln DBL_MIN
  return _mm256_blendv_pd(exp4_normal(expm1, shifted_bits), below, is_below);
}
ASPERITY_ALWAYS_INLINE __m256d exp4(__m256d x) noexcept {
  __m256i shifted_bits;
  const __m256d expm1 = exp4_expm1(x, shifted_bits);
  if (__builtin_expect(exp4_surely_normal(x), 1)) return exp4_normal(expm1, shifted_bits);
  // the tails' X below DBL_MIN (the batch's usual slow lanes) without fast_exp_lanes' masks
  const int down_to_subnormal = _mm256_movemask_pd(_mm256_and_pd(
      _mm256_cmp_pd(x, _mm256_set1_pd(-760.0), _CMP_GE_OQ), _mm256_cmp_pd(x, _mm256_set1_pd(NaturalExp::surely_normal_max), _CMP_LE_OQ)));
  if (down_to_subnormal == 0xf) return exp4_down_to_subnormal(x, expm1, shifted_bits);
  return exp4_any(x, expm1, shifted_bits);
}

#if defined(__AVX512F__)
// 2^(j/16), j = 0..15: hi and lo 64-byte aligned (four aligned loads fill the four registers)
alignas(64) constexpr Exp2Table<16> exp2_table16 = make_exp2_table<16>();

// The shifter that rounds x / ln 2 to a multiple of 1/16, k = m + j/16: the sum's low four bits
// are j (vpermt2pd reads only those), and k itself is vscalefpd's exponent (it takes floor(k) = m)
constexpr double exp8_shifter = 1.5 * 281474976710656.0;  // 1.5 * 2^48
// Below ln DBL_MIN a vscalefpd that makes a subnormal (or 0) takes a microcode assist on Intel
// cores (a Xeon of the Sapphire Rapids class: bench_lookup BM_BatchTail/avx512/subnormal_results
// 5.1x normal_results, and the 3% of the Weibull a = 2 tail's results below DBL_MIN made
// BM_Batch/avx512 2.1x slower: 16.9 us against 8.2 us with this alone). There the result's bits
// are made as an integer, as in
// exp4_down_to_subnormal: scale 2^(m + 1074) + 2^52 rounds once to the integer that is the
// subnormal's bits (ties to even, as vscalefpd rounds; 2^53 gives DBL_MIN's bits), every
// operand a normal double. m = floor(k) >= -1097 (x >= -760): 2^(m + 1074) is normal.
constexpr double exp8_normal_min = -708.3964185322641;  // ln DBL_MIN
ASPERITY_ALWAYS_INLINE __m512d exp8_below_normal(__m512d scale, __m512d k) noexcept {
  const __m512d two_52 = _mm512_set1_pd(4503599627370496.0);
  const __m512d power = _mm512_scalef_pd(_mm512_set1_pd(1.0), _mm512_add_pd(k, _mm512_set1_pd(1074.0)));
  const __m512d units = _mm512_fmadd_pd(scale, power, two_52);  // < 2^53 + 1
  return _mm512_castsi512_pd(_mm512_sub_epi64(_mm512_castpd_si512(units), _mm512_castpd_si512(two_52)));
}
ASPERITY_ALWAYS_INLINE __m512d exp8(__m512d x) noexcept {
  // [-760, 710]: e^x is 0 below, inf above; NaN kept (vmaxpd and vminpd return their second
  // operand where one is NaN). Without it, r would be NaN for infinite x.
  const __m512d clamped = _mm512_min_pd(_mm512_set1_pd(710.0), _mm512_max_pd(_mm512_set1_pd(-760.0), x));
  const __m512d shifter = _mm512_set1_pd(exp8_shifter);
  const __m512d shifted = _mm512_fmadd_pd(clamped, _mm512_set1_pd(1.4426950408889634), shifter);  // 1 / ln 2
  const __m512d k = _mm512_sub_pd(shifted, shifter);  // m + j/16
  const __m512i shifted_bits = _mm512_castpd_si512(shifted);
  // ln2 in two parts, the first with 32 significant bits: k ln2_hi is exact (k has at most 15)
  __m512d r = _mm512_fnmadd_pd(k, _mm512_set1_pd(6.93147180369123816490e-01), clamped);
  r = _mm512_fnmadd_pd(k, _mm512_set1_pd(1.90821492927058770002e-10), r);
  // e^r - 1 = r + r^2 P(r), P of degree 4, minimax on |r| <= 1.0001 ln2 / 32 (scripts/exp_minimax.py:
  // error 1.2e-17; the Taylor polynomial of degree 7, 1.2e-18, took one operation more), by
  // Horner's rule: the batch's exps are bound by the multiply-add pipes, not by latency
  __m512d p = _mm512_fmadd_pd(_mm512_set1_pd(0.0013889129027039896), r, _mm512_set1_pd(0.008333471951132567));
  p = _mm512_fmadd_pd(p, r, _mm512_set1_pd(0.0416666666596544));
  p = _mm512_fmadd_pd(p, r, _mm512_set1_pd(0.16666666664416963));
  p = _mm512_fmadd_pd(p, r, _mm512_set1_pd(0.5000000000000006));
  const __m512d expm1 = _mm512_fmadd_pd(_mm512_mul_pd(r, r), p, r);
  const __m512d hi = _mm512_permutex2var_pd(_mm512_load_pd(exp2_table16.hi), shifted_bits, _mm512_load_pd(exp2_table16.hi + 8));
  const __m512d lo = _mm512_permutex2var_pd(_mm512_load_pd(exp2_table16.lo), shifted_bits, _mm512_load_pd(exp2_table16.lo + 8));
  const __m512d scale = _mm512_add_pd(hi, _mm512_fmadd_pd(hi, expm1, lo));
  const __mmask8 below_normal = _mm512_cmp_pd_mask(x, _mm512_set1_pd(exp8_normal_min), _CMP_LT_OQ);
  if (__builtin_expect(below_normal == 0, 1)) return _mm512_scalef_pd(scale, k);
  // the other lanes' vscalefpd masked: a lane computed and then blended away would take the assist
  return _mm512_mask_scalef_pd(exp8_below_normal(scale, k), static_cast<__mmask8>(~below_normal), scale, k);
}
#endif

}  // namespace
}  // namespace asperity::detail
