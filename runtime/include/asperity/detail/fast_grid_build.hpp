// Building a curve's fast grid (fast_grid.hpp) from its compact form (compact_curve.hpp).
#pragma once
#include <array>
#include <functional>
#include <cstdint>
#include <vector>

#include "asperity/detail/compact_curve.hpp"
#include "asperity/detail/fast_grid.hpp"

namespace asperity::detail {

struct FastGridBuild {
  FastGrid grid;                                     // its directory points into `directory`
  std::vector<FastBinade> directory;                 // (a move keeps it there; a copy would not)
  std::vector<double> coefficients;                  // [held order][interval][fast_stride]
  std::array<std::int64_t, order_count> order_offset;  // into coefficients; -1: order not held
  double achieved = 0;  // the largest |error| in ln X found at the check points
  FastGridBuild() = default;
  FastGridBuild(FastGridBuild&&) = default;
  FastGridBuild& operator=(FastGridBuild&&) = default;
  FastGridBuild(const FastGridBuild&) = delete;
  FastGridBuild& operator=(const FastGridBuild&) = delete;
};

// What the grid is made from: ln X of all six orders at any s (NaN for an order not held; the
// series past the table's ends, which meet the table to its own error), and the range the
// table covers.
struct GridReference {
  std::function<void(double separation, double out[order_count])> log_values;
  unsigned order_mask = 0;
  double table_min = 0, table_max = 0;  // the grid covers these, cut to [grid_min, grid_max]
  double grid_min = -1.0 / 0.0, grid_max = 1.0 / 0.0;
  // ln X_n as the curve answers it just inside |s| = 2^-70 on each side ([0]: s > 0, [1]:
  // s < 0), where the closed forms answer: X_n(0), or exp(-s^a) for the Weibull order 0; NaN
  // on the bounded side (X_n -> 0 there: nothing to meet). What the grid meets next to s = 0.
  std::array<std::array<double, order_count>, 2> next_to_zero{};
  // The Weibull tail: order 0 is its closed form ln J_0 = -s^a (0 for s <= 0), which the grid
  // follows down to where s^a <= 2^-60 (not a first-contact zone of the tolerance's width).
  bool exact_order_zero = false;
};

// Fills what `reference` says about the curve from its compact form (all but log_values): the
// orders, the table's range, the grid's range [grid_min, grid_max], the closed forms next to 0.
void describe_grid(GridReference& reference, const CompactCurve& compact, double grid_min, double grid_max);

// The grid covers |s| from 2^-70 to the table's ends on each side the table covers. In each
// binade the knot count is doubled until the quintics reproduce the compact curve at the check
// points to `tolerance` in ln X (absolute: relative in X) where X >= 1e-100, and to far_factor
// times that below (CurveOptions::grid_far_factor). A binade whose error stops falling (less
// than 16x over four doublings: the table's pieces meet only to its own error there) keeps what
// it has, and the error is reported (FastGridBuild::achieved, Curve::grid_error). Next to s = 0
// the grid answers the closed form's value (next_to_zero) until ln X_n has moved by more than
// twice the tolerance and the table's own difference there: every curve monotone across s = 0,
// within ~5 times that; the Weibull order 0 (exact_order_zero) until s^a > 2^-60, then to 1e-3
// of s^a where s^a is below the tolerance (so that it stays monotone and below 0). Throws
// asperity::Error if the compact curve is not finite somewhere inside its range, or if the grid
// would take more than 2^17 interval fits (the default table's curves take at most ~3,100, those
// of shapes 0.34-35 ~7,600).
FastGridBuild build_fast_grid(const GridReference& reference, double tolerance, double far_factor = 100);

}  // namespace asperity::detail
