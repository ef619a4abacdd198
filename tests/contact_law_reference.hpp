// An independent reference for the rough-surface integrals of any contact law
// (asperity/contact_law.hpp): the Greenwood-Williamson mean over summit heights of one
// asperity's count, area, load and stiffness at a dimensionless separation s (docs/model.md
// sections 1-3, origin convention), by adaptive double-exponential quadrature (Boost.Math
// tanh_sinh and exp_sinh), the range split at every switch point of the law and at the
// density's own edge. It shares no code with tablegen's generator: phase B's tables of each law
// are tested against it.
//
// Per summit (multiply by N for a surface), with interference omega = sigma_s w:
//   count     = P(w >= w_lo)                     (the summits in contact)
//   area      = E[A(sigma_s w)]                  (Hertz: pi R sigma_s X_1)
//   load      = E[P(sigma_s w)]                  (Hertz: (4/3) E* R^1/2 sigma_s^3/2 X_3/2)
//   stiffness = -d load / d(sigma_s s)
//             = E[dP/domega] + sum over jumps of P (at first contact and at switch points) of
//               (P(w_k+) - P(w_k-)) phi(z_k) / sigma_s                     (Hertz: 2 E* R^1/2 sigma_s^1/2 X_1/2)
// Tail side: z = s + w over the heights' support; bounded side: z = -s - w (docs/model.md 2).
#pragma once
// Defined in contact_law_reference.cpp, compiled once (the asperity_test_reference library).
#include <cmath>

#include <algorithm>
#include <limits>
#include <vector>

#include "asperity/contact_law.hpp"
#include "asperity/integrals.hpp"

namespace asperity::test {

struct SummitHeights {
  Distribution distribution = Distribution::gaussian;
  Side side = Side::tail;
  double shape = 2;    // Weibull a
  double scale = 1e-6; // sigma_s [m] (the Gaussian's: the rms summit height)
};

struct RoughSurfaceValues {
  double count = 0, area = 0, load = 0, stiffness = 0;
};

// Which asperities are in contact: on approach (loading) those with omega >= max(0, the law's
// lowest interference); when the flat is withdrawn after reaching `deepest_separation` (fixed
// grips, Fuller-Tabor), those that touched then (interference >= 0 at the deepest separation)
// and still have omega >= the law's lowest interference.
struct ContactHistory {
  bool unloading = false;
  double deepest_separation = 0;  // dimensionless s at the deepest approach (unloading only)
};

// Which part of the load (docs/contact-laws.md section 8): the net load, or its compressive
// part, the Hertz-like term K a^3 / R of the contact radius a = (A/pi)^1/2 (K = (4/3) E*; for
// Maugis-Dugdale A is the repulsive disc), and the tensile part, compressive - net. For a law
// without adhesion the compressive part is the load. Made here from the law's area and load
// alone, not from asperity_load_split (the split the generator uses).
enum class LoadPart { net, compressive, tensile };

// The load, or the part of it asked for, of one asperity at interference omega.
double law_load_part(const ContactLaw& law, double omega, LoadPart part);

// The summit heights' density phi(z) and its slope d phi / dz.
double summit_density(const SummitHeights& h, double z);
double summit_density_slope(const SummitHeights& h, double z);

// The per-summit mean values at separation s for `law` over `heights` (see the top of the file).
// `load_only`: the load alone (the others 0), for searches over many separations.
// `part`: the load and stiffness of that part of the load (compressive or tensile: the stiffness
// by parts, for Gaussian summits and Weibull shapes > 1 only, else NaN).
RoughSurfaceValues law_integrals(const ContactLaw& law, const SummitHeights& heights, double s,
                                 ContactHistory history = {}, bool load_only = false, LoadPart part = LoadPart::net);

// The greatest tension (-load, per summit) while the flat is withdrawn under fixed grips after
// reaching separation s0 (Fuller & Tabor 1975): a grid over s from s0 to past the last
// asperity's pull-off (the law's lowest interference), refined by golden section.
double pull_off(const ContactLaw& law, const SummitHeights& heights, double s0);

}  // namespace asperity::test
