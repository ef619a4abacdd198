// Serving a scene (asperity/scene.hpp) from a table: a scene table made for it by
// `tablegen --scene`, or any full table such as the shipped default (the shapes between its
// grid nodes are then interpolated here, once). Each curve holds only the orders the scene
// asks for, and comes with the separations it was asked over and the error the table
// guarantees there.
#pragma once
#include <vector>

#include "asperity/curve.hpp"
#include "asperity/scene.hpp"
#include "asperity/table.hpp"

namespace asperity {

struct SceneCurveView {
  SceneCurve spec;
  Curve curve;                       // the requested orders only (others answer NaN)
  double separation_min = 0, separation_max = 0;  // loads resolved to separations
  double error_bound = 0;            // the table's bound for these orders at this shape
};

// Throws asperity::Error if the table lacks a curve, a shape is outside it, or its error bound
// is looser than the scene asks (generate a scene table then).
//   Bounds: a table's stored, measured error (max_rel_error) at one of its own shapes; between
//   the grid shapes of a full table, the tested bound of docs/accuracy.md (1e-10).
std::vector<SceneCurveView> serve_scene(const Table& table, const Scene& scene);

// The separation where X_3/2 = load on a curve (bisection on ln X_3/2, which falls with s).
// NaN if the curve lacks order 3/2 or the load is not reached.
double separation_at_load(const Curve& curve, double load);

}  // namespace asperity
