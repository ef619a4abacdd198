// The runtime's lookup grid: ln X_n(s) as a piecewise quintic on a grid that the bits of s
// index directly. A binade [2^e, 2^(e+1)) of |s| holds K = 2^k intervals uniform in s; the
// exponent field of s picks the binade (one table load), the mantissa the interval and the
// position in it. So a lookup is a few integer operations, two loads, one quintic and one exp:
// no log and no branch on the data. Knots are packed geometrically toward s = 0 (where the
// Weibull integrals have their power terms |s|^(n + a)) and K per binade follows the curve.
//
// The grid is built at load time from the table's own layout (compact_curve.hpp) by
// interpolating ln X at the six Chebyshev-Lobatto points of each interval (values only; the
// quintic is kept in the power basis of y = x - 1/2, x in [0, 1] the position in the
// interval), with K per binade doubled until the quintic reproduces the table at check points
// between the nodes (fast_grid.cpp). Where it does not reach (|s| below 2^-70, past the
// table's ends, NaN, infinities) the curve answers from the compact layout and the series.
#pragma once
#include <cstdint>
#include <cstring>

#include "asperity/detail/fast_math.hpp"

namespace asperity::detail {

// One binade of |s|, in one 64-bit word: 2^k intervals (k = log2_knots <= 16), the first at
// index `first` of the coefficients (partial binades at the grid's ends keep their numbering,
// so `first` may point before the allocated intervals: only the covered ones are read). The
// top 52 bits of the mantissa of s then give the interval (its top k bits) and the position in
// it (the rest): shifts and masks, no multiply, no conversion.
struct FastBinade {
  static constexpr std::int64_t first_bias = std::int64_t(1) << 40;  // first + bias >= 0 always
  std::uint64_t packed = 0;  // (first + first_bias) << 6 | k
  static FastBinade make(std::int64_t first, int log2_knots) {
    return {static_cast<std::uint64_t>(first + first_bias) << 6 | static_cast<std::uint64_t>(log2_knots)};
  }
  std::int64_t first() const { return static_cast<std::int64_t>(packed >> 6) - first_bias; }
  int log2_knots() const { return static_cast<int>(packed & 63); }
};

// The grid of one sign of s: |s| in [lower, upper]; the binade of biased exponent E is
// directory[offset + E]. directory[0] is no binade's: one interval, the first (`first` 0,
// k 0), which the batch passes give a query off the grid (entry 0: interval 0 whatever its
// mantissa, a valid record to read, no mask on the index).
struct FastSide {
  double lower = 1;   // lower > upper: this sign is not covered
  double upper = 0;
  std::int32_t offset = 0;
};

inline constexpr int fast_stride = 6;  // coefficients per interval (see bench: 48-byte records)

// A view, trivially copied: the directory's storage is its owner's (FastGridBuild, then
// CurveData). So a Curve holds the grid itself (curve_data.hpp's CurveLookup), and a lookup's
// first loads are from the Curve, not through its shared pointer.
struct FastGrid {
  FastSide sides[2];                          // [0]: s > 0, [1]: s < 0 (the sign bit)
  const FastBinade* directory = nullptr;
  std::int32_t intervals = 0;                 // per order (at most 2^17)
};

// contact_at's arithmetic on the grid (Curve::contact_products), as built for one instruction
// set: state[0..3] = the factors times X of order 0, 1, 3/2, 1/2 (count, area, load, stiffness)
// and state[4] = 1.5 X_1/2 / X_3/2, from one position and one 4-lane vector of contact records
// (curve_data.hpp); false, nothing written, off the grid or for a factor outside (0, DBL_MAX].
// The factors come in registers: a vector load of four doubles that the caller has just stored
// one or two at a time cannot be forwarded from those stores.
// The four doubles are the factors (count, area, load, stiffness: ContactInputs::factors) or
// the surface they come from (N, R, sigma_s, E*: ContactInputs::surface), whose factors the
// kernel computes as contact_scales does, in vector registers.
using ContactProducts = bool (*)(const FastGrid& grid, const double* contact_records, double separation,
                                 double first, double second, double third, double fourth, double* state) noexcept;
enum class ContactInputs { factors, surface };

// The kernel below is `static` like fast_math.hpp's functions: each instruction-set build of
// the batch kernel (runtime/core/kernel/) keeps its own copy.

// The position of s on the grid, or inside = false where the grid does not reach.
struct FastPosition {
  std::uint64_t interval;  // index of the interval (into one order's coefficients / fast_stride)
  double y;               // position in the interval, in [-1/2, 1/2]
};

static ASPERITY_ALWAYS_INLINE bool fast_position(const FastGrid& grid, double separation,
                                                 FastPosition& out) noexcept {
  std::uint64_t bits;
  std::memcpy(&bits, &separation, sizeof bits);
  const FastSide& side = grid.sides[bits >> 63];
  // |s| against the side's range as integers (the bits of non-negative doubles order as their
  // values; NaN and inf lie above every finite bound): no floating-point operation
  std::uint64_t lower_bits, upper_bits;
  std::memcpy(&lower_bits, &side.lower, sizeof lower_bits);
  std::memcpy(&upper_bits, &side.upper, sizeof upper_bits);
  const std::uint64_t magnitude_bits = bits & 0x7fffffffffffffffull;
  if (!(magnitude_bits >= lower_bits && magnitude_bits <= upper_bits)) return false;
  const std::uint64_t packed = grid.directory[side.offset + static_cast<std::int32_t>((bits >> 52) & 0x7ff)].packed;
  const std::uint64_t log2_knots = packed & 63, mantissa = bits & 0x000fffffffffffffull;
  const std::uint64_t cell = mantissa >> (52 - log2_knots);
  const std::uint64_t fraction_bits = ((mantissa << log2_knots) & 0x000fffffffffffffull) | 0x3ff0000000000000ull;
  double fraction;  // 1 + the position in the interval, in [1, 2)
  std::memcpy(&fraction, &fraction_bits, sizeof fraction);
  out.interval = (packed >> 6) - static_cast<std::uint64_t>(FastBinade::first_bias) + cell;
  out.y = fraction - 1.5;
  return true;
}

// The quintic of one interval at y (Estrin's scheme: three independent pairs, then y^2), the
// coefficients read by index from one base. The x86 batch kernel computes the same sums four
// queries a vector (runtime/core/kernel/batch_x86.hpp).
static ASPERITY_ALWAYS_INLINE double fast_quintic(const double* coefficients, std::uint64_t at, double y) noexcept {
  const double y2 = y * y;
  const double low = coefficients[at] + y * coefficients[at + 1];
  const double middle = coefficients[at + 2] + y * coefficients[at + 3];
  const double high = coefficients[at + 4] + y * coefficients[at + 5];
  return low + y2 * (middle + y2 * high);
}

}  // namespace asperity::detail
