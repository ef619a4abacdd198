// Series that answer beyond the tabulated range (docs/model.md section 5), and seed the generator.
//
//   Weibull far tail   ln J_n = -t + n ln(t^(1/a-1)/a) + ln Gamma(n+1) + ln sum_k e_k t^-k
//                      (Watson's lemma to all orders; t = s^a)
//   Gaussian far tail  ln F_n = ln phi(s) - (n+1) ln s + ln Gamma(n+1) + ln sum_k e_k s^-2k
//   Bounded, near      ln K_n = (n+a) ln d + ln sum_k e_k tau^k   (d = -s, tau = d^a; a
//   first contact      convergent series from expanding exp(-z^a))
//
// The tail series are asymptotic: used only where t >= 700 (or s^2/2 >= 700), where twelve
// terms are exact to rounding. The contact series converges for every tau but is used only for
// tau <= 0.05, where twelve terms leave less than 1e-20.
#pragma once
#include <array>

#include "asperity/integrals.hpp"

namespace asperity {

inline constexpr int series_terms = 12;

struct Series {
  double log_constant = 0;  // ln Gamma(n+1) (+ n ln(1/a) for the Weibull tail)
  std::array<double, series_terms> coefficient{};  // e_0 = 1 for the tail series
};

// order may be any real > -1 (the generator uses -1/2).
Series weibull_tail_series(double shape, double order);
Series gaussian_tail_series(double order);
Series bounded_contact_series(double shape, double order);

double sum_series(const Series& series, double variable) noexcept;  // sum_k e_k variable^k

// ln X_n by the series (valid only in the ranges above).
double weibull_tail_log(const Series& series, double shape, double order, double separation) noexcept;
double gaussian_tail_log(const Series& series, double order, double separation) noexcept;
double bounded_contact_log(const Series& series, double shape, double order, double separation) noexcept;

}  // namespace asperity
