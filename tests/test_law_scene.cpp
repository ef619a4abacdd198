// Law scenes (asperity/scene.hpp's [[law]], docs/contact-laws.md section 8): each law's
// tabulated rough-surface curves (the generator's contact-curves table, served by ContactCurves)
// against the independent reference of tests/contact_law_reference.hpp (adaptive quadrature in
// the interference, which shares no code with the generator), within the asked tolerance and the
// stored bound everywhere sampled: the range's ends, both sides of every point where a switch of
// the law meets the density's edge, and random separations; extreme shapes (Weibull 0.5, 20, 50,
// the bounded side). Also the scene format's errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "asperity/contact_curves.hpp"
#include "asperity/error.hpp"
#include "asperity/generator/law_curves.hpp"
#include "asperity/scene.hpp"
#include "contact_law_reference.hpp"

namespace {
using namespace asperity;

// A surface and material of the Kogut-Etsion 2003 kind: omega_c ~ 5e-8 m against sigma_s = 1e-6
// m (psi ~ 4.5), eta R sigma_s = 0.04
constexpr double modulus = 1.13e11, yield = 1.0e9, hardness = 2.8e9, poisson = 0.3;
constexpr double sigma = 1e-6, radius = 1e-4, density = 4e8, area = 1e-4;

SceneLaw scene_law(ContactLaw law, Distribution distribution, Side side, double shape, double lo, double hi,
                   double tolerance) {
  SceneLaw out;
  out.law = law;
  out.distribution = distribution;
  out.side = side;
  out.shape = shape;
  out.height_scale = sigma;
  out.summit_radius = radius;
  out.summit_density = density;
  out.nominal_area = area;
  out.range_min = lo;
  out.range_max = hi;
  out.max_rel_error = tolerance;
  return out;
}

struct Case {
  const char* label;
  SceneLaw law;
};

std::vector<Case> cases() {
  using D = Distribution;
  using S = Side;
  return {
      {"kogut-etsion gaussian", scene_law(kogut_etsion_law(radius, modulus, yield, poisson), D::gaussian, S::tail, 2,
                                          -1.0, 4.0, 1e-6)},
      {"hertz gaussian 1e-8", scene_law(hertz_law(radius, modulus), D::gaussian, S::tail, 2, -1.0, 4.0, 1e-8)},
      {"chang-etsion-bogy weibull tail 2", scene_law(chang_etsion_bogy_law(radius, modulus, hardness, poisson),
                                                     D::weibull, S::tail, 2, -0.5, 3.0, 1e-6)},
      {"zhao-maietta-chang weibull bounded 2", scene_law(zhao_maietta_chang_law(radius, modulus, hardness),
                                                         D::weibull, S::bounded, 2, -3.0, -0.05, 1e-6)},
      {"hertz weibull tail 0.5", scene_law(hertz_law(radius, modulus), D::weibull, S::tail, 0.5, -0.5, 20.0, 1e-6)},
      {"hertz weibull bounded 0.5", scene_law(hertz_law(radius, modulus), D::weibull, S::bounded, 0.5, -3.0, -0.01,
                                              1e-6)},
      {"jackson-green gaussian", scene_law(jackson_green_law(radius, modulus, yield, poisson), D::gaussian, S::tail, 2,
                                           -1.0, 4.0, 1e-6)},
      {"jackson-green 2006 weibull bounded 3",
       scene_law(jackson_green_law(radius, modulus, yield, poisson, JacksonGreenHardness::exponential_2006), D::weibull,
                 S::bounded, 3, -3.0, -0.02, 1e-6)},
      {"kogut-etsion weibull tail 20", scene_law(kogut_etsion_law(radius, modulus, yield, poisson), D::weibull,
                                                 S::tail, 20, -0.5, 1.2, 1e-6)},
      {"kogut-etsion weibull bounded 50", scene_law(kogut_etsion_law(radius, modulus, yield, poisson), D::weibull,
                                                    S::bounded, 50, -2.0, -0.01, 1e-6)},
  };
}

// The separations sampled: the ends, both sides of each point where the integrals are not
// smooth (s = 0 and s = -omega_k/sigma), points near every switch's own separation scale, random ones
std::vector<double> samples(const SceneLaw& law) {
  const double lo = law.range_min, hi = law.range_max, span = hi - lo;
  std::vector<double> out{lo, lo + 1e-9 * span, lo + 1e-4 * span, hi - 1e-4 * span, hi - 1e-9 * span, hi};
  std::vector<double> edges{0.0};
  const SwitchPoints points = switch_points(law.law);
  for (int k = 0; k < points.count; ++k) edges.push_back(-points.interference[k] / sigma);
  for (double edge : edges)
    for (double offset : {-1e-2, -1e-3, -1e-6, 0.0, 1e-6, 1e-3, 1e-2}) out.push_back(edge + offset * span);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(lo, hi);
  for (int i = 0; i < 60; ++i) out.push_back(uniform(random));
  out.erase(std::remove_if(out.begin(), out.end(), [&](double s) { return !(s >= lo && s <= hi); }), out.end());
  return out;
}

TEST(LawScene, EveryLawsCurvesAgainstTheIndependentReference) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    const generator::LawCurvesResult result = generator::generate_law_curves(c.law);
    const ContactCurves curves(result.data);
    const test::SummitHeights heights{c.law.distribution, c.law.side, c.law.shape, sigma};
    double worst[3] = {0, 0, 0};
    for (double s : samples(c.law)) {
      const test::RoughSurfaceValues truth = test::law_integrals(c.law.law, heights, s);
      const ContactCurvesState served = curves.at_separation(sigma * s);
      const double expected[3] = {density * truth.load, density * truth.stiffness, density * truth.area};
      const double got[3] = {served.pressure, served.stiffness, served.area_fraction};
      for (int k = 0; k < 3; ++k) {
        const double error = std::fabs(got[k] - expected[k]) / expected[k];
        worst[k] = std::max(worst[k], error);
        EXPECT_LE(error, c.law.max_rel_error) << "quantity " << k << " at s = " << s;
        EXPECT_LE(error, result.data.max_rel_error[k] + 1e-12) << "quantity " << k << " at s = " << s
                                                                << ": beyond the stored bound";
      }
    }
    std::printf("%-40s nodes %4d  stored p %.2e k %.2e a %.2e  against the reference p %.2e k %.2e a %.2e\n",
                c.label, result.nodes, result.data.max_rel_error[0], result.data.max_rel_error[1],
                result.data.max_rel_error[2], worst[0], worst[1], worst[2]);
  }
}

