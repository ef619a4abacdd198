// The factors of docs/model.md section 3 (quantity = factor * X_n) of the law the contact
// kernels serve, Hertz's (law_combination.hpp's hertz_combination: its numbers are defined
// there once): contact_scales (contact.hpp) and the contact kernels (runtime/core/kernel/),
// whose x86 build computes them in vector registers in the same order of operations (the same
// bits: test_kernels, test_contact).
#pragma once
#include <cmath>

#include "asperity/law_combination.hpp"

namespace asperity {

struct ContactScales {
  double count = 0;      // N
  double area = 0;       // pi N R sigma_s
  double load = 0;       // (4/3) N E* R^1/2 sigma_s^3/2
  double stiffness = 0;  // 2 N E* R^1/2 sigma_s^1/2
};

namespace detail {
// The combination the contact kernels and ContactScales serve: the numbers in the factors (count,
// area, load, stiffness) and the orders they multiply
inline constexpr const LawCombination& served_combination = hertz_combination;
inline constexpr const double (&contact_multipliers)[4] = served_combination.multiplier;

// One square root (R^(1/2) sigma^(3/2) = sigma sqrt(R sigma)), grouped as (1, pi, 4/3, 2) N
// times (1, R sigma, sigma E* sqrt(R sigma), E* sqrt(R sigma)): one vector product in the kernels
inline ContactScales contact_scales_of(double n, double radius, double scale, double modulus) noexcept {
  const double product = radius * scale, modulus_root = modulus * std::sqrt(product);
  ContactScales scales;
  scales.count = contact_multipliers[0] * n;
  scales.area = (contact_multipliers[1] * n) * product;
  scales.load = (contact_multipliers[2] * n) * (scale * modulus_root);
  scales.stiffness = (contact_multipliers[3] * n) * modulus_root;
  return scales;
}
}  // namespace detail

}  // namespace asperity
