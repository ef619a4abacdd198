// The batch loop written with Highway (libhwy, Debian libhwy-dev 1.0.3) instead of the
// runtime's auto-vectorized C++ (runtime/core/kernel/kernels.hpp), for issue 14's question
// "Highway or the hand-written per-instruction-set code?": the same arithmetic (bits of s ->
// directory -> interval -> Estrin quintic -> exp), Highway's gathers and its own Exp
// (hwy/contrib/math), one build per Highway target chosen by Highway's dynamic dispatch. It
// reads the same grid as Curve (grid_copy.hpp); bench_lookup --check compares the answers.
#pragma once
#include <cstdint>
#include <vector>

#include "record_kernels.hpp"

namespace asperity::bench {

struct HighwayTarget {
  const char* name;   // Highway's target name, lower case (emu128, ssse3, sse4, avx2, avx3)
  bool available;     // this CPU runs it (hwy::SupportedTargets)
  BlockLookup block;  // the loop built for this target
};

// Every target this binary holds, best first.
const std::vector<HighwayTarget>& highway_targets();
// The loop through HWY_DYNAMIC_DISPATCH: the best target this CPU has, chosen on the first call.
std::uint64_t highway_block_dispatched(const detail::FastGrid& grid, const double* coefficients,
                                       const double* separations, double* out, int count);

}  // namespace asperity::bench
