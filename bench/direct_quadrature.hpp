// The baseline a user has without tables: X_n(s) by adaptive double-exponential quadrature of
// the defining integrals (docs/model.md, section 2) at tolerance 1e-14, the integrand written
// once for any shape, in double, with no scaling (not the generator's forms, tablegen/
// quadrature.cpp, which are built never to underflow):
//   tail      J_n(s) = int_{z > max(s,0)} (z - s)^n phi(z) dz      Boost exp_sinh on the half line
//   bounded   K_n(s) = int_0^{-s} (-s - z)^n phi(z) dz              Boost tanh_sinh on the interval
// (exp_sinh is for half-infinite ranges; the bounded integral is over a finite one), with the
// Weibull phi(z) = a z^(a-1) exp(-z^a) or the Gaussian phi(z) = exp(-z^2/2)/sqrt(2 pi).
// Where X is below ~1e-308 the answer underflows, as the naive user's would.
#pragma once
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

#include "asperity/integrals.hpp"

namespace asperity::bench {

class DirectQuadrature {
 public:
  static constexpr double tolerance = 1e-14;

  DirectQuadrature(Distribution distribution, Side side, double shape, int twice_order)
      : gaussian_(distribution == Distribution::gaussian), bounded_(side == Side::bounded), shape_(shape),
        order_(0.5 * twice_order) {}

  double density(double z) const {
    if (gaussian_) return std::exp(-0.5 * z * z) * 0.39894228040143267794;
    // z^(a-1) e^(-z^a) as one exp: the product of the two overflows to inf * 0 for large z
    const double log_power = shape_ == 1 ? 0.0 : (shape_ - 1) * std::log(z);
    return shape_ * std::exp(log_power - std::pow(z, shape_));
  }
  double power(double base) const { return order_ == 0 ? 1.0 : std::pow(base, order_); }
  // (z - s)^n phi(z), 0 where phi is: exp_sinh reaches abscissae where the power overflows
  double integrand(double interference, double z) const {
    const double weight = density(z);
    return weight == 0 ? 0.0 : power(interference) * weight;
  }

  // X_n(s)
  double operator()(double separation) const {
    if (bounded_) {
      if (!(separation < 0)) return 0;
      const double depth = -separation;
      // phi(z) is 0 in double beyond z^a = 745: the range stops there, or tanh_sinh, whose
      // points crowd the ends, can miss a narrow peak far inside (a = 20, depth 11: off by 55%)
      const double end = std::min(depth, std::pow(745.0, 1 / shape_));
      // the two-argument form gives the distance to the nearer end exactly (xc), so that
      // (depth - z) keeps its digits near z = depth
      return interval_.integrate(
          [this, depth, end](double z, double complement) {
            const double gap = complement > 0 && end == depth ? complement : depth - z;
            return integrand(gap, z);
          },
          0.0, end, tolerance);
    }
    // z = lower + x: the interference z - s = x + (lower - s) is exact where lower = s
    const double lower = gaussian_ ? separation : std::max(separation, 0.0);
    const double shift = lower - separation;
    return half_line_.integrate([this, lower, shift](double x) { return integrand(x + shift, lower + x); },
                                tolerance);
  }

 private:
  bool gaussian_, bounded_;
  double shape_, order_;
  // mutable: Boost 1.74 declares integrate() const but defines it without const
  mutable boost::math::quadrature::exp_sinh<double> half_line_;
  mutable boost::math::quadrature::tanh_sinh<double> interval_;
};

}  // namespace asperity::bench
