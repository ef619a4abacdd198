// The contact-law registry (asperity/contact_law_registry.hpp), and the recipe for a new law
// (docs/architecture.md "Recipes") proved by following it in the test build: one more law is
// registered here, and the registry's readers take it without a change of their own: the typed
// constructor and its checks, the scene reader, the generator's tabulation (against the law's
// closed form on the Gaussian), the command line's options and help, the summaries.
//
// The law: Abbott & Firestone's (1933) fully plastic asperity, A = 2 pi R omega, P = H A. On a
// Gaussian of summit heights its rough-surface means have closed forms (Greenwood & Williamson
// 1966): p = 2 pi eta R sigma H F1(s), A/A0 = 2 pi eta R sigma F1(s), k = 2 pi eta R H F0(s),
// F0 = Q(s), F1 = phi(s) - s Q(s): the reference shares no code with the generator.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "asperity/contact_curves.hpp"
#include "asperity/contact_law.hpp"
#include "asperity/contact_law_registry.hpp"
#include "asperity/error.hpp"
#include "asperity/generator/law_curves.hpp"
#include "asperity/scene.hpp"
#ifdef ASPERITY_TEST_LAW_OPTIONS
#include "law_options.hpp"
#endif

namespace {
using namespace asperity;

constexpr double pi = 3.14159265358979323846;

// ---- the new law: what its file runtime/core/laws/NAME.cpp would hold ----
ContactLaw make_abbott_firestone(double radius, double modulus, const LawValues& values) noexcept {
  ContactLaw law;
  law.radius = radius;
  law.modulus = modulus;
  law.hardness = values[LawParameter::hardness];
  law.lowest_interference = 0;
  law.valid_up_to = std::numeric_limits<double>::infinity();
  law.critical_interference = std::numeric_limits<double>::quiet_NaN();
  if (!(radius > 0 && modulus > 0 && law.hardness > 0)) law.lowest_interference = law.critical_interference;
  return law;
}

AsperityResponse abbott_firestone_response(const ContactLaw& law, double w) noexcept {
  const double area = 2 * pi * law.radius * w;
  return {law.hardness * area, area, 2 * pi * law.radius * law.hardness};
}

constexpr LawParameterUse abbott_firestone_parameters[] = {{LawParameter::hardness, true, 0}};

// Its family is `elastic` though the law is fully plastic: a family says what figure tells the
// law's regime (contact_law_registry.hpp), and none of the three fits. `elastic_plastic`'s figure
// is the plasticity index (sigma_s / omega_c)^1/2 with the law's omega_c of first yield, which a
// law that yields at first touch does not have (omega_c would be 0 and psi infinite at every load;
// this law leaves omega_c NaN, so `asperity contact --law` would print omega_c and psi as nan);
// `adhesive`'s is Fuller-Tabor's parameter.
// `elastic` states no figure, which is right for a law with no transition to tell: the report
// still gives GW's (E*/H)(sigma_s/R)^1/2 from its hardness. A `plastic` family would be a change
// of the registry's vocabulary (every switch over LawFamily), not of this test's law.
const ContactLawDescriptor abbott_firestone = {
    ContactLawKind::hertz,  // the registry gives the kind
    "abbott-firestone", "Abbott-Firestone 1933", "fully plastic: A = 2 pi R omega, P = H A",
    LawFamily::elastic, abbott_firestone_parameters, 1, make_abbott_firestone, abbott_firestone_response,
    nullptr, 0, {0, 0, 0, 0}, false};

ContactLawKind registered() {
  static const ContactLawKind kind = register_contact_law(abbott_firestone);
  return kind;
}

// ---- the recipe, followed ----

TEST(LawRegistry, BuiltInsAreListedOnceInTheirOrder) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < static_cast<std::size_t>(built_in_contact_law_count); ++i) {
    const ContactLawDescriptor& law = contact_law_at(i);
    EXPECT_EQ(static_cast<std::size_t>(law.kind), i) << law.name;
    EXPECT_TRUE(names.insert(law.name).second) << law.name;
    EXPECT_EQ(find_contact_law(law.kind), &law);
    EXPECT_EQ(find_contact_law(std::string(law.name)), &law);
    EXPECT_STREQ(contact_law_name(law.kind), law.name);
  }
  EXPECT_EQ(contact_law_at(0).name, std::string("hertz"));
  EXPECT_EQ(laws_taking(LawParameter::yield_strength), "kogut-etsion or jackson-green");
  EXPECT_EQ(laws_taking(LawParameter::work_of_adhesion), "dmt, jkr or maugis-dugdale");
  // every parameter is listed once, in its enum's order
  for (int k = 0; k < law_parameter_count; ++k)
    EXPECT_EQ(static_cast<int>(law_parameters_begin()[k].id), k);
}

