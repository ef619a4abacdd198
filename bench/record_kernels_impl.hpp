// The bodies of record_kernels.hpp, included once per instruction-set build
// (record_kernels_<isa>.cpp). Internal linkage, like the runtime's kernels (fast_math.hpp).
#pragma once
#include <cmath>
#include <cstdint>

#include "record_kernels.hpp"

namespace asperity::bench {
namespace {
using namespace asperity::detail;

struct LibraryExp {
  static double exp(double x) noexcept { return __builtin_exp(x); }
};
struct InlineExp {  // one call at a time, as Curve::value
  static ASPERITY_ALWAYS_INLINE double exp(double x) noexcept { return fast_exp(x); }
};
struct LanesExp {  // the form for vectorized loops, as the runtime's AVX2 / AVX-512 kernels
  static ASPERITY_ALWAYS_INLINE double exp(double x) noexcept { return fast_exp_lanes(x); }
};

// Curve::value on the grid, out of line, with the stride as a parameter.
template <int stride, class Math>
__attribute__((noinline)) double scalar_lookup(const FastGrid& grid, const double* coefficients, double separation) {
  FastPosition at;
  if (!fast_position(grid, separation, at)) return __builtin_nan("");
  return Math::exp(fast_quintic(coefficients, at.interval * stride, at.y));
}

// The runtime's former fused batch loop (record_kernels.hpp), value output, with the stride as a parameter.
template <int stride, class Math>
__attribute__((noinline)) std::uint64_t run_block(const FastGrid& grid, const FastBinade* __restrict directory,
                                                  const double* __restrict coefficients,
                                                  const double* __restrict separations, double* __restrict out,
                                                  int count) noexcept {
  const std::uint64_t lower0_bits = bits_of(grid.sides[0].lower), upper0_bits = bits_of(grid.sides[0].upper);
  const std::uint64_t lower1_bits = bits_of(grid.sides[1].lower), upper1_bits = bits_of(grid.sides[1].upper);
  const std::uint64_t offset0 = static_cast<std::uint64_t>(grid.sides[0].offset);
  const std::uint64_t offset1 = static_cast<std::uint64_t>(grid.sides[1].offset);
  std::uint64_t outside = 0;
  for (int j = 0; j < count; ++j) {
    const double separation = separations[j];
    const std::uint64_t bits = bits_of(separation);
    const std::uint64_t negative = static_cast<std::uint64_t>(static_cast<std::int64_t>(bits) >> 63);
    const double magnitude = double_of(bits & 0x7fffffffffffffffull);
    const double lower = double_of((lower1_bits & negative) | (lower0_bits & ~negative));
    const double upper = double_of((upper1_bits & negative) | (upper0_bits & ~negative));
    const bool inside = (magnitude >= lower) & (magnitude <= upper);
    const std::uint64_t keep = 0 - static_cast<std::uint64_t>(inside);
    const std::uint64_t offset = (offset1 & negative) | (offset0 & ~negative);
    const std::uint64_t entry = (offset + ((bits >> 52) & 0x7ff)) & keep;
    const std::uint64_t packed = directory[entry].packed;
    const std::uint64_t log2_knots = packed & 63, mantissa = bits & 0x000fffffffffffffull;
    const std::uint64_t cell = mantissa >> (52 - log2_knots);
    const double fraction = double_of(((mantissa << log2_knots) & 0x000fffffffffffffull) | 0x3ff0000000000000ull);
    const std::uint64_t index = ((packed >> 6) - static_cast<std::uint64_t>(FastBinade::first_bias) + cell) & keep;
    const double log_value = fast_quintic(coefficients, index * stride, fraction - 1.5);
    out[j] = Math::exp(log_value);
    outside += inside ? 0 : 1;
  }
  return outside;
}

template <int stride, class Math>
std::uint64_t block_lookup(const FastGrid& grid, const double* coefficients, const double* separations, double* out,
                           int count) {
  return run_block<stride, Math>(grid, grid.directory, coefficients, separations, out, count);
}

// The generic build calls the inline exp one call at a time in the batch loop, the vector
// builds its masked form: as the runtime does (kernels_<isa>.cpp).
template <class BatchMath>
constexpr RecordKernels make_record_kernels() {
  return RecordKernels{scalar_lookup<6, LibraryExp>, scalar_lookup<6, InlineExp>, block_lookup<6, BatchMath>,
                       block_lookup<8, BatchMath>};
}

}  // namespace
}  // namespace asperity::bench
