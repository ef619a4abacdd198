// contact4 (kernels.hpp) for AVX2 + FMA, shared by the AVX2 and AVX-512 builds (each compiles
// its own copy): the four orders' quintics as one 4-lane vector and, where all four results
// are surely normal (fast_math.hpp's exp_surely_normal_min/max: nearly every query), exp_parts with 2^m applied by
// one exact multiplication; otherwise fast_exp lane by lane. The same bits as fast_exp built
// with the same flags (tests/test_kernels.cpp), with no masks to blend on the way: contact_orders is
// latency-bound (with the compiler's masked 4-lane exp it took 1.29x one order, now 1.16x:
// docs/speed-vs-error.md, BM_ContactOrders against BM_ScalarKind/weibull_tail_a2).
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

void contact4_x86(const double* __restrict record, double y, double* __restrict logs,
                  double* __restrict values) noexcept {
  // fast_quintic's Estrin scheme, one order a lane (the record is 64-byte aligned)
  const __m256d at = _mm256_set1_pd(y), at2 = _mm256_mul_pd(at, at);
  const __m256d low = _mm256_fmadd_pd(at, _mm256_load_pd(record + 4), _mm256_load_pd(record));
  const __m256d middle = _mm256_fmadd_pd(at, _mm256_load_pd(record + 12), _mm256_load_pd(record + 8));
  const __m256d high = _mm256_fmadd_pd(at, _mm256_load_pd(record + 20), _mm256_load_pd(record + 16));
  const __m256d x = _mm256_fmadd_pd(at2, _mm256_fmadd_pd(at2, high, middle), low);
  _mm256_storeu_pd(logs, x);
  const __m256d in_range = _mm256_and_pd(_mm256_cmp_pd(x, _mm256_set1_pd(exp_surely_normal_min), _CMP_GE_OQ),
                                         _mm256_cmp_pd(x, _mm256_set1_pd(exp_surely_normal_max), _CMP_LE_OQ));
  if (__builtin_expect(_mm256_movemask_pd(in_range) != 0xf, 0)) {
    for (int lane = 0; lane < 4; ++lane) values[lane] = fast_exp(logs[lane]);
    return;
  }
  // exp_parts (fast_math.hpp), four lanes
  const __m256d shifter = _mm256_set1_pd(round_shifter);
  const __m256d shifted = _mm256_fmadd_pd(x, _mm256_set1_pd(184.66496523378731), shifter);  // 128 / ln 2
  const __m256d k = _mm256_sub_pd(shifted, shifter);
  const __m256i k_bits = _mm256_sub_epi64(_mm256_castpd_si256(shifted), _mm256_castpd_si256(shifter));
  const __m256i index = _mm256_and_si256(k_bits, _mm256_set1_epi64x(127));
  __m256d r = _mm256_fnmadd_pd(k, _mm256_set1_pd(6.93147180369123816490e-01 / 128), x);
  r = _mm256_fnmadd_pd(k, _mm256_set1_pd(1.90821492927058770002e-10 / 128), r);
  const __m256d r2 = _mm256_mul_pd(r, r);
  const __m256d p01 = _mm256_fmadd_pd(r, _mm256_set1_pd(1.0 / 6), _mm256_set1_pd(0.5));
  const __m256d p23 = _mm256_fmadd_pd(r, _mm256_set1_pd(1.0 / 120), _mm256_set1_pd(1.0 / 24));
  const __m256d expm1 = _mm256_fmadd_pd(r2, _mm256_fmadd_pd(r2, p23, p01), r);
  const __m256d hi = _mm256_i64gather_pd(exp2_table.hi, index, 8);
  const __m256d lo = _mm256_i64gather_pd(exp2_table.lo, index, 8);
  const __m256d scale = _mm256_add_pd(hi, _mm256_fmadd_pd(hi, expm1, lo));
  // 2^m as a double, m = floor(k / 128) by a logical shift of k + 2^20 (as exp_parts)
  const __m256i biased = _mm256_sub_epi64(_mm256_srli_epi64(_mm256_add_epi64(k_bits, _mm256_set1_epi64x(1 << 20)), 7),
                                          _mm256_set1_epi64x((1 << 13) - 1023));
  _mm256_storeu_pd(values, _mm256_mul_pd(scale, _mm256_castsi256_pd(_mm256_slli_epi64(biased, 52))));
}

}  // namespace
}  // namespace asperity::detail
