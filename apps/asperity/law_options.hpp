// A contact law named on the command line (`asperity contact --law`, `asperity surface --law`):
// its options, made from the contact-law registry (one per parameter a law may take: name, help,
// which laws take it), and the law scene they make on a surface through the one typed
// constructor the scene reader and Python use too (asperity/scene.hpp's make_scene_law).
#pragma once
#include <string>

#include "asperity/contact_law_registry.hpp"
#include "asperity/scene.hpp"
#include "asperity/surface.hpp"
#include "command_line.hpp"

namespace asperity::cli {

struct LawOptions {
  std::string law;                        // --law NAME (empty: none)
  LawValues material;                     // the numbers given (NaN: not given)
  std::string choice[law_parameter_count];  // a choice parameter's text as given ("" : not given)
  double tolerance = 0.0 / 0.0;           // --law-tolerance
  double approach_separation = 0.0 / 0.0;  // --approach-separation: an adhesive law's withdrawal (NaN: approach)
};

// The curves' relative error when --law-tolerance is not given.
inline constexpr double default_law_tolerance = 1e-6;

// --law (its help: `lead`, the laws' names, then `tail`: what the command does with it), an option
// per law parameter (the registry's), --law-tolerance and --approach-separation (an adhesive law's
// withdrawal branch: `approach_help` says what s0 is measured against), in the group "Contact law".
void add_law_options(CLI::App& command, LawOptions& options, const std::string& lead, const std::string& tail,
                     const std::string& approach_help);

// With no --law, the material options are refused ("... go with --law"; `also` names the
// command's own options that go with it too, e.g. "--law-range, "). With --law, its kind, or a
// usage error for a name that is not a law's.
void check_no_law_options(const LawOptions& options, const std::string& also = "");
ContactLawKind law_kind(const LawOptions& options);
// The law's parameters as given, checked against what the law takes (a usage error naming the
// option at fault), before any work.
LawValues law_values(const LawOptions& options);

// The law scene of the options on `surface` (every field of it used: distribution, shape, side,
// height scale, summit radius and density, nominal area, contact modulus) over the dimensionless
// separations [s_min, s_max] (an adhesive law's withdrawal after an approach to
// approach_separation, s0 <= s_min; NaN: its approach branch). Throws asperity::Error naming the
// option at fault; `source` names the command in the message.
SceneLaw law_scene(const LawOptions& options, const RoughSurface& surface, double s_min, double s_max,
                   const std::string& source, double approach_separation = 0.0 / 0.0);

}  // namespace asperity::cli
