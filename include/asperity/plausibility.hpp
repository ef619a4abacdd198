// Units caught: a surface whose SI parameters are physically implausible, most likely a value
// given in another unit (a radius in µm, a modulus in GPa). Not an error: the model is made and
// answers; these are the warnings every interface shows (the command on standard error, C
// asperity_model_warnings, Python asperity.ImplausibleValueWarning), one line each, naming the
// value and the likely slip. Checked where a model is made, never on a query.
//
// The bounds (docs/model.md section 3, "Units caught"), each far outside engineering surfaces:
//   summit radius R          1 nm .. 1 mm        (GW summit radii: 1 µm .. 1 mm)
//   height scale sigma_s     0.1 nm .. 1 mm      (rms summit heights: 1 nm .. 100 µm)
//   summit density           1e4 .. 1e18 per m^2 (summit spacings 1 cm .. 1 nm)
//   contact modulus E*       1 MPa .. 10 TPa     (rubber ~1 MPa, diamond ~1 TPa)
//   nominal area A0          up to 100 m^2
//   summit count N = density * A0  at least 1   (a statistical model of less than one summit)
//   sigma_s < R                                  (GW's asperities are paraboloids: heights << radius)
#pragma once
#include <string>
#include <vector>

#include "asperity/surface.hpp"

namespace asperity {

struct PlausibleRange {
  double min, max;
};
inline constexpr PlausibleRange plausible_summit_radius{1e-9, 1e-3};     // m
inline constexpr PlausibleRange plausible_height_scale{1e-10, 1e-3};     // m
inline constexpr PlausibleRange plausible_summit_density{1e4, 1e18};     // 1/m^2
inline constexpr PlausibleRange plausible_contact_modulus{1e6, 1e13};    // Pa
inline constexpr double plausible_nominal_area_max = 100;                // m^2

// One line per implausible value (none for a plausible surface), e.g. "summit radius 10 m is
// implausible (above 1 mm): did you mean 10 µm (1e-05 m)?". Values that validate() refuses (not
// finite, <= 0) are validate()'s to report: none here.
std::vector<std::string> implausible_values(const RoughSurface& surface);

// The mean-plane datum's mean summit height above the mean plane [m] (separation_datum.hpp):
// one line if it is implausible, none otherwise. Summits are the surface's local maxima, their
// mean height stands above the mean plane: below it (negative) is most likely a sign slip; a
// length outside the height scale's bounds above (0.1 nm .. 1 mm) a unit slip. NaN (not given)
// or not finite: none (the datum's own check refuses it).
std::vector<std::string> implausible_mean_summit_height(const RoughSurface& surface, double mean_summit_height);

}  // namespace asperity
