// intrinsics_kernel.hpp's loop: built with the runtime's AVX-512 flags (bench/CMakeLists.txt).
#include "intrinsics_kernel.hpp"

#if defined(__AVX512F__) && defined(__AVX512DQ__) && defined(__AVX512VL__)
#include "asperity/detail/intrinsics.hpp"

namespace asperity::bench {
namespace {
using namespace detail;

ASPERITY_ALWAYS_INLINE __m512i splat(std::uint64_t value) { return _mm512_set1_epi64(static_cast<long long>(value)); }
ASPERITY_ALWAYS_INLINE __m512d as_double(__m512i bits) { return _mm512_castsi512_pd(bits); }
ASPERITY_ALWAYS_INLINE __m512i as_bits(__m512d value) { return _mm512_castpd_si512(value); }

// fast_exp_lanes (fast_math.hpp) on eight lanes: exp_parts, exp_normal, exp_below_normal, and the
// special values by mask registers.
ASPERITY_ALWAYS_INLINE __m512d exp8(__m512d x) {
  const __m512d shifter = _mm512_set1_pd(round_shifter);
  const __m512d shifted = _mm512_fmadd_pd(x, _mm512_set1_pd(184.66496523378731), shifter);  // 128 / ln 2
  const __m512d k = _mm512_sub_pd(shifted, shifter);
  const __m512i k_bits = _mm512_sub_epi64(as_bits(shifted), as_bits(shifter));
  const __m512i index = _mm512_and_si512(k_bits, splat(127));
  __m512d r = _mm512_fnmadd_pd(k, _mm512_set1_pd(6.93147180369123816490e-01 / 128), x);
  r = _mm512_fnmadd_pd(k, _mm512_set1_pd(1.90821492927058770002e-10 / 128), r);
  const __m512d r2 = _mm512_mul_pd(r, r);
  const __m512d low = _mm512_fmadd_pd(r, _mm512_set1_pd(1.0 / 6), _mm512_set1_pd(0.5));
  const __m512d high = _mm512_fmadd_pd(r, _mm512_set1_pd(1.0 / 120), _mm512_set1_pd(1.0 / 24));
  const __m512d expm1 = _mm512_fmadd_pd(r2, _mm512_fmadd_pd(r2, high, low), r);
  const __m512d hi = _mm512_i64gather_pd(index, exp2_table.hi, 8);
  const __m512d lo = _mm512_i64gather_pd(index, exp2_table.lo, 8);
  const __m512i scale = as_bits(_mm512_add_pd(hi, _mm512_fmadd_pd(hi, expm1, lo)));
  const __m512i m = _mm512_srai_epi64(k_bits, 7);  // floor(k / 128)
  const __m512i exponent = _mm512_add_epi64(_mm512_srli_epi64(scale, 52), m);
  const __m512i normal = _mm512_add_epi64(scale, _mm512_slli_epi64(m, 52));
  // below the normal range: the integer nearest scale 2^(m + 1074), made by adding 2^52
  const __m512d two_52 = _mm512_set1_pd(4503599627370496.0);
  const __m512i clamped = _mm512_max_epi64(m, _mm512_set1_epi64(-1100));
  const __m512d power = as_double(_mm512_slli_epi64(_mm512_add_epi64(clamped, splat(1074 + 1023)), 52));
  const __m512i below = _mm512_sub_epi64(as_bits(_mm512_fmadd_pd(as_double(scale), power, two_52)), as_bits(two_52));
  const __mmask8 is_below = _mm512_cmple_epi64_mask(exponent, _mm512_setzero_si512());
  const __mmask8 is_zero = _mm512_cmp_pd_mask(x, _mm512_set1_pd(-746.0), _CMP_LT_OQ);
  const __mmask8 is_inf = (_mm512_cmpge_epi64_mask(exponent, splat(2047)) |
                           _mm512_cmp_pd_mask(x, _mm512_set1_pd(710.0), _CMP_GT_OQ)) &
                          static_cast<__mmask8>(~is_zero);
  const __mmask8 is_nan = _mm512_cmp_pd_mask(x, x, _CMP_UNORD_Q);
  __m512i result = _mm512_mask_blend_epi64(is_below, normal, below);
  result = _mm512_mask_mov_epi64(result, is_inf, splat(0x7ff0000000000000ull));
  result = _mm512_mask_mov_epi64(result, is_zero, _mm512_setzero_si512());
  return _mm512_mask_mov_pd(as_double(result), is_nan, x);
}

// run_block (runtime/core/kernel/kernels.hpp) on eight queries a step; the last step masked. Lanes off the grid
// load nothing (masked gathers) and are counted.
std::uint64_t run_block_avx512(const FastGrid& grid, const double* coefficients, const double* separations,
                               double* out, int count) {
  const FastBinade* directory = grid.directory;
  const __m512d lower0 = _mm512_set1_pd(grid.sides[0].lower), upper0 = _mm512_set1_pd(grid.sides[0].upper);
  const __m512d lower1 = _mm512_set1_pd(grid.sides[1].lower), upper1 = _mm512_set1_pd(grid.sides[1].upper);
  const __m512i offset0 = _mm512_set1_epi64(grid.sides[0].offset), offset1 = _mm512_set1_epi64(grid.sides[1].offset);
  const __m512i first_bias = splat(static_cast<std::uint64_t>(FastBinade::first_bias));
  const __m512i magnitude_mask = splat(0x7fffffffffffffffull), mantissa_mask = splat(0x000fffffffffffffull);
  const __m512i one_bits = splat(0x3ff0000000000000ull);
  const long long* directory_words = reinterpret_cast<const long long*>(directory);
  std::uint64_t outside = 0;
  for (int j = 0; j < count; j += 8) {
    const int left = count - j;
    const __mmask8 valid = left >= 8 ? static_cast<__mmask8>(0xff) : static_cast<__mmask8>((1u << left) - 1);
    const __m512d separation = _mm512_maskz_loadu_pd(valid, separations + j);
    const __m512i bits = as_bits(separation);
    const __mmask8 negative = _mm512_movepi64_mask(bits);
    const __m512d magnitude = as_double(_mm512_and_si512(bits, magnitude_mask));
    const __m512d lower = _mm512_mask_blend_pd(negative, lower0, lower1);
    const __m512d upper = _mm512_mask_blend_pd(negative, upper0, upper1);
    const __mmask8 inside = _mm512_mask_cmp_pd_mask(_mm512_cmp_pd_mask(magnitude, lower, _CMP_GE_OQ) & valid,
                                                    magnitude, upper, _CMP_LE_OQ);
    outside += static_cast<std::uint64_t>(__builtin_popcount(valid & ~inside & 0xffu));
    const __m512i offset = _mm512_mask_blend_epi64(negative, offset0, offset1);
    const __m512i entry = _mm512_add_epi64(offset, _mm512_and_si512(_mm512_srli_epi64(bits, 52), splat(0x7ff)));
    const __m512i packed = _mm512_mask_i64gather_epi64(_mm512_setzero_si512(), inside, entry, directory_words, 8);
    const __m512i log2_knots = _mm512_and_si512(packed, splat(63));
    const __m512i mantissa = _mm512_and_si512(bits, mantissa_mask);
    const __m512i cell = _mm512_srlv_epi64(mantissa, _mm512_sub_epi64(splat(52), log2_knots));
    const __m512d fraction = as_double(
        _mm512_or_si512(_mm512_and_si512(_mm512_sllv_epi64(mantissa, log2_knots), mantissa_mask), one_bits));
    const __m512i index = _mm512_add_epi64(_mm512_sub_epi64(_mm512_srli_epi64(packed, 6), first_bias), cell);
    const __m512i at = _mm512_add_epi64(_mm512_slli_epi64(index, 2), _mm512_slli_epi64(index, 1));  // 6 index
    const __m512d zero = _mm512_setzero_pd();
    const __m512d c0 = _mm512_mask_i64gather_pd(zero, inside, at, coefficients + 0, 8);
    const __m512d c1 = _mm512_mask_i64gather_pd(zero, inside, at, coefficients + 1, 8);
    const __m512d c2 = _mm512_mask_i64gather_pd(zero, inside, at, coefficients + 2, 8);
    const __m512d c3 = _mm512_mask_i64gather_pd(zero, inside, at, coefficients + 3, 8);
    const __m512d c4 = _mm512_mask_i64gather_pd(zero, inside, at, coefficients + 4, 8);
    const __m512d c5 = _mm512_mask_i64gather_pd(zero, inside, at, coefficients + 5, 8);
    const __m512d y = _mm512_sub_pd(fraction, _mm512_set1_pd(1.5));
    const __m512d y2 = _mm512_mul_pd(y, y);
    // fast_quintic's Estrin scheme
    const __m512d low = _mm512_fmadd_pd(y, c1, c0), middle = _mm512_fmadd_pd(y, c3, c2);
    const __m512d high = _mm512_fmadd_pd(y, c5, c4);
    const __m512d log_value = _mm512_fmadd_pd(y2, _mm512_fmadd_pd(y2, high, middle), low);
    _mm512_mask_storeu_pd(out + j, valid, exp8(log_value));
  }
  return outside;
}

}  // namespace

const BlockLookup intrinsics_block_avx512 = run_block_avx512;
}  // namespace asperity::bench
#else
namespace asperity::bench {
const BlockLookup intrinsics_block_avx512 = nullptr;
}  // namespace asperity::bench
#endif
