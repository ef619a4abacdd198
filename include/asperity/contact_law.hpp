// Contact laws: what one spherical asperity of radius R carries at interference omega (load,
// contact area, normal stiffness dP/domega), one definition per law, with the points where a law
// changes its formula (its switch points) and where its source stops supporting it.
// docs/model.md "Contact laws" gives the formulas; docs/contact-laws.md the sources, the
// measured continuity at every switch point and the rough-surface curves.
//
// Every function is pure, noexcept and allocation-free: bad input (a NaN, a non-positive radius,
// modulus, hardness...) gives NaN, never an exception. A law is made once by its factory
// (which computes its critical interference and constants) and evaluated many times.
//
// Units: SI throughout (R, omega in m; E*, H, Y in Pa; work of adhesion in J/m^2 = N/m).
// E* is the contact modulus, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (asperity::contact_modulus_from).
#pragma once
#include "asperity/law_combination.hpp"  // Hertz's numbers (hertz_combination), shared with the kernels

namespace asperity {

// The built-in laws, one line each, in the order messages list them: X(kind, descriptor), the
// descriptor defined in runtime/core/laws/ (contact_law_registry.hpp: what each law takes).
//   hertz               elastic (Hertz)
//   chang_etsion_bogy   CEB 1987: Hertz to omega_c, then volume conservation at mean pressure K H
//   zhao_maietta_chang  ZMC 2000: Hertz to omega_1, cubic blend to 54 omega_1, then fully plastic
//   kogut_etsion        KE 2002: FE fits on [1, 6] and [6, 110] omega_c, fully plastic beyond
//   jackson_green       JG 2005: Hertz to 1.9 omega_c, then FE fits with a geometric hardness
//   dmt                 Derjaguin-Muller-Toporov: Hertz less the pull-off 2 pi dgamma R
//   jkr                 Johnson-Kendall-Roberts (Maugis-Dugdale's lambda -> infinity)
//   maugis_dugdale      Maugis-Dugdale 1992 through the Maugis parameter lambda (DMT .. JKR)
#define ASPERITY_BUILT_IN_CONTACT_LAWS(X)                                                         \
  X(hertz, hertz_law_descriptor)                                                                 \
  X(chang_etsion_bogy, chang_etsion_bogy_law_descriptor)                                         \
  X(zhao_maietta_chang, zhao_maietta_chang_law_descriptor)                                       \
  X(kogut_etsion, kogut_etsion_law_descriptor)                                                   \
  X(jackson_green, jackson_green_law_descriptor)                                                 \
  X(dmt, dmt_law_descriptor)                                                                     \
  X(jkr, jkr_law_descriptor)                                                                     \
  X(maugis_dugdale, maugis_dugdale_law_descriptor)

// A law's kind: the built-ins', then those a program registers (contact_law_registry.hpp), which
// take the values after built_in_contact_law_count.
enum class ContactLawKind : int {
#define ASPERITY_LAW_KIND(kind, descriptor) kind,
  ASPERITY_BUILT_IN_CONTACT_LAWS(ASPERITY_LAW_KIND)
#undef ASPERITY_LAW_KIND
};
inline constexpr int built_in_contact_law_count = 0
#define ASPERITY_LAW_COUNT(kind, descriptor) +1
    ASPERITY_BUILT_IN_CONTACT_LAWS(ASPERITY_LAW_COUNT)
#undef ASPERITY_LAW_COUNT
    ;

// The name used in files and messages ("hertz", "chang-etsion-bogy", "zhao-maietta-chang",
// "kogut-etsion", "jackson-green", "dmt", "jkr", "maugis-dugdale", or a registered law's);
// "unknown" for a kind no law has.
const char* contact_law_name(ContactLawKind kind) noexcept;
// The kind of such a name; false (and `kind` untouched) for a name that is not a law's.
bool contact_law_kind_of(const char* name, ContactLawKind& kind) noexcept;

// Jackson-Green's geometric hardness H_G/S_y as a function of a/R, named by its formula:
//   cosine       2.84 - 0.92 (1 - cos(pi a/R))       (Jackson & Green 2006, Tribol. Int. 39, 906)
//   exponential  2.84 (1 - exp(-0.82 (a/R)^-0.7))    (Jackson & Green 2005, J. Tribol. 127, 343)
// The old names had the years the wrong way round; kept, deprecated, for the same formulas.
enum class JacksonGreenHardness {
  cosine,
  exponential,
  cosine_2005 [[deprecated("the cosine form is Jackson & Green 2006's: JacksonGreenHardness::cosine")]] = cosine,
  exponential_2006 [[deprecated("the exponential form is Jackson & Green 2005's: JacksonGreenHardness::exponential")]] =
      exponential,
};

// What one asperity carries at one interference.
struct AsperityResponse {
  double load;       // P [N]; negative is tension (adhesion)
  double area;       // A [m^2]: the contact area (pi a^2; for Maugis-Dugdale the repulsive disc a)
  double stiffness;  // dP/domega [N/m] (left derivative at a switch point where P jumps)
};

// At most four switch points, increasing: omega where a law changes formula (and where its
// rough-surface integrals are split: what a table must put a knot at).
struct SwitchPoints {
  int count = 0;
  double interference[4] = {0, 0, 0, 0};
};

// A law with its parameters and the constants its factory derived. Make it by a factory below;
// a default-constructed or badly parametrized law answers NaN.
struct ContactLaw {
  ContactLawKind kind = ContactLawKind::hertz;
  double radius = 0;                 // R [m]
  double modulus = 0;                // E* [Pa]
  double hardness = 0;               // H [Pa] (CEB, ZMC; KE: 2.8 Y)
  double yield_strength = 0;         // Y = S_y [Pa] (KE, JG)
  double poisson = 0;                // nu of the deforming asperity (CEB, KE: K; JG: C)
  double pressure_factor = 0;        // CEB, KE: K = 0.454 + 0.41 nu; ZMC: its K (0.6 in the paper)
  double work_of_adhesion = 0;       // Delta gamma [J/m^2] (DMT, JKR, MD)
  double maugis_parameter = 0;       // lambda (MD)
  JacksonGreenHardness jackson_green_hardness = JacksonGreenHardness::cosine;
  // derived by the factory
  double critical_interference = 0;  // omega_c: CEB, KE, JG (first yield); ZMC omega_1; adhesive: the length scale
  double critical_load = 0;          // P_c: the Hertz load at omega_c (ZMC: K H pi R omega_1); adhesive: pi dgamma R
  double critical_area = 0;          // A_c = pi R omega_c; adhesive: pi a_s^2
  double jackson_green_b = 0;        // B = 0.14 exp(23 S_y/E*)
  double jackson_green_c = 0;        // C = 1.295 exp(0.736 nu)
  double md_turning = 0;             // MD: the parameter t = sqrt(m^2 - 1) where the stable branch ends (inf: none)
  double lowest_interference = 0;    // the least omega in contact: 0, or < 0 for JKR/MD (unloading, fixed grips)
  double valid_up_to = 0;            // the largest omega the law's source supports (+inf: every omega)
};

// Factories. NaN-filled (kind set, every derived value NaN) for bad parameters.
ContactLaw hertz_law(double radius, double modulus) noexcept;
// CEB 1987: omega_c = (pi K H / (2 E*))^2 R, K = 0.454 + 0.41 nu; beyond omega_c
// A = pi R (2 omega - omega_c), P = K H A.
ContactLaw chang_etsion_bogy_law(double radius, double modulus, double hardness, double poisson) noexcept;
// ZMC 2000: omega_1 = (3 pi K H / (4 E*))^2 R, omega_2 = 54 omega_1 (K = 0.6 in the paper).
ContactLaw zhao_maietta_chang_law(double radius, double modulus, double hardness, double pressure_factor = 0.6) noexcept;
// KE 2002: H = 2.8 Y, K = 0.454 + 0.41 nu, omega_c = (pi K H / (2 E*))^2 R.
ContactLaw kogut_etsion_law(double radius, double modulus, double yield_strength, double poisson) noexcept;
// JG 2005: omega_c = (pi C S_y / (2 E*))^2 R, C = 1.295 exp(0.736 nu).
ContactLaw jackson_green_law(double radius, double modulus, double yield_strength, double poisson,
                             JacksonGreenHardness hardness = JacksonGreenHardness::cosine) noexcept;
ContactLaw dmt_law(double radius, double modulus, double work_of_adhesion) noexcept;
ContactLaw jkr_law(double radius, double modulus, double work_of_adhesion) noexcept;
// lambda = 2 sigma_0 (R / (pi dgamma K^2))^(1/3), K = (4/3) E* (Maugis 1992; sigma_0 the Dugdale
// stress, h_0 = dgamma / sigma_0 its range). lambda > 0.
ContactLaw maugis_dugdale_law(double radius, double modulus, double work_of_adhesion, double maugis_parameter) noexcept;

// P, A, dP/domega at interference omega [m]. Out of contact (omega below the law's lowest
// interference) every field is 0. NaN for a NaN omega or a bad law. For JKR and MD, omega
// between the lowest interference and 0 is the stable (fixed-grips) branch an asperity follows
// while it is pulled off after contact; the caller decides which asperities are in contact.
AsperityResponse asperity_response(const ContactLaw& law, double interference) noexcept;

// The load split into a compressive and a tensile part, P = compressive - tensile, each >= 0,
// with their derivatives in omega: the Hertz-like term K a^3 / R of the contact radius a
// (K = (4/3) E*) and the adhesive term. DMT: Hertz, and 2 pi dgamma R; JKR: K a^3/R and
// sqrt(8 pi dgamma E* a^3); Maugis-Dugdale: K a^3/R and the Dugdale zone's
// pi dgamma R lambda A^2 (t + m^2 atan t) (A, t, m as in maugis_dugdale_point below);
// every other law: (P, 0). On each law's stable branch both parts grow with omega, so that a
// rough surface's mean of each is positive and monotone in the separation (what a contact-curves
// table stores of an adhesive law: docs/contact-laws.md section 8). Zeros out of contact, NaN for
// a NaN omega or a bad law, like asperity_response.
struct AsperityLoadSplit {
  double compressive = 0, tensile = 0;                      // [N]
  double compressive_stiffness = 0, tensile_stiffness = 0;  // d/domega [N/m]
};
AsperityLoadSplit asperity_load_split(const ContactLaw& law, double interference) noexcept;
// Whether the law's load has a tensile part (DMT, JKR, Maugis-Dugdale: the adhesive family).
bool is_adhesive(ContactLawKind kind) noexcept;

// The omegas where the formula changes (KE: omega_c, 6 omega_c, 110 omega_c; JG: 1.9 omega_c;
// CEB: omega_c; ZMC: omega_1, 54 omega_1; DMT: 0, where the load jumps; JKR, MD: none inside
// the stable branch). Empty for a bad law.
SwitchPoints switch_points(const ContactLaw& law) noexcept;

// The plasticity index psi = sqrt(sigma_s / omega_c), sigma_s the summit height scale [m]
// (Kogut-Etsion 2003: psi = (2 E* / (pi K H)) sqrt(sigma_s / R), which is this with the CEB/KE
// omega_c). For laws without omega_c (Hertz, adhesive) NaN.
double plasticity_index(const ContactLaw& law, double summit_scale) noexcept;
// Greenwood-Williamson's psi = (E*/H) sqrt(sigma_s / R).
double greenwood_williamson_plasticity_index(double modulus, double hardness, double summit_scale,
                                             double radius) noexcept;
// Fuller & Tabor's (1975) adhesion parameter sigma_s / delta_c for an adhesive law (DMT, JKR,
// MD), delta_c = (3/4)(pi^2 dgamma^2 R / E*^2)^(1/3) the approach at which one JKR asperity
// separates under fixed grips: the larger, the less of the smooth surfaces' adhesion survives the
// roughness (docs/contact-laws.md section 5). NaN for a law without adhesion.
double adhesion_parameter(const ContactLaw& law, double summit_scale) noexcept;

// Maugis-Dugdale in its dimensionless form (Maugis 1992; Johnson & Greenwood 1997): lengths
// a = A a_s, a_s = (pi dgamma R^2 / K)^(1/3); interference omega = D d_s, d_s = a_s^2 / R;
// load P = Pbar pi dgamma R. `parameter` t = sqrt(m^2 - 1), m = c/a the Dugdale zone's ratio.
struct MaugisDugdalePoint {
  double t, contact_radius, interference, load;  // t, A, D, Pbar (dimensionless)
};
MaugisDugdalePoint maugis_dugdale_point(double maugis_parameter, double t) noexcept;

}  // namespace asperity
