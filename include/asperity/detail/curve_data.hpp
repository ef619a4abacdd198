// What a Curve shares (curve.hpp): the lookup grid first (the hot data), then what answers off
// the grid. In a header so that the hot path inlines into a caller's loop.
#pragma once
#include <array>
#include <vector>

#include "asperity/detail/compact_curve.hpp"
#include "asperity/detail/fast_grid.hpp"

namespace asperity::detail {

struct Kernels;

struct CurveData {
  FastGrid grid;
  std::array<const double*, order_count> order_coefficients{};  // into coefficients; null: not held
  std::vector<double> coefficients;  // [held order][interval][fast_stride]
  CompactCurve outside;              // the all-touching segment, the series, the values at 0
  const Kernels* kernels = nullptr;  // the batch kernel of the widest instruction set here
  double grid_error = 0;
};

}  // namespace asperity::detail
