// What a Curve holds (curve.hpp): the lookup's hot part in the Curve's own storage
// (CurveLookupStorage: the entry points in front, then a CurveLookup), and, shared, the storage
// it points into and what answers off the grid (CurveData). Internal: the public header sees
// the storage as bytes, so that the kernels and the grid can change without changing the ABI.
#pragma once
#include <array>
#include <new>
#include <type_traits>
#include <vector>

#include "asperity/curve.hpp"
#include "asperity/detail/compact_curve.hpp"
#include "asperity/detail/fast_grid.hpp"

namespace asperity::detail {

struct Kernels;

// Everything a query on the grid reads before its data, in the Curve itself: the grid's sides
// and directory pointer, the orders' coefficients. Behind the shared pointer they would cost
// one more dependent load at the head of every lookup's chain. Trivially copied; every pointer
// is into the CurveData the same Curve shares. The orders held are the storage's order_mask.
struct CurveLookup {
  FastGrid grid;
  std::array<const double*, order_count> order_coefficients{};  // null: not held
  // X off the grid, from `data` (the table's own layout, the series, the values at 0): rare,
  // out of line
  double (*value_outside)(const CurveData& data, int twice_order, double separation) noexcept = nullptr;
  const CurveData* data = nullptr;
  // log2 X of orders 0..3, [interval][coefficient][order] from a 64-byte boundary (three cache
  // lines an interval: runtime/core/kernel/kernels.hpp): contact_orders' four quintics as one
  // 4-lane vector. Null: not all four held, or CurveOptions::contact_records off.
  const double* contact_records = nullptr;
};
static_assert(sizeof(CurveLookup) <= sizeof(CurveLookupStorage::opaque), "CurveLookup outgrew the Curve's storage");
static_assert(alignof(CurveLookup) <= 8, "CurveLookup needs more alignment than the Curve's storage has");
static_assert(std::is_trivially_copyable<CurveLookup>::value, "a Curve copies its lookup as bytes");

// The lookup in a Curve's storage (put there by Curve::build; a zeroed one holds no order)
inline const CurveLookup& lookup_in(const CurveLookupStorage& storage) noexcept {
  return *std::launder(reinterpret_cast<const CurveLookup*>(storage.opaque));
}

struct CurveData {
  std::vector<FastBinade> directory;  // the grid's (CurveLookup::grid points into it)
  std::vector<double> coefficients;   // [held order][interval][fast_stride]
  std::vector<double> contact_storage;  // CurveLookup::contact_records, aligned inside it
  CompactCurve outside;               // the all-touching segment, the series, the values at 0
  const Kernels* kernels = nullptr;   // the batch kernel of the widest instruction set here
  double grid_error = 0;
};

}  // namespace asperity::detail

namespace asperity {
inline const detail::CurveLookup& Curve::lookup() const noexcept { return detail::lookup_in(lookup_); }
}  // namespace asperity
