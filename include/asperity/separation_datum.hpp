// Where a separation is measured from (docs/model.md section 2, "Datum"): defined once, for the
// C++ model, the C API, Fortran, Python, the `asperity contact` command and the FE export's
// overclosure datum.
//
//   origin       the origin convention: the Weibull origin (the lowest summit on the tail side,
//                the highest on the bounded side) or the Gaussian's mean summit height; the
//                paper's d0*. The default of every interface (kept: existing programs give the
//                same numbers).
//   mean-summit  the mean summit height: GW's and McCool's datum, what a Gaussian comparison
//                uses. For the Weibull the origin plus sigma_s Gamma(1 + 1/a) (tail side) or less
//                it (bounded side); for the Gaussian the origin itself.
//   mean-plane   the mean plane of the surface heights. The summit heights alone do not say where
//                it is: the user gives the mean summit height above it (`asperity surface`
//                reports it for a measured map), and the separation from the mean plane is the
//                separation from the mean summit height plus that height.
#pragma once
#include <string>

#include "asperity/surface.hpp"

namespace asperity {

enum class SeparationDatum { origin, mean_summit, mean_plane };
inline constexpr SeparationDatum default_separation_datum = SeparationDatum::origin;

// "origin", "mean-summit", "mean-plane" (and back; false for another name)
const char* separation_datum_name(SeparationDatum datum) noexcept;
bool parse_separation_datum(const std::string& name, SeparationDatum& datum) noexcept;
// One line for outputs: what the separations are measured from.
std::string describe_separation_datum(SeparationDatum datum, double mean_summit_height);

// The datum's place as a separation in the origin convention [m]: a separation from the datum is
// the origin-convention separation less this. mean_summit_height [m] is the mean summit height
// above the mean plane, needed by mean_plane only (NaN: not given). Throws asperity::Error for
// mean_plane without a finite mean_summit_height, or a mean_summit_height given with another datum.
double separation_datum_position(const RoughSurface& surface, SeparationDatum datum, double mean_summit_height);

}  // namespace asperity
