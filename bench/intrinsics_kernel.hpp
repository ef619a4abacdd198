// The batch loop written by hand in AVX-512 intrinsics, against the runtime's loop that the
// compiler vectorizes (runtime/core/kernel/kernels.hpp), for issue 14's question "the
// compiler's code or hand-written per-instruction-set code?". GCC 12 builds one of the
// runtime loop's six coefficient loads element by element instead of by gather; this loop
// gathers all six (masked: lanes off the grid load nothing), with fast_exp_lanes' arithmetic
// on mask registers. Same grid (grid_copy.hpp); bench_lookup --check compares the answers.
#pragma once
#include "record_kernels.hpp"

namespace asperity::bench {

// Null where this binary has no AVX-512 build (not x86-64, or another compiler).
extern const BlockLookup intrinsics_block_avx512;

}  // namespace asperity::bench
