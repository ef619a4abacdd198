// test_fast_math.cpp built as the AVX2 and AVX-512 kernels are (-mavx2 -mfma): fast_math.hpp's
// exp reduces its argument with one fused multiply-add there, so the same bounds are checked on
// that arithmetic too. Exits 77 (ctest: skipped) on a CPU without AVX2 and FMA.
#include <cstdio>
#include <cstdlib>

namespace {
const bool cpu_checked = [] {
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) {
    std::puts("this CPU has no AVX2 and FMA: test_fast_math_fma skipped");
    std::exit(77);
  }
  return true;
}();
}  // namespace

#include "test_fast_math.cpp"