// The parameters' one list: the table is in the enum's order, the key is the enum's name, and
// Jackson-Green's geometric hardness is chosen by its formula (the years were the wrong way round
// before 0.3: refused, the message says why), the cosine form the default.
TEST(LawRegistry, ParametersFromTheirOneList) {
  ASSERT_EQ(law_parameters_end() - law_parameters_begin(), law_parameter_count);
  for (int k = 0; k < law_parameter_count; ++k)
    EXPECT_EQ(static_cast<int>(law_parameters_begin()[k].id), k) << law_parameters_begin()[k].key;
  EXPECT_STREQ(law_parameter_info(LawParameter::yield_strength).key, "yield_strength");
  EXPECT_STREQ(law_parameter_info(LawParameter::maugis_parameter).option, "--maugis-parameter");
  double index = -1;
  EXPECT_TRUE(law_choice_index(LawParameter::geometric_hardness, "cosine", index));
  EXPECT_EQ(index, 0);
  EXPECT_TRUE(law_choice_index(LawParameter::geometric_hardness, "exponential", index));
  EXPECT_EQ(index, 1);
  for (const char* year : {"2005", "2006"}) EXPECT_FALSE(law_choice_index(LawParameter::geometric_hardness, year, index));
  EXPECT_NE(std::string(law_parameter_info(LawParameter::geometric_hardness).range_text).find("2005 and 2006 are not taken"),
            std::string::npos);
  const ContactLaw jg = make_contact_law(ContactLawKind::jackson_green, 1e-4, 1e11,
                                         LawValues().set(LawParameter::yield_strength, 1e9).set(LawParameter::poisson, 0.3));
  EXPECT_EQ(jg.jackson_green_hardness, JacksonGreenHardness::cosine);
  EXPECT_EQ(law_parameters_text(jg), "Y = 1e+09 Pa, nu = 0.3, H_G = cosine");
}

TEST(LawRegistry, TypedConstructionEqualsTheFactories) {
  LawValues values;
  values.set(LawParameter::yield_strength, 1e9).set(LawParameter::poisson, 0.3);
  const ContactLaw typed = make_contact_law(ContactLawKind::kogut_etsion, 1e-4, 1.13e11, values);
  const ContactLaw factory = kogut_etsion_law(1e-4, 1.13e11, 1e9, 0.3);
  EXPECT_EQ(typed.critical_interference, factory.critical_interference);
  for (double w : {1e-9, 3e-8, 1e-6, 1e-5})
    EXPECT_EQ(asperity_response(typed, w).load, asperity_response(factory, w).load);
  // an optional parameter takes its default: ZMC's K = 0.6, Jackson-Green's cosine H_G
  LawValues zmc;
  zmc.set(LawParameter::hardness, 2e9);
  EXPECT_EQ(make_contact_law(ContactLawKind::zhao_maietta_chang, 1e-4, 1e11, zmc).pressure_factor, 0.6);
  // refusals name the parameter in the caller's vocabulary
  try {
    make_contact_law(ContactLawKind::hertz, 1e-4, 1e11, zmc, LawNaming::option);
    ADD_FAILURE() << "hertz took a hardness";
  } catch (const LawValuesError& error) {
    EXPECT_EQ(error.parameter, LawParameter::hardness);
    EXPECT_STREQ(error.what(), "--hardness does not apply to --law hertz");
  }
  try {
    make_contact_law(ContactLawKind::kogut_etsion, 1e-4, 1e11, LawValues().set(LawParameter::poisson, 0.3),
                     LawNaming::keyword);
    ADD_FAILURE() << "kogut-etsion made without its yield strength";
  } catch (const LawValuesError& error) {
    EXPECT_STREQ(error.what(), "kogut-etsion needs yield_strength=");
  }
  EXPECT_THROW(make_contact_law(ContactLawKind::chang_etsion_bogy, 1e-4, 1e11,
                                LawValues().set(LawParameter::hardness, 1e9).set(LawParameter::poisson, 0.7)),
               LawValuesError);
}

TEST(LawRegistry, RegistrationRefusesWhatItCannotServe) {
  registered();
  ContactLawDescriptor copy = abbott_firestone;
  EXPECT_THROW(register_contact_law(copy), Error);  // the name exists
  copy.name = "Bad Name";
  EXPECT_THROW(register_contact_law(copy), Error);
  copy.name = "no-response";
  copy.response = nullptr;
  EXPECT_THROW(register_contact_law(copy), Error);
}

