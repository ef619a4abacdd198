#include "asperity/layout.hpp"
#include "asperity/detail/segment_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "asperity/error.hpp"

namespace asperity {

std::vector<SegmentSpec> default_layout(Distribution distribution, Side side) {
  // The Gaussian: one segment linear in s from -10 to the far tail's end (s^2/2 = 760), knots
  // 0.0425 apart (the spacing that gives 1e-14 near s = 0, where H varies most).
  if (distribution == Distribution::gaussian)
    return {{SegmentKind::reciprocal, 33, 0.0, 0.0},
            {SegmentKind::gaussian_linear, 1153, -10.0, 38.987177379235862}};
  // The tail past s = 0.1 in u = ln t, cut at s = t = 1 (for every shape): below, u spans
  // a ln 10 (46 at a = 20), where H barely moves; above, u spans ln 760 for every shape, knots
  // 0.017 apart. There the knots' second derivatives carry a rounding of ~t^2 eps (the chain's
  // X_(n-1)/X_n ratios cancel to O(1/t)), which the interpolant scales by h^2: knots as far
  // apart as one segment from s = 0.1 gave at a = 20 (0.082) left 3e-12 at t = 210 (issue #28).
  if (side == Side::tail)
    return {{SegmentKind::reciprocal, 129, 0.0, 0.0},
            {SegmentKind::log_distance, 97, -3.0, -0.1},
            {SegmentKind::graded_bare, 97, 0.0, -0.1},
            {SegmentKind::graded_bare, 97, 0.0, 0.1},
            {SegmentKind::log_exponent, 577, 0.1, 1.0},
            {SegmentKind::log_exponent, 385, 1.0, 760.0}};
  // Bounded: log_tau to tau = 100 (exp(-tau) negligible beyond), then 10 more units of distance.
  return {{SegmentKind::reciprocal, 129, 0.0, 0.0},
          {SegmentKind::bounded_far, 193, 100.0, 10.0},
          {SegmentKind::log_tau, 257, 0.05, 100.0}};
}

std::vector<SegmentSpec> scale_knot_density(const std::vector<SegmentSpec>& layout, double density) {
  if (!(density > 0) || !std::isfinite(density)) throw Error("knot density must be positive and finite");
  std::vector<SegmentSpec> scaled = layout;
  for (SegmentSpec& spec : scaled) {
    const double intervals = std::round(density * (spec.knots - 1));
    if (intervals > 1e6) throw Error("knot density too large");
    spec.knots = 1 + std::max(2, static_cast<int>(intervals));
  }
  return scaled;
}

const char* to_string(SegmentKind kind) noexcept {
  switch (kind) {
#define ASPERITY_KIND_NAME(number, name, Type, text) \
  case SegmentKind::name: return #name;
    ASPERITY_SEGMENT_KINDS(ASPERITY_KIND_NAME)
#undef ASPERITY_KIND_NAME
  }
  return "unknown";
}

namespace detail {

std::vector<SegmentMap> SegmentMap::resolve(const std::vector<SegmentSpec>& layout, Distribution distribution,
                                            Side side, double shape) {
  std::vector<SegmentMap> maps;
  for (const SegmentSpec& spec : layout) {
    if (!is_segment_kind(static_cast<int>(spec.kind))) throw Error("unknown segment kind");
    SegmentMap map;
    map.kind = spec.kind;
    map.distribution = distribution;
    map.side = side;
    map.shape = distribution == Distribution::gaussian ? 2.0 : shape;
    map.p0 = spec.p0;
    map.p1 = spec.p1;
    visit_segment_kind(spec.kind, [&](auto kind) { decltype(kind)::set_range(map); });
    maps.push_back(map);
  }
  for (std::size_t i = 0; i < maps.size(); ++i) {
    if (maps[i].kind == SegmentKind::gaussian_linear && distribution != Distribution::gaussian)
      throw Error("a gaussian_linear segment is for the Gaussian only");
    if (maps[i].kind == SegmentKind::reciprocal) {
      if (i + 1 >= maps.size() || !(maps[i + 1].s_lo < 0)) throw Error("a reciprocal segment must precede one at s < 0");
      maps[i].p0 = maps[i].s_hi = maps[i + 1].s_lo;
    }
    if (!(maps[i].u_hi > maps[i].u_lo)) throw Error("a layout segment is empty for this shape");
    if (i > 0 && std::fabs(maps[i].s_lo - maps[i - 1].s_hi) > 1e-12 * (1 + std::fabs(maps[i].s_lo)))
      throw Error("layout segments do not meet");
  }
  return maps;
}

}  // namespace detail
}  // namespace asperity
