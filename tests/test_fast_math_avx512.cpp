// test_fast_math.cpp built as the AVX-512 kernels are (-mavx512f -mavx512dq -mavx512vl -mavx2
// -mfma): fast_math.hpp's exp applies 2^m by vscalefpd there, so the same bounds, the special
// values and the bit-for-bit agreement with fast_exp_lanes are checked on that arithmetic too.
// Exits 77 (ctest: skipped) on a CPU without AVX-512 F, DQ and VL.
#include <cstdio>
#include <cstdlib>

namespace {
const bool cpu_checked = [] {
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("avx512f") || !__builtin_cpu_supports("avx512dq") ||
      !__builtin_cpu_supports("avx512vl")) {
    std::puts("this CPU has no AVX-512 F, DQ and VL: test_fast_math_avx512 skipped");
    std::exit(77);
  }
  return true;
}();
}  // namespace

#include "test_fast_math.cpp"
