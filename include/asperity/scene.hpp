// A scene: the few curves one program needs (docs/scenes.md). Read from a TOML file:
//
//   name = "journal bearing"        # optional
//   max_rel_error = 1e-8            # default for every curve (1e-13 .. 1e-2)
//   memory_budget_kib = 64          # optional: the generator fails if the table would be larger
//
//   [[curve]]
//   name = "pad"                    # optional
//   distribution = "weibull"        # or "gaussian"
//   shape = 1.73                    # Weibull shape a in [0.3, 50] (not for the Gaussian)
//   side = "bounded"                # "tail" (default) or "bounded" (Weibull only)
//   quantities = ["load", "stiffness"]   # count, stiffness, area, load, F2, F5/2 ...
//   orders = [1.5, 0.5]             # ... or the orders n themselves (one of the two)
//   separation = [-2.0, -0.01]      # the separations the program visits, origin convention
//   load = [1e-6, 1e-2]             # ... or the range of X_3/2 it visits (one of the two)
//   max_rel_error = 1e-10           # optional, overrides the scene's
//
// A scene may instead name a contact law (docs/contact-laws.md section 8): one [[law]] and no
// [[curve]]; tablegen tabulates that law's rough-surface pressure, stiffness and area fraction
// against separation as a contact-curves table (contact_curves_data.hpp):
//
//   [[law]]
//   name = "steel pad"              # optional
//   law = "kogut-etsion"            # a law's name (contact_law_registry.hpp: hertz, chang-etsion-bogy, ...)
//   contact_modulus = 1.15e11       # E* [Pa] (every law)
//   yield_strength = 1.0e9          # the law's parameters, by the registry's keys: which law takes
//   poisson = 0.3                   # which, with units and ranges, is its descriptor's (docs/contact-laws.md)
//   distribution = "gaussian"       # summit heights: as a [[curve]]'s (shape, side)
//   height_scale = 1e-6             # sigma_s [m]
//   summit_radius = 1e-4            # R [m]
//   summit_density = 1e10           # summits per m^2
//   nominal_area = 1e-4             # A0 [m^2]
//   separation = [-1.0, 4.0]        # dimensionless s (origin convention), the range served
//   max_rel_error = 1e-6            # optional (1e-10 .. 1e-2; default the scene's, 1e-8)
//   approach_separation = -1.0      # optional, an adhesive law's (dmt, jkr, maugis-dugdale): the
//                                   # withdrawal branch after an approach to this s (<= the range's
//                                   # lower end) instead of the approach branch
//
// Errors name the file, the line and the key (asperity::Error). A scene file is untrusted input
// (docs/reliability.md): before TOML parsing it must be valid UTF-8 without control characters,
// at most scene_max_bytes long, nested at most scene_max_nesting deep, with at most
// scene_max_list_entries commas; after it, at most scene_max_curves curves and names of at most
// scene_max_name_bytes. Anything else is refused quickly, with the limit in the message.
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "asperity/contact_law.hpp"
#include "asperity/contact_law_registry.hpp"
#include "asperity/error.hpp"
#include "asperity/integrals.hpp"

namespace asperity {

struct SceneCurve {
  std::string name;
  Distribution distribution = Distribution::weibull;
  Side side = Side::tail;
  double shape = 2.0;                // 2 for the Gaussian (its exponent is s^2/2)
  std::vector<int> twice_orders;     // sorted, distinct, in 0..5
  bool by_load = false;              // the range below is of X_3/2, not of separation
  double range_min = 0, range_max = 0;
  double max_rel_error = 1e-8;
  int line = 0;                      // where the curve starts in the file
};

// A contact law on a physical surface (see the top of this file)
struct SceneLaw {
  std::string name;
  ContactLaw law;                    // made by its factory (radius: summit_radius)
  Distribution distribution = Distribution::gaussian;
  Side side = Side::tail;
  double shape = 2.0;
  double height_scale = 0;           // sigma_s [m]
  double summit_radius = 0;          // R [m]
  double summit_density = 0;         // [1/m^2]
  double nominal_area = 0;           // A0 [m^2]
  double range_min = 0, range_max = 0;  // dimensionless separation s
  double max_rel_error = 1e-8;
  // NaN: the approach (loading) branch. Otherwise the withdrawal (unloading, fixed grips) branch
  // after an approach to this dimensionless separation s0 <= range_min: a summit that touched
  // there stays in contact down to its law's lowest interference (docs/contact-laws.md section 8).
  double approach_separation = 0.0 / 0.0;
  int line = 0;

