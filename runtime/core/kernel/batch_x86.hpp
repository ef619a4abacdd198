// The batch path's three passes (kernels.hpp: block) written for x86, shared by the AVX2 and
// AVX-512 builds (each compiles its own copy):
//
// - positions: ScalarPasses::positions four queries a step, with AVX2 intrinsics: the
//   compiler's loop narrows the shift counts to 32 bits and back (bench_lookup BM_Batch, this
//   against the compiler's loop: 9-12% of the whole batch path on AMD Zen 4); eight a step in
//   the AVX-512 build, the directory by a gather (positions8).
// - quintics: the six coefficients of four queries by twelve 128-bit loads (a record is six
//   doubles in a row), paired in registers and unpacked, not by six gathers. Gathers are what
//   the compiler's loop spent its time on (AMD Zen 4: a gather of 4 or 8 doubles costs more
//   than the loads and shuffles that replace it; bench_lookup BM_Batch against the former fused
//   loop, which is kept as BM_Record/batch_*/48B).
// - exps, for value output: exp_x86.hpp's exp4 (AVX2 build) or exp8 (AVX-512 build), whole
//   vectors, the last one partial.
#pragma once
#include "exp_x86.hpp"
#include "kernels.hpp"

namespace asperity::detail {
namespace {

// fast_quintic for the four queries at[0..3] (their intervals), y[0..3]
ASPERITY_ALWAYS_INLINE __m256d quintic_rows4(const double* coefficients, const std::uint64_t* at,
                                             const double* y) noexcept {
  const double *r0 = coefficients + at[0] * fast_stride, *r1 = coefficients + at[1] * fast_stride;
  const double *r2 = coefficients + at[2] * fast_stride, *r3 = coefficients + at[3] * fast_stride;
  // each pair of coefficients of rows 0 and 2 (1 and 3) in one register, two 128-bit loads,
  // then one unpack per coefficient: six shuffles and six inserts where a 4 x 4 transpose of
  // row loads took eight shuffles for c0..c3 and four more for c4, c5 (no slower: bench_lookup
  // BM_Batch/avx512)
  const auto pairs = [](const double* lower, const double* upper) {
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(lower)), _mm_loadu_pd(upper), 1);
  };
  const __m256d p02 = pairs(r0, r2), p13 = pairs(r1, r3);  // c0 c1 of rows 0, 2 (1, 3)
  const __m256d q02 = pairs(r0 + 2, r2 + 2), q13 = pairs(r1 + 2, r3 + 2);
  const __m256d u02 = pairs(r0 + 4, r2 + 4), u13 = pairs(r1 + 4, r3 + 4);
  const __m256d c0 = _mm256_unpacklo_pd(p02, p13), c1 = _mm256_unpackhi_pd(p02, p13);
  const __m256d c2 = _mm256_unpacklo_pd(q02, q13), c3 = _mm256_unpackhi_pd(q02, q13);
  const __m256d c4 = _mm256_unpacklo_pd(u02, u13), c5 = _mm256_unpackhi_pd(u02, u13);
  // fast_quintic's Estrin scheme
  const __m256d at_y = _mm256_loadu_pd(y), y2 = _mm256_mul_pd(at_y, at_y);
  const __m256d low = _mm256_fmadd_pd(at_y, c1, c0), middle = _mm256_fmadd_pd(at_y, c3, c2);
  const __m256d high = _mm256_fmadd_pd(at_y, c5, c4);
  return _mm256_fmadd_pd(y2, _mm256_fmadd_pd(y2, high, middle), low);
}

#if defined(__AVX512F__)
constexpr int wide_lanes = 8;
ASPERITY_ALWAYS_INLINE __m512d exp_wide(__m512d x) noexcept { return exp8(x); }
ASPERITY_ALWAYS_INLINE __m512d load_wide(const double* from) noexcept { return _mm512_loadu_pd(from); }
ASPERITY_ALWAYS_INLINE void store_wide(double* to, __m512d value) noexcept { _mm512_storeu_pd(to, value); }
ASPERITY_ALWAYS_INLINE void store_wide_first(double* to, __m512d value, int count) noexcept {
  _mm512_mask_storeu_pd(to, static_cast<__mmask8>((1u << count) - 1), value);
}
#else
constexpr int wide_lanes = 4;
ASPERITY_ALWAYS_INLINE __m256d exp_wide(__m256d x) noexcept { return exp4(x); }
ASPERITY_ALWAYS_INLINE __m256d load_wide(const double* from) noexcept { return _mm256_loadu_pd(from); }
ASPERITY_ALWAYS_INLINE void store_wide(double* to, __m256d value) noexcept { _mm256_storeu_pd(to, value); }
ASPERITY_ALWAYS_INLINE void store_wide_first(double* to, __m256d value, int count) noexcept {
  alignas(32) double lanes[4];
  _mm256_store_pd(lanes, value);
  for (int lane = 0; lane < count; ++lane) to[lane] = lanes[lane];
}
#endif

