// contact4 (kernels.hpp) for AVX2 + FMA, shared by the AVX2 and AVX-512 builds (each compiles
// its own copy, the same bits): the four orders' quintics as one 4-lane vector and, where all
// four results are surely normal (fast_math.hpp's exp_surely_normal_min/max: nearly every
// query), exp_x86.hpp's exp4 with 2^k applied by one exact multiplication; otherwise fast_exp
// lane by lane. exp4 needs no table: the 128-entry table of fast_exp took two gathers, which
// on AMD Zen 4 made contact_orders 1.5x one order (bench_lookup BM_ContactOrders against
// BM_ScalarKind/weibull_tail_a2; 1.2x with exp4).
#pragma once
#include "exp_x86.hpp"
#include "kernels.hpp"

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
  if (__builtin_expect(!exp4_surely_normal(x), 0)) {
    for (int lane = 0; lane < 4; ++lane) values[lane] = fast_exp(logs[lane]);
    return;
  }
  __m256i k_bits;
  const __m256d scale = exp4_scale(x, k_bits);
  _mm256_storeu_pd(values, exp4_normal(scale, k_bits));
}

}  // namespace
}  // namespace asperity::detail
