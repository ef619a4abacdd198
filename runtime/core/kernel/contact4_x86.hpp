// contact4 and contact_products (kernels.hpp) for AVX2 + FMA, shared by the AVX2 and AVX-512
// builds (each compiles its own copy, the same bits): a contact record's four quintics as one
// 4-lane vector of log2 X (orders 0, 1, 3/2, 1/2: kernels.hpp) and exp_x86.hpp's exp4 in base 2,
// X = m 2^k with m = 1 + (e^r - 1) and k an integer. contact_products multiplies the factors
// into m and applies 2^k once: no product ever takes a subnormal operand (on Zen 5 that costs a
// multiplication twice its time), and a subnormal result is rounded once. The AVX-512 build
// applies 2^k by vscalefpd, every regime at once, so the deep tails (~3% of random queries
// over a table's range) take no branch; the AVX2 build multiplies by 2^k made in the exponent
// field where every lane's X is surely normal, and answers the rest by the same arithmetic one
// lane at a time (std::ldexp), the same bits. exp4 needs no table: the 128-entry table of
// fast_exp took two gathers, which on AMD Zen 4 made contact_orders 1.5x one order (1.2x with
// exp4).
#pragma once
#include <cmath>

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

// the record's lanes (the served combination's orders, contact_lane_orders) in contact4's
// order (twice_order 0, 1, 2, 3): output k takes the lane whose order is k
constexpr int lane_of_order(int twice_order) noexcept {
  int lane = 0;
  while (contact_lane_orders[lane] != twice_order) ++lane;
  return lane;
}
constexpr int contact4_order_permutation = lane_of_order(0) | lane_of_order(1) << 2 | lane_of_order(2) << 4 |
                                           lane_of_order(3) << 6;
// The ratio is taken within the vector's upper half: the load in lane 2, its derivative's
// order (the stiffness) in lane 3
static_assert(contact_lane_orders[3] == contact_lane_orders[2] - 2, "the stiffness lane must follow the load lane");

void contact4_x86(const double* __restrict record, double y, double* __restrict log2s,
                  double* __restrict values) noexcept {
  const __m256d t = contact4_quintics(record, y);
  __m256i shifted_bits;
  const __m256d expm1 = exp4_expm1<BinaryExp>(t, shifted_bits);
#if defined(__AVX512VL__)
  const __m256d x = exp4_any<BinaryExp>(t, expm1, shifted_bits);  // vscalefpd where k is exact
#else
  const __m256d x = __builtin_expect(exp4_surely_normal<BinaryExp>(t), 1) ? exp4_normal(expm1, shifted_bits)
                                                                          : exp4_any<BinaryExp>(t, expm1, shifted_bits);
#endif
  _mm256_storeu_pd(log2s, _mm256_permute4x64_pd(t, contact4_order_permutation));
  _mm256_storeu_pd(values, _mm256_permute4x64_pd(x, contact4_order_permutation));
}

// contact_scales_of's factors (contact_scales.hpp) as one vector, in the same order of
// operations (the same bits, test_kernels): the served multipliers (1, pi, 4/3, 2) N times (1, R sigma, sigma E*
// sqrt(R sigma), E* sqrt(R sigma)): a square root, three scalar products and two vector ones
// besides the vector's assembly, where the caller made eleven scalar operations and std::sqrt's
// errno test (faster in bench_lookup's BM_ContactAllFour; BM_ContactAllFourScales unchanged)
ASPERITY_ALWAYS_INLINE __m256d surface_factors_x86(double n, double radius, double scale, double modulus) noexcept {
  const double product = radius * scale;
  const double modulus_root = modulus * std::sqrt(product);  // one vsqrtsd: the kernels build with -fno-math-errno
  const __m256d numbers = _mm256_mul_pd(_mm256_loadu_pd(contact_multipliers), _mm256_set1_pd(n));
  return _mm256_mul_pd(numbers, _mm256_set_pd(modulus_root, scale * modulus_root, product, 1.0));
}

