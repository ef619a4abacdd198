#include "law_options.hpp"

#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "asperity/number_text.hpp"
#include "option_helpers.hpp"

namespace asperity::cli {
namespace {

// The options' values as the registry holds them: numbers as given, a choice's text as its index
LawValues given_values(const LawOptions& o) {
  LawValues values = o.material;
  for (const LawParameterInfo* p = law_parameters_begin(); p != law_parameters_end(); ++p) {
    const std::string& text = o.choice[static_cast<int>(p->id)];
    if (!p->choices[0] || text.empty()) continue;
    double index;
    if (!law_choice_index(p->id, text, index))
      usage(std::string(p->option) + ": '" + quote_text(text) + "' is not " + p->range_text);
    values.set(p->id, index);
  }
  return values;
}

bool any_given(const LawOptions& o) {
  for (int k = 0; k < law_parameter_count; ++k)
    if (o.material.given(static_cast<LawParameter>(k)) || !o.choice[k].empty()) return true;
  return !std::isnan(o.tolerance) || !std::isnan(o.approach_separation);
}

// --approach-separation, as the scene key's table names it (asperity/scene.hpp)
std::string approach_option() { return scene_law_key_name("approach_separation", LawNaming::option); }

}  // namespace

void add_law_options(CLI::App& command, LawOptions& o, const std::string& lead, const std::string& tail,
                     const std::string& approach_help) {
  const char* group = "Contact law";
  add_text(command, "--law", o.law, lead + ": " + contact_law_names() + tail)->type_name("NAME")->group(group);
  for (const LawParameterInfo* p = law_parameters_begin(); p != law_parameters_end(); ++p) {
    const std::string help = "with --law " + laws_taking(p->id) + ": " + p->meaning;
    if (p->choices[0])
      add_text(command, p->option, o.choice[static_cast<int>(p->id)], help)->type_name(p->type_name)->group(group);
    else
      add_number(command, p->option, o.material.value[static_cast<int>(p->id)], help)
          ->type_name(p->type_name)->group(group);
  }
  add_number(command, "--law-tolerance", o.tolerance, "with --law: the curves' relative error (default 1e-6)")
      ->type_name("REL")->group(group);
  add_number(command, approach_option(), o.approach_separation,
             "with --law " + laws_taking(LawParameter::work_of_adhesion) +
                 ": the withdrawal (unloading, fixed grips) branch after an approach to this dimensionless separation "
                 "s0 (" + approach_help + "; default: the approach branch)")
      ->type_name("S0")->group(group);
}

void check_no_law_options(const LawOptions& o, const std::string& also) {
  if (!o.law.empty() || !any_given(o)) return;
  std::string options;
  for (const LawParameterInfo* p = law_parameters_begin(); p != law_parameters_end(); ++p)
    options += std::string(p->option) + ", ";
  usage(also + options + "--law-tolerance and " + approach_option() + " go with --law");
}

ContactLawKind law_kind(const LawOptions& o) {
  ContactLawKind kind;
  if (!contact_law_kind_of(o.law.c_str(), kind))
    usage("--law: '" + quote_text(o.law) + "' is not one of " + contact_law_names());
  return kind;
}

LawValues law_values(const LawOptions& o) {
  const ContactLawKind kind = law_kind(o);
  try {
    checked_law_tolerance(o.tolerance, default_law_tolerance, LawNaming::option);
    return checked_law_values(*find_contact_law(kind), given_values(o), LawNaming::option);
  } catch (const LawValuesError& error) {
    usage(error.what());
  } catch (const SceneLawError& error) {
    usage(error.what());
  }
}

SceneLaw law_scene(const LawOptions& o, const RoughSurface& surface, double s_min, double s_max,
                   const std::string& source, double approach_separation) {
  SceneLawInputs in;
  in.law = law_kind(o);
  in.material = given_values(o);
  in.contact_modulus = surface.contact_modulus;
  in.distribution = surface.distribution;
  in.side = surface.side;
  in.side_given = surface.distribution == Distribution::weibull;
  in.shape = surface.distribution == Distribution::weibull ? surface.shape : 0.0 / 0.0;
  in.height_scale = surface.height_scale;
  in.summit_radius = surface.summit_radius;
  in.summit_density = surface.summit_density;
  in.nominal_area = surface.nominal_area;
  in.range_min = s_min;
  in.range_max = s_max;
  in.max_rel_error = std::isnan(o.tolerance) ? default_law_tolerance : o.tolerance;
  in.approach_separation = approach_separation;
  try {
    return make_scene_law(in, LawNaming::option);
  } catch (const SceneLawError& error) {
    throw Error(source + ": " + error.what());
  }
}

}  // namespace asperity::cli
