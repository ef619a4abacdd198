// Independent references for the tests: the asperity integrals by double-exponential
// quadrature in 50-digit arithmetic (Boost.Multiprecision), straight from their definitions
// (docs/model.md section 2) in the height variable z, not in the generator's scaled forms.
#pragma once
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "asperity/model.hpp"

namespace asperity::test {

using Precise = boost::multiprecision::cpp_bin_float_50;

inline Precise precise_density(Distribution distribution, const Precise& shape, const Precise& height) {
  using boost::multiprecision::exp;
  using boost::multiprecision::pow;
  if (distribution == Distribution::gaussian) {
    const Precise tail = exp(-height * height / 2);
    return tail == 0 ? tail : tail / boost::math::constants::root_two_pi<Precise>();
  }
  if (height <= 0) return 0;
  const Precise tail = exp(-pow(height, shape));
  if (tail == 0) return 0;  // before pow(height, a - 1) can overflow
  return shape * pow(height, shape - 1) * tail;
}

// ln X_n(s) for dist/side/shape, n = order (any real > -1). -inf where X is exactly 0.
inline Precise reference_log(Distribution distribution, Side side, double shape_value, double order_value,
                             double separation_value) {
  using boost::multiprecision::log;
  using boost::multiprecision::pow;
  static thread_local boost::math::quadrature::exp_sinh<Precise> half_line;
  static thread_local boost::math::quadrature::tanh_sinh<Precise> finite;
  const Precise shape = shape_value, order = order_value, separation = separation_value;
  const Precise tolerance = 1e-26;
  // Integrals over [from, to] and [from, inf), shifted to start at 0: Boost 1.74's
  // double-exponential rules lose the endpoint distance when a lower limit is not small.
  auto over = [&](auto f, const Precise& from, const Precise& to) {
    return finite.integrate([&](const Precise& x) { return f(from + x); }, Precise(0), Precise(to - from), tolerance);
  };
  auto beyond = [&](auto f, const Precise& from) {
    return half_line.integrate([&](const Precise& x) { return f(from + x); }, tolerance);
  };
  const Precise inf = std::numeric_limits<Precise>::infinity();
  auto power = [&](const Precise& base) { return order == 0 ? Precise(1) : Precise(pow(base, order)); };
  Precise value;
  if (side == Side::bounded) {
    if (separation >= 0) return -inf;
    const Precise distance = -separation;
    auto integrand = [&](const Precise& z) {
      const Precise gap = distance - z;
      return gap <= 0 ? Precise(0) : power(gap) * precise_density(distribution, shape, z);
    };
    const Precise split = distance < 1 ? Precise(distance / 2) : Precise(1);  // near the density's bulk
    value = over(integrand, Precise(0), split) + over(integrand, split, distance);
  } else if (distribution == Distribution::weibull && separation < 0) {
    const Precise distance = -separation;
    auto integrand = [&](const Precise& z) {
      const Precise density = precise_density(distribution, shape, z);
      return density == 0 ? density : power(z + distance) * density;
    };
    value = over(integrand, Precise(0), Precise(1)) + beyond(integrand, Precise(1));
  } else {
    // int_0^inf w^n phi(s + w) dw in units of the integrand's own length L (w = L v):
    // 1/(a s^(a-1)) or 1/s beyond the bulk, 1 inside it; split at v = 1 (or at the Gaussian's peak).
    Precise scale = 1;
    if (separation > 0) {
      scale = distribution == Distribution::gaussian ? Precise(1 / separation)
                                                     : Precise(1 / (shape * pow(separation, shape - 1)));
      if (scale > 1) scale = 1;
    }
    auto integrand = [&](const Precise& v) {
      if (v <= 0) return Precise(0);
      const Precise density = precise_density(distribution, shape, separation + scale * v);
      return density == 0 ? density : power(v) * density;
    };
    Precise split = 1;
    if (distribution == Distribution::gaussian && separation < 0) split = -separation;
    value = (over(integrand, Precise(0), split) + beyond(integrand, split)) * pow(scale, order + 1);
  }
  return log(value);
}

}  // namespace asperity::test