// contact_products_x86 where a lane or a factor is outside the vector form's range: the same
// arithmetic one lane at a time (std::ldexp rounds once, as vscalefpd does), and for a lane whose
// log2 X is not finite or beyond 2^50, or an extreme factor, the factor times X itself. Its
// inputs in memory (a plain struct: vectors passed by value, or 32-byte aligned locals, made
// the caller realign its stack on every call)
struct ContactLanes {
  double t[4], expm1[4], shifted[4], factor[4];
};
__attribute__((noinline)) void contact_products_lanes_x86(const ContactLanes& in, double* __restrict state) noexcept {
  const __m256d t = _mm256_loadu_pd(in.t), expm1 = _mm256_loadu_pd(in.expm1);
  const __m256i shifted_bits = _mm256_castpd_si256(_mm256_loadu_pd(in.shifted));
  double mantissas[4], k[4], x[4];
  _mm256_storeu_pd(mantissas, _mm256_add_pd(_mm256_set1_pd(1.0), expm1));
  _mm256_storeu_pd(k, _mm256_sub_pd(_mm256_castsi256_pd(shifted_bits), _mm256_set1_pd(exp4_shifter)));
  _mm256_storeu_pd(x, exp4_any<BinaryExp>(t, expm1, shifted_bits));
  const auto exact = [&](int lane) { return std::fabs(in.t[lane]) <= BinaryExp::exact_k_max; };  // NaN: false
  for (int lane = 0; lane < 4; ++lane) {
    const double factor = in.factor[lane];
    const bool in_range = factor >= contact_factor_min && factor <= contact_factor_max;
    state[lane] = exact(lane) && in_range
                      ? scaled_by_power_of_two(mantissas[lane] * factor, k[lane])
                      : factor * x[lane];
  }
  state[4] = exact(3) && exact(2) ? contact_ratio_of_parts(mantissas[3], k[3], mantissas[2], k[2])
                                  : contact_ratio_of_log2s(in.t[3], in.t[2]);
}

