#include "spacing_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlopt.hpp>

#include "vector_math.hpp"

namespace asperity::topography::detail {
namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
}  // namespace

double spacing_objective(const SpacingProblem& problem, const double p[3], double* gradient) {
  const std::vector<double>& y = *problem.y;
  const std::size_t n = y.size();
  const double gap = std::exp(p[0]), shape = std::exp(p[2]);
  const double log_scale = p[1];
  // The transcendental functions a vector at a time (vector_math.hpp), into the problem's
  // buffers: ln z, t = w^shape, then expm1 and ln of the steps between neighbours' t. A point
  // whose argument leaves the vector functions' range is recomputed with <cmath> below.
  problem.workspace.resize(4 * n);
  double* const log_z = problem.workspace.data();
  double* const t = log_z + n;
  double* const em1 = t + n;
  double* const log_em1 = em1 + n;
  constexpr double tiny = std::numeric_limits<double>::min();  // below: subnormal, <cmath>'s
  for (std::size_t k = 0; k < n; ++k) {
    const double z = y[k] + gap;
    if (!(z > 0)) return -inf;
    em1[k] = z;
  }
  vector_log(em1, log_z, n);
  for (std::size_t k = 0; k < n; ++k) {
    if (em1[k] < tiny) log_z[k] = std::log(em1[k]);
    em1[k] = shape * (log_z[k] - log_scale);  // ln t
  }
  vector_exp(em1, t, n);
  for (std::size_t k = 0; k < n; ++k) {
    if (!(std::fabs(em1[k]) < 700)) t[k] = std::exp(em1[k]);  // overflow, or a subnormal t
    const double step = t[k] - (k > 0 ? t[k - 1] : 0.0);
    log_em1[k] = step >= tiny && step < vector_exp_max ? step : 1.0;  // the others taken below
  }
  vector_expm1(log_em1, em1, n);
  vector_log(em1, log_em1, n);
  double sum = 0, g0 = 0, g1 = 0, g2 = 0;
  // t and its derivatives at the previous point (t_0 = 0)
  double t_previous = 0, d0_previous = 0, d1_previous = 0, d2_previous = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double z = y[k] + gap;
    const double log_w = log_z[k] - log_scale;
    const double tk = t[k];
    // dt/d(ln gap), dt/d(ln scale), dt/d(ln shape)
    const double d0 = shape * tk * gap / z, d1 = -shape * tk, d2 = shape * log_w * tk;
    const double step = tk - t_previous;
    if (step > 0) {
      // ln(e^-t_prev - e^-t) = -t + ln(e^step - 1): one expm1 and one log a point
      double e = em1[k], log_e = log_em1[k];
      if (!(step < vector_exp_max)) {
        e = std::numeric_limits<double>::infinity();
      } else if (step < tiny) {
        e = std::expm1(step);
        log_e = std::log(e);
      }
      sum += std::isfinite(e) ? -tk + log_e : -t_previous + std::log1p(-std::exp(-step));
      if (gradient) {
        const double r = std::isfinite(e) ? 1 / e : 0;
        g0 += -d0_previous + (d0 - d0_previous) * r;
        g1 += -d1_previous + (d1 - d1_previous) * r;
        g2 += -d2_previous + (d2 - d2_previous) * r;
      }
    } else {
      // a tie: ln(f(y) delta), f = (shape/scale) w^(shape-1) e^-t in standardized units
      sum += p[2] - log_scale + (shape - 1) * log_w - tk + problem.log_delta;
      if (gradient) {
        g0 += (shape - 1) * gap / z - d0;
        g1 += -shape - d1;
        g2 += 1 + shape * log_w - d2;
      }
    }
    t_previous = tk;
    d0_previous = d0;
    d1_previous = d1;
    d2_previous = d2;
  }
  sum -= t_previous;  // the last spacing, 1 - F(y_n) = e^-t_n
  const double scale_n = 1 / static_cast<double>(n + 1);
  if (gradient) {
    gradient[0] = (g0 - d0_previous) * scale_n;
    gradient[1] = (g1 - d1_previous) * scale_n;
    gradient[2] = (g2 - d2_previous) * scale_n;
  }
  return sum * scale_n;
}

namespace {
struct Search {
  const SpacingProblem* problem;
  int evaluations = 0;
};

double nlopt_objective(unsigned, const double* p, double* gradient, void* data) {
  auto* search = static_cast<Search*>(data);
  ++search->evaluations;
  const double value = spacing_objective(*search->problem, p, gradient);
  if (std::isfinite(value)) return value;
  if (gradient) gradient[0] = gradient[1] = gradient[2] = 0;
  return -1e300;
}
}  // namespace

SpacingMaximum maximize_spacing(const SpacingProblem& problem, const std::vector<std::vector<double>>& starts,
                                const double lower[3], const double upper[3], double xtol_rel) {
  Search search{&problem, 0};
  nlopt::opt optimizer(nlopt::LD_LBFGS, 3);
  optimizer.set_max_objective(nlopt_objective, &search);
  optimizer.set_lower_bounds({lower[0], lower[1], lower[2]});
  optimizer.set_upper_bounds({upper[0], upper[1], upper[2]});
  optimizer.set_xtol_rel(xtol_rel);
  optimizer.set_ftol_abs(1e-15);
  optimizer.set_maxeval(2000);
  SpacingMaximum best;
  best.objective = -inf;
  for (std::vector<double> point : starts) {
    for (int k = 0; k < 3; ++k) point[static_cast<std::size_t>(k)] = std::clamp(point[static_cast<std::size_t>(k)], lower[k], upper[k]);
    double value = -inf;
    try {
      optimizer.optimize(point, value);
    } catch (const std::exception&) {
      value = spacing_objective(problem, point.data(), nullptr);  // roundoff-limited: keep where it stopped
    }
    if (value > best.objective) {
      best.objective = value;
      std::copy(point.begin(), point.end(), best.p);
    }
  }
  best.evaluations = search.evaluations;
  return best;
}

}  // namespace asperity::topography::detail
