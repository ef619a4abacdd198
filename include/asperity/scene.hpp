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
// Errors name the file, the line and the key (asperity::Error). A scene file is untrusted input
// (docs/reliability.md): before TOML parsing it must be valid UTF-8 without control characters,
// at most scene_max_bytes long, nested at most scene_max_nesting deep, with at most
// scene_max_list_entries commas; after it, at most scene_max_curves curves and names of at most
// scene_max_name_bytes. Anything else is refused quickly, with the limit in the message.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

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

struct Scene {
  std::string name;
  std::string source;                // the file it came from (for messages)
  double memory_budget_bytes = 0;    // 0: no budget
  std::vector<SceneCurve> curves;
};

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