TEST(LawScene, TheGeneratorsMeansAgainstTheReferenceAtSwitchPoints) {
  // the exact values themselves (not the interpolation): at the separations where a switch
  // meets the density's edge and between
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    const test::SummitHeights heights{c.law.distribution, c.law.side, c.law.shape, sigma};
    for (double s : samples(c.law)) {
      const generator::LawMeans mine = generator::law_means(c.law, s);
      const test::RoughSurfaceValues truth = test::law_integrals(c.law.law, heights, s);
      EXPECT_NEAR(mine.load / truth.load, 1, 1e-10) << s;
      EXPECT_NEAR(mine.stiffness / truth.stiffness, 1, 1e-10) << s;
      EXPECT_NEAR(mine.area / truth.area, 1, 1e-10) << s;
      EXPECT_NEAR(mine.count / truth.count, 1, 1e-10) << s;
    }
  }
}

TEST(LawScene, TheSceneFormat) {
  const std::string surface = R"(
distribution = "gaussian"
height_scale = 1e-6
summit_radius = 1e-4
summit_density = 4e8
nominal_area = 1e-4
separation = [0.0, 4.0]
)";
  const Scene scene = parse_scene("[[law]]\nlaw = \"kogut-etsion\"\ncontact_modulus = 1.13e11\nyield_strength = 1e9\n"
                                  "poisson = 0.3\nmax_rel_error = 1e-7\n" + surface, "ke.toml");
  ASSERT_EQ(scene.laws.size(), 1u);
  EXPECT_TRUE(scene.curves.empty());
  EXPECT_EQ(scene.laws[0].law.kind, ContactLawKind::kogut_etsion);
  EXPECT_DOUBLE_EQ(scene.laws[0].law.critical_interference,
                   kogut_etsion_law(1e-4, 1.13e11, 1e9, 0.3).critical_interference);
  EXPECT_EQ(scene.laws[0].max_rel_error, 1e-7);
  auto refused = [&](const std::string& text, const std::string& words) {
    try {
      parse_scene(text, "bad.toml");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
    }
  };
  refused("[[law]]\nlaw = \"kogut-etsion\"\ncontact_modulus = 1.13e11\nhardness = 1e9\npoisson = 0.3\n" + surface,
          "'hardness' does not apply to kogut-etsion");
  refused("[[law]]\nlaw = \"kogut-etsion\"\ncontact_modulus = 1.13e11\npoisson = 0.3\n" + surface,
          "has no 'yield_strength'");
  refused("[[law]]\nlaw = \"dmt\"\ncontact_modulus = 1.13e11\n" + surface, "adhesive laws are not tabulated");
  refused("[[law]]\nlaw = \"plastic\"\ncontact_modulus = 1.13e11\n" + surface, "unknown law");
  refused("[[law]]\nlaw = \"hertz\"\ncontact_modulus = -1\n" + surface, "must be positive");
  refused("[[law]]\nlaw = \"hertz\"\ncontact_modulus = 1e11\nmax_rel_error = 1e-12\n" + surface, "at least 1e-10");
  refused("[[law]]\nlaw = \"hertz\"\ncontact_modulus = 1e11\n" + surface +
              "[[curve]]\ndistribution = \"gaussian\"\nquantities = [\"load\"]\nseparation = [0, 1]\n",
          "a law or curves, not both");
  // interferences beyond the law's source (Jackson-Green: a = R), with a heavy tail: refused
  try {
    generator::generate_law_curves(scene_law(jackson_green_law(radius, modulus, yield, poisson), Distribution::weibull,
                                             Side::tail, 0.5, -0.5, 20.0, 1e-6));
    ADD_FAILURE() << "interferences beyond a = R were tabulated";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("beyond the interference its source supports"), std::string::npos)
        << error.what();
  }
  // a switch point where the density is infinite (Weibull a < 1 at its edge): the stiffness has
  // an infinite slope at s = -omega_1/sigma_s (ZMC: dP/domega jumps at omega_1); refused, with where
  try {
    generator::generate_law_curves(scene_law(zhao_maietta_chang_law(radius, modulus, hardness), Distribution::weibull,
                                             Side::bounded, 0.5, -3.0, -0.01, 1e-6));
    ADD_FAILURE() << "a singular point was tabulated";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("not smooth enough near s = -0.1227"), std::string::npos) << error.what();
  }
  // an area fraction beyond 1 inside the range is refused by the generator, with the fix
  SceneLaw crowded = scene_law(hertz_law(radius, modulus), Distribution::gaussian, Side::tail, 2, -3.0, 1.0, 1e-6);
  crowded.summit_density = 1e10;
  try {
    generator::generate_law_curves(crowded);
    ADD_FAILURE() << "an area fraction beyond 1 was tabulated";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("beyond 1 Greenwood-Williamson does not hold"), std::string::npos);
  }
}

TEST(LawScene, TheInverseServesTheLoadsSeparation) {
  const SceneLaw law = cases()[0].law;
  const ContactCurves curves(generator::generate_law_curves(law).data);
  const test::SummitHeights heights{law.distribution, law.side, law.shape, sigma};
  for (double s : {-0.7, 0.3, 1.9, 3.6}) {
    const double pressure = density * test::law_integrals(law.law, heights, s).load;
    EXPECT_NEAR(curves.separation_at_pressure(pressure) / sigma, s, 1e-7) << s;
  }
}

}  // namespace
