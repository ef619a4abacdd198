// The batch path's floor (issue 41, item 7): what Curve::value_batch must do at the least, each
// part timed alone in bench_lookup (BM_BatchFloor rows) over the batch's own count of doubles:
// - exp: e^x by the runtime's vector exp (exp_x86.hpp: exp4, exp8) and by glibc's libmvec
//   (_ZGVdN4v_exp, _ZGVeN8v_exp), for comparison;
// - quintic: the batch's polynomial, fast_quintic's Estrin scheme, coefficients in registers
//   (no interval to find, no coefficient to load);
// - quintic_exp: both in one pass, y -> quintic -> exp -> out: the arithmetic every query needs;
// - stream (bench_lookup itself: memcpy): the memory traffic, the separations in, the values out.
// Each is built with the runtime's flags for its instruction set (bench/CMakeLists.txt).
#pragma once

namespace asperity::bench {

struct BatchFloorKernels {
  void (*exp)(const double* x, double* out, int count);          // the runtime's vector exp
  void (*libmvec_exp)(const double* x, double* out, int count);  // glibc's
  // out[j] = the quintic with coefficients c[0..5] at y[j]
  void (*quintic)(const double* c, const double* y, double* out, int count);
  void (*quintic_exp)(const double* c, const double* y, double* out, int count);
};

// Null members where this binary has no such build (not x86-64, or another compiler). count: a
// multiple of 8.
extern const BatchFloorKernels batch_floor_avx2, batch_floor_avx512;

}  // namespace asperity::bench
