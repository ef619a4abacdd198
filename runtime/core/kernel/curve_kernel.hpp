// The lookup kernel: separation -> segment variable u -> quintic in the power basis -> ln X.
// One definition of the arithmetic for the scalar functions and for the batch loops, which are
// compiled once per instruction set (kernels_<isa>.cpp) and which the compiler vectorizes
// (exp and log included) 2, 4 or 8 queries at a time.
//
// The scalar functions are compiled once, for the baseline, in runtime/curve.cpp.
// Everything here is `static` (internal linkage): each instruction-set build keeps its own
// copy (see detail/fast_math.hpp). Separations are already known to be finite and inside the
// table (the callers send NaN, infinities and the series beyond the table to the cold path).
#pragma once
#include <cstddef>
#include <type_traits>

#include "asperity/detail/fast_math.hpp"
#include "asperity/detail/kernel_segment.hpp"

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace asperity::detail {

// The elementary functions, as a policy: the batch loops use the inline, vectorizable
// fast_exp / fast_log; the scalar path calls the C library's, which are faster one at a time
// (shorter latency: table-driven, and glibc picks FMA versions itself; measured in
// bench_lookup, BM_StdExp / BM_FastExp, and in the scalar lookup: 34 ns vs 43 ns).
// In an unnamed namespace, like everything else here that is code: internal linkage.
namespace {
struct FastMath {
  static ASPERITY_ALWAYS_INLINE double exp(double x) noexcept { return fast_exp(x); }
  static ASPERITY_ALWAYS_INLINE double log(double x) noexcept { return fast_log(x); }
};
struct LibraryMath {
  static double exp(double x) noexcept { return __builtin_exp(x); }
  static double log(double x) noexcept { return __builtin_log(x); }
};
}  // namespace

// ln X = base + per_order * n + H(u).
struct MappedSeparation {
  double u;
  double base;
  double per_order;
};

template <KernelKind kind, class Math>
static ASPERITY_ALWAYS_INLINE MappedSeparation map_separation(const KernelSegment& segment, double separation) noexcept {
  if constexpr (kind == KernelKind::reciprocal) {  // u = sqrt(s1 / s), offset n ln(-s)
    return {__builtin_sqrt(segment.p0 / separation), 0.0, Math::log(-separation)};
  } else if constexpr (kind == KernelKind::linear) {
    return {separation, 0.0, 0.0};
  } else if constexpr (kind == KernelKind::gaussian_linear) {  // u = s, offset -s^2/2: no log, no exp
    return {separation, -0.5 * separation * separation, 0.0};
  } else if constexpr (kind == KernelKind::graded || kind == KernelKind::graded_exponent) {
    // u = ((s - p0) / (p1 - p0))^(1/power); offset -s^a on the tail side past s = 0
    const double log_ratio = Math::log((separation - segment.p0) * segment.inv_range);
    const double u = Math::exp(log_ratio * segment.inv_power);
    if constexpr (kind == KernelKind::graded) return {u, 0.0, 0.0};
    else return {u, -Math::exp(segment.shape * log_ratio + segment.shape_log_p1), 0.0};
  } else if constexpr (kind == KernelKind::weibull_far) {  // u = ln t, t = s^a, offset -t
    const double u = segment.shape * Math::log(separation);
    return {u, -Math::exp(u), 0.0};
  } else if constexpr (kind == KernelKind::gaussian_far) {  // t = s^2 / 2
    const double exponent = 0.5 * separation * separation;
    return {Math::log(exponent), -exponent, 0.0};
  } else if constexpr (kind == KernelKind::log_tau) {  // u = ln tau = a ln(-s), offset (n + a) ln(-s)
    const double log_distance = Math::log(-separation);
    const double u = segment.shape * log_distance;
    return {u, u, log_distance};
  } else if constexpr (kind == KernelKind::log_distance) {
    return {Math::log(-separation), 0.0, 0.0};
  } else {  // bounded_far: d = d0 exp(L u^2); the ratio is >= 1 inside the segment
    const double log_ratio = Math::log(separation / segment.s_hi) * segment.inv_span;
    return {__builtin_sqrt(log_ratio > 0 ? log_ratio : 0.0), 0.0, 0.0};
  }
}

// H(u) from the interval's power-basis coefficients (6 per interval, order-major).
static ASPERITY_ALWAYS_INLINE double interpolate(const KernelSegment& segment, const double* order_coefficients, double u) noexcept {
  double position = (u - segment.u_lo) * segment.inv_step;
  position = position > 0 ? position : 0.0;  // also maps a NaN to the first knot
  const double cell = position < segment.last_interval ? position : segment.last_interval;
  const int interval = static_cast<int>(cell);
  const double x = position - interval;
  // indexed loads (not a pointer per query): the form the vectorizer turns into gathers
  const int at = (segment.first_interval + interval) * 6;
  const double* c = order_coefficients;
  // Estrin's scheme: three independent pairs, then two steps in x^2 (half Horner's latency)
  const double x2 = x * x;
  const double low = c[at] + x * c[at + 1], middle = c[at + 2] + x * c[at + 3], high = c[at + 4] + x * c[at + 5];
  return low + x2 * (middle + x2 * high);
}

template <KernelKind kind, class Math>
static ASPERITY_ALWAYS_INLINE double log_value_in(const KernelSegment& segment, const double* order_coefficients,
                                                  double order, double separation) noexcept {
  const MappedSeparation mapped = map_separation<kind, Math>(segment, separation);
  return mapped.base + mapped.per_order * order + interpolate(segment, order_coefficients, mapped.u);
}

// The one switch over the kinds: visit(KindTag<kind>{}) for a segment's kind, so that each
// kind's map is compiled on its own (no per-query branches inside it).
template <KernelKind kind>
using KindTag = std::integral_constant<KernelKind, kind>;

template <class Visit>
static ASPERITY_ALWAYS_INLINE auto with_kind(KernelKind kind, Visit&& visit) noexcept {
  switch (kind) {
    case KernelKind::reciprocal: return visit(KindTag<KernelKind::reciprocal>{});
    case KernelKind::linear: return visit(KindTag<KernelKind::linear>{});
    case KernelKind::graded: return visit(KindTag<KernelKind::graded>{});
    case KernelKind::graded_exponent: return visit(KindTag<KernelKind::graded_exponent>{});
    case KernelKind::weibull_far: return visit(KindTag<KernelKind::weibull_far>{});
    case KernelKind::gaussian_far: return visit(KindTag<KernelKind::gaussian_far>{});
    case KernelKind::log_tau: return visit(KindTag<KernelKind::log_tau>{});
    case KernelKind::log_distance: return visit(KindTag<KernelKind::log_distance>{});
    case KernelKind::bounded_far: return visit(KindTag<KernelKind::bounded_far>{});
    case KernelKind::gaussian_linear: return visit(KindTag<KernelKind::gaussian_linear>{});
  }
  return visit(KindTag<KernelKind::linear>{});  // not reached: every kind is listed
}

// The scalar lookup: ln X_n(s) for s inside the table (segment found by the caller).
template <class Math>
static ASPERITY_ALWAYS_INLINE double log_value_scalar(const KernelSegment& segment, const double* order_coefficients,
                                                     double order, double separation) noexcept {
  return with_kind(segment.kind, [&](auto kind) __attribute__((always_inline)) {
    return log_value_in<decltype(kind)::value, Math>(segment, order_coefficients, order, separation);
  });
}

// Several orders at one separation: one map, one Horner step per order.
// order_coefficients[k]: order k's coefficients, or null for an order the curve does not hold (NaN).
template <class Math>
static ASPERITY_ALWAYS_INLINE void log_values_scalar(const KernelSegment& segment,
                                                    const double* const* order_coefficients, double separation,
                                                    int first, int last, double* out) noexcept {
  const MappedSeparation mapped = with_kind(segment.kind, [&](auto kind) __attribute__((always_inline)) {
    return map_separation<decltype(kind)::value, Math>(segment, separation);
  });
  for (int k = first; k <= last; ++k)
    out[k - first] = order_coefficients[k] ? mapped.base + mapped.per_order * (0.5 * k) +
                                                 interpolate(segment, order_coefficients[k], mapped.u)
                                           : __builtin_nan("");
}

// ---- the batch path ----

struct KernelCurve {
  const KernelSegment* segments;
  int segment_count;
  const double* coefficients;  // the order's [interval][6]
};

// Queries are taken a block at a time: sorted by segment into compact arrays (one scalar
// pass), then each segment's queries run through one branch-free loop of that segment's map
// on contiguous data, which the compiler vectorizes (only the coefficient loads are gathers),
// and the results are scattered back.
inline constexpr int batch_block = 256;

struct BatchScratch {
  // 16 spare entries: the AVX-512 sort stores whole vectors past the last entry it keeps
  double separations[batch_block + 16];
  double results[batch_block];
  int indices[batch_block + 16];
};

// Not inlined, and with restrict: the promise that the results do not overlap the
// coefficients is what lets the compiler gather the coefficients in vectors.
template <KernelKind kind, bool log_output, class Math>
__attribute__((noinline)) static void run_segment(const KernelSegment& segment_in,
                                                  const double* __restrict order_coefficients, double order,
                                                  const double* __restrict separations, double* __restrict results,
                                                  int count) noexcept {
  // A local copy: the compiler can then keep the segment's constants in registers.
  const KernelSegment segment = segment_in;
  for (int m = 0; m < count; ++m) {
    const double log_value = log_value_in<kind, Math>(segment, order_coefficients, order, separations[m]);
    results[m] = log_output ? log_value : Math::exp(log_value);
  }
}

template <bool log_output, class Math>
static inline void run_segment_of_kind(const KernelSegment& segment, const double* order_coefficients, double order,
                                       const double* separations, double* results, int count) noexcept {
  with_kind(segment.kind, [&](auto kind) {
    run_segment<decltype(kind)::value, log_output, Math>(segment, order_coefficients, order, separations, results,
                                                        count);
  });
}

// One block (count <= batch_block). Writes ln X or X for every query inside the table and
// returns how many were not (NaN, infinite, beyond the table), their indices in `rest`.
template <class Math>
static inline int evaluate_block(const KernelCurve& curve, int twice_order, const double* separations, double* out,
                                 int count, bool log_output, int* rest) noexcept {
  constexpr double largest = 1.7976931348623157e308, inf = __builtin_inf();
  BatchScratch scratch[6];  // one per segment (at most six)
  int counts[6] = {0, 0, 0, 0, 0, 0};
  int rest_count = 0;
  const int last = curve.segment_count - 1;
  const double table_end = curve.segments[last].s_hi;
  // The segment of a separation is the number of segment ends below it: five compares with
  // the unused ends at +inf, no data-dependent branch (random separations would mispredict).
  double ends[5];
  for (int k = 0; k < 5; ++k) ends[k] = k < last ? curve.segments[k].s_hi : inf;
#if defined(__AVX512F__)
  // Sorting by segment with vector compress, 16 queries a step: a counting sort's
  // count[segment]++ would chain every query through a store and a reload.
  alignas(64) int segment_of[batch_block + 16];
  for (int j = 0; j < count; ++j) {
    const double separation = separations[j];
    const bool inside = separation <= table_end && separation >= -largest;
    const int segment = (separation > ends[0]) + (separation > ends[1]) + (separation > ends[2]) +
                        (separation > ends[3]) + (separation > ends[4]);
    segment_of[j] = inside ? segment : 6;
  }
  for (int j = count; j < batch_block + 16; ++j) segment_of[j] = 7;  // matches nothing
  const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  for (int segment = 0; segment <= last + 1; ++segment) {
    const bool is_rest = segment == last + 1;
    const __m512i wanted = _mm512_set1_epi32(is_rest ? 6 : segment);
    int* indices = is_rest ? rest : scratch[segment].indices;
    double* kept = scratch[is_rest ? 0 : segment].separations;
    int kept_count = 0;
    for (int j = 0; j < count; j += 16) {
      const __mmask16 match = _mm512_cmpeq_epi32_mask(_mm512_load_si512(segment_of + j), wanted);
      if (match == 0) continue;
      const int matched = __builtin_popcount(match);
      const __m512i index = _mm512_maskz_compress_epi32(match, _mm512_add_epi32(lane, _mm512_set1_epi32(j)));
      if (is_rest) {  // rest has room for batch_block entries only: store exactly what matched
        _mm512_mask_compressstoreu_epi32(indices + kept_count, match, _mm512_add_epi32(lane, _mm512_set1_epi32(j)));
      } else {
        _mm512_storeu_si512(indices + kept_count, index);
        const __mmask8 low = static_cast<__mmask8>(match), high = static_cast<__mmask8>(match >> 8);
        const int remaining = count - j;  // load only what exists
        const __mmask8 load_low = remaining >= 8 ? 0xff : static_cast<__mmask8>((1u << remaining) - 1);
        const __mmask8 load_high =
            remaining >= 16 ? 0xff : remaining <= 8 ? 0 : static_cast<__mmask8>((1u << (remaining - 8)) - 1);
        const __m512d first = _mm512_maskz_compress_pd(low, _mm512_maskz_loadu_pd(load_low, separations + j));
        const __m512d second = _mm512_maskz_compress_pd(high, _mm512_maskz_loadu_pd(load_high, separations + j + 8));
        _mm512_storeu_pd(kept + kept_count, first);
        _mm512_storeu_pd(kept + kept_count + __builtin_popcount(low), second);
      }
      kept_count += matched;
    }
    if (is_rest) rest_count = kept_count;
    else counts[segment] = kept_count;
  }
#else
  for (int j = 0; j < count; ++j) {
    const double separation = separations[j];
    if (!(separation <= table_end && separation >= -largest)) {
      rest[rest_count++] = j;
      continue;
    }
    const int segment = (separation > ends[0]) + (separation > ends[1]) + (separation > ends[2]) +
                        (separation > ends[3]) + (separation > ends[4]);
    BatchScratch& bucket = scratch[segment];
    bucket.separations[counts[segment]] = separation;
    bucket.indices[counts[segment]++] = j;
  }
#endif
  const double* order_coefficients = curve.coefficients;
  const double order = 0.5 * twice_order;
  for (int segment = 0; segment <= last; ++segment) {
    BatchScratch& bucket = scratch[segment];
    const int segment_count = counts[segment];
    if (segment_count == 0) continue;
    if (log_output)
      run_segment_of_kind<true, Math>(curve.segments[segment], order_coefficients, order, bucket.separations,
                                bucket.results, segment_count);
    else
      run_segment_of_kind<false, Math>(curve.segments[segment], order_coefficients, order, bucket.separations,
                                 bucket.results, segment_count);
    for (int m = 0; m < segment_count; ++m) out[bucket.indices[m]] = bucket.results[m];
  }
  return rest_count;
}

}  // namespace asperity::detail
