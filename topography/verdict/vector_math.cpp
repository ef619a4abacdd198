// vector_math.hpp: compiled once per Highway target (foreach_target.h re-includes this file).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "vector_math.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "vector_math.hpp"

HWY_BEFORE_NAMESPACE();
namespace asperity::topography::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// f over x[0, n): whole vectors, then the rest through a padded copy (its padding lanes hold 1,
// inside every function's range)
template <class F>
HWY_INLINE void apply(const double* HWY_RESTRICT x, double* HWY_RESTRICT out, std::size_t n, F f) {
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  std::size_t k = 0;
  for (; k + lanes <= n; k += lanes) hn::StoreU(f(d, hn::LoadU(d, x + k)), d, out + k);
  if (k < n) {
    HWY_ALIGN double in[hn::MaxLanes(d)];
    HWY_ALIGN double result[hn::MaxLanes(d)];
    const std::size_t rest = n - k;
    for (std::size_t j = 0; j < hn::MaxLanes(d); ++j) in[j] = j < rest ? x[k + j] : 1.0;
    hn::Store(f(d, hn::Load(d, in)), d, result);
    for (std::size_t j = 0; j < rest; ++j) out[k + j] = result[j];
  }
}

void VectorLog(const double* HWY_RESTRICT x, double* HWY_RESTRICT out, std::size_t n) {
  apply(x, out, n, [](auto d, auto v) { return hn::Log(d, v); });
}
void VectorExp(const double* HWY_RESTRICT x, double* HWY_RESTRICT out, std::size_t n) {
  apply(x, out, n, [](auto d, auto v) { return hn::Exp(d, v); });
}
void VectorExpm1(const double* HWY_RESTRICT x, double* HWY_RESTRICT out, std::size_t n) {
  apply(x, out, n, [](auto d, auto v) { return hn::Expm1(d, v); });
}

}  // namespace HWY_NAMESPACE
}  // namespace asperity::topography::detail
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace asperity::topography::detail {
HWY_EXPORT(VectorLog);
HWY_EXPORT(VectorExp);
HWY_EXPORT(VectorExpm1);

void vector_log(const double* x, double* out, std::size_t n) noexcept { HWY_DYNAMIC_DISPATCH(VectorLog)(x, out, n); }
void vector_exp(const double* x, double* out, std::size_t n) noexcept { HWY_DYNAMIC_DISPATCH(VectorExp)(x, out, n); }
void vector_expm1(const double* x, double* out, std::size_t n) noexcept {
  HWY_DYNAMIC_DISPATCH(VectorExpm1)(x, out, n);
}
}  // namespace asperity::topography::detail
#endif
