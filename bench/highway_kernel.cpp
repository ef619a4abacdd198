// highway_kernel.hpp: compiled once per Highway target (foreach_target.h re-includes this file).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "highway_kernel.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "highway_kernel.hpp"

HWY_BEFORE_NAMESPACE();
namespace asperity::bench {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// One vector of queries: what run_block does for one query, lane by lane.
template <class D>
HWY_INLINE hn::Vec<D> lookup(D d, const detail::FastGrid& grid, const std::int64_t* HWY_RESTRICT directory,
                             const double* HWY_RESTRICT coefficients, hn::Vec<D> separation,
                             hn::Mask<D>& inside) {
  const hn::RebindToUnsigned<D> du;
  const hn::RebindToSigned<D> di;
  const auto bits = hn::BitCast(du, separation);
  const auto magnitude = hn::Abs(separation);
  // the sign bit picks the side's range and directory offset (-0 counts as negative, as in the
  // runtime). A mask from a comparison, not IfNegativeThenElse: Highway 1.0.3's SSSE3 target
  // uses the whole lane as the blend mask there, not its sign bit.
  const auto negative = hn::RebindMask(d, hn::Ne(hn::And(bits, hn::Set(du, 0x8000000000000000ull)), hn::Zero(du)));
  const auto lower = hn::IfThenElse(negative, hn::Set(d, grid.sides[1].lower), hn::Set(d, grid.sides[0].lower));
  const auto upper = hn::IfThenElse(negative, hn::Set(d, grid.sides[1].upper), hn::Set(d, grid.sides[0].upper));
  inside = hn::And(hn::Ge(magnitude, lower), hn::Le(magnitude, upper));
  const auto keep = hn::RebindMask(di, inside);
  const auto offset = hn::IfThenElse(hn::RebindMask(di, negative), hn::Set(di, grid.sides[1].offset),
                                     hn::Set(di, grid.sides[0].offset));
  const auto exponent = hn::BitCast(di, hn::And(hn::ShiftRight<52>(bits), hn::Set(du, 0x7ff)));
  // off the grid: directory entry 0 and interval 0, valid loads whose answers the caller replaces
  const auto entry = hn::IfThenElseZero(keep, hn::Add(offset, exponent));
  const auto packed = hn::BitCast(du, hn::GatherIndex(di, directory, entry));  // one 64-bit word an entry
  // as the runtime: log2 of the knots in the low 6 bits, the first interval (biased) above
  const auto log2_knots = hn::And(packed, hn::Set(du, 63));
  const auto mantissa = hn::And(bits, hn::Set(du, 0x000fffffffffffffull));
  const auto cell = hn::Shr(mantissa, hn::Sub(hn::Set(du, 52), log2_knots));
  const auto fraction = hn::BitCast(
      d, hn::Or(hn::And(hn::Shl(mantissa, log2_knots), hn::Set(du, 0x000fffffffffffffull)),
                hn::Set(du, 0x3ff0000000000000ull)));
  const auto interval = hn::IfThenElseZero(
      keep, hn::BitCast(di, hn::Add(hn::Sub(hn::ShiftRight<6>(packed),
                                            hn::Set(du, static_cast<std::uint64_t>(detail::FastBinade::first_bias))),
                                    cell)));
  const auto at = hn::Add(hn::ShiftLeft<2>(interval), hn::ShiftLeft<1>(interval));  // 6 doubles an interval
  const auto y = hn::Sub(fraction, hn::Set(d, 1.5));
  const auto y2 = hn::Mul(y, y);
  // Estrin, as detail::fast_quintic
  const auto low = hn::MulAdd(y, hn::GatherIndex(d, coefficients + 1, at), hn::GatherIndex(d, coefficients, at));
  const auto middle = hn::MulAdd(y, hn::GatherIndex(d, coefficients + 3, at), hn::GatherIndex(d, coefficients + 2, at));
  const auto high = hn::MulAdd(y, hn::GatherIndex(d, coefficients + 5, at), hn::GatherIndex(d, coefficients + 4, at));
  return hn::Exp(d, hn::MulAdd(y2, hn::MulAdd(y2, high, middle), low));
}

std::uint64_t HighwayBlock(const detail::FastGrid& grid, const double* HWY_RESTRICT coefficients,
                           const double* HWY_RESTRICT separations, double* HWY_RESTRICT out, int count) {
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  const std::int64_t* directory = reinterpret_cast<const std::int64_t*>(grid.directory);
  static_assert(sizeof(detail::FastBinade) == sizeof(std::int64_t), "a directory entry is one 64-bit word");
  std::uint64_t outside = 0;
  std::size_t j = 0;
  const std::size_t total = static_cast<std::size_t>(count);
  hn::Mask<decltype(d)> inside;
  for (; j + lanes <= total; j += lanes) {
    const auto value = lookup(d, grid, directory, coefficients, hn::LoadU(d, separations + j), inside);
    hn::StoreU(value, d, out + j);
    outside += lanes - hn::CountTrue(d, inside);
  }
  if (j < total) {  // the last partial vector, through a padded copy
    HWY_ALIGN double in[hn::MaxLanes(d)] = {};
    HWY_ALIGN double result[hn::MaxLanes(d)];
    const std::size_t rest = total - j;
    for (std::size_t k = 0; k < rest; ++k) in[k] = separations[j + k];
    hn::Store(lookup(d, grid, directory, coefficients, hn::Load(d, in), inside), d, result);
    for (std::size_t k = 0; k < rest; ++k) out[j + k] = result[k];
    outside += rest - hn::CountTrue(d, hn::And(inside, hn::FirstN(d, rest)));
  }
  return outside;
}

}  // namespace HWY_NAMESPACE
}  // namespace asperity::bench
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace asperity::bench {
HWY_EXPORT(HighwayBlock);

std::uint64_t highway_block_dispatched(const detail::FastGrid& grid, const double* coefficients,
                                       const double* separations, double* out, int count) {
  return HWY_DYNAMIC_DISPATCH(HighwayBlock)(grid, coefficients, separations, out, count);
}

const std::vector<HighwayTarget>& highway_targets() {
  static const std::vector<HighwayTarget> targets = [] {
    const std::int64_t supported = hwy::SupportedTargets();
    std::vector<HighwayTarget> out;
#if HWY_TARGETS & HWY_AVX3
    out.push_back({"avx3", (supported & HWY_AVX3) != 0, N_AVX3::HighwayBlock});
#endif
#if HWY_TARGETS & HWY_AVX2
    out.push_back({"avx2", (supported & HWY_AVX2) != 0, N_AVX2::HighwayBlock});
#endif
#if HWY_TARGETS & HWY_SSE4
    out.push_back({"sse4", (supported & HWY_SSE4) != 0, N_SSE4::HighwayBlock});
#endif
#if HWY_TARGETS & HWY_SSSE3
    out.push_back({"ssse3", (supported & HWY_SSSE3) != 0, N_SSSE3::HighwayBlock});
#endif
#if HWY_TARGETS & HWY_EMU128
    out.push_back({"emu128", (supported & HWY_EMU128) != 0, N_EMU128::HighwayBlock});
#endif
    return out;
  }();
  return targets;
}
}  // namespace asperity::bench
#endif  // HWY_ONCE
