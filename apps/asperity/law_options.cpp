#include "law_options.hpp"

#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "asperity/number_text.hpp"

namespace asperity::cli {
namespace {

bool given(double value) { return !std::isnan(value); }

[[noreturn]] void usage(const std::string& message) { throw CLI::ValidationError(message); }

// Each scene key the options write, and the option it comes from (for the scene's messages).
struct KeyOption {
  const char* key;
  const char* option;
};
constexpr KeyOption key_options[] = {{"hardness", "--hardness"},
                                     {"yield_strength", "--yield-strength"},
                                     {"poisson", "--law-poisson"},
                                     {"geometric_hardness", "--geometric-hardness"},
                                     {"work_of_adhesion", "--work-of-adhesion"},
                                     {"maugis_parameter", "--maugis-parameter"},
                                     {"max_rel_error", "--law-tolerance"}};

// `key` in `text` as a word of its own (not "hardness" in "geometric_hardness")
bool names_key(const std::string& text, const std::string& key) {
  const auto part_of_name = [](char c) { return (c >= 'a' && c <= 'z') || c == '_'; };
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1))
    if ((at == 0 || !part_of_name(text[at - 1])) &&
        (at + key.size() == text.size() || !part_of_name(text[at + key.size()])))
      return true;
  return false;
}

}  // namespace

void add_law_options(CLI::App& command, LawOptions& o, const std::string& law_description) {
  const char* group = "Contact law";
  add_text(command, "--law", o.law, law_description)->type_name("NAME")->group(group);
  add_number(command, "--hardness", o.hardness, "with --law chang-etsion-bogy or zhao-maietta-chang: hardness H [Pa]")
      ->type_name("PA")->group(group);
  add_number(command, "--yield-strength", o.yield_strength,
             "with --law kogut-etsion or jackson-green: yield strength Y [Pa]")
      ->type_name("PA")->group(group);
  add_number(command, "--law-poisson", o.poisson,
             "with --law chang-etsion-bogy, kogut-etsion or jackson-green: Poisson's ratio of the asperity")
      ->type_name("X")->group(group);
  add_text(command, "--geometric-hardness", o.geometric_hardness,
           "with --law jackson-green: its geometric hardness H_G(a/R), 2005 (the cosine form, default) or 2006 "
           "(the rough-surface paper's exponential form)")
      ->type_name("YEAR")->group(group);
  add_number(command, "--work-of-adhesion", o.work_of_adhesion,
             "with --law dmt, jkr or maugis-dugdale: work of adhesion [J/m^2] (the approach branch is tabulated)")
      ->type_name("J/M2")->group(group);
  add_number(command, "--maugis-parameter", o.maugis_parameter,
             "with --law maugis-dugdale: Maugis' parameter lambda > 0 (0: DMT, infinity: JKR)")
      ->type_name("X")->group(group);
  add_number(command, "--law-tolerance", o.tolerance, "with --law: the curves' relative error (default 1e-6)")
      ->type_name("REL")->group(group);
}

void check_no_law_options(const LawOptions& o, const std::string& also) {
  if (o.law.empty() && (given(o.hardness) || given(o.yield_strength) || given(o.poisson) || given(o.tolerance) ||
                        !o.geometric_hardness.empty() || given(o.work_of_adhesion) || given(o.maugis_parameter)))
    usage(also + "--hardness, --yield-strength, --law-poisson, --geometric-hardness, --work-of-adhesion, "
                 "--maugis-parameter and --law-tolerance go with --law");
}

ContactLawKind law_kind(const LawOptions& o) {
  ContactLawKind kind;
  if (!contact_law_kind_of(o.law.c_str(), kind)) {
    std::string names;
    for (ContactLawKind each : contact_law_kinds) names += std::string(names.empty() ? "" : ", ") + contact_law_name(each);
    usage("--law: '" + quote_text(o.law) + "' is not one of " + names);
  }
  return kind;
}

SceneLaw law_scene(const LawOptions& o, const RoughSurface& surface, double s_min, double s_max,
                   const std::string& source) {
  const ContactLawKind kind = law_kind(o);
  std::string scene = "[[law]]\nlaw = \"" + std::string(contact_law_name(kind)) + "\"\n";
  const auto key = [&](const char* name, double value) {
    scene += std::string(name) + " = " + format_double(value) + "\n";
  };
  key("contact_modulus", surface.contact_modulus);
  if (given(o.hardness)) key("hardness", o.hardness);
  if (given(o.yield_strength)) key("yield_strength", o.yield_strength);
  if (given(o.poisson)) key("poisson", o.poisson);
  if (given(o.work_of_adhesion)) key("work_of_adhesion", o.work_of_adhesion);
  if (given(o.maugis_parameter)) key("maugis_parameter", o.maugis_parameter);
  if (!o.geometric_hardness.empty()) {
    if (o.geometric_hardness != "2005" && o.geometric_hardness != "2006")
      usage("--geometric-hardness: '" + quote_text(o.geometric_hardness) + "' is not 2005 or 2006");
    scene += "geometric_hardness = \"" + o.geometric_hardness + "\"\n";
  }
  scene += std::string("distribution = \"") + to_string(surface.distribution) + "\"\n";
  if (surface.distribution == Distribution::weibull) {
    key("shape", surface.shape);
    scene += std::string("side = \"") + to_string(surface.side) + "\"\n";
  }
  key("height_scale", surface.height_scale);
  key("summit_radius", surface.summit_radius);
  key("summit_density", surface.summit_density);
  key("nominal_area", surface.nominal_area);
  scene += "separation = [" + format_double(s_min) + ", " + format_double(s_max) + "]\n";
  key("max_rel_error", given(o.tolerance) ? o.tolerance : default_law_tolerance);
  try {
    return parse_scene(scene, source).laws.front();
  } catch (const Error& error) {
    // the scene names its keys: say which option each is
    std::string message = error.what(), options;
    for (const KeyOption& k : key_options)
      if (names_key(message, k.key))
        options += std::string(options.empty() ? "" : ", ") + "'" + k.key + "' is " + k.option;
    if (!options.empty()) message += "\n(the options make this scene: " + options + ")";
    throw Error(message);
  }
}

}  // namespace asperity::cli
