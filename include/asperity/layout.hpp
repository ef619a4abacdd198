// The knot layout of a tabulated curve: the table format's geometry, shared by the
// generator (which fills the knots) and the runtime (which interpolates them).
//
// A curve covers the real separation axis with a few segments. Each segment has its own
// interpolation variable u, in which the knots are uniform (so a lookup is O(1)), and an
// analytic offset so that what is stored, H = ln X - offset(u), is smooth and O(1-100):
//
//   reciprocal   s <= s1 < 0, u = sqrt(s1 / s) in [0, 1]   offset n ln(-s)   (all touching;
//                s1 is where the next segment starts; u^2 ~ 1/d packs knots toward d = inf,
//                where heavy tails (a < 1) make H's derivatives grow like the moments)
//   linear       p0 <= s <= p1, u = s                      offset 0
//   graded       s = p0 + (p1 - p0) w^6, u = w in [0, 1]   offset -t on the Weibull tail
//                (w^ceil(2/a) for a < 1/3)
//                                                          for p0 = 0 < p1 (else 0)
//   log_exponent s >= p0 > 0, exponent t <= p1, u = ln t   offset -t      (far tail)
//   log_tau      tau = (-s)^a in [p0, p1], u = ln tau      offset (n + a) ln(-s)
//                                                                         (bounded side)
//   log_distance p0 <= s <= p1 < 0, u = ln(-s)              offset 0
//   bounded_far  -s = d in [d0, d0 + p1], d0 = p0^(1/a), d = d0 exp(L u^2), u in [0, 1],
//                L = ln((d0 + p1)/d0), offset 0 (bounded side beyond the bulk: starts where
//                log_tau ends, knots packed toward d0 where the bulk's edge is near)
//   gaussian_linear p0 <= s <= p1, u = s                   offset -s^2/2  (the Gaussian from
//                all-touching to the far tail in one segment: no log in the map, one exp)
// where t = s^a (Weibull) or s^2/2 (Gaussian). The graded segments cluster knots at s = 0,
// where the Weibull integrals have the power-law terms s^(n + a) of a density that is
// singular (a < 1) or flat (a > 1) at the origin.
#pragma once
#include <array>
#include <vector>

#include "asperity/model.hpp"

namespace asperity {

enum class SegmentKind : int {
  reciprocal = 0, linear = 1, graded = 2, log_exponent = 3, log_tau = 4, log_distance = 5,
  bounded_far = 6, gaussian_linear = 7
};
inline constexpr int segment_kind_count = 8;

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

// Map a segment to its variable for one curve (distribution, side, shape).
struct SegmentMap {
  SegmentKind kind;
  Distribution distribution;
  Side side;
  double shape;       // Weibull a (2 for the Gaussian, whose exponent is s^2/2)
  double p0, p1;
  double u_lo, u_hi;  // the u range the knots span
  double s_lo, s_hi;  // the separations the segment covers (may be infinite)
  double span = 0;    // bounded_far: L = ln(s_lo / s_hi), fixed when the map is made
  double power = 6;   // graded: s = p0 + (p1 - p0) u^power; 6, or ceil(2/a) for a < 1/3 so that
                      // the offset -s^a = -(p1 u^power)^a keeps a finite second derivative at u = 0
  bool exponent_offset;  // offset -t (tail side, s > 0)

  // All the maps of a layout, in order (the reciprocal segment's anchor is the next
  // segment's lower end). Throws asperity::Error for a layout that does not tile the axis.
  static std::vector<SegmentMap> resolve(const std::vector<SegmentSpec>& layout, Distribution distribution,
                                         Side side, double shape);
  double u_of_s(double separation) const;
  // s(u) with its first and second derivatives.
  void s_of_u(double u, double& separation, double& ds_du, double& d2s_du2) const;
  // offset(n, u) and its first two u-derivatives.
  void offset(double order, double u, double& value, double& d1, double& d2) const;
  double offset_value(double order, double u) const;
};

// The exponent t(s) of the far tail: s^a for the Weibull, s^2/2 for the Gaussian.
double tail_exponent(Distribution distribution, double shape, double separation);

}  // namespace asperity
