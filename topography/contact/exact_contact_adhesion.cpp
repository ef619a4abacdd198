// The exact contact at a given position of the flat, and its adhesive form: the Maugis-Dugdale
// cohesive zone (exact_contact.hpp). Dugdale's law on every pixel: the tension sigma0 wherever the
// gap is at most h0 = work of adhesion / sigma0 (the contact points included: their gap is 0),
// besides the contact pressure p >= 0 where the gap is 0, so that the net pressure is at least
// -sigma0 and reaches it at the contact's edge (Maugis 1992; the same conditions as tamaas'
// adhesion by a pressure bounded below, Rey, Anciaux and Molinari 2017).
//
// The zone is found by fixed-point passes at the flat's position: with the zone Z held, its
// tension is a known load, whose displacement G[sigma0 1_Z] pulls the surface towards the flat;
// the contact of the heights less that pull is the elastic problem the constrained conjugate
// gradient solves (by approach); the new zone is then the points whose gap is at most h0. The
// passes repeat until the zone does not change. The map from a zone to the next is monotone (a
// larger zone pulls harder: smaller gaps, a larger zone), so from the last step's zone the passes
// move one way to the nearest fixed point: loading stays out of contact until the zone's pull
// makes the surface jump in, and unloading keeps the contact until its branch ends (pull-off).
#include <cmath>
#include <cstddef>
#include <string>

#include "asperity/error.hpp"
#include "asperity/interrupt.hpp"
#include "asperity/number_text.hpp"
#include "asperity/topography/exact_contact.hpp"

namespace asperity::topography {
namespace {

// Passes of the fixed point before it is declared not converging (each is a contact solve,
// warm-started; a jump into contact on the tests' spheres takes up to about 40).
constexpr int max_adhesive_passes = 2000;
// The passes' tolerance until the zone settles (relative, as ExactContactOptions::tolerance).
constexpr double loose_adhesive_tolerance = 1e-5;

}  // namespace

void ExactContact::refuse_pressure_with_adhesion(double pressure) const {
  throw Error("adhesive contact is solved at the flat's positions, not at a pressure (" + format_double(pressure) +
              " Pa asked): its load is not monotone in the position (it falls to the pull-off and a load can have "
              "two solutions or none); give mean gaps (--gap, at_mean_gap) on a periodic map without missing "
              "points, or positions (at_approach)");
}

// heights_ = base_heights_ + G[sigma0 on the zone]: the gap of the contact problem is then the
// gap under both the contact pressure and the zone's tension. stiffness_x_ and work_ are free
// here (the constrained solve and the stiffness solve overwrite them).
void ExactContact::set_adhesive_heights() {
  std::vector<double>& tension = stiffness_x_;
  std::vector<double>& pull = work_;
  bool any = false;
  for (std::size_t k = 0; k < tension.size(); ++k) {
    tension[k] = cohesive_[k] ? adhesive_stress_ : 0.0;
    any = any || cohesive_[k];
  }
  if (any) apply(tension, pull);
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i) {
      const std::size_t k = j * sx_ + i;
      heights_[k] = active_[k] ? base_heights_[k] + (any ? pull[k] : 0.0) : 0.0;
    }
}

ContactStep ExactContact::solve_adhesive(double approach) {
  // The passes solve to a looser tolerance until the zone settles, then once more to the
  // tolerance asked (and on, if that moves the zone): the zone is decided by the tolerance's gaps.
  const double tolerance = options_.tolerance;
  struct Restore {
    ExactContactOptions& options;
    double tolerance;
    ~Restore() { options.tolerance = tolerance; }
  } restore{options_, tolerance};
  bool fine = loose_adhesive_tolerance <= tolerance;
  int iterations = 0, passes = 0;
  Solve solve;
  for (;;) {
    poll_interrupt();
    set_adhesive_heights();
    options_.tolerance = fine ? tolerance : loose_adhesive_tolerance;
    solve = constrained(false, approach);
    iterations += solve.iterations;
    ++passes;
    // the zone from the gaps just solved (work_: the gaps at the flat's position, 0 in contact
    // to the tolerance, so every contact point is in the zone)
    std::size_t changed = 0;
    for (std::size_t j = 0; j < ny_; ++j)
      for (std::size_t i = 0; i < nx_; ++i) {
        const std::size_t k = j * sx_ + i;
        const unsigned char inside = active_[k] && (pressure_[k] > 0 || work_[k] <= adhesive_range_);
        changed += inside != cohesive_[k];
        cohesive_[k] = inside;
      }
    if (changed == 0) {
      if (fine) break;
      fine = true;
      continue;
    }
    if (passes >= max_adhesive_passes)
      throw Error("the adhesive contact's cohesive zone did not settle: " + std::to_string(passes) +
                  " passes at the flat's position " + format_double(approach) + " m, " + std::to_string(changed) +
                  " points still changing (the adhesive range " + format_double(adhesive_range_) +
                  " m against the pixels: see docs/exact-contact.md, Adhesive contact)");
  }
  options_.tolerance = tolerance;
  ContactStep step = describe(solve);
  step.iterations = iterations;
  step.solves = passes;
  if (options_.stiffness) stiffness_of(step);  // the zone's tension held: the tangent with both sets held
  return step;
}

ContactStep ExactContact::at_approach(double approach) {
  if (!std::isfinite(approach)) throw Error("the flat's position must be finite, got " + format_double(approach));
  try {
    if (adhesive_) return solve_adhesive(approach);
    const Solve solve = constrained(false, approach);
    ContactStep step = describe(solve);
    if (options_.stiffness) stiffness_of(step);
    return step;
  } catch (const std::bad_alloc&) {
    out_of_memory("solving at the flat's position " + format_double(approach) + " m");
  }
}

}  // namespace asperity::topography
