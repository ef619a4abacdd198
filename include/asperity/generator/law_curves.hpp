// A contact law's rough-surface curves (a law scene, asperity/scene.hpp's [[law]]): the pressure,
// stiffness and real area fraction of a physical surface under that law against separation,
// tabulated as a contact-curves table (contact_curves_data.hpp, served by ContactCurves) to the
// scene's tolerance, with the error measured and stored (docs/contact-laws.md section 8).
//
// Method. The per-summit means E[P], E[dP/domega] (plus the load's jumps where they move with
// the separation) and E[A] over the summit heights by double-exponential quadrature in the
// height z, split at every switch point of the law (mapped to z at that separation), at the
// density's edge and across its mass. Nodes: a few uniform in s, plus a knot wherever the
// integrals themselves are not smooth (a Weibull density's edge z = 0 meeting first contact or
// a switch point: s = 0 and s = -omega_k/sigma_s); then every interval whose midpoint the served
// curves (the table's own interpolation) miss by more than half the tolerance is halved, until
// none does. The stored bound is the largest midpoint error times 2.
#pragma once
#include <functional>
#include <string>

#include "asperity/contact_curves_data.hpp"
#include "asperity/scene.hpp"

namespace asperity::generator {

// The per-summit means at dimensionless separation s (origin convention): count (the fraction
// of summits in contact), area [m^2], load [N], stiffness -d load / d(sigma_s s) [N/m], and the
// load's tensile part with its stiffness (asperity_load_split: the compressive part is load +
// tensile_load; 0 for a law without adhesion). Adhesive laws on approach (loading): the summits
// with omega >= 0, each on its law's stable branch (docs/contact-laws.md section 8). On
// withdrawal after an approach to s0 (SceneLaw::approach_separation): the summits that touched at
// s0 (omega >= 0 there) and whose interference has not fallen below the law's lowest, omega_min;
// from the kink s0 - omega_min / sigma_s on, summits leave at omega_min, whose load (the law's
// at its end) drops to 0 there: the detach_ terms, the share of each part's stiffness that adds
// (0 before the kink: the stiffness jumps there, a break of the table).
struct LawMeans {
  double count = 0, area = 0, load = 0, stiffness = 0;
  double tensile_load = 0, tensile_stiffness = 0;
  double detach_compressive_stiffness = 0, detach_tensile_stiffness = 0;
};
LawMeans law_means(const SceneLaw& law, double s);

// The withdrawal's kink, s0 - omega_min / sigma_s (dimensionless): where the summits that touched
// at s0 start to detach (s0 itself for DMT, whose omega_min is 0); NaN on approach.
double withdrawal_kink(const SceneLaw& law) noexcept;

struct LawCurvesResult {
  ContactCurvesData data;
  int nodes = 0;
  int evaluations = 0;  // exact evaluations (nodes and midpoints)
};

// Where a tabulation is, for a progress report: the pass (each halves the intervals that miss),
// its nodes, the intervals of this pass checked so far, the exact evaluations made.
struct LawCurvesProgress {
  int pass = 0, nodes = 0, checked = 0, intervals = 0, evaluations = 0;
};

// Throws asperity::Error where the curves cannot be tabulated (an area fraction beyond 1 or a
// pressure below the format's range inside the asked separations, too many nodes), Interrupted
// when its InterruptScope asks (asperity/interrupt.hpp). progress, if given, is called on this
// thread after every interval checked (cheap to call: the caller decides what to show and when).
LawCurvesResult generate_law_curves(const SceneLaw& law, const std::string& generator_options = "",
                                    const std::function<void(const LawCurvesProgress&)>& progress = {});

}  // namespace asperity::generator
