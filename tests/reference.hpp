// Independent references for the tests: the asperity integrals by double-exponential
// quadrature in 50-digit arithmetic (Boost.Multiprecision), straight from their definitions
// (docs/model.md section 2) in the height variable z, not in the generator's scaled forms.
// Defined in reference.cpp, compiled once (the asperity_test_reference library): the 50-digit
// quadratures' instantiations cost a minute of compiling in each test that would include them.
#pragma once
#include <optional>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "asperity/integrals.hpp"

namespace asperity::test {

using Precise = boost::multiprecision::cpp_bin_float_50;

// The summit heights' density at z (the Gaussian's, or Weibull's of shape a on z > 0).
Precise precise_density(Distribution distribution, const Precise& shape, const Precise& height);

// precise_density remembered per thread for the last distribution and shape: the orders of one
// point, and the points of one curve, share most quadrature nodes (a double-exponential rule's
// nodes depend on the interval only), and a 50-digit pow and exp cost tens of microseconds.
// The same values, only not computed twice.
Precise remembered_density(Distribution distribution, const Precise& shape, const Precise& height);

// base^order for order = (twice order)/2 by multiplications and one sqrt (a pow costs much more).
Precise precise_power(const Precise& base, int twice_order);

// ln X_n(s) for dist/side/shape, n = order (any real > -1). -inf where X is exactly 0.
Precise reference_log(Distribution distribution, Side side, double shape_value, double order_value,
                      double separation_value);

// ln X_n(s) from closed forms and convergent series, where they hold: a second reference,
// independent of the quadrature above and far cheaper, for the points near first contact.
// - s = 0: the Weibull moments J_n(0) = Gamma(1 + n/a), the Gaussian's
//   F_n(0) = 2^((n-1)/2) Gamma((n+1)/2) / sqrt(2 pi); the bounded side is exactly 0 (-inf).
// - The Weibull tail's integer orders n = 0, 1, 2: for s <= 0 (d = -s) the moments of z + d,
//   J_0 = 1, J_1 = Gamma(1+1/a) + d, J_2 = Gamma(1+2/a) + 2 d Gamma(1+1/a) + d^2; for
//   s > 0 (t = s^a) J_0 = exp(-t) and J_1 = Gamma(1/a, t)/a (upper incomplete), which do not
//   cancel, and for 0 < s <= 1 J_2 = sum_k C(2,k) (-s)^(2-k) Gamma(1 + k/a, t).
// - The Weibull bounded side where tau = d^a <= 1, every order: exp(-z^a) as its power series,
//   term by term K_n(d) = a d^(n+a) sum_m (-tau)^m / m! B(n + 1, a (m + 1)); where tau > 1 the
//   orders 0 and 1: K_0 = 1 - exp(-tau), K_1 = d - gamma(1/a, tau)/a (lower incomplete).
// nullopt elsewhere.
std::optional<Precise> closed_form_log(Distribution distribution, Side side, double shape_value, int twice_order,
                                       double separation_value);

}  // namespace asperity::test
