// A contact law beside a measured surface's elastic curves (topography/law_contact.hpp, issue 30
// item 6), on each of the three fits (the Gaussian, the tail-up and the bounded Weibull): Hertz as
// the law gives the fit's elastic curve back (the generator's table against the default table's);
// Kogut-Etsion's pressure, stiffness and area at the separations it reports agree with the
// independent reference quadrature (tests/contact_law_reference.hpp); and what it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "asperity/topography/analysis.hpp"
#include "asperity/topography/law_contact.hpp"
#include "asperity/topography/synthetic.hpp"
#include "contact_law_reference.hpp"
#include "law_options.hpp"

namespace t = asperity::topography;

namespace {

// A small synthetic surface's elastic curves at two pressures, no ensemble (its verdict is not needed)
const t::SurfaceAnalysis& analysis() {
  static const t::SurfaceAnalysis a = [] {
    t::HeightMap map = t::gaussian_random_field(96, 96, 1e-7, 1e-7, {{1.5, 4e-16}}, 3);
    map.source = "synthetic-3";
    t::AnalysisOptions options;
    options.assessment.bootstrap = 0;
    options.fit_heights = false;
    t::ContactOptions contact;
    contact.contact_modulus = 1e11;
    contact.curve_points = 9;
    contact.table_path = ASPERITY_TEST_TABLE;
    contact.pressures = {1e6, 1e7};
    contact.persson = false;
    options.contact = contact;
    return t::analyse_height_map(map, options);
  }();
  return a;
}

// The law as `asperity surface --law` makes it (the command's one definition)
t::LawSceneMaker maker(const std::string& name, double yield_strength = NAN, double poisson = NAN) {
  asperity::cli::LawOptions law;
  law.law = name;
  law.material.set(asperity::LawParameter::yield_strength, yield_strength);
  law.material.set(asperity::LawParameter::poisson, poisson);
  return [law](const asperity::RoughSurface& surface, double s_min, double s_max, double approach) {
    return asperity::cli::law_scene(law, surface, s_min, s_max, "test", approach);
  };
}

double relative(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

}  // namespace

TEST(LawContact, HertzIsEachFitsElasticCurve) {
  const t::SurfaceAnalysis& a = analysis();
  for (t::HeightModel model : t::all_height_models) {
    const t::ModelContact* elastic = a.contact->find(t::to_string(model));
    ASSERT_TRUE(elastic && elastic->served) << t::to_string(model) << ": " << (elastic ? elastic->note : "none");
    const t::LawContact law = t::compare_law(*a.contact, a.summits, model, "test", maker("hertz"));
    ASSERT_TRUE(law.served) << t::to_string(model) << ": " << law.note;
    EXPECT_TRUE(std::isnan(law.plasticity_index));
    EXPECT_EQ(law.fit, model);
    ASSERT_EQ(law.at_pressures.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_LT(std::fabs(law.area_over_elastic[k] - 1), 1e-6) << t::to_string(model) << " " << k;
      EXPECT_LT(std::fabs(law.stiffness_over_elastic[k] - 1), 1e-6) << t::to_string(model) << " " << k;
      EXPECT_LT(std::fabs(law.separation_minus_elastic[k]), 1e-7 * law.surface.height_scale) << t::to_string(model) << " " << k;
      EXPECT_LT(std::fabs(law.at_pressures[k].separation - elastic->at_pressures[k].separation),
                1e-7 * law.surface.height_scale)
          << t::to_string(model) << " " << k << ": the origin convention";
    }
    EXPECT_EQ(law.curve.size(), elastic->curve.size());
  }
}

TEST(LawContact, KogutEtsionAgainstTheReferenceOnEachFit) {
  const t::SurfaceAnalysis& a = analysis();
  const double e = 1e11, y = 1e9, nu = 0.3;
  for (t::HeightModel model : t::all_height_models) {
    const t::LawContact law = t::compare_law(*a.contact, a.summits, model, "test", maker("kogut-etsion", y, nu));
    ASSERT_TRUE(law.served) << t::to_string(model) << ": " << law.note;
    const asperity::ContactLaw ke = asperity::kogut_etsion_law(a.summits.radius, e, y, nu);
    EXPECT_EQ(law.critical_interference, ke.critical_interference);
    asperity::test::SummitHeights heights;
    heights.distribution = law.surface.distribution;
    heights.side = law.surface.side;
    heights.shape = law.surface.shape;
    heights.scale = law.surface.height_scale;
    const double density = law.surface.summit_density;
    for (std::size_t k = 0; k < law.at_pressures.size(); ++k) {
      const asperity::PhysicalState& state = law.at_pressures[k];
      const asperity::test::RoughSurfaceValues exact =
          asperity::test::law_integrals(ke, heights, state.separation / heights.scale);
      const std::string where = std::string(t::to_string(model)) + " at " + std::to_string(state.pressure) + " Pa";
      EXPECT_LT(relative(density * exact.load, state.pressure), 1e-6) << where;
      EXPECT_LT(relative(density * exact.stiffness * a.contact->nominal_area, state.stiffness), 1e-5) << where;
      EXPECT_LT(relative(density * exact.area, state.area_fraction), 1e-5) << where;
      EXPECT_EQ(state.pressure, a.contact->pressures[k]);
    }
  }
}

// Every parameter the law takes, from the registry in the law's order, with the value it was made
// with: given, a default filled in, a choice as its index (issue 38, item 1); Hertz takes none.
TEST(LawContact, EveryParameterTheLawTakes) {
  const t::SurfaceAnalysis& a = analysis();
  asperity::cli::LawOptions options;
  options.law = "jackson-green";
  options.material.set(asperity::LawParameter::yield_strength, 1e9);
  options.material.set(asperity::LawParameter::poisson, 0.3);
  options.choice[static_cast<int>(asperity::LawParameter::geometric_hardness)] = "exponential";
  const t::LawContact law =
      t::compare_law(*a.contact, a.summits, t::HeightModel::gaussian, "test",
                     [options](const asperity::RoughSurface& surface, double s_min, double s_max, double approach) {
                       return asperity::cli::law_scene(options, surface, s_min, s_max, "test", approach);
                     });
  const asperity::ContactLawDescriptor* jg = asperity::find_contact_law("jackson-green");
  ASSERT_TRUE(jg);
  ASSERT_EQ(law.parameters.size(), static_cast<std::size_t>(jg->parameter_count));
  for (int k = 0; k < jg->parameter_count; ++k) {
    const asperity::LawParameter parameter = jg->parameters[k].parameter;
    EXPECT_EQ(law.parameters[k].parameter, parameter) << k;
    const double expected = parameter == asperity::LawParameter::yield_strength ? 1e9
                            : parameter == asperity::LawParameter::poisson      ? 0.3
                            : parameter == asperity::LawParameter::geometric_hardness
                                ? 1  // "exponential"
                                : NAN;
    EXPECT_EQ(law.parameters[k].value, expected) << asperity::law_parameter_info(parameter).key;
  }
  EXPECT_EQ(law.parameters_text, "Y = 1e+09 Pa, nu = 0.3, H_G = exponential");

  const t::LawContact hertz = t::compare_law(*a.contact, a.summits, t::HeightModel::gaussian, "test", maker("hertz"));
  EXPECT_TRUE(hertz.parameters.empty());
  EXPECT_EQ(hertz.parameters_text, "");
}

TEST(LawContact, AdhesiveLawAgainstTheReferenceWithItsPullOff) {
  // JKR asperities (the approach branch) on the Gaussian fit: the same positive pressures on the
  // stable branch, and the pull-off, each against the reference quadrature of the net load. A
  // work of adhesion of 0.5 J/m^2 on this hard surface leaves no measurable tension (adhesion
  // parameter ~100: stated, no pull-off); 200 J/m^2 stands in for a softer pair (parameter ~2)
  const t::SurfaceAnalysis& a = analysis();
  {
    asperity::cli::LawOptions options;
    options.law = "jkr";
    options.material.set(asperity::LawParameter::work_of_adhesion, 0.5);
    const t::LawSceneMaker weak = [options](const asperity::RoughSurface& surface, double s_min, double s_max, double approach) {
      return asperity::cli::law_scene(options, surface, s_min, s_max, "test", approach);
    };
    const t::LawContact law = t::compare_law(*a.contact, a.summits, t::HeightModel::gaussian, "test", weak);
    ASSERT_TRUE(law.served) << law.note;
    EXPECT_GT(law.adhesion_parameter, 20);
    EXPECT_TRUE(std::isnan(law.pull_off_pressure));
    ASSERT_FALSE(law.warnings.empty());
    EXPECT_NE(law.warnings.back().find("no pull-off"), std::string::npos);
  }
  const double e = 1e11, dgamma = 200;
  asperity::cli::LawOptions options;
  options.law = "jkr";
  options.material.set(asperity::LawParameter::work_of_adhesion, dgamma);
  const t::LawSceneMaker jkr = [options](const asperity::RoughSurface& surface, double s_min, double s_max, double approach) {
    return asperity::cli::law_scene(options, surface, s_min, s_max, "test", approach);
  };
  const t::LawContact law = t::compare_law(*a.contact, a.summits, t::HeightModel::gaussian, "test", jkr);
  ASSERT_TRUE(law.served) << law.note;
  EXPECT_TRUE(law.adhesive);
  EXPECT_LT(law.adhesion_parameter, 5);
  const asperity::ContactLaw exact_law = asperity::jkr_law(a.summits.radius, e, dgamma);
  EXPECT_DOUBLE_EQ(law.adhesion_parameter, asperity::adhesion_parameter(exact_law, law.summit_height_sd));
  EXPECT_TRUE(std::isnan(law.plasticity_index));
  asperity::test::SummitHeights heights;
  heights.distribution = law.surface.distribution;
  heights.scale = law.surface.height_scale;
  const double density = law.surface.summit_density, mean_summit = law.at_pressures[0].separation -
                                                                   law.at_pressures[0].mean_separation;
  const auto net_pressure = [&](double separation) {
    return density * asperity::test::law_integrals(exact_law, heights, separation / heights.scale).load;
  };
  for (std::size_t k = 0; k < law.at_pressures.size(); ++k) {
    const asperity::PhysicalState& state = law.at_pressures[k];
    EXPECT_LT(relative(net_pressure(state.separation), state.pressure), 1e-6) << state.pressure << " Pa";
    EXPECT_EQ(state.pressure, a.contact->pressures[k]);
    EXPECT_GT(state.count, 0);  // the law tables' summit count
  }
  // the pull-off: a tension, the least net pressure of the reference near it
  ASSERT_TRUE(std::isfinite(law.pull_off_pressure));
  EXPECT_LT(law.pull_off_pressure, 0);
  const double u = law.pull_off_mean_separation + mean_summit, p0 = net_pressure(u);
  EXPECT_LT(std::fabs(p0 - law.pull_off_pressure), 1e-6 * std::fabs(law.pull_off_pressure));
  for (double offset : {-1e-2, -1e-3, 1e-3, 1e-2})
    EXPECT_GE(net_pressure(u + offset * heights.scale), p0 - 1e-9 * std::fabs(p0)) << offset;

  // The withdrawal branch (asperity surface --approach-separation, issue 41 item 2): after an approach
  // 0.2 below the approach curves' first separation, at the same positive pressures, each against the
  // reference's fixed-grips quadrature after that approach; more tension, a greater pull-off
  const double s0 = law.separation_min - 0.2;
  const t::LawContact back = t::compare_law(*a.contact, a.summits, t::HeightModel::gaussian, "test", jkr, s0);
  ASSERT_TRUE(back.served) << back.note;
  EXPECT_EQ(back.approach_separation, s0);
  // from where its pressure covers the largest compared (the approach's start, or nearer s0), not below s0
  EXPECT_GE(back.separation_min, s0);
  EXPECT_LE(back.separation_min, law.separation_min);
  EXPECT_NE(back.regime.find("the withdrawal branch after an approach to s0"), std::string::npos) << back.regime;
  EXPECT_NE(back.note.find("the withdrawal after an approach to s0"), std::string::npos) << back.note;
  const asperity::test::ContactHistory history{true, s0};
  const auto withdrawn_pressure = [&](double separation) {
    return density * asperity::test::law_integrals(exact_law, heights, separation / heights.scale, history).load;
  };
  for (std::size_t k = 0; k < back.at_pressures.size(); ++k) {
    const asperity::PhysicalState& state = back.at_pressures[k];
    EXPECT_LT(relative(withdrawn_pressure(state.separation), state.pressure), 1e-6) << state.pressure << " Pa";
    EXPECT_LT(state.separation, law.at_pressures[k].separation);  // more tension: closer for the same pressure
  }
  ASSERT_TRUE(std::isfinite(back.pull_off_pressure));
  EXPECT_LT(back.pull_off_pressure, law.pull_off_pressure);
  const double uw = back.pull_off_mean_separation + mean_summit;
  EXPECT_LT(std::fabs(withdrawn_pressure(uw) - back.pull_off_pressure), 1e-6 * std::fabs(back.pull_off_pressure));
  // an approach that does not reach the largest pressure compared: the reason, no curves
  const t::LawContact shallow =
      t::compare_law(*a.contact, a.summits, t::HeightModel::gaussian, "test", jkr, law.separation_max);
  EXPECT_FALSE(shallow.served);
  EXPECT_NE(shallow.note.find("approach further"), std::string::npos) << shallow.note;
  // a law without adhesion has no withdrawal branch: refused before any work
  EXPECT_THROW(t::compare_law(*a.contact, a.summits, t::HeightModel::gaussian, "test", maker("hertz"), s0),
               asperity::Error);
}

TEST(LawContact, RefusalsAndLimits) {
  const t::SurfaceAnalysis& a = analysis();
  // the material, from the scene's checks: before any curve
  try {
    t::compare_law(*a.contact, a.summits, t::HeightModel::gaussian, "test", maker("chang-etsion-bogy", NAN, 0.3));
    ADD_FAILURE() << "no hardness accepted";
  } catch (const asperity::Error& error) {
    EXPECT_NE(std::string(error.what()).find("chang-etsion-bogy needs --hardness"), std::string::npos) << error.what();
  }
  // a fit without elastic curves has nothing to set the law beside
  t::ContactComparison without = *a.contact;
  for (t::ModelContact& m : without.models)
    if (m.kind == t::ContactModelKind::gaussian) m.served = false;
  EXPECT_THROW(t::compare_law(without, a.summits, t::HeightModel::gaussian, "test", maker("hertz")), asperity::Error);
  // a yield strength so low that the real area passes 1 within the pressures: stated, psi still given
  const t::LawContact soft =
      t::compare_law(*a.contact, a.summits, t::HeightModel::gaussian, "test", maker("kogut-etsion", 1e5, 0.3));
  EXPECT_FALSE(soft.served);
  EXPECT_EQ(soft.note.rfind("no curves over the pressures 1e+05 to 3e+07 Pa", 0), 0u) << soft.note;
  EXPECT_TRUE(soft.at_pressures.empty());
  EXPECT_GT(soft.plasticity_index, 1);
  EXPECT_GT(soft.gw_plasticity_index, 1);
}
