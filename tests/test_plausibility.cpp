// Units caught (asperity/plausibility.hpp): each bound warns in one line naming the value and
// the likely slip; plausible surfaces (the defaults, the README's, measured-map scales) do not.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "asperity/plausibility.hpp"

namespace {
using namespace asperity;

RoughSurface steel() {  // the README's quick start
  RoughSurface surface;
  surface.shape = 2;
  surface.height_scale = 5.6e-7;
  surface.summit_radius = 1e-4;
  surface.summit_density = 1e10;
  surface.nominal_area = 1e-4;
  surface.contact_modulus = 1.15e11;
  return surface;
}

// the one line for a surface with one slip
std::string warning_of(const RoughSurface& surface) {
  const std::vector<std::string> lines = implausible_values(surface);
  EXPECT_EQ(lines.size(), 1u);
  if (lines.size() != 1) return "";
  EXPECT_EQ(lines[0].find('\n'), std::string::npos);
  return lines[0];
}

TEST(Plausibility, PlausibleSurfacesDoNotWarn) {
  RoughSurface former_defaults = steel();  // what RoughSurface{} held before its values became required
  former_defaults.height_scale = 1e-6;
  former_defaults.contact_modulus = 1e11;
  EXPECT_TRUE(implausible_values(former_defaults).empty());
  EXPECT_TRUE(implausible_values(steel()).empty());
  RoughSurface afm = steel();  // an AFM map: nm heights, 10 um window
  afm.height_scale = 1e-8, afm.summit_radius = 2e-7, afm.summit_density = 1.6e13, afm.nominal_area = 1e-10;
  EXPECT_TRUE(implausible_values(afm).empty());
  RoughSurface rubber = steel();
  rubber.contact_modulus = 2e6;
  EXPECT_TRUE(implausible_values(rubber).empty());
}

TEST(Plausibility, EachSlipInOneLine) {
  RoughSurface s = steel();
  s.summit_radius = 10;  // 10 um given as 10
  EXPECT_EQ(warning_of(s), "summit radius 10 m is implausible (above 0.001 m): did you mean 10 µm (1e-05 m)?");
  s = steel();
  s.height_scale = 0.5;  // 0.5 um given as 0.5
  EXPECT_EQ(warning_of(s), "height scale sigma_s 0.5 m is implausible (above 0.001 m): did you mean 0.5 µm (5e-07 m)?");
  s = steel();
  s.height_scale = 2e-12;
  EXPECT_NE(warning_of(s).find("height scale sigma_s 2e-12 m is implausible (below 1e-10 m"), std::string::npos);
  s = steel();
  s.contact_modulus = 210;  // GPa
  EXPECT_EQ(warning_of(s),
            "contact modulus E* 210 Pa is implausible (below 1 MPa, softer than rubber): did you mean 210 GPa (2.1e+11 Pa)?");
  s = steel();
  s.contact_modulus = 115000;  // MPa
  EXPECT_NE(warning_of(s).find("did you mean 115000 MPa (1.15e+11 Pa)?"), std::string::npos);
  s = steel();
  s.contact_modulus = 2e14;
  EXPECT_NE(warning_of(s).find("above 10 TPa"), std::string::npos);
  s = steel();
  s.summit_density = 100;  // per mm^2
  s.nominal_area = 1;
  EXPECT_NE(warning_of(s).find("summit density 100 per m^2 is implausible"), std::string::npos);
  EXPECT_NE(implausible_values(s)[0].find("did you mean 100 per mm^2 (1e+08 per m^2)?"), std::string::npos);
  s = steel();
  s.summit_density = 1e20;
  EXPECT_NE(warning_of(s).find("above 1e+18 per m^2"), std::string::npos);
  s = steel();
  s.nominal_area = 500;  // mm^2
  EXPECT_NE(warning_of(s).find("did you mean 500 mm^2 (5e-04 m^2)?"), std::string::npos);
  s = steel();
  s.nominal_area = 1e-11;  // 1e-1 summits
  EXPECT_NE(warning_of(s).find("less than one summit"), std::string::npos);
}

TEST(Plausibility, AtTheBoundsAndBadValues) {
  RoughSurface s = steel();
  s.summit_radius = plausible_summit_radius.max;  // at the bound: plausible
  EXPECT_TRUE(implausible_values(s).empty());
  s.summit_radius = 1.0000001e-3;
  EXPECT_EQ(implausible_values(s).size(), 1u);
  s = steel();
  s.contact_modulus = plausible_contact_modulus.min;
  EXPECT_TRUE(implausible_values(s).empty());
  s = steel();
  s.summit_radius = -1;  // validate()'s to refuse: no warning here
  s.contact_modulus = NAN;
  EXPECT_TRUE(implausible_values(s).empty());
  s = steel();
  s.summit_radius = 1e-7;  // sigma_s 5.6e-7 above R: GW's paraboloids are wider than high
  EXPECT_NE(warning_of(s).find("is not below the summit radius"), std::string::npos);
}

}  // namespace
