// The rough-surface reference of contact_law_reference.hpp, compiled once.
#include "contact_law_reference.hpp"

#include <cmath>

#include <algorithm>
#include <limits>
#include <vector>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

namespace asperity::test {

double law_load_part(const ContactLaw& law, double omega, LoadPart part) {
  const AsperityResponse response = asperity_response(law, omega);
  if (part == LoadPart::net) return response.load;
  const bool adhesive = law.kind == ContactLawKind::dmt || law.kind == ContactLawKind::jkr ||
                        law.kind == ContactLawKind::maugis_dugdale;
  const double a = std::sqrt(response.area / M_PI);
  const double compressive = adhesive ? (4.0 / 3.0) * law.modulus * a * a * a / law.radius : response.load;
  return part == LoadPart::compressive ? compressive : compressive - response.load;
}

double summit_density_slope(const SummitHeights& h, double z) {
  if (h.distribution == Distribution::gaussian) return -z * std::exp(-0.5 * z * z) / std::sqrt(2 * M_PI);
  if (!(z > 0)) return 0;
  const double power = std::pow(z, h.shape), tail = std::exp(-power);
  if (tail == 0) return 0;
  const double density = h.shape * power / z * tail;
  return density * ((h.shape - 1) / z - h.shape * power / z);
}

double summit_density(const SummitHeights& h, double z) {
  if (h.distribution == Distribution::gaussian) return std::exp(-0.5 * z * z) / std::sqrt(2 * M_PI);
  if (!(z > 0)) return 0;
  const double power = std::pow(z, h.shape), tail = std::exp(-power);
  return tail == 0 ? 0 : h.shape * power / z * tail;
}

namespace detail {

// Integrates f(w, z) over a piece [w_a, w_b] (w_b may be +inf), both halves from their ends
// inward so that an end's distance is exact (a singularity of the law at a switch point, of the
// Weibull density at z = 0): z_a is z at w_a, dz/dw = orientation (+1 tail, -1 bounded).
template <class F>
double integrate_piece(const F& f, double w_a, double z_a, double w_b, double z_b, double orientation,
                       double tail_length) {
  static thread_local boost::math::quadrature::tanh_sinh<double> finite(15);
  static thread_local boost::math::quadrature::exp_sinh<double> half_line(12);
  const double tolerance = 1e-13;
  if (!(w_b > w_a)) return 0;
  if (std::isinf(w_b)) {
    // [w_a, w_a + L] from both ends, then the rest in units of the integrand's decay length L
    const double l = tail_length, mid_w = w_a + l, mid_z = z_a + orientation * l;
    return integrate_piece(f, w_a, z_a, mid_w, mid_z, orientation, l) +
           l * half_line.integrate([&](double x) { return f(mid_w + l * x, mid_z + orientation * l * x); }, tolerance);
  }
  const double half = 0.5 * (w_b - w_a);
  const double from_a = finite.integrate([&](double x) { return f(w_a + x, z_a + orientation * x); }, 0.0, half, tolerance);
  const double from_b = finite.integrate([&](double x) { return f(w_b - x, z_b - orientation * x); }, 0.0, half, tolerance);
  return from_a + from_b;
}

}  // namespace detail

RoughSurfaceValues law_integrals(const ContactLaw& law, const SummitHeights& heights, double s,
                                 ContactHistory history, bool load_only, LoadPart part) {
  const double sigma = heights.scale, inf = std::numeric_limits<double>::infinity();
  const bool tail = heights.side == Side::tail;
  const double orientation = tail ? 1 : -1;
  auto z_of = [&](double w) { return tail ? s + w : -s - w; };

  // the lowest w in contact, and whether the law makes contact there (a moving edge: its jump counts)
  double w_law = law.lowest_interference / sigma;
  if (!history.unloading) w_law = std::max(w_law, 0.0);
  double w_lo = w_law;
  bool law_edge = true;
  double w_hi = inf;
  if (history.unloading) {
    // touched at the deepest approach: tail z >= deepest (w >= deepest - s); bounded z <= -deepest
    // (bounded: -s0 - z >= 0 is z <= -s0, i.e. w = -s - z >= s0 - s: the same expression)
    const double w_touch = history.deepest_separation - s;
    if (w_touch > w_lo) w_lo = w_touch, law_edge = false;
  }
  if (heights.distribution == Distribution::weibull) {
    // support z >= 0: tail w >= -s; bounded w <= -s
    if (tail) {
      if (-s > w_lo) w_lo = -s, law_edge = false;
    } else {
      w_hi = -s;
    }
  }
  RoughSurfaceValues out;
  if (!(w_hi > w_lo)) return out;

  // the pieces: w_lo, the switch points inside, the density's peak (Gaussian z = 0), w_hi
  std::vector<double> cuts{w_lo};
  const SwitchPoints points = switch_points(law);
  for (int k = 0; k < points.count; ++k) {
    const double w = points.interference[k] / sigma;
    if (w > w_lo && w < w_hi) cuts.push_back(w);
  }
  if (heights.distribution == Distribution::gaussian && -s > w_lo && -s < w_hi) cuts.push_back(-s);
  // a cut one unit past the first contact: the bulk of the density
  if (w_lo + 1 < w_hi) cuts.push_back(w_lo + 1);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  cuts.push_back(w_hi);

  // the decay length of the density beyond the last cut (tail side only)
  double tail_length = 1;
  const double z_last = z_of(cuts[cuts.size() - 2]);
  if (std::isinf(w_hi) && z_last > 1) {
    tail_length = heights.distribution == Distribution::gaussian
                      ? 1 / z_last
                      : 1 / (heights.shape * std::pow(z_last, heights.shape - 1));
    tail_length = std::min(tail_length, 1.0);
  }

  auto integrate = [&](auto quantity, bool slope = false) {
    double total = 0;
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
      const double a = cuts[i], b = cuts[i + 1];
      const double za = (heights.distribution == Distribution::weibull && a == -s && tail) ? 0.0 : z_of(a);
      const double zb = std::isinf(b) ? inf : (heights.distribution == Distribution::weibull && b == -s && !tail) ? 0.0 : z_of(b);
      total += detail::integrate_piece(
          [&](double w, double z) {
            const double density = slope ? summit_density_slope(heights, z) : summit_density(heights, z);
            if (density == 0) return 0.0;
            return quantity(w) * density;
          },
          a, za, b, zb, orientation, tail_length);
    }
    return total;
  };
  out.load = integrate([&](double w) { return law_load_part(law, sigma * w, part); });
  if (load_only) return out;
  out.count = integrate([](double) { return 1.0; });
  out.area = integrate([&](double w) { return asperity_response(law, sigma * w).area; });
  // JKR's and MD's dP/domega are infinite where fixed grips lose contact (a vertical tangent,
  // ~ (omega - omega_min)^-1/2): where that is the edge, the stiffness by parts instead,
  // K = -(dz/ds / sigma) int P(sigma w) phi'(z) dw, the law's edge fixed in w (no jump terms)
  const bool singular_edge = law_edge && (law.kind == ContactLawKind::jkr || law.kind == ContactLawKind::maugis_dugdale) &&
                             (heights.distribution == Distribution::gaussian || heights.shape > 1);
  if (part != LoadPart::net) {
    // by parts: the edges fixed in w (first contact on approach) or where the density is 0
    const bool by_parts_exact = heights.distribution == Distribution::gaussian || heights.shape > 1;
    out.stiffness = by_parts_exact ? -orientation / sigma * integrate([&](double w) {
      return law_load_part(law, sigma * w, part);
    }, true) : std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  if (singular_edge) {
    out.stiffness = -orientation / sigma * integrate([&](double w) { return asperity_response(law, sigma * w).load; }, true);
    return out;
  }
  out.stiffness = integrate([&](double w) { return asperity_response(law, sigma * w).stiffness; });
  // the load's jumps at edges that move with s: first contact and the switch points
  auto jump_at = [&](double omega) {
    const double below = asperity_response(law, std::nextafter(omega, -inf)).load;
    const double above = asperity_response(law, std::nextafter(omega, inf)).load;
    return above - below;
  };
  if (law_edge) {
    const double omega = sigma * w_lo;
    const double first = asperity_response(law, omega == 0 && law.kind != ContactLawKind::dmt
                                                    ? std::nextafter(0.0, 1.0) : omega).load;
    out.stiffness += first * summit_density(heights, z_of(w_lo)) / sigma;
  }
  for (int k = 0; k < points.count; ++k) {
    const double w = points.interference[k] / sigma;
    if (w > w_lo && w < w_hi) out.stiffness += jump_at(points.interference[k]) * summit_density(heights, z_of(w)) / sigma;
  }
  return out;
}

double pull_off(const ContactLaw& law, const SummitHeights& heights, double s0) {
  const ContactHistory history{true, s0};
  auto tension = [&](double s) { return -law_integrals(law, heights, s, history, true).load; };
  double best_s = s0, best = tension(s0);
  const double step = 0.05, reach = 6 - law.lowest_interference / heights.scale;
  for (double s = s0 + step; s <= s0 + reach; s += step) {
    const double t = tension(s);
    if (t > best) best = t, best_s = s;
  }
  double a = std::max(s0, best_s - step), b = best_s + step;
  const double r = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 40; ++i) {
    const double c = b - r * (b - a), d = a + r * (b - a);
    if (tension(c) > tension(d)) b = d; else a = c;
  }
  return std::max(best, tension(0.5 * (a + b)));
}

}  // namespace asperity::test
