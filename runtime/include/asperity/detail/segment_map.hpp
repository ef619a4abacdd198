// A layout's segments resolved for one curve (distribution, side, shape): each segment's kind
// (segment_kind.hpp) on its geometry. The generator fills the knots through these maps and the
// runtime interpolates through them; not installed (the public layout is layout.hpp's).
#pragma once
#include <vector>

#include "asperity/detail/segment_kind.hpp"
#include "asperity/integrals.hpp"
#include "asperity/layout.hpp"

namespace asperity::detail {

// Inline: what only the generator uses (s_of_u, the offset's derivatives) is compiled only into
// the generator.
struct SegmentMap : SegmentGeometry {
  // All the maps of a layout, in order (the reciprocal segment's anchor is the next
  // segment's lower end). Throws asperity::Error for a layout that does not tile the axis.
  // Exported (cmake/asperity.map): the generator resolves its layouts with it.
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

}  // namespace asperity::detail
