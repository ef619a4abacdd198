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
  OverclosureDatum datum = OverclosureDatum::mean_summit;
  if (!text.empty() && !parse_overclosure_datum(text, datum))
    usage("--overclosure-datum: '" + quote_text(text) + "' is not mean-summit, origin, zero-pressure or mean-plane");
  return datum;
}

void check_face_size_option(double face_size, CardFormat format, const std::string& card_option) {
  if (std::isnan(face_size)) return;
  if (!(face_size > 0)) usage("--face-size must be a positive length [m], got " + format_double(face_size));
  if (format != CardFormat::calculix)
    usage("--face-size checks CalculiX's contact-spring cut-off: it goes with " + card_option + " calculix");
}

void check_spring_cutoff(const CLI::App& command, double clearance, double face_size,
                         const std::function<double(double)>& pressure_at, const std::string& remedy) {
  if (std::isnan(face_size)) {
    if (clearance > 0)
      note(command, "for CalculiX: the card reaches a clearance of " + approximately(clearance) +
                        " m; give --face-size L (the slave faces' edge, m) to check it against node-to-surface "
                        "contact's spring cut-off (1e-3 L)");
    return;
  }
  const double cutoff = calculix_spring_cutoff_per_root_area * face_size;
  if (!(clearance > cutoff)) return;
  warn(command, "the card reaches a clearance of " + approximately(clearance) +
                    " m, but CalculiX's node-to-surface contact makes a contact spring only within a clearance of "
                    "1e-3 sqrt(A) (A the slave node's area) = " + approximately(cutoff) + " m for faces of " +
                    format_double(face_size) + " m (less at the mesh's edges): below " +
                    approximately(pressure_at(cutoff)) + " Pa the card never acts and contact starts at that "
                    "pressure in one increment; " + remedy);
}

}  // namespace asperity::cli