// fast_grid.hpp's ContactProducts: the position, the four lanes' exps as m 2^k, the state's
// count, area, load and stiffness as (m f) 2^k, in the lanes' order, and the ratio 1.5 X_1/2 /
// X_3/2 as (1.5 (m_1/2 / m_3/2)) 2^(k_1/2 - k_3/2), from the vector's upper half (kernels.hpp's
// contact_ratio_of_parts). One branch, for the factors (in [2^-1000, 2^1000]) and the lanes:
// on AVX-512 any log2 X within 2^50 of 0 (vscalefpd); on AVX2 every X surely normal and
// |log2 (X_1/2 / X_3/2)| <= 1000 (2^k and 2^(k_1/2 - k_3/2) normal doubles, one rounding of
// each product, as vscalefpd). Elsewhere contact_products_lanes_x86, the same bits; false for a
// factor outside (0, DBL_MAX] or off the grid.
// ContactInputs::surface: the four doubles are N, R, sigma_s, E* (contact_products_of_surface),
// the factors computed here.
// Measured and not kept (bench_lookup BM_ContactAllFour, BM_ContactAllFourScales): the exps'
// values times the factors, one branch for every X surely normal, the rest out of line (the
// tails: a mispredicted branch, a second exp and products with subnormal operands): slower.
template <ContactInputs inputs>
bool contact_products_x86(const FastGrid& grid, const double* __restrict contact_records, double separation,
                          double first, double second, double third, double fourth,
                          double* __restrict state) noexcept {
  FastPosition at;
  if (__builtin_expect(!fast_position(grid, separation, at), 0)) return false;
  const __m256d t = contact4_quintics(contact_records + at.interval * contact_record_size, at.y);
  const __m256d factors = inputs == ContactInputs::surface ? surface_factors_x86(first, second, third, fourth)
                                                           : _mm256_set_pd(fourth, third, second, first);
  __m256i shifted_bits;
  const __m256d expm1 = exp4_expm1<BinaryExp>(t, shifted_bits);
  const __m256d mantissas = _mm256_add_pd(_mm256_set1_pd(1.0), expm1);
  // lane 3 against lane 2 in place (X_1/2 and X_3/2): the upper pair's first element in both
  const auto across = [](__m256d v) { return _mm256_permute_pd(v, 0b0000); };
  const __m256d ratio_mantissa =
      _mm256_mul_pd(_mm256_set1_pd(served_combination.load_order), _mm256_div_pd(mantissas, across(mantissas)));
#if defined(__AVX512VL__)
  const int in_range = _mm256_mask_cmp_pd_mask(_mm256_cmp_pd_mask(factors, _mm256_set1_pd(contact_factor_min), _CMP_GE_OQ),
                                               factors, _mm256_set1_pd(contact_factor_max), _CMP_LE_OQ);
  const __m256d magnitudes = _mm256_andnot_pd(_mm256_set1_pd(-0.0), t);
  const int exact = _mm256_cmp_pd_mask(magnitudes, _mm256_set1_pd(BinaryExp::exact_k_max), _CMP_LE_OQ);
  if (__builtin_expect((in_range & exact) == 0xf, 1)) {
    const __m256d k = _mm256_sub_pd(_mm256_castsi256_pd(shifted_bits), _mm256_set1_pd(exp4_shifter));
    _mm256_storeu_pd(state, _mm256_scalef_pd(_mm256_mul_pd(mantissas, factors), k));
    const __m256d ratio = _mm256_scalef_pd(ratio_mantissa, _mm256_sub_pd(k, across(k)));
    _mm_storeh_pd(state + 4, _mm256_extractf128_pd(ratio, 1));
    return true;
  }
  // a factor outside (0, DBL_MAX] (NaN, +-0, +-inf, negative): one vfpclasspd
  if (_mm256_fpclass_pd_mask(factors, 0x01 | 0x02 | 0x04 | 0x08 | 0x10 | 0x40 | 0x80) != 0) return false;
#else
  const int in_range = _mm256_movemask_pd(
      _mm256_and_pd(_mm256_cmp_pd(factors, _mm256_set1_pd(contact_factor_min), _CMP_GE_OQ),
                    _mm256_cmp_pd(factors, _mm256_set1_pd(contact_factor_max), _CMP_LE_OQ)));
  const __m256d ratio_log2 = _mm256_sub_pd(t, across(t));
  const int moderate_ratio = _mm256_movemask_pd(
      _mm256_cmp_pd(_mm256_andnot_pd(_mm256_set1_pd(-0.0), ratio_log2), _mm256_set1_pd(1000.0), _CMP_LE_OQ));
  if (__builtin_expect((in_range & exp4_surely_normal_lanes<BinaryExp>(t) & (moderate_ratio | 0x7)) == 0xf, 1)) {
    // 2^k and 2^(k_1/2 - k_3/2) made in the exponent field: normal doubles here
    const __m256i k_field = _mm256_slli_epi64(shifted_bits, 52);  // k + 1023, shifted
    _mm256_storeu_pd(state, _mm256_mul_pd(_mm256_mul_pd(mantissas, factors), _mm256_castsi256_pd(k_field)));
    const __m256i difference = _mm256_sub_epi64(shifted_bits, _mm256_castpd_si256(across(_mm256_castsi256_pd(shifted_bits))));
    const __m256d power = _mm256_castsi256_pd(_mm256_slli_epi64(_mm256_add_epi64(difference, _mm256_set1_epi64x(1023)), 52));
    _mm_storeh_pd(state + 4, _mm256_extractf128_pd(_mm256_mul_pd(ratio_mantissa, power), 1));
    return true;
  }
  const int usable = _mm256_movemask_pd(
      _mm256_and_pd(_mm256_cmp_pd(factors, _mm256_setzero_pd(), _CMP_GT_OQ),
                    _mm256_cmp_pd(factors, _mm256_set1_pd(std::numeric_limits<double>::max()), _CMP_LE_OQ)));
  if (usable != 0xf) return false;
#endif
  ContactLanes lanes;
  _mm256_storeu_pd(lanes.t, t);
  _mm256_storeu_pd(lanes.expm1, expm1);
  _mm256_storeu_pd(lanes.shifted, _mm256_castsi256_pd(shifted_bits));
  _mm256_storeu_pd(lanes.factor, factors);
  contact_products_lanes_x86(lanes, state);
  return true;
}

}  // namespace
}  // namespace asperity::detail
