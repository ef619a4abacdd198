// contact4 (kernels.hpp) for AVX2 + FMA, shared by the AVX2 and AVX-512 builds (each compiles
// its own copy, the same bits): the four orders' quintics as one 4-lane vector and, where all
// four results are surely normal (fast_math.hpp's exp_surely_normal_min/max: nearly every
// query), exp_x86.hpp's exp4 with 2^k applied in one fused multiply-add; otherwise fast_exp
// lane by lane. exp4 needs no table: the 128-entry table of fast_exp took two gathers, which
// on AMD Zen 4 made contact_orders 1.5x one order (bench_lookup BM_ContactOrders against
// BM_ScalarKind/weibull_tail_a2; 1.2x with exp4).
#pragma once
#include "exp_x86.hpp"
#include "kernels.hpp"

namespace asperity::detail {
namespace {

// fast_quintic's Estrin scheme, one order a lane (the record is 64-byte aligned)
ASPERITY_ALWAYS_INLINE __m256d contact4_logs(const double* __restrict record, double y) noexcept {
  __m256d at = _mm256_set1_pd(y);
  asm("" : "+x"(at));  // y^2 by one vector multiplication (the compiler's scalar one and broadcast: two operations)
  const __m256d at2 = _mm256_mul_pd(at, at);
  const __m256d low = _mm256_fmadd_pd(at, _mm256_load_pd(record + 4), _mm256_load_pd(record));
  const __m256d middle = _mm256_fmadd_pd(at, _mm256_load_pd(record + 12), _mm256_load_pd(record + 8));
  const __m256d high = _mm256_fmadd_pd(at, _mm256_load_pd(record + 20), _mm256_load_pd(record + 16));
  return _mm256_fmadd_pd(at2, _mm256_fmadd_pd(at2, high, middle), low);
}

void contact4_x86(const double* __restrict record, double y, double* __restrict logs,
                  double* __restrict values) noexcept {
  const __m256d x = contact4_logs(record, y);
  _mm256_storeu_pd(logs, x);
  if (__builtin_expect(!exp4_surely_normal(x), 0)) {
    for (int lane = 0; lane < 4; ++lane) values[lane] = fast_exp(logs[lane]);
    return;
  }
  __m256i shifted_bits;
  const __m256d expm1 = exp4_expm1(x, shifted_bits);
  _mm256_storeu_pd(values, exp4_normal(expm1, shifted_bits));
}

// fast_grid.hpp's ContactProducts: the position, then contact4_x86's exps, the lanes (0, 1/2, 1,
// 3/2) permuted to (0, 1, 3/2, 1/2) and multiplied in the register, one branch for the
// factors' test (each in (0, DBL_MAX]) and the exps' (all surely normal); where an exp is not,
// exp4's masks and contact_ratio answer in the same call, without a second lookup.
bool contact_products_x86(const FastGrid& grid, const double* __restrict contact_records, double separation,
                          double count_factor, double area_factor, double load_factor, double stiffness_factor,
                          double* __restrict state) noexcept {
  FastPosition at;
  if (__builtin_expect(!fast_position(grid, separation, at), 0)) return false;
  const __m256d x = contact4_logs(contact_records + at.interval * contact_record_size, at.y);
  const __m256d factors = _mm256_set_pd(stiffness_factor, load_factor, area_factor, count_factor);
#if defined(__AVX512DQ__) && defined(__AVX512VL__)
  // a factor is unusable where it is NaN, +-0, +-inf or negative: one vfpclasspd to a mask
  // register (a positive subnormal is in (0, DBL_MAX]), fewer operations than two compares and
  // a movemask (bench_lookup BM_ContactAllFourScales 12.2 -> 11.8 ns with exp4_surely_normal_lanes')
  const int usable_factors =
      0xf & ~static_cast<int>(_mm256_fpclass_pd_mask(factors, 0x01 | 0x02 | 0x04 | 0x08 | 0x10 | 0x40 | 0x80));
#else
  const int usable_factors =
      _mm256_movemask_pd(_mm256_and_pd(_mm256_cmp_pd(factors, _mm256_setzero_pd(), _CMP_GT_OQ),
                                       _mm256_cmp_pd(factors, _mm256_set1_pd(std::numeric_limits<double>::max()), _CMP_LE_OQ)));
#endif
  const int normal = exp4_surely_normal_lanes(x);
  __m256i shifted_bits;
  const __m256d expm1 = exp4_expm1(x, shifted_bits);
  if (__builtin_expect((usable_factors & normal) == 0xf, 1)) {
    const __m256d values = exp4_normal(expm1, shifted_bits);
    const __m256d permuted = _mm256_permute4x64_pd(values, 0 | 2 << 2 | 3 << 4 | 1 << 6);  // X_0, X_1, X_3/2, X_1/2
    _mm256_storeu_pd(state, _mm256_mul_pd(permuted, factors));
    // lane 3 of permuted / values: X_1/2 / X_3/2 (both normal)
    const __m256d ratio = _mm256_mul_pd(_mm256_div_pd(permuted, values), _mm256_set1_pd(1.5));
    _mm_storeh_pd(state + 4, _mm256_extractf128_pd(ratio, 1));
    return true;
  }
  if (usable_factors != 0xf) return false;
  alignas(32) double logs[4], values[4];
  _mm256_store_pd(logs, x);
  _mm256_store_pd(values, exp4_any(x, expm1, shifted_bits));
  contact_state(logs, values, count_factor, area_factor, load_factor, stiffness_factor, state);
  return true;
}

}  // namespace
}  // namespace asperity::detail
