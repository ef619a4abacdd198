#include "asperity/topography/next_steps.hpp"

#include <cstdio>
#include <filesystem>

#include "asperity/integrals.hpp"
#include "asperity/number_text.hpp"
#include "asperity/topography/surface_formats.hpp"

namespace asperity::topography {
namespace {

// A word a POSIX shell reads back as it is: quoted where it holds anything but plain characters
std::string shell_word(const std::string& word) {
  bool plain = !word.empty();
  for (char c : word)
    plain = plain && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      std::string("_./:=,+-@%").find(c) != std::string::npos);
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string number(double value) { return format_double(value); }

// a pressure range's end: six digits (the range is a choice, not a result to reproduce)
std::string pressure_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// The options that read the map as the analysis read it (format, sampling, units, leveling)
std::string read_options(const SurfaceAnalysis& a) {
  const ReadOptions& read = a.options.read;
  std::string options;
  if (const SurfaceFormat* format = surface_format(read.format)) options += " --format " + std::string(format->name);
  if (read.pixel_size_x > 0) {
    options += " --pixel-size " + number(read.pixel_size_x) + "m";
    if (read.pixel_size_y > 0 && read.pixel_size_y != read.pixel_size_x) options += "," + number(read.pixel_size_y) + "m";
  }
  if (!read.lateral_unit.empty()) options += " --unit " + shell_word(read.lateral_unit);
  if (!read.height_unit.empty()) options += " --height-unit " + shell_word(read.height_unit);
  if (!a.leveled) options += " --no-level";
  return options;
}

// `asperity contact`'s options for a fitted model's surface (separations from its mean summit height)
std::string surface_options(const RoughSurface& s) {
  std::string options = " --dist " + std::string(to_string(s.distribution));
  if (s.distribution == Distribution::weibull)
    options += " --side " + std::string(to_string(s.side)) + " --shape " + number(s.shape);
  return options + " --sigma " + number(s.height_scale) + " --radius " + number(s.summit_radius) + " --density " +
         number(s.summit_density) + " --area " + number(s.nominal_area) + " --modulus " + number(s.contact_modulus);
}

std::string python_call(const RoughSurface& s) {
  std::string call = "import asperity\nsurface = asperity.RoughSurface(\"" + std::string(to_string(s.distribution)) + "\"";
  if (s.distribution == Distribution::weibull)
    call += ", \"" + std::string(to_string(s.side)) + "\", shape=" + number(s.shape);
  else
    call += ", shape=None";
  call += ", height_scale=" + number(s.height_scale) + ",\n                                 summit_radius=" +
          number(s.summit_radius) + ", summit_density=" + number(s.summit_density) + ",\n                                 nominal_area=" +
          number(s.nominal_area) + ", contact_modulus=" + number(s.contact_modulus) + ")\n";
  return call + "model = asperity.ContactModel(asperity.Table.open_default(), surface, datum=\"mean-summit\")";
}

// The map's exact contact over the comparison's pressures, tabulated, and its card
std::string exact_command(const SurfaceAnalysis& a, const ContactComparison& c) {
  const std::string stem = std::filesystem::path(a.map.source).stem().string();
  return "asperity exact-contact " + shell_word(a.map.source) + read_options(a) + " --modulus " +
         number(c.options.contact_modulus) + " --boundary padded --kernel love --sweep pressure:" + pressure_text(c.pressure_min) +
         ":" + pressure_text(c.pressure_max) + ":17 --table " + shell_word(stem + "-exact.h5") + " --card " +
         shell_word(stem + "-exact.inp");
}

}  // namespace

NextSteps next_steps(const SurfaceAnalysis& a) {
  NextSteps next;
  const SurfaceVerdict& v = a.verdict;
  if (a.noise_floor.reached) {
    next.why = "no model: " + a.noise_floor.text;
    next.text = "Next: nothing to model at the noise floor; measure the surface with a finer height resolution.";
    return next;
  }
  next.model_named = v.named;
  if (v.named) {
    next.model = contact_model_kind(v.model);
    next.why = std::string("the verdict names ") + describe(v.model) + " for the contact (the summit heights' fit)";
  } else {
    next.why = "the verdict names no model for the contact (its reasons are in the verdict)";
  }
  if (!a.contact) {
    next.text = "Next: " + next.why + ". With --modulus (the contact modulus E*), the report gives the `asperity contact` "
                "command, the Python call and the FE card of " + (v.named ? "that model" : "the map's exact contact") + ".";
    return next;
  }
  const ContactComparison& c = *a.contact;
  next.exact_command = exact_command(a, c);
  const ModelContact* curves = v.named ? c.find(contact_model_kind(v.model)) : nullptr;
  if (curves && curves->served) {
    const std::string options = surface_options(curves->surface);
    next.contact_command = "asperity contact" + options + " --datum mean-summit --sweep pressure:" +
                           pressure_text(c.pressure_min) + ":" + pressure_text(c.pressure_max) + ":9";
    next.python = python_call(curves->surface);
    next.card_command = "asperity contact" + options + " --export calculix --pressure-range " + pressure_text(c.pressure_min) +
                        ":" + pressure_text(c.pressure_max) + " > " + shell_word(contact_model_name(next.model) + ".inp");
    next.text = "Next: " + next.why + ". Its curves in your code: `" + next.contact_command + "`; in Python:\n\n" +
                next.python + "\n\nIts pressure-overclosure card for CalculiX: `" + next.card_command +
                "` (or `asperity surface ... --card FILE`). The map's own exact contact, what every model is judged "
                "against, as a table `asperity contact --table` serves and as a card: `" + next.exact_command + "`.";
  } else {
    next.instead = "the map's exact contact: its curves as a table that `asperity contact --table FILE` serves "
                   "(and C++, C, Python), and its card";
    next.text = "Next: " + next.why + ". Use instead " + next.instead + ": `" + next.exact_command + "`.";
  }
  return next;
}

}  // namespace asperity::topography
