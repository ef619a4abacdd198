// (The integrators are non-const: Boost 1.74 defines integrate() without const.)
// Direct evaluation of the asperity integrals by double-exponential quadrature (Boost.Math),
// in scaled forms that never underflow: what seeds the ODE chain where it cannot close
// (X_-1/2 and its slope), fills the all-touching segment, and checks the finished table.
#pragma once
#include "asperity/integrals.hpp"

namespace asperity::generator {

struct CurveId {
  Distribution distribution;
  Side side;
  double shape;  // Weibull a; ignored for the Gaussian
};

// ln X_m(s) for any real order m >= -1/2 wherever X_m(s) > 0 (X_-1/2 is infinite at s = 0
// for a <= 1/2, and on the bounded side X = 0 for s >= 0).
double log_integral(const CurveId& curve, double order, double separation);

// d ln X_-1/2 / ds, which the chain cannot give (it would need X_-3/2).
double log_slope_minus_half(const CurveId& curve, double separation);

}  // namespace asperity::generator
