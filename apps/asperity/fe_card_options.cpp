#include "fe_card_options.hpp"

#include <cmath>
#include <cstdio>

#include "asperity/number_text.hpp"
#include "command_line.hpp"
#include "option_helpers.hpp"

namespace asperity::cli {

std::size_t card_max_points(long long asked, CardFormat format) {
  if (asked > 0) return static_cast<std::size_t>(asked);
  return format == CardFormat::calculix ? calculix_points_max : card_points_max;
}

OverclosureDatum overclosure_datum_option(const std::string& text) {
  OverclosureDatum datum = OverclosureDatum::zero_pressure;
  if (!text.empty() && !parse_overclosure_datum(text, datum))
    usage("--overclosure-datum: '" + quote_text(text) + "' is not zero-pressure, mean-summit, origin or mean-plane");
  return datum;
}

CLI::Option* add_face_size_option(CLI::App& command, double& face_size, const std::string& card,
                                  const std::string& group) {
  return add_number(command, "--face-size", face_size,
                    card + ": the slave faces' edge, in the card's units (m; mm with --units mm); warns (and the "
                           "card's header says) when the card reaches beyond node-to-surface contact's spring "
                           "cut-off, a clearance of 1e-3 times it")
      ->type_name("L")->group(group);
}

double face_size_option(double face_size, CardFormat format, CardUnits units, const std::string& card_option) {
  if (std::isnan(face_size)) return face_size;
  const std::string unit = units == CardUnits::mm ? "mm, with --units mm" : "m; mm with --units mm";
  if (!(face_size > 0)) usage("--face-size must be a positive length [" + unit + "], got " + format_double(face_size));
  if (format != CardFormat::calculix)
    usage("--face-size checks CalculiX's contact-spring cut-off: it goes with " + card_option + " calculix");
  return face_size * card_length_unit(units);
}

void check_spring_cutoff(const CLI::App& command, const std::vector<PressureOverclosurePoint>& rows, double face_size,
                         CardUnits units, const std::string& remedy) {
  const double clearance = rows.empty() ? 0.0 : -rows.front().overclosure;
  if (std::isnan(face_size)) {
    if (clearance > 0)
      note(command, "for CalculiX: the card reaches a clearance of " +
                        approximately(clearance / card_length_unit(units)) +
                        (units == CardUnits::mm ? " mm" : " m") + "; give --face-size L (the slave faces' edge, " +
                        (units == CardUnits::mm ? "mm" : "m") +
                        ") to check it against node-to-surface contact's spring cut-off (1e-3 L)");
    return;
  }
  std::string text = calculix_cutoff_warning(rows, face_size, units);
  if (text.empty()) return;
  for (std::size_t at; (at = text.find("\n  ")) != std::string::npos;) text.replace(at, 3, " ");
  warn(command, text + "; " + remedy);
}

}  // namespace asperity::cli
