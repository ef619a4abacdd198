// Persson's (2007) law for comparison (docs/model.md section 6): the nominal pressure falls
// exponentially with the separation, p = p_ref exp(-s / beta), s in units of the rms roughness,
// beta about 0.5 to 1; its stiffness/load ratio is the constant 1/beta.
#pragma once
#include <cmath>

namespace asperity {

struct PerssonLaw {
  double beta = 0.5;
  double reference_pressure = 1;  // p at s = 0 (any unit: only ratios are compared)
  double pressure(double separation) const noexcept { return reference_pressure * std::exp(-separation / beta); }
  double separation_at(double pressure_value) const noexcept {
    return -beta * std::log(pressure_value / reference_pressure);
  }
  double stiffness_over_load() const noexcept { return 1 / beta; }
};

}  // namespace asperity