  bool withdrawal() const noexcept { return approach_separation == approach_separation; }
};

struct Scene {
  std::string name;
  std::string source;                // the file it came from (for messages)
  double memory_budget_bytes = 0;    // 0: no budget
  std::vector<SceneCurve> curves;
  std::vector<SceneLaw> laws;        // at most one, and then no curves
};

// The tolerances a law scene may ask (its exact values are quadratures to ~1e-13)
inline constexpr double scene_law_error_min = 1e-10;

// A [[law]]'s values, typed: what a scene file, the command line (asperity contact --law) and
// Python (asperity.law_curves) give. NaN: not given.
struct SceneLawInputs {
  std::string name;
  ContactLawKind law = ContactLawKind::hertz;
  LawValues material;                // the law's parameters (contact_law_registry.hpp)
  double contact_modulus = 0.0 / 0.0;
  Distribution distribution = Distribution::gaussian;
  bool side_given = false;
  Side side = Side::tail;
  double shape = 0.0 / 0.0;          // the Weibull's (not for the Gaussian)
  double height_scale = 0.0 / 0.0, summit_radius = 0.0 / 0.0, summit_density = 0.0 / 0.0, nominal_area = 0.0 / 0.0;
  double range_min = 0.0 / 0.0, range_max = 0.0 / 0.0;  // separation [s_min, s_max]
  double max_rel_error = 0.0 / 0.0;  // NaN: the default given to make_scene_law
  double approach_separation = 0.0 / 0.0;  // NaN: the approach branch (SceneLaw's)
};

// A [[law]]'s keys beyond its material's, and what the command line and Python call each.
struct SceneLawKey {
  const char* key;      // in a scene file ("height_scale")
  const char* option;   // on the command line ("--sigma")
  const char* keyword;  // in Python (asperity.law_curves's keyword)
};
inline constexpr SceneLawKey scene_law_keys[] = {
    {"name", "", "name"},
    {"law", "--law", "law"},
    {"contact_modulus", "--modulus", "contact_modulus"},
    {"distribution", "--dist", "distribution"},
    {"shape", "--shape", "shape"},
    {"side", "--side", "side"},
    {"height_scale", "--sigma", "height_scale"},
    {"summit_radius", "--radius", "summit_radius"},
    {"summit_density", "--density", "summit_density"},
    {"nominal_area", "--area", "nominal_area"},
    {"separation", "--law-range", "separation"},
    {"max_rel_error", "--law-tolerance", "max_rel_error"},
    {"approach_separation", "--approach-separation", "approach_separation"},
};
// The name of a [[law]] key (its own or its material's) in `naming`'s vocabulary ('key', --option, keyword=).
std::string scene_law_key_name(const std::string& key, LawNaming naming);

// A law scene's input refused: `key` is the scene key at fault ("" for the law as a whole).
class SceneLawError : public Error {
 public:
  SceneLawError(std::string key, const std::string& message, std::string label)
      : Error(message), key(std::move(key)), label(std::move(label)) {}
  std::string key, label;
};

// The law scene of typed inputs, every check of a [[law]] applied in one place (the scene reader,
// the command line and Python call it); messages name the inputs in `naming`'s vocabulary.
// Throws SceneLawError.
SceneLaw make_scene_law(const SceneLawInputs& inputs, LawNaming naming, double default_tolerance = 1e-8);
// A law scene's max_rel_error: `asked` checked (NaN: the default, at least scene_law_error_min).
double checked_law_tolerance(double asked, double default_tolerance, LawNaming naming);

// The limits a scene is checked against (a shape: integrals.hpp's weibull_shape_min .. weibull_shape_max).
inline constexpr double scene_error_min = 1e-13, scene_error_max = 1e-2;
inline constexpr std::size_t scene_max_bytes = 64 * 1024;
inline constexpr int scene_max_nesting = 4;          // [ and { (a [[curve]] header counts 2)
inline constexpr int scene_max_list_entries = 1024;  // commas outside strings and comments
inline constexpr std::size_t scene_max_curves = 64;
inline constexpr std::size_t scene_max_name_bytes = 256;

Scene read_scene_file(const std::string& path);
// `source` names the text in messages.
Scene parse_scene(const std::string& text, const std::string& source);

// Twice the order of a quantity's integral: count 0, stiffness 1, area 2, load 3, F2 4, F5/2 5;
// -1 for a name that is not a quantity.
int quantity_twice_order(const std::string& quantity);

}  // namespace asperity
