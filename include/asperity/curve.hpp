// One resolved curve (distribution, side, shape): the hot handle. A Curve is a small handle
// over immutable shared data (a shared pointer, and the lookup's pointers into that data held
// by value, in storage whose layout is the library's own): copies share the data, and any
// number of threads may query one at once.
//
// Complexity: a query is O(1): the bits of s pick a binade and an interval of the lookup grid
// (detail/fast_grid.hpp), then one quintic (six coefficients) and one exp; no log, no search,
// no branch on the data. Outside the grid (|s| < 2^-70, beyond the table, NaN, infinities) the
// table's own layout and the series answer. No allocation, no exception, no lock.
// Accuracy: the table's measured error plus at most CurveOptions::grid_tolerance (docs/accuracy.md).
// Errors by value: NaN for a NaN or infinite separation, an order outside 0..5 or one the
// curve does not hold, or a separation outside the separations it serves (a scene table's
// range: served_min_separation, served_max_separation; a full table's curves serve every s);
// value 0 (log -inf) where the integral is exactly 0 (bounded side, s >= 0), wherever s is.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "asperity/instruction_set.hpp"
#include "asperity/layout.hpp"
#include "asperity/integrals.hpp"

namespace asperity {
namespace detail {
class CompactCurve;
struct GridReference;
struct CurveData;
struct CurveLookup;

// The storage of a Curve's lookup (the lookup grid's sides and directory, the orders'
// coefficients, the contact records), laid out by the library for the kernels it chose for
// this CPU: opaque here. What a caller's inlined code reads of it is fixed: the three entry
// points in front, each given the storage itself, and the mask of the orders held. A change of the kernels, of the grid or of
// what the storage holds changes none of this (the ABI: docs/architecture.md).
struct CurveLookupStorage;
using CurveValueEntry = double (*)(const CurveLookupStorage& lookup, int twice_order, double separation) noexcept;
using CurveContactEntry = bool (*)(const CurveLookupStorage& lookup, double separation, double first, double second,
                                   double third, double fourth, double* state) noexcept;
inline constexpr std::size_t curve_lookup_bytes = 256;
struct CurveLookupStorage {
  CurveValueEntry value;                              // Curve::value
  CurveContactEntry contact_products;                 // Curve::contact_products
  CurveContactEntry contact_products_of_surface;      // Curve::contact_products_of_surface
  unsigned order_mask;                                // the orders held (Curve::order_mask)
  alignas(8) unsigned char opaque[curve_lookup_bytes - 4 * sizeof(void*)];
};
// What a Curve that holds no order answers: NaN, and false (no contact products here).
double no_curve_value(const CurveLookupStorage& lookup, int twice_order, double separation) noexcept;
bool no_contact_products(const CurveLookupStorage& lookup, double separation, double first, double second,
                         double third, double fourth, double* state) noexcept;
}  // namespace detail

struct CurveOptions {
  // The largest error the lookup grid may add to the table's own, in ln X (so relative in X)
  // where X >= 1e-100, and grid_far_factor times that below. Smaller costs memory, never time.
  double grid_tolerance = 1e-13;
  // 1 to 1e6: 100 for a full table (its bound is 1e-10 where X < 1e-100), 1 for a scene table's
  // curves (their tolerance holds everywhere in their range).
  double grid_far_factor = 100;
  // The separations the grid covers (within the table's range); outside, the table's own
  // layout answers (a scene table: the scene's range).
  double grid_min_separation = -1.0 / 0.0;
  double grid_max_separation = 1.0 / 0.0;
  // The separations the curve serves: outside them every lookup answers NaN (the bounded side
  // at s >= 0 excepted, where X is exactly 0). A scene table's curves serve the range its scene
  // asked for, no more (Table::curve narrows what is given here to it); the grid never covers
  // more than this.
  double served_min_separation = -1.0 / 0.0;
  double served_max_separation = 1.0 / 0.0;
  // contact_orders (and contact_at) from a second copy of orders 0..3 laid out for one 4-lane
  // vector: 192 bytes more per grid interval (+67% of the grid), for four quantities at ~1.3x
  // the cost of one (docs/speed-vs-error.md). Off: they cost four lookups' worth of loads.
  bool contact_records = true;
};

// A curve between the shapes of a grid (Table::curve): Lagrange interpolation across shapes at
// the same separation, ln X_n(s) = sum_i weights[i] ln X_n(s; shape i), of ln X_n + s^a on
// the Weibull tail past s = 0 (where ln X falls like -s^a). The Weibull order 0 is exact
// instead: exp(-s^a), 1 - exp(-d^a).
struct ShapeBlend {
  std::vector<double> shapes;
  std::vector<const double*> knot_data;  // each [order][knot][3] on the curve's layout
  std::vector<double> weights;
};

class Curve {
 public:
  Curve() = default;  // holds no order: every query answers NaN
  Curve(const Curve&) = default;
  Curve& operator=(const Curve&) = default;
  // A moved-from Curve is a default one (holds no order), not one whose pointers outlive its data.
  Curve(Curve&& other) noexcept;
  Curve& operator=(Curve&& other) noexcept;
  static constexpr unsigned all_orders = (1u << order_count) - 1;
  // Builds a curve from knot data [order][knot][3] (H, dH/du, d2H/du2) laid out by `layout`,
  // keeping the orders whose bit (1 << twice_order, see model.hpp's order_bit) is set in
  // order_mask: a curve of fewer orders takes proportionally less memory, and answers NaN for
  // the others. Throws asperity::Error for a layout or data that cannot make a curve.
  Curve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
        const double* knot_data, unsigned order_mask = all_orders, const CurveOptions& options = {});
  // A curve between grid shapes: the blend answers on the lookup grid; outside it (below the
  // table's end, where all summits touch) knot_data answers: the nodes' knot data blended with
  // the same weights (the all-touching segment's variable does not depend on the shape).
  Curve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
        const double* knot_data, const ShapeBlend& blend, unsigned order_mask = all_orders,
        const CurveOptions& options = {});

  // ln X_n(s), twice_order = 2n in 0..5, s in the origin convention of docs/model.md.
  double log_value(int twice_order, double separation) const noexcept;
  // X_n(s); underflows to 0 below ~1e-308 (use log_value there). On the grid through a kernel
  // built for this CPU (fused multiply-adds where it has them), so exp(log_value) to the
  // rounding of the quintic: measured within 2.2e-16 (1 + |ln X|) (tests/test_curve.cpp).
  double value(int twice_order, double separation) const noexcept;
  // ln X_n(s) of all six orders at once (one position on the grid): out[twice_order].
  void log_values(double separation, double out[order_count]) const noexcept;
  // ln X_n(s) for twice_order = first..last (inclusive): out[twice_order - first].
  void log_values(double separation, int first_twice_order, int last_twice_order, double* out) const noexcept;
  // Orders 0, 1/2, 1, 3/2 (count, stiffness, area, load: what contact_at needs), logs and
  // values, from one position and (with CurveOptions::contact_records) one 4-lane vector: the
  // records hold log2 X (each of the grid's coefficients times log2 e, rounded once), the
  // values are 2 to them and the logs ln 2 times them, log_value's to ~1e-16 |ln X| (measured
  // within 4.3e-16 (1 + |ln X|), tested to 1e-15); without the records, log_value's bits.
  void contact_orders(double separation, double log_out[4], double value_out[4]) const noexcept;
  // contact_at's arithmetic (contact.hpp) in one kernel call: state[0..3] = the factors times X_n
  // for n = 0, 1, 3/2, 1/2 and state[4] = 1.5 X_1/2 / X_3/2 (detail/contact_ratio.hpp's rule),
  // from contact_orders' exps as m 2^k: (m f) 2^k, which is the factor times contact_orders'
  // value rounded once wherever both are normal doubles, and right where X alone under- or
  // overflows (docs/accuracy.md); false, nothing written, without contact records, off the
  // grid, or for a factor outside (0, DBL_MAX].
  bool contact_products(double separation, double count_factor, double area_factor, double load_factor,
                        double stiffness_factor, double state[5]) const noexcept;
  // The same from the surface (N, R, sigma_s, E*): the factors computed as contact_scales does,
  // in the kernel's vector registers (contact_at's fast path)
  bool contact_products_of_surface(double separation, double summit_count, double summit_radius,
                                   double height_scale, double contact_modulus, double state[5]) const noexcept;

  // The batch path: out[i] = value / log_value(twice_order, separations[i]) for i < count,
  // vectorized for the widest instruction set this CPU has (or the one named; a set it lacks
  // falls back to the best it has). Same results as the scalar functions to rounding.
  // A bad order gives NaN everywhere. out may be the same array as separations (not a
  // partial overlap).
  void value_batch(int twice_order, const double* separations, double* out, std::size_t count,
                   InstructionSet isa = InstructionSet::automatic) const noexcept;
  void log_value_batch(int twice_order, const double* separations, double* out, std::size_t count,
                       InstructionSet isa = InstructionSet::automatic) const noexcept;

  Distribution distribution() const noexcept;
  Side side() const noexcept;
  double shape() const noexcept;
  unsigned order_mask() const noexcept { return lookup_.order_mask; }
  bool has_order(int twice_order) const noexcept {
    return static_cast<unsigned>(twice_order) < static_cast<unsigned>(order_count) &&
           (lookup_.order_mask >> twice_order & 1u);
  }
  // The separations the curve serves, [served_min_separation, served_max_separation]: -inf and
  // +inf for a full table's curves (and a default Curve); a scene table's range for its curves
  // (docs/scenes.md).
  // Outside it every lookup (scalar, batch, contact_orders, log_values) answers NaN, except on
  // the bounded side at s >= 0, where X is exactly 0 (log -inf) wherever the range ends.
  double served_min_separation() const noexcept;
  double served_max_separation() const noexcept;
  // True where the curve answers (the range above, or the bounded side at s >= 0); false for
  // NaN and outside.
  bool serves(double separation) const noexcept;
  // The separations the table's knots span, from the end of the all-touching segment (which
  // reaches -inf) to the start of the series beyond the table (see asymptotic.hpp).
  double table_min_separation() const noexcept;
  double table_max_separation() const noexcept;
  // Bytes of the curve's data (shared by its copies).
  std::size_t memory_bytes() const noexcept;
  // Intervals of the lookup grid per order, and the largest difference from the table the grid
  // showed where it was checked (ln X).
  std::size_t grid_intervals() const noexcept;
  double grid_error() const noexcept;

 private:
  friend class Table;
  void build(detail::CompactCurve& compact, const detail::GridReference& reference, const CurveOptions& options);
  // A curve without a lookup grid: `answer` answers every query (Table::direct_curve)
  static Curve without_grid(detail::CompactCurve answer);
  void adopt(std::shared_ptr<detail::CurveData> data, detail::CurveLookup lookup, bool contact_records);
  // off the grid: the table's own layout, the series, the values at 0 (not inlined: rare)
  double log_value_outside(int twice_order, double separation) const noexcept;
  void batch(int twice_order, const double* separations, double* out, std::size_t count, InstructionSet isa,
             bool log_output) const noexcept;

  const detail::CurveLookup& lookup() const noexcept;  // in the storage (runtime/include/asperity/detail/curve_data.hpp)
  static detail::CurveLookupStorage empty_lookup() noexcept {
    return {&detail::no_curve_value, &detail::no_contact_products, &detail::no_contact_products, 0, {}};
  }

  // The lookup's hot part, held here and not behind data_ (one dependent load fewer a query);
  // its pointers are into *data_. A default Curve's holds no order, and so answers NaN without
  // touching data_.
  detail::CurveLookupStorage lookup_ = empty_lookup();
  std::shared_ptr<const detail::CurveData> data_;
};

