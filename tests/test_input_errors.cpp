// Nonsense in, a clear answer out (issue 37, items 5 and 6): a model's range reported where a
// scene table ends (what the command refuses a query with), an implausible datum height warned,
// and the errors of Boost.Math under the generator's quadratures named by the inputs that caused
// them, never Boost's own text.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "asperity/contact_model.hpp"
#include "asperity/error.hpp"
#include "asperity/generator/law_curves.hpp"
#include "asperity/generator/quadrature.hpp"
#include "asperity/generator/scene_table.hpp"
#include "asperity/plausibility.hpp"
#include "asperity/scene.hpp"

namespace asperity {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

RoughSurface worn_surface() {
  RoughSurface surface;
  surface.distribution = Distribution::weibull;
  surface.side = Side::bounded;
  surface.shape = 1.73;
  surface.height_scale = 1e-6;
  surface.summit_radius = 1e-4;
  surface.summit_density = 1e10;
  surface.nominal_area = 1e-4;
  surface.contact_modulus = 1e11;
  return surface;
}

// What the error message of `run` says (empty if it threw no asperity::Error)
template <class Run>
std::string error_of(Run run) {
  try {
    run();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(ModelRange, AFullTableServesEverything) {
  const ContactModel model(Table::open(ASPERITY_TEST_TABLE), worn_surface());
  EXPECT_EQ(model.min_separation(), -inf);
  EXPECT_EQ(model.max_separation(), inf);
  EXPECT_EQ(model.min_load(), 0.0);
  EXPECT_EQ(model.max_load(), inf);
  EXPECT_EQ(model.min_real_area(), 0.0);
  EXPECT_EQ(model.max_real_area(), inf);
  EXPECT_TRUE(model.answers_separation(-1e300));
  EXPECT_TRUE(model.answers_separation(1e300));
  EXPECT_FALSE(model.answers_separation(std::nan("")));
}

// The bearing scene (tables/scenes/bearing.toml): s from -2 to -1e-6 on the bounded side
TEST(ModelRange, ASceneTableReportsItsRangeInEachUnit) {
  const Scene scene = parse_scene(
      "max_rel_error = 1e-8\n[[curve]]\ndistribution = \"weibull\"\nshape = 1.73\nside = \"bounded\"\n"
      "quantities = [\"load\", \"stiffness\"]\nseparation = [-2.0, -1e-6]\n",
      "bearing");
  const Table table(generator::generate_scene_table(scene, 1).table);
  const ContactModel model(table, worn_surface());
  EXPECT_DOUBLE_EQ(model.min_separation(), -2e-6);
  EXPECT_DOUBLE_EQ(model.max_separation(), -1e-12);
  EXPECT_TRUE(model.answers_separation(-1e-6));
  EXPECT_TRUE(model.answers_separation(1e-7));  // past first contact: no contact, answered
  EXPECT_FALSE(model.answers_separation(-3e-6));
  EXPECT_FALSE(model.answers_separation(-1e-13));  // between the range's end and first contact
  // the ends answer, and the range's loads and areas are those of its ends
  EXPECT_GT(model.min_load(), 0.0);
  EXPECT_LT(model.min_load(), model.max_load());
  EXPECT_LT(model.max_load(), inf);
  EXPECT_DOUBLE_EQ(model.min_load(), model.at_separation(-1e-12).load);
  EXPECT_DOUBLE_EQ(model.max_load(), model.at_separation(-2e-6).load);
  EXPECT_DOUBLE_EQ(model.max_real_area(), model.at_separation(-2e-6).real_area);
  EXPECT_FALSE(std::isnan(model.at_load(model.max_load()).separation));
  EXPECT_TRUE(std::isnan(model.at_load(2 * model.max_load()).separation));
  EXPECT_TRUE(std::isnan(model.at_real_area(2 * model.max_real_area()).separation));
}

TEST(Plausibility, AMeanSummitHeightBelowTheMeanPlaneIsOneLine) {
  const RoughSurface surface = worn_surface();
  EXPECT_TRUE(implausible_mean_summit_height(surface, 1e-6).empty());
  EXPECT_TRUE(implausible_mean_summit_height(surface, std::nan("")).empty());
  const auto negative = implausible_mean_summit_height(surface, -1);
  ASSERT_EQ(negative.size(), 1u);
  EXPECT_NE(negative[0].find("mean summit height -1 m above the mean plane is implausible"), std::string::npos);
  EXPECT_NE(negative[0].find("is its sign right?"), std::string::npos);
  const auto metres = implausible_mean_summit_height(surface, 2);
  ASSERT_EQ(metres.size(), 1u);
  EXPECT_EQ(metres[0], "mean summit height 2 m is implausible (above 0.001 m): did you mean 2 µm (2e-06 m)?");
}

// Boost's exp_sinh meets inf there (a shape far below the generator's): named by the curve
TEST(DependencyErrors, AQuadratureFailureNamesTheCurveAndSeparation) {
  const generator::CurveId curve{Distribution::weibull, Side::tail, 1e-300};
  const std::string message = error_of([&] { generator::log_integral(curve, 1.5, -1e300); });
  EXPECT_NE(message.find("quadrature failed: ln X of order 1.5 of the weibull shape 1e-300 tail curve at separation "
                         "s = -1e+300"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("shapes 0.3 to 50"), std::string::npos) << message;
}

SceneLaw kogut_etsion(const std::string& material) {
  const Scene scene = parse_scene(
      "max_rel_error = 1e-6\n[[law]]\nlaw = \"kogut-etsion\"\n" + material +
          "poisson = 0.3\ndistribution = \"gaussian\"\nheight_scale = 1e-6\nsummit_radius = 1e-4\n"
          "summit_density = 4e8\nnominal_area = 1e-4\nseparation = [0.0, 4.0]\n",
      "absurd");
  return scene.laws.front();
}

// A yield strength that makes omega_c underflow to 0 (the law divides by it): Boost's tanh_sinh
// met NaN; the message names the yield strength, its value and the range that works
TEST(DependencyErrors, ALawsQuadratureFailureNamesTheParameter) {
  const SceneLaw law = kogut_etsion("contact_modulus = 1.13e11\nyield_strength = 1e-300\n");
  for (const std::string& message : {error_of([&] { generator::law_means(law, 0.0); }),
                                     error_of([&] { generator::generate_law_curves(law); })}) {
    EXPECT_NE(message.find("(kogut-etsion): its curves cannot be computed at s = 0"), std::string::npos) << message;
    EXPECT_NE(message.find("the yield strength Y 1e-300 Pa is outside 113000 to 1.13e+12 Pa"), std::string::npos)
        << message;
    EXPECT_NE(message.find("omega_c it gives is 0 m"), std::string::npos) << message;
    EXPECT_EQ(message.find("tanh_sinh"), std::string::npos) << message;
  }
  const SceneLaw stiff = kogut_etsion("contact_modulus = 1e300\nyield_strength = 1e9\n");
  const std::string message = error_of([&] { generator::generate_law_curves(stiff); });
  EXPECT_NE(message.find("the contact modulus E* 1e+300 Pa is outside 1e+06 to 1e+13 Pa"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace asperity
