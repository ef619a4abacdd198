#include "asperity/plausibility.hpp"

#include <cmath>

#include "asperity/number_text.hpp"

namespace asperity {
namespace {

std::string g(double value) { return format_double(value); }

bool positive(double value) { return std::isfinite(value) && value > 0; }

// A length: too large reads as µm (or mm when µm would still be implausible), too small as nm.
void check_length(std::vector<std::string>& out, const char* name, double value, PlausibleRange range) {
  if (!positive(value)) return;
  if (value > range.max) {
    // (divided, not multiplied by 1e-6: 10 / 1e6 is the double nearest 1e-5, 10 * 1e-6 is not)
    const bool micrometres = value / 1e6 >= range.min && value / 1e6 <= range.max;
    out.push_back(std::string(name) + " " + g(value) + " m is implausible (above " + g(range.max) +
                  " m): did you mean " + g(value) + (micrometres ? " µm (" + g(value / 1e6) : " nm (" + g(value / 1e9)) +
                  " m)?");
  } else if (value < range.min) {
    out.push_back(std::string(name) + " " + g(value) + " m is implausible (below " + g(range.min) +
                  " m, smaller than an atom): is it in m?");
  }
}

}  // namespace

std::vector<std::string> implausible_values(const RoughSurface& surface) {
  std::vector<std::string> out;
  check_length(out, "summit radius", surface.summit_radius, plausible_summit_radius);
  check_length(out, "height scale sigma_s", surface.height_scale, plausible_height_scale);

  const double density = surface.summit_density;
  if (positive(density) && density < plausible_summit_density.min)
    out.push_back("summit density " + g(density) + " per m^2 is implausible (below " +
                  g(plausible_summit_density.min) + " per m^2, summits more than 1 cm apart): did you mean " +
                  g(density) + " per mm^2 (" + g(density * 1e6) + " per m^2)?");
  else if (positive(density) && density > plausible_summit_density.max)
    out.push_back("summit density " + g(density) + " per m^2 is implausible (above " +
                  g(plausible_summit_density.max) + " per m^2, summits less than 1 nm apart): is it per m^2?");

  const double modulus = surface.contact_modulus;
  if (positive(modulus) && modulus < plausible_contact_modulus.min) {
    // a small number is most likely GPa (steel 210), a larger one MPa (steel 210000)
    const bool gpa = modulus < 1000;
    out.push_back("contact modulus E* " + g(modulus) + " Pa is implausible (below 1 MPa, softer than rubber): did you mean " +
                  g(modulus) + (gpa ? " GPa (" + g(modulus * 1e9) : " MPa (" + g(modulus * 1e6)) + " Pa)?");
  } else if (positive(modulus) && modulus > plausible_contact_modulus.max) {
    out.push_back("contact modulus E* " + g(modulus) + " Pa is implausible (above 10 TPa, stiffer than diamond): is it in Pa?");
  }

  const double area = surface.nominal_area;
  if (positive(area) && area > plausible_nominal_area_max)
    out.push_back("nominal area A0 " + g(area) + " m^2 is implausible (above " + g(plausible_nominal_area_max) +
                  " m^2): did you mean " + g(area) + " mm^2 (" + g(area / 1e6) + " m^2)?");

  const double count = surface.summit_count();
  if (positive(density) && positive(area) && count < 1)
    out.push_back("summit count N = density * A0 = " + g(count) +
                  " is less than one summit: is the density per m^2 and the area in m^2?");

  const auto within = [](double value, PlausibleRange range) { return value >= range.min && value <= range.max; };
  if (within(surface.height_scale, plausible_height_scale) && within(surface.summit_radius, plausible_summit_radius) &&
      surface.height_scale >= surface.summit_radius)  // (one line per slip: not where either is already named)
    out.push_back("height scale sigma_s " + g(surface.height_scale) + " m is not below the summit radius " +
                  g(surface.summit_radius) + " m: GW's summits are paraboloids much wider than high; is one of them "
                  "in another unit?");
  return out;
}

std::vector<std::string> implausible_mean_summit_height(const RoughSurface& surface, double mean_summit_height) {
  std::vector<std::string> out;
  if (!std::isfinite(mean_summit_height)) return out;
  if (mean_summit_height < 0) {
    out.push_back("mean summit height " + g(mean_summit_height) +
                  " m above the mean plane is implausible (below it: summits, the surface's local maxima, stand "
                  "above the mean plane, typically by about the height scale sigma_s, " + g(surface.height_scale) +
                  " m here): is its sign right?");
    return out;
  }
  check_length(out, "mean summit height", mean_summit_height, plausible_height_scale);
  return out;
}

}  // namespace asperity
