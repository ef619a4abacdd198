// <immintrin.h> for the x86 code (the kernels, fast_math.hpp's AVX-512 form, the benchmarks'
// copies): GCC 12's AVX-512 headers initialize their placeholder operands from themselves,
// which -Wmaybe-uninitialized reports at every use (GCC bug 105593, fixed in GCC 13).
#pragma once
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