#if defined(__AVX512F__)
// X86Passes::positions eight queries a step (the AVX-512 build): the directory entries by one
// 8-lane gather, where four queries a step took four scalar loads and the inserts that pack
// them (Intel Xeon, Sapphire Rapids class: this pass 0.47 ns a query against 0.79 ns, timed
// alone in a harness outside the repository, about a fifth of BM_Batch/avx512; on AMD Zen 4 a
// 4-lane gather was slower than the loads, 8 lanes unmeasured).
// Returns how many queries it placed (a multiple of 8) and adds those inside to inside_count.
ASPERITY_ALWAYS_INLINE int positions8(const FastGrid& grid, const double* separations, std::uint64_t* at, double* y,
                                      int count, std::uint64_t& inside_count) noexcept {
  const __m512d lower0 = _mm512_set1_pd(grid.sides[0].lower), lower1 = _mm512_set1_pd(-grid.sides[1].upper);
  const __m512d upper0 = _mm512_set1_pd(grid.sides[0].upper), upper1 = _mm512_set1_pd(-grid.sides[1].lower);
  const __m512i offset0 = _mm512_set1_epi64(grid.sides[0].offset);
  const __m512i offset1 = _mm512_set1_epi64(grid.sides[1].offset - 2048ll);  // as in positions
  const __m512i mantissa_mask = _mm512_set1_epi64(0x000fffffffffffffll);
  const __m512i knots_mask = _mm512_set1_epi64(63), fifty_two = _mm512_set1_epi64(52);
  const __m512i one_bits = _mm512_set1_epi64(0x3ff0000000000000ll);
  const __m512i first_bias = _mm512_set1_epi64(FastBinade::first_bias);
  const long long* directory = reinterpret_cast<const long long*>(grid.directory);
  int j = 0;
  for (; j + 8 <= count; j += 8) {
    const __m512d separation = _mm512_loadu_pd(separations + j);
    const __m512i bits = _mm512_castpd_si512(separation);
    const __mmask8 negative = _mm512_movepi64_mask(bits);
    const __mmask8 inside = _mm512_mask_cmp_pd_mask(
        _mm512_cmp_pd_mask(separation, _mm512_mask_blend_pd(negative, lower0, lower1), _CMP_GE_OQ), separation,
        _mm512_mask_blend_pd(negative, upper0, upper1), _CMP_LE_OQ);  // NaN fails too
    inside_count += static_cast<std::uint64_t>(__builtin_popcount(static_cast<unsigned>(inside)));
    const __m512i offset = _mm512_mask_blend_epi64(negative, offset0, offset1);
    const __m512i entry = _mm512_maskz_add_epi64(inside, offset, _mm512_srli_epi64(bits, 52));  // off: entry 0
    const __m512i packed = _mm512_i64gather_epi64(entry, directory, 8);
    const __m512i knots = _mm512_and_si512(packed, knots_mask), mantissa = _mm512_and_si512(bits, mantissa_mask);
    const __m512i cell = _mm512_srlv_epi64(mantissa, _mm512_sub_epi64(fifty_two, knots));
    // (mantissa << knots) & mantissa_mask | one_bits in one ternary-logic operation
    const __m512d fraction =
        _mm512_castsi512_pd(_mm512_ternarylogic_epi64(_mm512_sllv_epi64(mantissa, knots), mantissa_mask, one_bits, 0xea));
    const __m512i index = _mm512_add_epi64(_mm512_sub_epi64(_mm512_srli_epi64(packed, 6), first_bias), cell);
    _mm512_storeu_si512(at + j, index);
    _mm512_storeu_pd(y + j, _mm512_sub_pd(fraction, _mm512_set1_pd(1.5)));
  }
  return j;
}
#endif

