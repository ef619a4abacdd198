// How a contact law's rough-surface quantities are made of the tabulated dimensionless integrals
// X_n(s) = int (z - s)^n phi(z) dz (docs/model.md sections 3 and 7): the seam between a law's
// physics and the lookup kernels, which evaluate tabulated integrals and know no physics.
//
// A law whose asperity answers are power laws of the interference, q = c_q R^a E*^b omega^n_q,
// integrates over the summit heights to q(s) = c_q N R^a E*^b sigma_s^n_q X_n_q(s): it is a
// combination of orders, four (twice_order, multiplier) pairs in the state's order (count, area,
// load, stiffness). Hertz is the one such law (contact_law.hpp's hertz_law evaluates these very
// numbers); a law with dimensional parameters (CEB, KE, JG, ZMC, the adhesive ones) is not a
// combination of orders: its rough-surface integrals depend on its parameters and are tabulated
// per scene (docs/contact-laws.md).
//
// The load's order n gives the stiffness: dX_n/ds = -n X_{n-1}, so -(dP/ds)/P = n X_{n-1}/X_n
// and the stiffness multiplier is n times the load's (checked below at compile time).
#pragma once

namespace asperity {

struct LawCombination {
  int twice_order[4];     // count, area, load, stiffness: 2n of the X_n each is made of
  double multiplier[4];   // the number c_q of each
  double load_order;      // n of the load: the stiffness/load ratio is load_order X_{n-1} / X_n
};

// Hertz: count N X_0, area pi N R sigma X_1, load (4/3) N E* R^1/2 sigma^3/2 X_3/2,
// stiffness 2 N E* R^1/2 sigma^1/2 X_1/2 (one asperity: A = pi R w, P = (4/3) E* R^1/2 w^3/2,
// dP/dw = 2 E* R^1/2 w^1/2). pi spelled out: M_PI is POSIX, not C++.
inline constexpr LawCombination hertz_combination{
    {0, 2, 3, 1}, {1.0, 3.14159265358979323846, 4.0 / 3.0, 2.0}, 1.5};

namespace detail {
// A combination is consistent when its stiffness is the derivative of its load: order n - 1/2 ...
constexpr bool stiffness_is_load_derivative(const LawCombination& c) noexcept {
  return c.twice_order[3] == c.twice_order[2] - 2 && 2 * c.load_order == c.twice_order[2] &&
         c.multiplier[3] == c.multiplier[2] * c.load_order;
}
}  // namespace detail
static_assert(detail::stiffness_is_load_derivative(hertz_combination),
              "Hertz's stiffness must be the derivative of its load");

}  // namespace asperity
