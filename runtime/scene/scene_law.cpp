// A law scene from typed inputs (asperity/scene.hpp's make_scene_law): every check of a [[law]]
// once, for the scene reader, the command line and Python alike, the law's own through the
// contact-law registry.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "asperity/scene.hpp"

namespace asperity {
namespace {

[[noreturn]] void refuse(const std::string& key, const std::string& message, const std::string& label = "here") {
  throw SceneLawError(key, message, label);
}

double positive(double value, const char* key, LawNaming naming) {
  if (std::isnan(value)) refuse(key, "the law has no " + scene_law_key_name(key, naming), "this law");
  if (!(std::isfinite(value) && value > 0)) refuse(key, scene_law_key_name(key, naming) + " must be positive and finite");
  return value;
}

// distribution, side, shape
void check_heights(const SceneLawInputs& in, LawNaming naming) {
  if (in.distribution == Distribution::gaussian) {
    if (!std::isnan(in.shape)) refuse("shape", "the Gaussian has no shape", "remove this key");
    if (in.side_given && in.side == Side::bounded) refuse("side", "the Gaussian has a tail side only");
    return;
  }
  if (std::isnan(in.shape)) refuse("shape", "the law has no " + scene_law_key_name("shape", naming), "this law");
  if (!(in.shape >= weibull_shape_min && in.shape <= weibull_shape_max)) {
    std::ostringstream message;
    message << "shape must be between " << weibull_shape_min << " and " << weibull_shape_max;
    refuse("shape", message.str(), "out of range");
  }
}

void check_range(const SceneLaw& out, LawNaming naming) {
  const std::string name = scene_law_key_name("separation", naming);
  if (std::isnan(out.range_min) || std::isnan(out.range_max)) refuse("separation", "the law has no " + name, "this law");
  if (!std::isfinite(out.range_min) || !std::isfinite(out.range_max) || !(out.range_min < out.range_max))
    refuse("separation", name + " must be two finite numbers, min < max", "impossible range");
  if (out.side == Side::bounded && !(out.range_max < 0))
    refuse("separation", "on the bounded side nothing touches at separation >= 0: the range must end below 0",
           "impossible range");
  if (std::fabs(out.range_min) > 1e3 || std::fabs(out.range_max) > 1e3)
    refuse("separation", "a law's separations are within [-1e3, 1e3] (dimensionless)", "too far");
}

// The withdrawal branch's approach separation s0 (NaN: the approach branch): an adhesive law's
// (a law without adhesion unloads along its loading curve: nothing to tell apart), finite, at or
// below the range's lower end (the withdrawal visits only s >= s0), and a contact on the bounded side
void check_approach(const SceneLaw& out, ContactLawKind kind, LawNaming naming) {
  const double s0 = out.approach_separation;
  if (std::isnan(s0)) return;
  const std::string name = scene_law_key_name("approach_separation", naming);
  if (!is_adhesive(kind))
    refuse("approach_separation",
           std::string(contact_law_name(kind)) + " has no withdrawal branch apart from its approach (no adhesion: a "
               "summit leaves contact at zero interference either way); " + name + " goes with dmt, jkr or maugis-dugdale",
           "not adhesive");
  if (!std::isfinite(s0) || std::fabs(s0) > 1e3)
    refuse("approach_separation", name + " must be a finite dimensionless separation within [-1e3, 1e3]", "out of range");
  if (out.side == Side::bounded && !(s0 < 0))
    refuse("approach_separation", "on the bounded side nothing touches at separation >= 0: " + name + " must be below 0",
           "nothing touched");
  if (!(s0 <= out.range_min)) {
    std::ostringstream message;
    message << name << " " << s0 << " is above the separation range's lower end " << out.range_min
            << ": the withdrawal after an approach to s0 visits only separations >= s0 (start the range at s0 or above)";
    refuse("approach_separation", message.str(), "outside the range");
  }
}

}  // namespace

double checked_law_tolerance(double asked, double default_tolerance, LawNaming naming) {
  if (std::isnan(asked)) return std::max(default_tolerance, scene_law_error_min);
  if (!(asked >= scene_error_min && asked <= scene_error_max)) {
    std::ostringstream message;
    message << scene_law_key_name("max_rel_error", naming) << " must be between " << scene_error_min << " and "
            << scene_error_max;
    refuse("max_rel_error", message.str(), "out of range");
  }
  if (asked < scene_law_error_min)
    refuse("max_rel_error",
           scene_law_key_name("max_rel_error", naming) + " is at least 1e-10 for a law (its values are quadratures to ~1e-13)",
           "too small");
  return asked;
}

std::string scene_law_key_name(const std::string& key, LawNaming naming) {
  for (const LawParameterInfo* p = law_parameters_begin(); p != law_parameters_end(); ++p)
    if (key == p->key) return law_parameter_name(p->id, naming);
  for (const SceneLawKey& k : scene_law_keys)
    if (key == k.key) {
      if (naming == LawNaming::option && *k.option) return k.option;
      if (naming == LawNaming::keyword) return std::string(k.keyword) + "=";
      return "'" + key + "'";
    }
  return "'" + key + "'";
}

SceneLaw make_scene_law(const SceneLawInputs& in, LawNaming naming, double default_tolerance) {
  const ContactLawDescriptor* law = find_contact_law(in.law);
  if (!law) refuse("law", "law must be one of " + contact_law_names(", ", true), "unknown law");
  SceneLaw out;
  bool printable = in.name.size() <= scene_max_name_bytes;
  for (unsigned char c : in.name) printable = printable && c >= 0x20 && c != 0x7f;
  if (!printable)
    refuse("name", "a law's name is at most " + std::to_string(scene_max_name_bytes) +
                       " bytes of text without control characters");
  out.name = in.name;
  out.distribution = in.distribution;
  out.side = in.side;
  check_heights(in, naming);
  out.shape = in.distribution == Distribution::gaussian ? 2.0 : in.shape;
  out.height_scale = positive(in.height_scale, "height_scale", naming);
  out.summit_radius = positive(in.summit_radius, "summit_radius", naming);
  out.summit_density = positive(in.summit_density, "summit_density", naming);
  out.nominal_area = positive(in.nominal_area, "nominal_area", naming);
  const double modulus = positive(in.contact_modulus, "contact_modulus", naming);
  try {
    out.law = make_contact_law(in.law, out.summit_radius, modulus, in.material, naming);
  } catch (const LawValuesError& error) {
    refuse(law_parameter_info(error.parameter).key, error.what(), error.label);
  } catch (const Error& error) {
    refuse("law", error.what());
  }
  out.range_min = in.range_min;
  out.range_max = in.range_max;
  check_range(out, naming);
  out.approach_separation = in.approach_separation;
  check_approach(out, in.law, naming);
  out.max_rel_error = checked_law_tolerance(in.max_rel_error, default_tolerance, naming);
  return out;
}

}  // namespace asperity
