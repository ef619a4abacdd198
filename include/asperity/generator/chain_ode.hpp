// The generator's core: the derivative chain of docs/model.md section 4 integrated as an ODE in
// each segment's variable u with Boost.odeint (Runge-Kutta-Fehlberg 7(8), error-controlled),
// always toward growing values (stable), for H = ln X - offset(u) of all six orders at once.
#pragma once
#include <vector>

#include "asperity/layout.hpp"
#include "asperity/generator/quadrature.hpp"

namespace asperity::generator {

struct ChainOptions {
  double tolerance = 1e-14;  // odeint absolute = relative tolerance on H (H error = relative error of X)
};

// Knot data [order][knot][3] = H, dH/du, d2H/du2 for the curve, in the layout's knot order.
std::vector<double> integrate_curve(const CurveId& curve, const std::vector<SegmentSpec>& layout,
                                    const ChainOptions& options);

}  // namespace asperity::generator
