#include "asperity/layout.hpp"

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
  if (side == Side::tail)
    return {{SegmentKind::reciprocal, 129, 0.0, 0.0},
            {SegmentKind::log_distance, 97, -3.0, -0.1},
            {SegmentKind::graded, 97, 0.0, -0.1},
            {SegmentKind::graded, 97, 0.0, 0.1},
            {SegmentKind::log_exponent, 641, 0.1, 760.0}};
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

double tail_exponent(Distribution distribution, double shape, double separation) {
  return distribution == Distribution::gaussian ? 0.5 * separation * separation
                                                : std::pow(separation, shape);
}

namespace {
SegmentMap make_map(const SegmentSpec& spec, Distribution distribution, Side side, double shape) {
  SegmentMap map{};
  map.kind = spec.kind;
  map.distribution = distribution;
  map.side = side;
  map.shape = distribution == Distribution::gaussian ? 2.0 : shape;
  map.p0 = spec.p0;
  map.p1 = spec.p1;
  const double inf = std::numeric_limits<double>::infinity();
  switch (spec.kind) {
    case SegmentKind::reciprocal:  // anchored by resolve()
      map.u_lo = 0; map.u_hi = 1; map.s_lo = -inf;
      break;
    case SegmentKind::linear:
      map.u_lo = spec.p0; map.u_hi = spec.p1; map.s_lo = spec.p0; map.s_hi = spec.p1;
      break;
    case SegmentKind::gaussian_linear:
      map.u_lo = spec.p0; map.u_hi = spec.p1; map.s_lo = spec.p0; map.s_hi = spec.p1;
      map.exponent_offset = true;
      break;
    case SegmentKind::graded:
      map.u_lo = 0; map.u_hi = 1;
      map.s_lo = std::fmin(spec.p0, spec.p1); map.s_hi = std::fmax(spec.p0, spec.p1);
      map.exponent_offset = distribution == Distribution::weibull && side == Side::tail &&
                            spec.p1 > 0 && spec.p0 == 0;
      if (distribution == Distribution::weibull) map.power = std::max(6.0, std::ceil(2 / shape - 1e-9));
      break;
    case SegmentKind::log_exponent:
      map.u_lo = std::log(tail_exponent(distribution, map.shape, spec.p0));
      map.u_hi = std::log(spec.p1);
      map.s_lo = spec.p0;
      map.s_hi = distribution == Distribution::gaussian ? std::sqrt(2 * spec.p1)
                                                        : std::pow(spec.p1, 1 / map.shape);
      map.exponent_offset = true;
      break;
    case SegmentKind::log_distance:
      map.u_lo = std::log(-spec.p1); map.u_hi = std::log(-spec.p0);
      map.s_lo = spec.p0; map.s_hi = spec.p1;
      break;
    case SegmentKind::log_tau:
      map.u_lo = std::log(spec.p0); map.u_hi = std::log(spec.p1);
      map.s_lo = -std::pow(spec.p1, 1 / map.shape); map.s_hi = -std::pow(spec.p0, 1 / map.shape);
      break;
    case SegmentKind::bounded_far: {
      const double start = std::pow(spec.p0, 1 / map.shape);
      map.u_lo = 0; map.u_hi = 1;
      map.s_lo = -(start + spec.p1); map.s_hi = -start;
      map.span = std::log(map.s_lo / map.s_hi);
      break;
    }
  }
  return map;
}
}  // namespace

