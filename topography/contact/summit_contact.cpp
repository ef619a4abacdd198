#include "asperity/topography/summit_contact.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

#include "asperity/error.hpp"
#include "asperity/law_combination.hpp"

namespace asperity::topography {

SummitContact::SummitContact(const Summits& summits, double contact_modulus, double nominal_area, bool own_radii)
    : modulus_(contact_modulus), nominal_area_(nominal_area) {
  if (summits.list.empty() || !(summits.area_searched > 0)) throw Error("summit contact: no summits");
  if (!(contact_modulus > 0) || !std::isfinite(contact_modulus)) throw Error("summit contact: E* must be positive");
  if (!(nominal_area > 0) || !std::isfinite(nominal_area)) throw Error("summit contact: A0 must be positive");
  if (!own_radii && !(summits.radius > 0)) throw Error("summit contact: no positive mean curvature");
  scale_ = nominal_area / summits.area_searched;
  long double sum = 0;
  for (const Summit& s : summits.list) sum += s.height;
  mean_height_ = static_cast<double>(sum / summits.list.size());
  std::vector<std::pair<double, double>> ordered;  // (height above the mean, radius)
  for (const Summit& s : summits.list) {
    const double radius = own_radii ? (s.mean_curvature > 0 ? 1 / s.mean_curvature : 0) : summits.radius;
    if (radius > 0 && std::isfinite(radius)) ordered.emplace_back(s.height - mean_height_, radius);
  }
  if (ordered.empty()) throw Error("summit contact: no summit with a positive curvature");
  std::sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [height, radius] : ordered) {
    heights_.push_back(height);
    radii_.push_back(radius);
    root_radii_.push_back(std::sqrt(radius));
  }
}

PhysicalState SummitContact::at_separation(double d) const noexcept {
  PhysicalState state{};
  state.separation = state.mean_separation = d;
  long double count = 0, area = 0, load = 0, stiffness = 0;
  // Hertz for each summit (its numbers: law_combination.hpp, count, area, load, stiffness)
  const double(&hertz)[4] = hertz_combination.multiplier;
  for (std::size_t k = 0; k < heights_.size() && heights_[k] > d; ++k) {  // descending: stop at the first clear
    const double w = heights_[k] - d, root_w = std::sqrt(w);
    count += 1;
    area += hertz[1] * radii_[k] * w;
    load += hertz[2] * modulus_ * root_radii_[k] * w * root_w;
    stiffness += hertz[3] * modulus_ * root_radii_[k] * root_w;
  }
  state.count = static_cast<double>(count) * scale_;
  state.real_area = static_cast<double>(area) * scale_;
  state.area_fraction = state.real_area / nominal_area_;
  state.load = static_cast<double>(load) * scale_;
  state.pressure = state.load / nominal_area_;
  state.stiffness = static_cast<double>(stiffness) * scale_;
  state.stiffness_over_load = state.stiffness / state.load;
  return state;
}

std::size_t SummitContact::in_contact(double separation) const noexcept {
  // descending: the summits above d (those at_separation counts) are a prefix
  return static_cast<std::size_t>(std::lower_bound(heights_.begin(), heights_.end(), separation, std::greater<double>()) -
                                  heights_.begin());
}

PhysicalState SummitContact::at_pressure(double pressure) const {
  if (!(pressure > 0) || !std::isfinite(pressure)) return at_separation(std::numeric_limits<double>::infinity());
  // the load falls from the highest summit down: bracket, then Brent (TOMS 748)
  const double top = heights_.front();
  double span = std::max(top - heights_.back(), std::fabs(top)) + 1e-300;
  double lower = top - span;
  while (at_separation(lower).pressure < pressure && span < 1e300) {
    span *= 2;
    lower = top - span;
  }
  const auto f = [&](double d) { return at_separation(d).pressure - pressure; };
  boost::math::tools::eps_tolerance<double> tolerance(50);
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(f, lower, top, f(lower), -pressure, tolerance, iterations);
  return at_separation(0.5 * (a + b));
}

}  // namespace asperity::topography
