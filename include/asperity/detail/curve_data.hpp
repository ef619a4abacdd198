// What a Curve holds (curve.hpp): the lookup's hot part by value (CurveLookup), and, shared,
// the storage it points into and what answers off the grid (CurveData). In a header so that
// the hot path inlines into a caller's loop.
#pragma once
#include <array>
#include <vector>

#include "asperity/detail/compact_curve.hpp"
#include "asperity/detail/fast_grid.hpp"

namespace asperity::detail {

struct Kernels;
struct CurveData;
struct CurveLookup;

// Curve::value, whole, as built for one instruction set (runtime/core/kernel/): NaN for an
// order not held, the grid's answer on it, CurveLookup::value_outside's off it. The caller
// tests nothing: each test it made (the order, a null kernel, the NaN off the grid) cost
// 0.3-0.6 ns of 8.4 in a scratch A/B of bench_lookup's loop, not kept (independent lookups
// overlap, and at ~110 instructions in ~22 cycles a query, by our count, every one counts).
using ScalarValue = double (*)(const CurveLookup& lookup, int twice_order, double separation) noexcept;
// What a default CurveLookup's kernel answers: NaN (it holds no order)
inline double no_curve_value(const CurveLookup&, int, double) noexcept { return __builtin_nan(""); }
// What a CurveLookup without contact records answers for contact_products: false (not here)
inline bool no_contact_products(const FastGrid&, const double*, double, double, double, double, double,
                                double*) noexcept {
  return false;
}

// Everything a query on the grid reads before its data, in the Curve itself: the grid's sides
// and directory pointer, the orders' coefficients, the kernels. Behind the shared pointer they
// cost one more dependent load at the head of every lookup's chain (the Curve's pointer, then
// these): 8.3 against 7.5 ns a query in a scratch A/B of bench_lookup's loop, the pointer
// loaded on every query against held in a register. Trivially copied; every pointer is into
// the CurveData the same Curve shares.
struct CurveLookup {
  FastGrid grid;
  unsigned order_mask = 0;  // bit 1 << twice_order: the orders held
  std::array<const double*, order_count> order_coefficients{};  // null: not held
  // Curve::value, built for this CPU's instruction set
  ScalarValue value = no_curve_value;
  // X off the grid, from `data` (the table's own layout, the series, the values at 0): rare,
  // out of line
  double (*value_outside)(const CurveData& data, int twice_order, double separation) noexcept = nullptr;
  const CurveData* data = nullptr;
  // contact_at's fast path (Curve::contact_products); without contact records, one that says no
  ContactProducts contact_products = no_contact_products;
  // the same from the surface (ContactInputs::surface: Curve::contact_products_of_surface)
  ContactProducts contact_products_of_surface = no_contact_products;
  // log2 X of orders 0..3, [interval][coefficient][order] from a 64-byte boundary (three cache
  // lines an interval: runtime/core/kernel/kernels.hpp): contact_orders' four quintics as one
  // 4-lane vector. Null: not all four held, or CurveOptions::contact_records off.
  const double* contact_records = nullptr;
};

struct CurveData {
  std::vector<FastBinade> directory;  // the grid's (CurveLookup::grid points into it)
  std::vector<double> coefficients;   // [held order][interval][fast_stride]
  std::vector<double> contact_storage;  // CurveLookup::contact_records, aligned inside it
  CompactCurve outside;               // the all-touching segment, the series, the values at 0
  const Kernels* kernels = nullptr;   // the batch kernel of the widest instruction set here
  double grid_error = 0;
};

}  // namespace asperity::detail
