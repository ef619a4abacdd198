// The knot layout of a tabulated curve: the table format's geometry, shared by the
// generator (which fills the knots) and the runtime (which interpolates them).
//
// A curve covers the real separation axis with a few segments. Each segment has its own
// interpolation variable u, in which the knots are uniform, and an analytic offset so that
// what is stored, H = ln X - offset(n, u), is smooth and O(1-100). The kinds, their maps and
// offsets are defined once, in segment_kind.hpp.
#pragma once
#include <array>
#include <vector>

#include "asperity/integrals.hpp"
#include "asperity/segment_kind.hpp"

namespace asperity {

// A layout has 1 to max_segments segments (the loader refuses more).
inline constexpr int max_segments = 8;

struct SegmentSpec {
  SegmentKind kind;
  int knots;  // >= 2, uniform in u including both ends
  double p0;
  double p1;
};

// The default layouts (knot counts chosen by measurement, see docs/accuracy.md).
std::vector<SegmentSpec> default_layout(Distribution distribution, Side side);

// The same layout with every segment's knot count scaled by `density` (knots - 1 intervals
// become round(density * (knots - 1)), at least 2): a cheaper table for a stated error, or a
// denser one. Throws asperity::Error for a density that is not positive and finite.
std::vector<SegmentSpec> scale_knot_density(const std::vector<SegmentSpec>& layout, double density);

// A segment resolved for one curve (distribution, side, shape): its kind's functions
// (segment_kind.hpp) on its geometry. Inline: what only the generator uses (s_of_u, the
// offset's derivatives) is compiled only into the generator.
struct SegmentMap : SegmentGeometry {
  // All the maps of a layout, in order (the reciprocal segment's anchor is the next
  // segment's lower end). Throws asperity::Error for a layout that does not tile the axis.
  static std::vector<SegmentMap> resolve(const std::vector<SegmentSpec>& layout, Distribution distribution,
                                         Side side, double shape);
  double u_of_s(double separation) const {
    return visit_segment_kind(kind, [&](auto k) { return decltype(k)::u_of_s(*this, separation); });
  }
  // s(u) with its first and second derivatives.
  void s_of_u(double u, double& separation, double& ds_du, double& d2s_du2) const {
    visit_segment_kind(kind, [&](auto k) { decltype(k)::s_of_u(*this, u, separation, ds_du, d2s_du2); });
  }
  double separation_of_u(double u) const {
    double separation, d1, d2;
    s_of_u(u, separation, d1, d2);
    return separation;
  }
  // offset(n, u) and its first two u-derivatives.
  void offset(double order, double u, double& value, double& d1, double& d2) const {
    visit_segment_kind(kind, [&](auto k) { decltype(k)::offset(*this, order, u, value, d1, d2); });
  }
  double offset_value(double order, double u) const {
    double value, d1, d2;
    offset(order, u, value, d1, d2);
    return value;
  }
};

// The exponent t(s) of the far tail: s^a for the Weibull, s^2/2 for the Gaussian.
double tail_exponent(Distribution distribution, double shape, double separation);

}  // namespace asperity
