// A table for one scene (asperity/scene.hpp): its exact shapes only, knots where its curves
// need them, each curve's error measured and stored.
//
// Method. Every shape is integrated once on a fine layout (the default layout at a density
// chosen from the tolerance). Then, segment by segment, the knots are thinned by the largest
// power of two whose quintic interpolant still reproduces the dropped fine knots to half the
// tolerance, for the orders and separations the scene asks for (elsewhere a segment keeps
// three knots). The thinned table is then checked against direct double-precision quadrature
// at points across each curve's range; a segment that fails is refined and the check
// repeated, and if even the fine layout fails the fine density is doubled.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "asperity/scene.hpp"
#include "asperity/table.hpp"

namespace asperity::generator {

struct SceneCurveReport {
  SceneCurve curve;                  // with the separation range resolved (loads -> separations)
  double separation_min = 0, separation_max = 0;
  double achieved_error = 0;         // max over the requested orders, against quadrature
  int knots = 0;                     // knots of the curve's layout (all segments)
  std::size_t memory_bytes = 0;      // the curve in memory, its asked orders only (serve_scene)
};

struct SceneResult {
  TableData table;
  std::vector<SceneCurveReport> curves;
  double fine_density = 0;
};

// Throws asperity::Error when a curve cannot meet its tolerance or the memory budget.
// progress, if given, is told each step as it starts ("Weibull tail, 3 shapes: integrating at knot
// density 1", "... shape 1.5 integrated"); called from any of the run's threads, one at a time.
// Interrupted when the caller's InterruptScope asks (asperity/interrupt.hpp).
SceneResult generate_scene_table(const Scene& scene, int threads = 0,
                                 const std::function<void(const std::string&)>& progress = {});

// The separation where X_3/2 = load (dimensionless), by root finding on the quadrature.
double separation_at_load(Distribution distribution, Side side, double shape, double load);

}  // namespace asperity::generator
