// contact4 and contact_products (kernels.hpp) for AVX2 + FMA, shared by the AVX2 and AVX-512
// builds (each compiles its own copy, the same bits): the four orders' quintics as one 4-lane
// vector of log2 X (the contact records' units, kernels.hpp) and exp_x86.hpp's exp4 in base 2:
// where all four results are surely normal (nearly every query), 2^k applied in one fused
// multiply-add; otherwise exp4_any, every lane (vscalefpd on AVX-512, masks on AVX2). exp4 needs
// no table: the 128-entry table of fast_exp took two gathers, which on AMD Zen 4 made
// contact_orders 1.5x one order (bench_lookup BM_ContactOrders against
// BM_ScalarKind/weibull_tail_a2; 1.2x with exp4).
#pragma once
#include "exp_x86.hpp"
#include "kernels.hpp"

namespace asperity::detail {
namespace {

// fast_quintic's Estrin scheme, one order a lane (the record is 64-byte aligned)
ASPERITY_ALWAYS_INLINE __m256d contact4_quintics(const double* __restrict record, double y) noexcept {
  __m256d at = _mm256_set1_pd(y);
  asm("" : "+x"(at));  // y^2 by one vector multiplication (the compiler's scalar one and broadcast: two operations)
  const __m256d at2 = _mm256_mul_pd(at, at);
  const __m256d low = _mm256_fmadd_pd(at, _mm256_load_pd(record + 4), _mm256_load_pd(record));
  const __m256d middle = _mm256_fmadd_pd(at, _mm256_load_pd(record + 12), _mm256_load_pd(record + 8));
  const __m256d high = _mm256_fmadd_pd(at, _mm256_load_pd(record + 20), _mm256_load_pd(record + 16));
  return _mm256_fmadd_pd(at2, _mm256_fmadd_pd(at2, high, middle), low);
}

void contact4_x86(const double* __restrict record, double y, double* __restrict log2s,
                  double* __restrict values) noexcept {
  const __m256d t = contact4_quintics(record, y);
  _mm256_storeu_pd(log2s, t);
  __m256i shifted_bits;
  const __m256d expm1 = exp4_expm1<BinaryExp>(t, shifted_bits);
  // the same exps as contact_products_x86's, in both regimes: the same bits
  if (__builtin_expect(exp4_surely_normal<BinaryExp>(t), 1))
    _mm256_storeu_pd(values, exp4_normal(expm1, shifted_bits));
  else
    _mm256_storeu_pd(values, exp4_any<BinaryExp>(t, expm1, shifted_bits));
}

// contact_scales_of's factors (contact_scales.hpp) as one vector, in the same order of
// operations (the same bits, test_kernels): (1, pi, 4/3, 2) N times (1, R sigma, sigma E*
// sqrt(R sigma), E* sqrt(R sigma)): a square root, three scalar products and two vector ones
// besides the vector's assembly, where the caller made eleven scalar operations and std::sqrt's
// errno test (bench_lookup BM_ContactAllFour 10.1 -> 9.3 ns with this alone, Zen 5, alternated
// builds; BM_ContactAllFourScales unchanged)
ASPERITY_ALWAYS_INLINE __m256d surface_factors_x86(double n, double radius, double scale, double modulus) noexcept {
  const double product = radius * scale;
  const double modulus_root = modulus * _mm_cvtsd_f64(_mm_sqrt_sd(_mm_set_sd(product), _mm_set_sd(product)));
  const __m256d numbers = _mm256_mul_pd(_mm256_loadu_pd(contact_multipliers), _mm256_set1_pd(n));
  return _mm256_mul_pd(numbers, _mm256_set_pd(modulus_root, scale * modulus_root, product, 1.0));
}

// fast_grid.hpp's ContactProducts: the position, then contact4_x86's exps, the lanes (0, 1/2, 1,
// 3/2) permuted to (0, 1, 3/2, 1/2) and multiplied in the register, one branch for the
// factors' test (each in (0, DBL_MAX]) and the exps' (all surely normal); where an exp is not,
// exp4_any and contact_state answer in the same call, without a second lookup.
// ContactInputs::surface: the four doubles are N, R, sigma_s, E* (contact_products_of_surface),
// the factors computed here. Measured and not kept (bench_lookup BM_ContactAllFourScales,
// Zen 5): every finite lane through vscalefpd and the ratio from the exps' parts (1.5 (m_1/2 /
// m_3/2) 2^(k_1/2 - k_3/2)), with no branch, 8.5 -> 9.1 ns; lanes in the state's order (no
// permutation), no faster; the load as X_1/2 (X_3/2 / X_1/2) with the ratio 1.5 / (X_3/2 /
// X_1/2), 8.4 -> 8.0 ns, but X_3/2 loses its digits where X_1/2 is subnormal and X_3/2 is not
// (the heavy tails, a <= 1). A subnormal operand costs a multiplication 2x its time on Zen 5.
template <ContactInputs inputs>
bool contact_products_x86(const FastGrid& grid, const double* __restrict contact_records, double separation,
                          double first, double second, double third, double fourth,
                          double* __restrict state) noexcept {
  FastPosition at;
  if (__builtin_expect(!fast_position(grid, separation, at), 0)) return false;
  const __m256d t = contact4_quintics(contact_records + at.interval * contact_record_size, at.y);
  const __m256d factors = inputs == ContactInputs::surface ? surface_factors_x86(first, second, third, fourth)
                                                           : _mm256_set_pd(fourth, third, second, first);
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
  const int normal = exp4_surely_normal_lanes<BinaryExp>(t);
  __m256i shifted_bits;
  const __m256d expm1 = exp4_expm1<BinaryExp>(t, shifted_bits);
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
  alignas(32) double log2s[4], values[4], factor[4];
  _mm256_store_pd(log2s, t);
  _mm256_store_pd(values, exp4_any<BinaryExp>(t, expm1, shifted_bits));
  _mm256_store_pd(factor, factors);
  contact_state(log2s, values, factor[0], factor[1], factor[2], factor[3], state);
  return true;
}

}  // namespace
}  // namespace asperity::detail