struct X86Passes {
  // ScalarPasses::positions (kernels.hpp), four queries a step (eight in the AVX-512 build:
  // positions8); the last few one at a time.
  // at[j] is the interval, not times fast_stride: quintic_rows4 multiplies on the integer
  // registers, which this pass leaves idle (three vector operations fewer per four queries;
  // faster in bench_lookup BM_Batch/avx512. The baseline build keeps the product here: its
  // quintics were slower the other way).
  static std::uint64_t positions(const FastGrid& grid, const double* separations, std::uint64_t* at, double* y,
                                 int count) noexcept {
    std::uint64_t inside_count = 0;
#if defined(__AVX512F__)
    int j = positions8(grid, separations, at, y, count, inside_count);
#else
    int j = 0;
    // the range of s itself on each side (s < 0: [-upper, -lower]): no magnitude to make
    const __m256d lower0 = _mm256_set1_pd(grid.sides[0].lower), lower1 = _mm256_set1_pd(-grid.sides[1].upper);
    const __m256d upper0 = _mm256_set1_pd(grid.sides[0].upper), upper1 = _mm256_set1_pd(-grid.sides[1].lower);
    const __m256d offset0 = _mm256_castsi256_pd(_mm256_set1_epi64x(grid.sides[0].offset));
    // s < 0: bits >> 52 is 2048 + the exponent, so its side's offset is taken 2048 lower
    const __m256d offset1 = _mm256_castsi256_pd(_mm256_set1_epi64x(grid.sides[1].offset - 2048ll));
    const __m256i mantissa_mask = _mm256_set1_epi64x(0x000fffffffffffffll);
    const __m256i knots_mask = _mm256_set1_epi64x(63), fifty_two = _mm256_set1_epi64x(52);
    const __m256i one_bits = _mm256_set1_epi64x(0x3ff0000000000000ll);
    const __m256i first_bias = _mm256_set1_epi64x(FastBinade::first_bias);
    const long long* directory = reinterpret_cast<const long long*>(grid.directory);
    for (; j + 4 <= count; j += 4) {
      const __m256d separation = _mm256_loadu_pd(separations + j);
      const __m256i bits = _mm256_castpd_si256(separation);
      // the sign's grid: blendv picks by the sign bit, the separation's own
      const __m256d lower = _mm256_blendv_pd(lower0, lower1, separation);
      const __m256d upper = _mm256_blendv_pd(upper0, upper1, separation);
      const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(separation, lower, _CMP_GE_OQ),
                                           _mm256_cmp_pd(separation, upper, _CMP_LE_OQ));  // NaN fails too
      inside_count += static_cast<std::uint64_t>(__builtin_popcount(static_cast<unsigned>(_mm256_movemask_pd(inside))));
      const __m256i keep = _mm256_castpd_si256(inside);  // off the grid: entry 0 (fast_grid.hpp)
      const __m256i offset = _mm256_castpd_si256(_mm256_blendv_pd(offset0, offset1, separation));
      const __m256i entry = _mm256_and_si256(_mm256_add_epi64(offset, _mm256_srli_epi64(bits, 52)), keep);
      // four loads, not a gather (AMD Zen 4: 4% of the whole batch path, bench_lookup BM_Batch)
      alignas(32) long long entries[4];
      _mm256_store_si256(reinterpret_cast<__m256i*>(entries), entry);
      const __m256i packed = _mm256_set_epi64x(directory[entries[3]], directory[entries[2]], directory[entries[1]],
                                               directory[entries[0]]);
      const __m256i knots = _mm256_and_si256(packed, knots_mask), mantissa = _mm256_and_si256(bits, mantissa_mask);
      const __m256i cell = _mm256_srlv_epi64(mantissa, _mm256_sub_epi64(fifty_two, knots));
      const __m256d fraction = _mm256_castsi256_pd(
          _mm256_or_si256(_mm256_and_si256(_mm256_sllv_epi64(mantissa, knots), mantissa_mask), one_bits));
      // off the grid: entry 0, whose binade gives interval 0 (fast_grid.hpp), no mask
      const __m256i index = _mm256_add_epi64(_mm256_sub_epi64(_mm256_srli_epi64(packed, 6), first_bias), cell);
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(at + j), index);
      _mm256_storeu_pd(y + j, _mm256_sub_pd(fraction, _mm256_set1_pd(1.5)));
    }
#endif
    std::uint64_t outside = static_cast<std::uint64_t>(j) - inside_count;
    for (; j < count; ++j) {
      FastPosition position;
      const bool inside = fast_position(grid, separations[j], position);
      at[j] = inside ? position.interval : 0;
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
