// The kernels, one build per instruction set (kernels_<isa>.cpp), and the choice among them
// (kernels_dispatch.cpp): the batch path, Curve::value's scalar lookup and contact_orders'
// four-lane one. Every batch query runs the same branch-free arithmetic on the fast grid
// (fast_grid.hpp): bits of s -> binade -> interval -> quintic -> exp, in three passes
// (block): written with AVX2 intrinsics for the x86 builds (batch_x86.hpp, four queries a
// step), plain C++ for the baseline (ScalarPasses: the compiler vectorizes the positions two
// queries a step, the rest runs one call at a time).
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>

#include "asperity/contact_scales.hpp"
#include "asperity/detail/contact_kernel.hpp"
#include "asperity/detail/contact_ratio.hpp"
#include "asperity/detail/curve_data.hpp"
#include "asperity/detail/fast_grid.hpp"
#include "asperity/instruction_set.hpp"

namespace asperity::detail {

inline constexpr int batch_block = 256;

// The contact records: asperity/detail/contact_kernel.hpp (their one definition).
// In base 2 the exp's reduction is an addition, two exact subtractions and a product by ln 2,
// instead of a multiply-add, a subtraction and two multiply-adds for ln 2 in two parts: 3
// cycles off the lookup's chain (faster in bench_lookup BM_ContactAllFourScales and
// BM_ContactAllFour, this alone), and 2^t = m 2^k
// with k an integer: the kernels multiply the factors into m and scale once (contact4_x86.hpp).
// Each coefficient is the grid's ln X one times log2 e, rounded once from long double: ~1e-16
// |ln X| more rounding than the grid's own quintic in double (against its exact value,
// test_kernels ContactRecordsAgainstTheExactQuintic: 3.1e-16 (1 + |ln X|) at most, 2.2e-16 for
// the ln X quintic).

// One interval's record from the grid's ln X coefficients of orders 0, 1/2, 1, 3/2
// (twice_order k: ln_orders[k] points at the interval's fast_stride coefficients)
inline void write_contact_record(const double* const ln_orders[4], double* record) noexcept {
  constexpr long double log2_e = 1.44269504088896340735992468100189214L;
  for (int j = 0; j < fast_stride; ++j)
    for (int lane = 0; lane < 4; ++lane)
      record[4 * j + lane] = static_cast<double>(log2_e * ln_orders[contact_lane_orders[lane]][j]);
}

// contact_orders' ln X from log2 X: ln 2 rounded to double, the product once
static ASPERITY_ALWAYS_INLINE void contact_logs_of(const double log2s[4], double logs[4]) noexcept {
  for (int k = 0; k < 4; ++k) logs[k] = ln_2 * log2s[k];
}

struct Kernels {
  // Curve::value (curve.hpp's CurveValueEntry), with fused multiply-adds where the set has them
  CurveValueEntry value;
  // The four contact orders (count, stiffness, area, load: twice_order 0..3) at position y of
  // one interval's contact record: log2s[k] = log2 X and values[k] = 2^log2s[k] (fast_exp2 in
  // the baseline build; on x86 one 4-lane vector, contact4_x86.hpp).
  void (*contact4)(const double* record, double y, double* log2s, double* values) noexcept;
  // Curve::contact_products (fast_grid.hpp's ContactProducts): contact4's exps, multiplied by
  // the factors in the registers (contact4, then the products from its values in memory, was
  // 2.2x one order, bench_lookup BM_ContactAllFour), from the factors (ContactInputs::factors)
  // or from the surface (contact_products_of_surface, ContactInputs::surface).
  ContactProducts contact_products;
  ContactProducts contact_products_of_surface;
  // the same as Curve's entry points (curve.hpp's CurveContactEntry): the lookup's grid and
  // records read from its storage
  CurveContactEntry contact_entry;
  CurveContactEntry contact_entry_of_surface;
  // out[j] = ln X or X for every query on the grid (count <= batch_block); returns how many
  // were not (|s| < 2^-70, past the grid, NaN, infinite) and their indices in `rest`.
  int (*block)(const FastGrid& grid, const double* order_coefficients, const double* separations, double* out,
               int count, bool log_output, int* rest) noexcept;
  // block's exp pass: out[j] = e^logs[j], j < count, logs readable up to the next multiple of
  // batch_pad (here so that tests/test_kernels.cpp checks it on every set)
  void (*exps)(const double* logs, double* out, int count) noexcept;
};

// What each instruction-set build instantiates: internal linkage (see fast_math.hpp).
namespace {
// The exp of one call at a time (scalar_value in every build, contact4 in the baseline one):
// fast_exp's branches, cheaper there than fast_exp_lanes' masks (bench_lookup BM_FastExp
// against BM_FastExpLanes)
struct ScalarMath {
  static ASPERITY_ALWAYS_INLINE double exp(double x) noexcept { return fast_exp(x); }
  static ASPERITY_ALWAYS_INLINE double exp2(double t) noexcept { return fast_exp2(t); }
};

template <class Math>
void contact4(const double* __restrict record, double y, double* __restrict log2s, double* __restrict values) noexcept {
  const double y2 = y * y;
  for (int lane = 0; lane < 4; ++lane) {  // the quintic of fast_quintic, one order a lane
    const double low = record[lane] + y * record[4 + lane];
    const double middle = record[8 + lane] + y * record[12 + lane];
    const double high = record[16 + lane] + y * record[20 + lane];
    const double log2_value = low + y2 * (middle + y2 * high);
    log2s[contact_lane_orders[lane]] = log2_value;
    values[contact_lane_orders[lane]] = Math::exp2(log2_value);
  }
}

// The factors the contact kernels multiply into X's mantissa (m in [0.7, 1.5]): in
// [2^-1000, 2^1000] m f is a normal double; others (still in (0, DBL_MAX]) multiply X itself
inline constexpr double contact_factor_min = 0x1p-1000, contact_factor_max = 0x1p+1000;

// factor X with X = 2^t, as the x86 kernels make it: where X is a normal double, the product
// rounded once; elsewhere (t finite, the factor in range) from 2^(t - k) and 2^k, so that the
// product is right where X alone underflows or overflows
static ASPERITY_ALWAYS_INLINE double contact_product(double factor, double t, double x) noexcept {
  if (__builtin_expect(x >= std::numeric_limits<double>::min() && x <= std::numeric_limits<double>::max(), 1))
    return factor * x;
  if (!(std::fabs(t) <= BinaryExp::exact_k_max && factor >= contact_factor_min && factor <= contact_factor_max))
    return factor * x;  // X = 0, inf or NaN, or an extreme factor
  const double k = std::nearbyint(t);
  return scaled_by_power_of_two(factor * fast_exp2(t - k), k);
}

// The baseline build's ContactProducts: contact4's values times the factors (contact_product),
// the ratio by contact_ratio_of_log2s
template <class Math, ContactInputs inputs>
bool contact_products(const FastGrid& grid, const double* __restrict contact_records, double separation,
                      double first, double second, double third, double fourth, double* __restrict state) noexcept {
  ContactScales scales{first, second, third, fourth};
  if (inputs == ContactInputs::surface) scales = contact_scales_of(first, second, third, fourth);
  const double factors[4] = {scales.count, scales.area, scales.load, scales.stiffness};
  for (int k = 0; k < 4; ++k)
    if (!(factors[k] > 0 && factors[k] <= std::numeric_limits<double>::max())) return false;
  FastPosition at;
  if (__builtin_expect(!fast_position(grid, separation, at), 0)) return false;
  double log2s[4], values[4];
  contact4<Math>(contact_records + at.interval * contact_record_size, at.y, log2s, values);
  for (int lane = 0; lane < 4; ++lane) {
    const int order = contact_lane_orders[lane];
    state[lane] = contact_product(factors[lane], log2s[order], values[order]);
  }
  state[4] = contact_ratio_of_log2s(log2s[1], log2s[3]);
  return true;
}

// A ContactProducts kernel as a Curve's entry point
template <ContactProducts products>
bool contact_entry(const CurveLookupStorage& storage, double separation, double first, double second, double third,
                   double fourth, double* state) noexcept {
  const CurveLookup& lookup = lookup_in(storage);
  return products(lookup.grid, lookup.contact_records, separation, first, second, third, fourth, state);
}

template <class Math>
double scalar_value(const CurveLookupStorage& storage, int twice_order, double separation) noexcept {
  if (__builtin_expect(!(static_cast<unsigned>(twice_order) < static_cast<unsigned>(order_count) &&
                         (storage.order_mask >> twice_order & 1u)), 0))
    return __builtin_nan("");
  const CurveLookup& lookup = lookup_in(storage);
  FastPosition at;
  if (__builtin_expect(!fast_position(lookup.grid, separation, at), 0))
    return lookup.value_outside(*lookup.data, twice_order, separation);
  return Math::exp(fast_quintic(lookup.order_coefficients[twice_order], at.interval * fast_stride, at.y));
}

// The batch path in three passes over a block of queries: where each query falls
// (Passes::positions), ln X there (Passes::quintics) and, for values, e^(ln X) (Passes::exps).
// Apart, each pass is a short chain of independent work, which the out-of-order core overlaps
// across queries; fused, one query's chain (a directory load, six coefficient loads, the
// quintic, the exp) outlasted the window (bench_lookup BM_Batch against
// BM_Record/batch_*/48B, the fused loop).
inline constexpr int batch_pad = 8;  // the passes run whole vectors: the arrays are padded to it

// The three passes one call at a time (the baseline build; the x86 builds: batch_x86.hpp).
struct ScalarPasses {
  // at[j]: the element offset of query j's record (0 off the grid: a valid record, the caller
  // answers those queries), y[j] its position in it; returns how many were off the grid.
  // Not inlined, and with restrict: the promise that the outputs do not overlap the directory
  // is what lets the compiler vectorize the loop (two queries a step in the baseline build).
  // Every value is 64 bits wide (doubles, and 64-bit integers from the bits of s by shifts and
  // masks, never by conversions), so that the loop vectorizes with one lane per query.
  __attribute__((noinline)) static std::uint64_t positions(const FastGrid& grid, const double* __restrict separations,
                                                           std::uint64_t* __restrict at, double* __restrict y,
                                                           int count) noexcept {
    const FastBinade* __restrict directory = grid.directory;
    const std::uint64_t lower0_bits = bits_of(grid.sides[0].lower), upper0_bits = bits_of(grid.sides[0].upper);
    const std::uint64_t lower1_bits = bits_of(grid.sides[1].lower), upper1_bits = bits_of(grid.sides[1].upper);
    const std::uint64_t offset0 = static_cast<std::uint64_t>(grid.sides[0].offset);
    const std::uint64_t offset1 = static_cast<std::uint64_t>(grid.sides[1].offset);
    const std::uint64_t first_bias = static_cast<std::uint64_t>(FastBinade::first_bias);
    std::uint64_t outside = 0;
    for (int j = 0; j < count; ++j) {
      const std::uint64_t bits = bits_of(separations[j]);
      // the sign's grid by bit masks (all ones for s < 0), not by selects on a bool
      const std::uint64_t negative = static_cast<std::uint64_t>(static_cast<std::int64_t>(bits) >> 63);
      const double magnitude = double_of(bits & 0x7fffffffffffffffull);
      const double lower = double_of((lower1_bits & negative) | (lower0_bits & ~negative));
      const double upper = double_of((upper1_bits & negative) | (upper0_bits & ~negative));
      const bool inside = (magnitude >= lower) & (magnitude <= upper);  // no branch: &, not &&
      // all ones on the grid, 0 off it: the directory entry is masked, not selected (a select would
      // become a conditional load, which does not vectorize)
      const std::uint64_t keep = 0 - static_cast<std::uint64_t>(inside);
      const std::uint64_t offset = (offset1 & negative) | (offset0 & ~negative);
      const std::uint64_t entry = (offset + ((bits >> 52) & 0x7ff)) & keep;
      const std::uint64_t packed = directory[entry].packed;
      const std::uint64_t log2_knots = packed & 63, mantissa = bits & 0x000fffffffffffffull;
      const std::uint64_t cell = mantissa >> (52 - log2_knots);
      const double fraction = double_of(((mantissa << log2_knots) & 0x000fffffffffffffull) | 0x3ff0000000000000ull);
      at[j] = ((packed >> 6) - first_bias + cell) * fast_stride;  // entry 0: interval 0
      y[j] = fraction - 1.5;
      outside += inside ? 0 : 1;
    }
    return outside;
  }
  // logs[j] = ln X at (at[j], y[j]), j < count
  static void quintics(const double* __restrict coefficients, const std::uint64_t* __restrict at,
                       const double* __restrict y, double* __restrict logs, int count) noexcept {
    for (int j = 0; j < count; ++j) logs[j] = fast_quintic(coefficients, at[j], y[j]);
  }
  // out[j] = e^logs[j], j < count
  static void exps(const double* logs, double* out, int count) noexcept {
    for (int j = 0; j < count; ++j) out[j] = fast_exp(logs[j]);
  }
};

template <class Passes>
int block(const FastGrid& grid, const double* coefficients, const double* separations, double* out, int count,
          bool log_output, int* rest) noexcept {
  alignas(64) std::uint64_t at[batch_block + batch_pad];
  alignas(64) double y[batch_block + batch_pad];
  alignas(64) double logs[batch_block + batch_pad];
  const std::uint64_t outside = Passes::positions(grid, separations, at, y, count);
  const int padded = (count + batch_pad - 1) / batch_pad * batch_pad;
  for (int j = count; j < padded; ++j) {
    at[j] = 0;
    y[j] = 0;
  }
  Passes::quintics(coefficients, at, y, logs, padded);
  if (log_output)
    for (int j = 0; j < count; ++j) out[j] = logs[j];
  else
    Passes::exps(logs, out, count);
  if (outside == 0) return 0;
  int found = 0;
  FastPosition unused;
  for (int j = 0; j < count; ++j)
    if (!fast_position(grid, separations[j], unused)) rest[found++] = j;
  return found;
}
}  // namespace

extern const Kernels generic_kernels;
#if ASPERITY_X86_KERNELS
extern const Kernels avx2_kernels;
extern const Kernels avx512_kernels;
#endif

// The kernels for `isa`; automatic, or a set this machine lacks, gives the best available.
const Kernels& kernels_for(InstructionSet isa) noexcept;

}  // namespace asperity::detail
