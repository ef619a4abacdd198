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
  // orders 0..3 again, [interval][coefficient][order] from a 64-byte boundary (three cache lines
  // an interval): contact_orders' four quintics as one 4-lane vector. Null: not all four held,
  // or CurveOptions::contact_records off.
  const double* contact_records = nullptr;
  std::vector<double> contact_storage;
  CompactCurve outside;              // the all-touching segment, the series, the values at 0
  const Kernels* kernels = nullptr;  // the batch kernel of the widest instruction set here
  // Curve::value on the grid built for this CPU's instruction set, or null: the inline code
  ScalarValue scalar_value = nullptr;
  // contact_at's fast path (Curve::contact_products), or null without contact records
  ContactProducts contact_products = nullptr;
  double grid_error = 0;
};

}  // namespace asperity::detail
