// batch_floor.hpp's kernels, compiled once per instruction set (batch_floor_avx2.cpp,
// batch_floor_avx512.cpp): Wide is the vector of that set, its exp the runtime's own.
#pragma once
#include "batch_floor.hpp"
#include "exp_x86.hpp"  // runtime/core/kernel: the runtime's vector exps

#if defined(__AVX512F__)
extern "C" __m512d _ZGVeN8v_exp(__m512d);  // glibc's libmvec (linked: bench/CMakeLists.txt)
#else
extern "C" __m256d _ZGVdN4v_exp(__m256d);
#endif

namespace asperity::bench {
namespace {
using namespace detail;

#if defined(__AVX512F__)
using Wide = __m512d;
constexpr int lanes = 8;
ASPERITY_ALWAYS_INLINE Wide load(const double* from) { return _mm512_loadu_pd(from); }
ASPERITY_ALWAYS_INLINE void store(double* to, Wide value) { _mm512_storeu_pd(to, value); }
ASPERITY_ALWAYS_INLINE Wide splat(double value) { return _mm512_set1_pd(value); }
ASPERITY_ALWAYS_INLINE Wide fmadd(Wide a, Wide b, Wide c) { return _mm512_fmadd_pd(a, b, c); }
ASPERITY_ALWAYS_INLINE Wide mul(Wide a, Wide b) { return _mm512_mul_pd(a, b); }
ASPERITY_ALWAYS_INLINE Wide runtime_exp(Wide x) { return exp8(x); }
ASPERITY_ALWAYS_INLINE Wide library_exp(Wide x) { return _ZGVeN8v_exp(x); }
#else
using Wide = __m256d;
constexpr int lanes = 4;
extern "C" __m256d _ZGVdN4v_exp(__m256d);
ASPERITY_ALWAYS_INLINE Wide load(const double* from) { return _mm256_loadu_pd(from); }
ASPERITY_ALWAYS_INLINE void store(double* to, Wide value) { _mm256_storeu_pd(to, value); }
ASPERITY_ALWAYS_INLINE Wide splat(double value) { return _mm256_set1_pd(value); }
ASPERITY_ALWAYS_INLINE Wide fmadd(Wide a, Wide b, Wide c) { return _mm256_fmadd_pd(a, b, c); }
ASPERITY_ALWAYS_INLINE Wide mul(Wide a, Wide b) { return _mm256_mul_pd(a, b); }
ASPERITY_ALWAYS_INLINE Wide runtime_exp(Wide x) { return exp4(x); }
ASPERITY_ALWAYS_INLINE Wide library_exp(Wide x) { return _ZGVdN4v_exp(x); }
#endif

void floor_exp(const double* x, double* out, int count) {
  for (int j = 0; j < count; j += lanes) store(out + j, runtime_exp(load(x + j)));
}
void floor_libmvec_exp(const double* x, double* out, int count) {
  for (int j = 0; j < count; j += lanes) store(out + j, library_exp(load(x + j)));
}
// fast_quintic's Estrin scheme (batch_x86.hpp's quintic_rows4), the six coefficients splatted
ASPERITY_ALWAYS_INLINE Wide quintic(const Wide c[6], Wide y) {
  const Wide y2 = mul(y, y);
  const Wide low = fmadd(y, c[1], c[0]), middle = fmadd(y, c[3], c[2]), high = fmadd(y, c[5], c[4]);
  return fmadd(y2, fmadd(y2, high, middle), low);
}
void floor_quintic(const double* c, const double* y, double* out, int count) {
  const Wide splats[6] = {splat(c[0]), splat(c[1]), splat(c[2]), splat(c[3]), splat(c[4]), splat(c[5])};
  for (int j = 0; j < count; j += lanes) store(out + j, quintic(splats, load(y + j)));
}
void floor_quintic_exp(const double* c, const double* y, double* out, int count) {
  const Wide splats[6] = {splat(c[0]), splat(c[1]), splat(c[2]), splat(c[3]), splat(c[4]), splat(c[5])};
  for (int j = 0; j < count; j += lanes) store(out + j, runtime_exp(quintic(splats, load(y + j))));
}
constexpr BatchFloorKernels floor_kernels{floor_exp, floor_libmvec_exp, floor_quintic, floor_quintic_exp};

}  // namespace
}  // namespace asperity::bench
