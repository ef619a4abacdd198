#include "asperity/generator/quadrature.hpp"

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <algorithm>
#include <cmath>
#include <exception>
#include <new>
#include <sstream>
#include <string>

#include "asperity/error.hpp"

namespace asperity::generator {
namespace {

constexpr double tolerance = 1e-14;
// Beyond this exponent exp(-y) is below 1e-26 of the integral: the bounded integrand stops.
constexpr double bounded_cutoff = 60;

boost::math::quadrature::exp_sinh<double>& half_line() {
  static thread_local boost::math::quadrature::exp_sinh<double> integrator;
  return integrator;
}
boost::math::quadrature::tanh_sinh<double>& finite() {
  static thread_local boost::math::quadrature::tanh_sinh<double> integrator;
  return integrator;
}

template <class F>
double integrate_half_line(F f, double from = 0) {
  if (from == 0) return half_line().integrate(f, tolerance);
  return half_line().integrate(f, from, std::numeric_limits<double>::infinity(), tolerance);
}

double power(double base, double exponent) { return exponent == 0 ? 1.0 : std::pow(base, exponent); }

// Weibull tail, s > 0, with y = z^a = t + x^2:  J_m = e^-t  int_0^inf 2x D(x^2)^m e^(-x^2) dx,
// D(w) = (t+w)^(1/a) - t^(1/a) = s expm1(log1p(w/t)/a). Everything is carried in logs of
// D/x^2 (which tends to s/(a t) as x -> 0), so the integrand 2 x^(1+2m) (D/x^2)^m stays
// finite for m = -1/2 and nothing overflows when t = s^a underflows (a = 20, s -> 0).
struct TailLift {
  double log_s, log_t, r;
  // ln(x^2/t) and log1p(x^2/t) without forming x^2/t.
  double log1p_ratio(double log_ratio) const {
    return log_ratio > 35 ? log_ratio + std::exp(-log_ratio) : std::log1p(std::exp(log_ratio));
  }
  // ln(D/x^2)
  double log_lift(double x) const {
    const double log_ratio = 2 * std::log(x) - log_t;
    if (log_ratio < -28) return log_s + std::log(r) - log_t + std::log1p(0.5 * (r - 1) * std::exp(log_ratio));
    return log_s + std::log(std::expm1(r * log1p_ratio(log_ratio))) - 2 * std::log(x);
  }
  // (t/s) dD/dt / x^2 = r expm1((r-1) log1p(x^2/t)) / x^2, as sign and log of magnitude.
  double log_rate(double x, double& sign) const {
    sign = r > 1 ? 1.0 : -1.0;
    const double log_ratio = 2 * std::log(x) - log_t;
    if (log_ratio < -28)
      return std::log(r) + std::log(std::fabs(r - 1)) - log_t + std::log1p(0.5 * (r - 2) * std::exp(log_ratio));
    return std::log(r) + std::log(std::fabs(std::expm1((r - 1) * log1p_ratio(log_ratio)))) - 2 * std::log(x);
  }
};

TailLift tail_lift(double shape, double separation) {
  const double log_s = std::log(separation);
  return {log_s, shape * log_s, 1 / shape};
}

double tail_positive_integral(double shape, double order, double separation) {
  const TailLift lift = tail_lift(shape, separation);
  auto integrand = [=](double x) {
    const double weight = std::exp(-x * x);
    if (weight == 0 || x <= 0) return 0.0;
    return 2 * std::exp((1 + 2 * order) * std::log(x) + order * lift.log_lift(x)) * weight;
  };
  return integrate_half_line(integrand);
}

// The bounded side with y = tau q (tau <= cutoff): K_m = d^(m+a) int_0^1 (1 - q^(1/a))^m e^(-tau q) dq.
// extra_power multiplies the integrand by q^extra_power (for the tau-derivative).
double bounded_unit_integral(double shape, double order, double tau, int extra_power) {
  const double r = 1 / shape;
  // Boost's two-argument form on [-1, 1]: complement is 1 - x near +1 and -1 - x near -1,
  // exact where x itself has lost the digits; q = (1 + x)/2.
  auto integrand = [=](double x, double complement) {
    double q, gap;
    if (x > 0.5) {
      const double distance_to_one = 0.5 * complement;
      q = 1 - distance_to_one;
      gap = -std::expm1(r * std::log1p(-distance_to_one));
    } else {
      q = x < -0.5 ? -0.5 * complement : 0.5 * (1 + x);
      gap = -std::expm1(r * std::log(q));
    }
    if (gap <= 0 || q <= 0) return 0.0;
    return power(gap, order) * std::exp(-tau * q) * (extra_power ? q : 1.0);
  };
  return 0.5 * finite().integrate(integrand, tolerance);
}

double bounded_far_integral(double shape, double order, double distance) {
  const double r = 1 / shape;
  auto integrand = [=](double y) {
    const double gap = distance - std::pow(y, r);
    if (gap <= 0) return 0.0;
    return power(gap, order) * std::exp(-y);
  };
  return finite().integrate(integrand, 0.0, bounded_cutoff, tolerance);
}

void require_finite(double value, const char* what) {
  if (!std::isfinite(value)) throw Error(std::string("quadrature failed: ") + what);
}

// A failure inside Boost.Math (or an allocation) while X_m(s) of a curve is integrated, as an
// Error naming the curve, the order and the separation. Called in a catch block.
[[noreturn]] void throw_quadrature_failure(const char* what, const CurveId& curve, double order, double separation) {
  std::string cause;
  try {
    throw;
  } catch (const std::bad_alloc&) {
    cause = "memory ran out";
  } catch (const std::exception& error) {
    cause = std::string("Boost.Math: ") + error.what();
  }
  std::ostringstream message;
  message << "quadrature failed: " << what << " of order " << order << " of the " << to_string(curve.distribution);
  if (curve.distribution == Distribution::weibull) message << " shape " << curve.shape;
  message << " " << to_string(curve.side) << " curve at separation s = " << separation << " (" << cause
          << "); the generator integrates Weibull shapes " << weibull_shape_min << " to " << weibull_shape_max
          << " and the Gaussian at |s| up to 1e6";
  throw Error(message.str());
}

double log_integral_unchecked(const CurveId& curve, double order, double separation);
double log_slope_minus_half_unchecked(const CurveId& curve, double separation);

}  // namespace

// Boost.Math's errors (and an allocation's) named by the curve and separation
double log_integral(const CurveId& curve, double order, double separation) {
  try {
    return log_integral_unchecked(curve, order, separation);
  } catch (const Error&) {
    throw;
  } catch (...) {
    throw_quadrature_failure("ln X", curve, order, separation);
  }
}

double log_slope_minus_half(const CurveId& curve, double separation) {
  try {
    return log_slope_minus_half_unchecked(curve, separation);
  } catch (const Error&) {
    throw;
  } catch (...) {
    throw_quadrature_failure("d ln X / ds", curve, -0.5, separation);
  }
}

namespace {
double log_integral_unchecked(const CurveId& curve, double order, double separation) {
  double result = 0;
  // On the tail side X_n(s) moves from X_n(0) by terms c s and c |s|^(n + a), n + a > 0: below
  // |s| = 1e-200 that is far below rounding, and the scaled integrands lose their scale there.
  if (curve.side == Side::tail && std::fabs(separation) < 1e-200 && order > -0.5) separation = 0;
  if (curve.distribution == Distribution::gaussian) {
    if (separation >= 0) {  // F = phi(s) int w^m e^(-s w - w^2/2) dw
      auto integrand = [=](double w) {
        const double weight = std::exp(-separation * w - 0.5 * w * w);
        return (weight == 0 || w <= 0) ? 0.0 : power(w, order) * weight;
      };
      result = gaussian_log_density(separation) + std::log(integrate_half_line(integrand));
    } else if (separation >= -40) {  // the density peaks inside: split at w = -s
      auto integrand = [=](double w) {
        const double weight = std::exp(gaussian_log_density(separation + w));
        return (weight == 0 || w <= 0) ? 0.0 : power(w, order) * weight;
      };
      result = std::log(finite().integrate(integrand, 0.0, -separation, tolerance) +
                        integrate_half_line(integrand, -separation));
    } else {  // deep: in the height z itself (w = z - s would be rounded to ulp(s)); below
              // z = -40 the density is under e^-800 of its peak, and so is (z - s)'s endpoint
      auto integrand = [=](double z) {
        const double weight = std::exp(gaussian_log_density(z));
        return weight == 0 ? 0.0 : power(z - separation, order) * weight;
      };
      result = std::log(finite().integrate(integrand, -40.0, 0.0, tolerance) + integrate_half_line(integrand, 0.0));
    }
  } else if (curve.side == Side::tail) {
    const double shape = curve.shape;
    if (separation > 0) {
      result = -std::pow(separation, shape) + std::log(tail_positive_integral(shape, order, separation));
    } else {  // every summit touches: int_0^inf (y^(1/a) + d)^m e^-y dy
      const double distance = -separation, r = 1 / shape;
      auto integrand = [=](double y) {
        const double weight = std::exp(-y);
        if (weight == 0 || y <= 0) return 0.0;
        return power(std::pow(y, r) + distance, order) * weight;
      };
      result = std::log(integrate_half_line(integrand));
    }
  } else {
    if (separation >= 0) return -std::numeric_limits<double>::infinity();
    const double distance = -separation, tau = std::pow(distance, curve.shape);
    if (tau <= bounded_cutoff)
      result = (order + curve.shape) * std::log(distance) +
               std::log(bounded_unit_integral(curve.shape, order, tau, 0));
    else
      result = std::log(bounded_far_integral(curve.shape, order, distance));
  }
  require_finite(result, "log_integral");
  return result;
}

double log_slope_minus_half_unchecked(const CurveId& curve, double separation) {
  constexpr double order = -0.5;
  double slope = 0;
  if (curve.distribution == Distribution::gaussian) {
    // dF/ds = -int w^m (s + w) phi(s + w) dw, same scaling as log_integral.
    if (separation >= 0) {
      auto base = [=](double w, int moment) {
        const double weight = std::exp(-separation * w - 0.5 * w * w);
        return (weight == 0 || w <= 0) ? 0.0 : power(w, order) * weight * (moment ? separation + w : 1.0);
      };
      slope = -integrate_half_line([&](double w) { return base(w, 1); }) /
              integrate_half_line([&](double w) { return base(w, 0); });
    } else if (separation >= -40) {
      auto base = [=](double w, int moment) {
        const double weight = std::exp(gaussian_log_density(separation + w));
        return (weight == 0 || w <= 0) ? 0.0 : power(w, order) * weight * (moment ? separation + w : 1.0);
      };
      auto whole = [&](int moment) {
        auto f = [&](double w) { return base(w, moment); };
        return finite().integrate(f, 0.0, -separation, tolerance) + integrate_half_line(f, -separation);
      };
      slope = -whole(1) / whole(0);
    } else {  // deep: in the height z (as in log_integral), -int (z - s)^m z phi(z) dz / int (z - s)^m phi(z) dz
      auto whole = [&](int moment) {
        auto f = [=](double z) {
          const double weight = std::exp(gaussian_log_density(z));
          return weight == 0 ? 0.0 : power(z - separation, order) * weight * (moment ? z : 1.0);
        };
        return finite().integrate(f, -40.0, 0.0, tolerance) + integrate_half_line(f, 0.0);
      };
      slope = -whole(1) / whole(0);
    }
  } else if (curve.side == Side::tail) {
    const double shape = curve.shape;
    if (separation > 0) {
      // ln J = -t + ln I(t), so d ln J/ds = (a t/s)(-1 + I_t/I), and (a t/s) I_t is a times the
      // integral of 2 m x^(1+2m) (D/x^2)^(m-1) (t/s) D_t/x^2 e^(-x^2).
      const TailLift lift = tail_lift(shape, separation);
      auto derivative = [=](double x) {
        const double weight = std::exp(-x * x);
        if (weight == 0 || x <= 0) return 0.0;
        double sign;
        const double log_rate = lift.log_rate(x, sign);
        return 2 * order * sign *
               std::exp((1 + 2 * order) * std::log(x) + (order - 1) * lift.log_lift(x) + log_rate) * weight;
      };
      slope = -shape * std::exp(lift.log_t - lift.log_s) +
              shape * integrate_half_line(derivative) / tail_positive_integral(shape, order, separation);
    } else {
      const double distance = -separation, r = 1 / shape;
      auto integrand = [=](double y, double extra) {
        const double weight = std::exp(-y);
        if (weight == 0 || y <= 0) return 0.0;
        return power(std::pow(y, r) + distance, order - extra) * weight;
      };
      slope = -order * integrate_half_line([&](double y) { return integrand(y, 1); }) /
              integrate_half_line([&](double y) { return integrand(y, 0); });
    }
  } else {
    const double shape = curve.shape, distance = -separation, tau = std::pow(distance, shape);
    if (tau <= bounded_cutoff) {
      const double ratio = -bounded_unit_integral(shape, order, tau, 1) / bounded_unit_integral(shape, order, tau, 0);
      slope = -((order + shape) / distance + ratio * shape * tau / distance);
    } else {
      const double r = 1 / shape;
      auto integrand = [=](double y, double extra) {
        const double gap = distance - std::pow(y, r);
        return gap <= 0 ? 0.0 : power(gap, order - extra) * std::exp(-y);
      };
      slope = -order * finite().integrate([&](double y) { return integrand(y, 1); }, 0.0, bounded_cutoff, tolerance) /
              finite().integrate([&](double y) { return integrand(y, 0); }, 0.0, bounded_cutoff, tolerance);
    }
  }
  require_finite(slope, "log_slope_minus_half");
  return slope;
}
}  // namespace

}  // namespace asperity::generator
