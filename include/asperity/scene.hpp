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
//   law = "kogut-etsion"            # hertz, chang-etsion-bogy, zhao-maietta-chang, kogut-etsion, jackson-green,
//                                   # dmt, jkr, maugis-dugdale (contact_law.hpp's names)
//   contact_modulus = 1.15e11       # E* [Pa] (every law)
//   yield_strength = 1.0e9          # Y [Pa]: kogut-etsion, jackson-green
//   hardness = 2.0e9                # H [Pa]: chang-etsion-bogy, zhao-maietta-chang
//   poisson = 0.3                   # nu: chang-etsion-bogy, kogut-etsion, jackson-green
//   pressure_factor = 0.6           # zhao-maietta-chang's K (optional, 0.6)
//   geometric_hardness = "2005"     # jackson-green's H_G: "2005" (cosine, default) or "2006"
//   work_of_adhesion = 0.5          # dgamma [J/m^2]: dmt, jkr, maugis-dugdale (the approach branch
//                                   # is tabulated: contact-curves with a tensile part)
//   maugis_parameter = 1.0          # lambda > 0: maugis-dugdale
//   distribution = "gaussian"       # summit heights: as a [[curve]]'s (shape, side)
//   height_scale = 1e-6             # sigma_s [m]
//   summit_radius = 1e-4            # R [m]
//   summit_density = 1e10           # summits per m^2
//   nominal_area = 1e-4             # A0 [m^2]
//   separation = [-1.0, 4.0]        # dimensionless s (origin convention), the range served
//   max_rel_error = 1e-6            # optional (1e-10 .. 1e-2; default the scene's, 1e-8)
//
// Errors name the file, the line and the key (asperity::Error). A scene file is untrusted input
// (docs/reliability.md): before TOML parsing it must be valid UTF-8 without control characters,
// at most scene_max_bytes long, nested at most scene_max_nesting deep, with at most
// scene_max_list_entries commas; after it, at most scene_max_curves curves and names of at most
// scene_max_name_bytes. Anything else is refused quickly, with the limit in the message.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "asperity/contact_law.hpp"
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
  int line = 0;
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

// The limits a scene is checked against.
inline constexpr double scene_shape_min = 0.3, scene_shape_max = 50.0;
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