std::vector<SegmentMap> SegmentMap::resolve(const std::vector<SegmentSpec>& layout, Distribution distribution,
                                            Side side, double shape) {
  std::vector<SegmentMap> maps;
  for (const SegmentSpec& spec : layout) maps.push_back(make_map(spec, distribution, side, shape));
  for (std::size_t i = 0; i < maps.size(); ++i) {
    if (static_cast<int>(maps[i].kind) < 0 || static_cast<int>(maps[i].kind) >= segment_kind_count)
      throw Error("unknown segment kind");
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

double SegmentMap::u_of_s(double separation) const {
  switch (kind) {
    case SegmentKind::reciprocal: return std::sqrt(p0 / separation);
    case SegmentKind::linear:
    case SegmentKind::gaussian_linear: return separation;
    case SegmentKind::graded:
      return power == 6 ? std::cbrt(std::sqrt((separation - p0) / (p1 - p0)))
                        : std::pow((separation - p0) / (p1 - p0), 1 / power);
    case SegmentKind::log_exponent:  // t by one pow: a ln s would amplify rounding by a ln s
      return std::log(tail_exponent(distribution, shape, separation));
    case SegmentKind::log_tau: return shape * std::log(-separation);
    case SegmentKind::log_distance: return std::log(-separation);
    case SegmentKind::bounded_far:
      return std::sqrt(std::log(separation / s_hi) / span);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

void SegmentMap::s_of_u(double u, double& separation, double& ds_du, double& d2s_du2) const {
  switch (kind) {
    case SegmentKind::reciprocal:  // s = p0 / u^2
      separation = p0 / (u * u); ds_du = -2 * p0 / (u * u * u); d2s_du2 = 6 * p0 / (u * u * u * u);
      return;
    case SegmentKind::linear:
    case SegmentKind::gaussian_linear:
      separation = u; ds_du = 1; d2s_du2 = 0;
      return;
    case SegmentKind::graded: {
      const double span = p1 - p0;
      if (power == 6) {
        const double u2 = u * u, u4 = u2 * u2;
        separation = p0 + span * u4 * u2; ds_du = 6 * span * u4 * u; d2s_du2 = 30 * span * u4;
      } else {
        separation = p0 + span * std::pow(u, power);
        ds_du = power * span * std::pow(u, power - 1);
        d2s_du2 = power * (power - 1) * span * std::pow(u, power - 2);
      }
      return;
    }
    case SegmentKind::log_exponent:
      if (distribution == Distribution::gaussian) {
        separation = std::sqrt(2 * std::exp(u)); ds_du = separation / 2; d2s_du2 = separation / 4;
      } else {
        separation = std::exp(u / shape); ds_du = separation / shape;
        d2s_du2 = separation / (shape * shape);
      }
      return;
    case SegmentKind::log_distance: {
      const double distance = std::exp(u);
      separation = -distance; ds_du = -distance; d2s_du2 = -distance;
      return;
    }
    case SegmentKind::bounded_far: {
      const double distance = -s_hi * std::exp(span * u * u);
      separation = -distance; ds_du = -distance * 2 * span * u;
      d2s_du2 = -distance * (2 * span + 4 * span * span * u * u);
      return;
    }
    case SegmentKind::log_tau: {
      const double distance = std::exp(u / shape);
      separation = -distance; ds_du = -distance / shape; d2s_du2 = -distance / (shape * shape);
      return;
    }
  }
}

void SegmentMap::offset(double order, double u, double& value, double& d1, double& d2) const {
  value = d1 = d2 = 0;
  switch (kind) {
    case SegmentKind::reciprocal:
      value = order * (std::log(-p0) - 2 * std::log(u)); d1 = -2 * order / u; d2 = 2 * order / (u * u);
      return;
    case SegmentKind::linear:
    case SegmentKind::log_distance:
    case SegmentKind::bounded_far: return;
    case SegmentKind::graded:
      if (exponent_offset) {  // t = (p1 w^power)^a
        const double exponent = power * shape, scale = std::pow(p1, shape);
        value = -scale * std::pow(u, exponent);
        d1 = -scale * exponent * std::pow(u, exponent - 1);
        d2 = exponent == 2 ? -scale * 2 : -scale * exponent * (exponent - 1) * std::pow(u, exponent - 2);
      }
      return;
    case SegmentKind::log_exponent:
      value = d1 = d2 = -std::exp(u);
      return;
    case SegmentKind::gaussian_linear:
      value = -0.5 * u * u; d1 = -u; d2 = -1;
      return;
    case SegmentKind::log_tau:
      value = (order + shape) / shape * u; d1 = (order + shape) / shape;
      return;
  }
}

double SegmentMap::offset_value(double order, double u) const {
  switch (kind) {
    case SegmentKind::reciprocal: return order * (std::log(-p0) - 2 * std::log(u));
    case SegmentKind::linear:
    case SegmentKind::log_distance:
    case SegmentKind::bounded_far: return 0;
    case SegmentKind::graded:
      if (!exponent_offset) return 0;
      return power == 6 ? -std::pow(p1 * u * u * u * u * u * u, shape) : -std::pow(p1 * std::pow(u, power), shape);
    case SegmentKind::log_exponent: return -std::exp(u);
    case SegmentKind::log_tau: return (order + shape) / shape * u;
    case SegmentKind::gaussian_linear: return -0.5 * u * u;
  }
  return 0;
}

}  // namespace asperity
