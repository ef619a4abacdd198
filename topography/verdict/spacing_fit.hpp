// The maximum product of spacings for a three-parameter Weibull (internal to the fits,
// distribution_fit.hpp): the objective with its exact gradient, maximized by NLopt's L-BFGS.
// The gradient is what makes the surrogate ensembles affordable: a warm refit takes tens of
// evaluations where the derivative-free search took hundreds.
//
// On standardized data y (ascending, y[0] = 0) with p = (ln gap, ln scale, ln shape), location
// -gap: t_i = ((y_i + gap)/scale)^shape and S = 1/(n+1) [sum_i ln D_i - t_n],
// D_i = e^-t_(i-1) - e^-t_i (t_0 = 0), ln D_i = -t_(i-1) + ln(-expm1(-(t_i - t_(i-1)))); a tie
// (y_i = y_(i-1)) counts ln(f(y_i) delta) instead (Cheng & Amin's remedy).
#pragma once
#include <vector>

namespace asperity::topography::detail {

struct SpacingProblem {
  const std::vector<double>* y = nullptr;  // ascending, y[0] = 0
  double log_delta = 0;                    // ln of the quantization step (ties)
  mutable std::vector<double> workspace;   // the objective's buffers (4 n), kept between calls
};

// S at p, and dS/dp into gradient (if not null); -inf where the data leave the support.
double spacing_objective(const SpacingProblem& problem, const double p[3], double* gradient);

struct SpacingMaximum {
  double p[3] = {0, 0, 0};
  double objective = 0;
  int evaluations = 0;
};

// From each start in turn (p = (ln gap, ln scale, ln shape)), within [lower, upper]; the best.
// xtol_rel: the relative change of p at which a search stops.
SpacingMaximum maximize_spacing(const SpacingProblem& problem, const std::vector<std::vector<double>>& starts,
                                const double lower[3], const double upper[3], double xtol_rel);

}  // namespace asperity::topography::detail
