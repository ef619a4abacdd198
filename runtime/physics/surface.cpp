#include "asperity/surface.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "asperity/contact_scales.hpp"
#include "asperity/error.hpp"

namespace asperity {
namespace {
void require_positive(double value, const char* name) {
  if (std::isnan(value))  // RoughSurface's physical values have no default
    throw Error(std::string("surface: ") + name + " is not given (a RoughSurface's physical values have no default)");
  if (!(std::isfinite(value) && value > 0)) {
    std::ostringstream message;
    message << "surface: " << name << " must be a positive number, got " << value;
    throw Error(message.str());
  }
}
}  // namespace

void RoughSurface::validate() const {
  if (distribution == Distribution::weibull) {
    require_positive(shape, "shape");
    if (!(shape >= weibull_shape_min && shape <= weibull_shape_max)) {
      std::ostringstream message;
      message << "surface: Weibull shape must be between " << weibull_shape_min << " and " << weibull_shape_max
              << ", got " << shape;
      throw Error(message.str());
    }
  } else if (side == Side::bounded) {
    throw Error("surface: the Gaussian has no bounded side");
  }
  require_positive(height_scale, "height scale sigma_s");
  require_positive(summit_radius, "summit radius R");
  require_positive(summit_density, "summit density");
  require_positive(nominal_area, "nominal area A0");
  require_positive(contact_modulus, "contact modulus E*");
  // The factors of docs/model.md section 3 must be ordinary numbers: sigma_s = 1e-300 or E* = 1e308
  // would give a load of 0 or inf at every separation.
  // (the factors the kernels multiply: contact_scales.hpp)
  const double n = summit_count();
  const ContactScales scales = detail::contact_scales_of(n, summit_radius, height_scale, contact_modulus);
  const double factors[] = {scales.count, scales.area, scales.load, scales.stiffness, n / nominal_area};
  const char* names[] = {"summit count N = density * A0", "area factor pi N R sigma_s",
                         "load factor (4/3) N E* R^1/2 sigma_s^3/2", "stiffness factor 2 N E* R^1/2 sigma_s^1/2",
                         "summit density"};
  for (int i = 0; i < 5; ++i)
    if (!(std::isfinite(factors[i]) && factors[i] >= 1e-250 && factors[i] <= 1e250)) {
      std::ostringstream message;
      message << "surface: the " << names[i] << " is " << factors[i]
              << ", outside [1e-250, 1e250]: the parameters are not those of a physical surface (SI units?)";
      throw Error(message.str());
    }
}

double height_scale_from_rms(Distribution distribution, double shape, double rms) {
  require_positive(rms, "rms summit height");
  if (distribution == Distribution::gaussian) return rms;
  require_positive(shape, "shape");
  return rms / weibull_rms(shape);
}

double contact_modulus_from(double young1, double poisson1, double young2, double poisson2) {
  require_positive(young1, "E1");
  require_positive(young2, "E2");
  for (double poisson : {poisson1, poisson2})
    if (!(poisson > -1 && poisson <= 0.5)) {
      std::ostringstream message;
      message << "surface: a Poisson's ratio must be in (-1, 0.5], got " << poisson;
      throw Error(message.str());
    }
  return 1 / ((1 - poisson1 * poisson1) / young1 + (1 - poisson2 * poisson2) / young2);
}

double contact_modulus_given(double contact_modulus, double young1, double poisson1, double young2, double poisson2) {
  const auto given = [](double value) { return !std::isnan(value); };
  const bool four = given(young1) || given(poisson1) || given(young2) || given(poisson2);
  if (four && given(contact_modulus))
    throw Error("surface: give the contact modulus E* or the four E1, nu1, E2, nu2, not both");
  if (four && !(given(young1) && given(poisson1) && given(young2) && given(poisson2)))
    throw Error("surface: E1, nu1, E2, nu2 go together");
  if (four) return contact_modulus_from(young1, poisson1, young2, poisson2);
  if (given(contact_modulus) && !(contact_modulus > 0 && std::isfinite(contact_modulus)))
    throw Error("surface: the contact modulus E* must be a positive number");
  return contact_modulus;
}

double nominal_pressure_from_load(double load, double nominal_area) {
  require_positive(load, "load");
  require_positive(nominal_area, "nominal area");
  return load / nominal_area;
}

double bandwidth_alpha(double m0, double m2, double m4) {
  require_positive(m0, "m0");
  require_positive(m2, "m2");
  require_positive(m4, "m4");
  return m0 * m4 / (m2 * m2);
}

RoughSurface gaussian_surface_from_moments(double m0, double m2, double m4, double nominal_area,
                                              double contact_modulus) {
  const double alpha = bandwidth_alpha(m0, m2, m4);
  if (!(alpha > 0.9)) {
    std::ostringstream message;
    message << "surface: bandwidth alpha = m0 m4 / m2^2 = " << alpha
            << " must exceed 0.9 (McCool's summit statistics; alpha >= 1.5 for a real surface)";
    throw Error(message.str());
  }
  const double pi = 3.14159265358979323846;
  RoughSurface surface;
  surface.distribution = Distribution::gaussian;
  surface.side = Side::tail;
  surface.shape = 2;
  surface.summit_density = m4 / (6 * pi * std::sqrt(3.0) * m2);
  surface.summit_radius = 1 / ((8.0 / 3.0) * std::sqrt(m4 / pi));
  surface.height_scale = std::sqrt(m0 * (1 - 0.8968 / alpha));
  surface.nominal_area = nominal_area;
  surface.contact_modulus = contact_modulus;
  surface.validate();
  return surface;
}

}  // namespace asperity
