#include "asperity/separation_datum.hpp"

#include <cmath>
#include <sstream>

#include "asperity/error.hpp"
#include "asperity/number_text.hpp"

namespace asperity {

const char* separation_datum_name(SeparationDatum datum) noexcept {
  switch (datum) {
    case SeparationDatum::mean_summit: return "mean-summit";
    case SeparationDatum::mean_plane: return "mean-plane";
    case SeparationDatum::origin: break;
  }
  return "origin";
}

bool parse_separation_datum(const std::string& name, SeparationDatum& datum) noexcept {
  for (SeparationDatum candidate : {SeparationDatum::origin, SeparationDatum::mean_summit, SeparationDatum::mean_plane})
    if (name == separation_datum_name(candidate)) {
      datum = candidate;
      return true;
    }
  return false;
}

std::string describe_separation_datum(SeparationDatum datum, double mean_summit_height) {
  const std::string name = separation_datum_name(datum);
  const std::string is_default = datum == default_separation_datum ? ", the default" : "";
  switch (datum) {
    case SeparationDatum::mean_summit:
      return "separations from the mean summit height (datum " + name + is_default + ")";
    case SeparationDatum::mean_plane:
      return "separations from the mean plane of the surface heights, the mean summit height " +
             format_double(mean_summit_height) + " m above it (datum " + name + is_default + ")";
    case SeparationDatum::origin: break;
  }
  return "separations from the origin: the Weibull origin (lowest summit on the tail side, highest on the bounded "
         "side) or the Gaussian's mean summit height (datum " + name + is_default + ")";
}

double separation_datum_position(const RoughSurface& surface, SeparationDatum datum, double mean_summit_height) {
  if (datum != SeparationDatum::mean_plane && !std::isnan(mean_summit_height))
    throw Error(std::string("the mean summit height above the mean plane goes with the mean-plane datum, not ") +
                separation_datum_name(datum));
  if (datum == SeparationDatum::origin) return 0;
  // the mean summit, in origin-convention units of sigma_s: the heights are mirrored on the bounded side
  double mean = 0;
  if (surface.distribution == Distribution::weibull)
    mean = (surface.side == Side::bounded ? -1 : 1) * weibull_mean(surface.shape);
  const double mean_summit = mean * surface.height_scale;
  if (datum == SeparationDatum::mean_summit) return mean_summit;
  if (!std::isfinite(mean_summit_height)) {
    std::ostringstream message;
    message << "the mean-plane datum needs the mean summit height above the mean plane (a finite length in m; "
               "`asperity surface` reports it for a measured map): the summit heights alone do not fix the mean "
               "plane";
    if (!std::isnan(mean_summit_height)) message << ", got " << mean_summit_height;
    throw Error(message.str());
  }
  // the mean plane lies mean_summit_height below the mean summit: the flat is that much farther from it
  return mean_summit - mean_summit_height;
}

}  // namespace asperity