TEST(LawRegistry, ANewLawReachesEveryReader) {
  const ContactLawKind kind = registered();
  EXPECT_GE(static_cast<int>(kind), built_in_contact_law_count);
  EXPECT_STREQ(contact_law_name(kind), "abbott-firestone");
  EXPECT_NE(contact_law_names().find("maugis-dugdale or abbott-firestone"), std::string::npos);
  EXPECT_EQ(laws_taking(LawParameter::hardness), "chang-etsion-bogy, zhao-maietta-chang or abbott-firestone");

  // the typed constructor, the dispatch and the summaries
  const ContactLaw law = make_contact_law(kind, 1e-4, 1e11, LawValues().set(LawParameter::hardness, 2e9));
  EXPECT_EQ(law.kind, kind);
  EXPECT_DOUBLE_EQ(asperity_response(law, 1e-7).load, 2e9 * 2 * pi * 1e-4 * 1e-7);
  EXPECT_EQ(asperity_response(law, 0).load, 0);
  EXPECT_EQ(switch_points(law).count, 0);
  EXPECT_EQ(law_parameters_text(law), "H = 2e+09 Pa");

  // a scene file names it, and its keys are checked as any law's
  const std::string surface =
      "distribution = \"gaussian\"\nheight_scale = 1e-6\nsummit_radius = 1e-4\nsummit_density = 4e8\n"
      "nominal_area = 1e-4\nseparation = [-1.0, 3.0]\nmax_rel_error = 1e-8\n";
  const Scene scene = parse_scene("[[law]]\nlaw = \"abbott-firestone\"\ncontact_modulus = 1e11\nhardness = 2e9\n" +
                                      surface, "test");
  ASSERT_EQ(scene.laws.size(), 1u);
  EXPECT_EQ(scene.laws[0].law.kind, kind);
  try {
    parse_scene("[[law]]\nlaw = \"abbott-firestone\"\ncontact_modulus = 1e11\nhardness = 2e9\npoisson = 0.3\n" +
                    surface, "test");
    ADD_FAILURE() << "abbott-firestone took a Poisson's ratio";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("'poisson' does not apply to abbott-firestone"), std::string::npos)
        << error.what();
  }

  // the generator tabulates it; the served curves against the closed forms
  const ContactCurves curves(generator::generate_law_curves(scene.laws[0], "test").data);
  const double eta = 4e8, r = 1e-4, sigma = 1e-6, h = 2e9;
  double worst = 0;
  for (double s = -1; s <= 3; s += 1.0 / 16) {
    const double q = 0.5 * std::erfc(s / std::sqrt(2.0)), phi = std::exp(-0.5 * s * s) / std::sqrt(2 * pi);
    const double f1 = phi - s * q;
    const ContactCurvesState at = curves.at_separation(s * sigma);
    worst = std::max({worst, std::fabs(at.pressure / (2 * pi * eta * r * sigma * h * f1) - 1),
                      std::fabs(at.area_fraction / (2 * pi * eta * r * sigma * f1) - 1),
                      std::fabs(at.stiffness / (2 * pi * eta * r * h * q) - 1)});
  }
  EXPECT_LT(worst, 1e-8) << "asked 1e-8";
  EXPECT_NE(curves.data().description.find("abbott-firestone: E* = 1e+11 Pa, H = 2e+09 Pa"),
            std::string::npos)
      << curves.data().description;

#ifdef ASPERITY_TEST_LAW_OPTIONS
  // the command line's options and help (apps/asperity/law_options.hpp) take it too
  CLI::App app;
  cli::LawOptions options;
  cli::add_law_options(app, options, "a law", "", "at or below the range's start");
  const std::string help = app.help();
  // --approach-separation's help names the adhesive laws from the registry (the work of adhesion's takers)
  EXPECT_NE(help.find("with --law dmt, jkr or maugis-dugdale: the withdrawal (unloading, fixed grips) branch"),
            std::string::npos)
      << help;
  EXPECT_NE(help.find("maugis-dugdale or abbott-firestone"), std::string::npos) << help;
  EXPECT_NE(help.find("with --law chang-etsion-bogy, zhao-maietta-chang or abbott-firestone: hardness H [Pa]"),
            std::string::npos)
      << help;
  app.parse(std::vector<std::string>{"2e9", "--hardness", "abbott-firestone", "--law"});  // reversed: CLI11's order
  EXPECT_EQ(cli::law_kind(options), kind);
  RoughSurface gaussian;
  gaussian.distribution = Distribution::gaussian;
  gaussian.height_scale = sigma;
  gaussian.summit_radius = r;
  gaussian.summit_density = eta;
  gaussian.nominal_area = 1e-4;
  gaussian.contact_modulus = 1e11;
  EXPECT_EQ(cli::law_scene(options, gaussian, -1, 3, "test").law.hardness, h);
#endif
}

}  // namespace
