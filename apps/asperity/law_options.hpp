// A contact law named on the command line (`asperity contact --law`, `asperity surface --law`):
// its options and their checks, defined once, and the law scene they make on a surface. The
// options become a scene's text ([[law]], asperity/scene.hpp) so that their checks and messages
// are the scene file's; the generator then tabulates it (asperity/generator/law_curves.hpp).
#pragma once
#include <string>

#include "asperity/contact_law.hpp"
#include "asperity/scene.hpp"
#include "asperity/surface.hpp"
#include "command_line.hpp"

namespace asperity::cli {

struct LawOptions {
  std::string law;                 // --law NAME (empty: none)
  std::string geometric_hardness;  // --geometric-hardness 2005|2006 (Jackson-Green)
  double hardness = 0.0 / 0.0, yield_strength = 0.0 / 0.0, poisson = 0.0 / 0.0, tolerance = 0.0 / 0.0;
  double work_of_adhesion = 0.0 / 0.0, maugis_parameter = 0.0 / 0.0;  // dmt, jkr, maugis-dugdale
};

// The curves' relative error when --law-tolerance is not given.
inline constexpr double default_law_tolerance = 1e-6;

// --law (described by `law_description`, which says what the command does with it), --hardness,
// --yield-strength, --law-poisson, --geometric-hardness, --work-of-adhesion, --maugis-parameter and
// --law-tolerance, in the group "Contact law".
void add_law_options(CLI::App& command, LawOptions& options, const std::string& law_description);

// With no --law, the material options are refused ("... go with --law"; `also` names the
// command's own options that go with it too, e.g. "--law-range, "). With --law, its kind, or a
// usage error for a name that is not a tabulable law's.
void check_no_law_options(const LawOptions& options, const std::string& also = "");
ContactLawKind law_kind(const LawOptions& options);

// The law scene of the options on `surface` (every field of it used: distribution, shape, side,
// height scale, summit radius and density, nominal area, contact modulus) over the dimensionless
// separations [s_min, s_max]; `source` names it in messages. Throws asperity::Error with the
// scene's message (and which option a scene key is) for a material the law does not take or lacks.
SceneLaw law_scene(const LawOptions& options, const RoughSurface& surface, double s_min, double s_max,
                   const std::string& source);

}  // namespace asperity::cli
