// The 50-digit references of reference.hpp, compiled once.
#include "reference.hpp"

#include <cmath>

#include <limits>
#include <map>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

namespace asperity::test {


using Precise = boost::multiprecision::cpp_bin_float_50;

Precise precise_density(Distribution distribution, const Precise& shape, const Precise& height) {
  using boost::multiprecision::exp;
  using boost::multiprecision::pow;
  if (distribution == Distribution::gaussian) {
    const Precise tail = exp(-height * height / 2);
    return tail == 0 ? tail : tail / boost::math::constants::root_two_pi<Precise>();
  }
  if (height <= 0) return 0;
  const Precise exponent = pow(height, shape);  // one pow: a z^(a-1) = a z^a / z
  const Precise tail = exp(-exponent);
  if (tail == 0) return 0;
  return shape * exponent / height * tail;
}

Precise remembered_density(Distribution distribution, const Precise& shape, const Precise& height) {
  struct Memory {
    Distribution distribution = Distribution::gaussian;
    Precise shape = -1;
    std::map<Precise, Precise> density;
  };
  static thread_local Memory memory;
  if (memory.distribution != distribution || memory.shape != shape || memory.density.size() > 200000) {
    memory.distribution = distribution;
    memory.shape = shape;
    memory.density.clear();
  }
  const auto found = memory.density.find(height);
  if (found != memory.density.end()) return found->second;
  const Precise value = precise_density(distribution, shape, height);
  memory.density.emplace(height, value);
  return value;
}

Precise precise_power(const Precise& base, int twice_order) {
  Precise result = twice_order % 2 ? Precise(boost::multiprecision::sqrt(base)) : Precise(1);
  for (int i = 0; i < twice_order / 2; ++i) result *= base;
  return result;
}

Precise reference_log(Distribution distribution, Side side, double shape_value, double order_value,
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
  const double twice_order = 2 * order_value;
  const bool half_integer = twice_order == std::floor(twice_order) && twice_order >= 0 && twice_order <= 64;
  auto power = [&](const Precise& base) {
    return half_integer ? precise_power(base, static_cast<int>(twice_order)) : Precise(pow(base, order));
  };
  Precise value;
  if (side == Side::bounded) {
    if (separation >= 0) return -inf;
    const Precise distance = -separation;
    auto integrand = [&](const Precise& z) {
      const Precise gap = distance - z;
      return gap <= 0 ? Precise(0) : power(gap) * remembered_density(distribution, shape, z);
    };
    const Precise split = distance < 1 ? Precise(distance / 2) : Precise(1);  // near the density's bulk
    value = over(integrand, Precise(0), split) + over(integrand, split, distance);
  } else if (distribution == Distribution::weibull && separation < 0) {
    const Precise distance = -separation;
    auto integrand = [&](const Precise& z) {
      const Precise density = remembered_density(distribution, shape, z);
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
      const Precise density = remembered_density(distribution, shape, separation + scale * v);
      return density == 0 ? density : power(v) * density;
    };
    Precise split = 1;
    if (distribution == Distribution::gaussian && separation < 0) split = -separation;
    value = (over(integrand, Precise(0), split) + beyond(integrand, split)) * pow(scale, order + 1);
  }
  return log(value);
}

std::optional<Precise> closed_form_log(Distribution distribution, Side side, double shape_value, int twice_order,
                                       double separation_value) {
  using boost::multiprecision::exp;
  using boost::multiprecision::log;
  using boost::multiprecision::pow;
  const Precise shape = shape_value, order = Precise(twice_order) / 2, separation = separation_value;
  const Precise inf = std::numeric_limits<Precise>::infinity();
  if (distribution == Distribution::gaussian) {
    if (side != Side::tail || separation != 0) return std::nullopt;
    return log(pow(Precise(2), (order - 1) / 2) * boost::math::tgamma((order + 1) / 2) /
               boost::math::constants::root_two_pi<Precise>());
  }
  if (side == Side::bounded) {
    if (separation >= 0) return -inf;
    const Precise distance = -separation, tau = pow(distance, shape);
    if (tau > 1) {
      if (twice_order == 0) return log(-boost::multiprecision::expm1(-tau));
      if (twice_order == 2) return log(distance - boost::math::tgamma_lower(1 / shape, tau) / shape);
      return std::nullopt;
    }
    Precise sum = 0, power = 1;  // power = (-tau)^m / m!
    for (int m = 0; m < 400; ++m) {
      const Precise term = power * boost::math::beta(order + 1, shape * (m + 1));
      sum += term;
      if (m > 0 && boost::multiprecision::abs(term) < sum * Precise(1e-60)) break;
      power *= -tau / (m + 1);
    }
    return log(shape * sum) + (order + shape) * log(distance);
  }
  if (separation == 0) return boost::math::lgamma(1 + order / shape);
  if (twice_order % 2 != 0) return std::nullopt;
  const int n = twice_order / 2;
  auto moment = [&](int k) { return boost::math::tgamma(1 + Precise(k) / shape); };
  if (separation < 0) {
    const Precise d = -separation;
    if (n == 0) return Precise(0);
    if (n == 1) return log(moment(1) + d);
    return log(moment(2) + 2 * d * moment(1) + d * d);
  }
  const Precise t = pow(separation, shape);
  if (n == 0) return -t;
  if (n == 1) return log(boost::math::tgamma(1 / shape, t) / shape);  // = Gamma(1 + 1/a, t) - s e^-t
  if (separation > 1) return std::nullopt;  // the sum cancels more and more beyond the bulk
  auto upper = [&](int k) { return k == 0 ? Precise(exp(-t)) : Precise(boost::math::tgamma(1 + Precise(k) / shape, t)); };
  return log(upper(2) - 2 * separation * upper(1) + separation * separation * upper(0));
}

}  // namespace asperity::test
