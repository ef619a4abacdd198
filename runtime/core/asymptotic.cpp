#include "asperity/asymptotic.hpp"

// ln Gamma by Boost.Math: std::lgamma writes the global signgam (a data race when curves are
// built on several threads at once).
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>

namespace asperity {

Series weibull_tail_series(double shape, double order) {
  // (t+w)^r - t^r = r t^(r-1) w B(w/t), B(x) = sum_k b_k x^k, b_k = C(r, k+1)/r; then
  // B^n = sum_k c_k x^k and J_n = e^-t (r t^(r-1))^n sum_k c_k Gamma(n+k+1) t^-k.
  const double r = 1 / shape;
  std::array<double, series_terms> b{}, c{};
  b[0] = 1;
  for (int k = 1; k < series_terms; ++k) b[k] = b[k - 1] * (r - k) / (k + 1);
  c[0] = 1;  // power of a series with b_0 = 1 (J.C.P. Miller's recurrence)
  for (int k = 1; k < series_terms; ++k) {
    double sum = 0;
    for (int j = 1; j <= k; ++j) sum += ((order + 1) * j - k) * b[j] * c[k - j];
    c[k] = sum / k;
  }
  Series series;
  series.log_constant = boost::math::lgamma(order + 1) + order * std::log(r);
  double rising = 1;  // (n+1)_k = Gamma(n+k+1)/Gamma(n+1)
  for (int k = 0; k < series_terms; ++k) {
    series.coefficient[k] = c[k] * rising;
    rising *= order + 1 + k;
  }
  return series;
}

Series gaussian_tail_series(double order) {
  // D_-nu(s) ~ s^-nu e^(-s^2/4) sum_k (-1)^k (nu)_2k / (k! 2^k s^2k), nu = n + 1.
  Series series;
  series.log_constant = boost::math::lgamma(order + 1);
  double term = 1;
  for (int k = 0; k < series_terms; ++k) {
    series.coefficient[k] = term;
    term *= -(order + 1 + 2 * k) * (order + 2 + 2 * k) / (2.0 * (k + 1));
  }
  return series;
}

Series bounded_contact_series(double shape, double order) {
  // K_n = sum_k (-1)^k/k! a B(n+1, a(k+1)) d^(n + a(k+1)).
  Series series;
  series.log_constant = 0;
  for (int k = 0; k < series_terms; ++k) {
    const double magnitude =
        std::exp(boost::math::lgamma(order + 1) + std::log(shape) + boost::math::lgamma(shape * (k + 1)) -
                 boost::math::lgamma(order + 1 + shape * (k + 1)) - boost::math::lgamma(k + 1.0));
    series.coefficient[k] = (k % 2 ? -magnitude : magnitude);
  }
  return series;
}

double sum_series(const Series& series, double variable) noexcept {
  double sum = 0;
  for (int k = series_terms - 1; k >= 0; --k) sum = sum * variable + series.coefficient[k];
  return sum;
}

double weibull_tail_log(const Series& series, double shape, double order, double separation) noexcept {
  const double log_s = std::log(separation), t = std::pow(separation, shape);  // one rounding in t
  return -t + order * (1 - shape) * log_s + series.log_constant + std::log(sum_series(series, 1 / t));
}

double gaussian_tail_log(const Series& series, double order, double separation) noexcept {
  return gaussian_log_density(separation) - (order + 1) * std::log(separation) +
         series.log_constant + std::log(sum_series(series, 1 / (separation * separation)));
}

double bounded_contact_log(const Series& series, double shape, double order, double separation) noexcept {
  const double log_d = std::log(-separation);
  return (order + shape) * log_d + std::log(sum_series(series, std::exp(shape * log_d)));
}

}  // namespace asperity
