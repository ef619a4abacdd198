// The Greenwood-Williamson answer without a fitted law: the contact of a rigid flat summed
// directly over the measured summits (a non-parametric GW). Each summit in contact is a Hertz
// asperity at interference w = z_i - (mean summit height + d): count 1, area pi R w, load
// (4/3) E* R^(1/2) w^(3/2), stiffness 2 E* R^(1/2) w^(1/2) (docs/model.md, section 3), summed
// over the summits and scaled from the area searched to the nominal area A0 (the measured
// summit density). R is GW's one radius, 1 / <kappa_m> (so that against the fitted laws only
// the height distribution differs), or each summit's own 1 / kappa_m.
//
// It is what the fitted models approximate: the same summits, no law in between. It is also
// only as good as the summits measured: where a handful are in contact its answer is that
// handful's (the count says so), and like every summit statistic it depends on the sampling
// interval (the analysis gives it at 2 dx and 4 dx too).
#pragma once
#include <cstddef>
#include <vector>

#include "asperity/contact_model.hpp"
#include "asperity/topography/summits.hpp"

namespace asperity::topography {

class SummitContact {
 public:
  SummitContact() = default;
  // Throws asperity::Error for no summits, a modulus or nominal area not positive, or (own
  // radii) no summit with a positive curvature.
  SummitContact(const Summits& summits, double contact_modulus, double nominal_area, bool own_radii = false);

  // d from the measured mean summit height [m] (PhysicalState::mean_separation = separation = d).
  PhysicalState at_separation(double separation) const noexcept;
  // The separation that carries a nominal pressure [Pa] (Brent's method on the monotone sum).
  PhysicalState at_pressure(double pressure) const;
  // The measured summits in contact at a separation d (those above it), not scaled to the nominal
  // area: how many summits carry the answer there (PhysicalState::count is this times A0 / the
  // area searched).
  std::size_t in_contact(double separation) const noexcept;
  double mean_summit_height() const noexcept { return mean_height_; }

 private:
  std::vector<double> heights_;       // above the mean summit height, descending
  std::vector<double> root_radii_;    // R^(1/2) of each, in the same order
  std::vector<double> radii_;
  double scale_ = 0;                  // A0 / area searched
  double modulus_ = 0, nominal_area_ = 0, mean_height_ = 0;
};

}  // namespace asperity::topography