inline Curve::Curve(Curve&& other) noexcept : lookup_(other.lookup_), data_(std::move(other.data_)) {
  other.lookup_ = empty_lookup();
}
inline Curve& Curve::operator=(Curve&& other) noexcept {
  if (this != &other) {
    lookup_ = other.lookup_;
    data_ = std::move(other.data_);
    other.lookup_ = empty_lookup();
  }
  return *this;
}

// The hot path: the entry point the library chose for this CPU, called with the lookup's
// storage (one load and one call from the caller's loop); what it does is the library's.
inline double Curve::value(int twice_order, double separation) const noexcept {
  return lookup_.value(lookup_, twice_order, separation);
}

inline bool Curve::contact_products(double separation, double count_factor, double area_factor, double load_factor,
                                    double stiffness_factor, double state[5]) const noexcept {
  return lookup_.contact_products(lookup_, separation, count_factor, area_factor, load_factor, stiffness_factor, state);
}

inline bool Curve::contact_products_of_surface(double separation, double summit_count, double summit_radius,
                                               double height_scale, double contact_modulus,
                                               double state[5]) const noexcept {
  return lookup_.contact_products_of_surface(lookup_, separation, summit_count, summit_radius, height_scale,
                                             contact_modulus, state);
}

}  // namespace asperity
