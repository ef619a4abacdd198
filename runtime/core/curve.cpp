#include "asperity/curve.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "asperity/detail/compact_curve.hpp"
#include "asperity/detail/curve_data.hpp"
#include "asperity/detail/fast_grid_build.hpp"
#include "asperity/error.hpp"
#include "kernel/kernels.hpp"

namespace asperity {

namespace {
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

// CurveLookup::value_outside: off the grid, the table's own layout, the series, the values at 0
double value_outside(const detail::CurveData& data, int twice_order, double separation) noexcept {
  return std::exp(data.outside.log_value(twice_order, separation));
}
}  // namespace

namespace detail {
double no_curve_value(const CurveLookupStorage&, int, double) noexcept { return not_a_number; }
bool no_contact_products(const CurveLookupStorage&, double, double, double, double, double, double*) noexcept {
  return false;
}
}  // namespace detail

// On the grid: one position (a few integer operations, two loads), one quintic; off it, the
// table's own layout, the series, the values at 0 (out of line: rare).
double Curve::log_value(int twice_order, double separation) const noexcept {
  if (!has_order(twice_order)) return not_a_number;  // also a default Curve: it holds no order
  const detail::CurveLookup& lookup = this->lookup();
  detail::FastPosition at;
  if (__builtin_expect(detail::fast_position(lookup.grid, separation, at), 1))
    return detail::fast_quintic(lookup.order_coefficients[twice_order], at.interval * detail::fast_stride, at.y);
  return log_value_outside(twice_order, separation);
}

Curve::Curve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
             const double* knot_data, unsigned order_mask, const CurveOptions& options) {
  detail::CompactCurve compact(distribution, side, shape, layout, knot_data, order_mask);
  detail::GridReference reference;
  reference.log_values = [&compact](double separation, double* out) { compact.log_values(separation, 0, order_count - 1, out); };
  build(compact, reference, options);
}

Curve::Curve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
             const double* knot_data, const ShapeBlend& blend, unsigned order_mask, const CurveOptions& options) {
  if (blend.shapes.size() != blend.knot_data.size() || blend.shapes.size() != blend.weights.size() ||
      blend.shapes.empty())
    throw Error("a shape blend needs as many shapes, knot data and weights, at least one");
  detail::CompactCurve compact(distribution, side, shape, layout, knot_data, order_mask);
  std::vector<detail::CompactCurve> nodes;
  nodes.reserve(blend.shapes.size());
  for (std::size_t i = 0; i < blend.shapes.size(); ++i)
    nodes.emplace_back(distribution, side, blend.shapes[i], layout, blend.knot_data[i], compact.order_mask());
  const detail::NodeBlend blended(distribution, side, shape, blend.shapes, std::move(nodes), blend.weights);
  const bool exact_order_zero =
      distribution == Distribution::weibull && (compact.order_mask() & order_bit(orders::count));
  detail::GridReference reference;
  reference.log_values = [&](double separation, double* out) {
    blended.log_values(separation, out);
    if (exact_order_zero) out[0] = compact.log_value(orders::count, separation);
  };
  build(compact, reference, options);
}

void Curve::build(detail::CompactCurve& compact, const detail::GridReference& reference_in,
                  const CurveOptions& options) {
  if (!(options.grid_min_separation < options.grid_max_separation))
    throw Error("CurveOptions: the grid's separations must be an interval (min < max)");
  if (!(options.served_min_separation < options.served_max_separation))
    throw Error("CurveOptions: the served separations must be an interval (min < max)");
  // the grid never covers what the curve does not serve (it may then cover nothing)
  const double grid_min = std::max(options.grid_min_separation, options.served_min_separation);
  const double grid_max = std::min(options.grid_max_separation, options.served_max_separation);
  detail::GridReference reference = reference_in;
  detail::describe_grid(reference, compact, grid_min, grid_max);
  auto data = std::make_shared<detail::CurveData>();
  detail::FastGridBuild build = detail::build_fast_grid(reference, options.grid_tolerance, options.grid_far_factor);
  // where the grid covers the whole table, the table's own layout answers only outside it
  if (grid_min <= compact.table_min() && grid_max >= compact.table_max()) compact.keep_outside_only();
  compact.serve_only(options.served_min_separation, options.served_max_separation);
  detail::CurveLookup lookup;
  lookup.grid = build.grid;
  data->directory = std::move(build.directory);  // a move: lookup.grid.directory still points into it
  data->coefficients = std::move(build.coefficients);
  for (int order = 0; order < order_count; ++order)
    lookup.order_coefficients[order] =
        build.order_offset[order] < 0 ? nullptr : data->coefficients.data() + build.order_offset[order];
  data->outside = std::move(compact);
  data->grid_error = build.achieved;
  adopt(std::move(data), lookup, options.contact_records);
}

Curve Curve::without_grid(detail::CompactCurve answer) {
  auto data = std::make_shared<detail::CurveData>();
  data->outside = std::move(answer);
  Curve curve;
  curve.adopt(std::move(data), detail::CurveLookup{}, false);  // a grid that covers nothing
  return curve;
}

// The lookup into the Curve's storage, with the entry points for this CPU and (where the grid
// holds orders 0..3 and they are asked for) the contact records
void Curve::adopt(std::shared_ptr<detail::CurveData> data, detail::CurveLookup lookup, bool contact_records) {
  data->kernels = &detail::kernels_for(InstructionSet::automatic);
  detail::CurveLookupStorage storage = empty_lookup();
  storage.value = data->kernels->value;
  lookup.value_outside = value_outside;
  lookup.data = data.get();
  bool all_contact_orders = contact_records;
  for (int k = 0; k < 4; ++k) all_contact_orders = all_contact_orders && lookup.order_coefficients[k];
  if (all_contact_orders) {
    const std::size_t intervals = static_cast<std::size_t>(lookup.grid.intervals);
    constexpr std::size_t line = 64 / sizeof(double);  // room to start on a cache line
    data->contact_storage.assign(intervals * detail::contact_record_size + line, 0.0);
    double* records = data->contact_storage.data();
    while (reinterpret_cast<std::uintptr_t>(records) % 64 != 0) ++records;
    for (std::size_t i = 0; i < intervals; ++i) {
      const double* const ln_orders[4] = {
          lookup.order_coefficients[0] + i * detail::fast_stride, lookup.order_coefficients[1] + i * detail::fast_stride,
          lookup.order_coefficients[2] + i * detail::fast_stride, lookup.order_coefficients[3] + i * detail::fast_stride};
      detail::write_contact_record(ln_orders, records + i * detail::contact_record_size);
    }
    lookup.contact_records = records;
    storage.contact_products = data->kernels->contact_entry;
    storage.contact_products_of_surface = data->kernels->contact_entry_of_surface;
  }
  storage.order_mask = data->outside.order_mask();
  new (storage.opaque) detail::CurveLookup(lookup);
  data_ = std::move(data);
  lookup_ = storage;
}

Distribution Curve::distribution() const noexcept { return data_ ? data_->outside.distribution() : Distribution::weibull; }
Side Curve::side() const noexcept { return data_ ? data_->outside.side() : Side::tail; }
double Curve::shape() const noexcept { return data_ ? data_->outside.shape() : 0.0; }
// A default Curve limits no separation (it holds no order: every query answers NaN anyway).
double Curve::served_min_separation() const noexcept {
  return data_ ? data_->outside.served_min() : -std::numeric_limits<double>::infinity();
}
double Curve::served_max_separation() const noexcept {
  return data_ ? data_->outside.served_max() : std::numeric_limits<double>::infinity();
}
bool Curve::serves(double separation) const noexcept {
  return data_ ? data_->outside.serves(separation) : !std::isnan(separation);
}
double Curve::table_min_separation() const noexcept { return data_ ? data_->outside.table_min() : not_a_number; }
double Curve::table_max_separation() const noexcept { return data_ ? data_->outside.table_max() : not_a_number; }
std::size_t Curve::grid_intervals() const noexcept { return data_ ? static_cast<std::size_t>(lookup().grid.intervals) : 0; }
double Curve::grid_error() const noexcept { return data_ ? data_->grid_error : not_a_number; }

std::size_t Curve::memory_bytes() const noexcept {
  if (!data_) return sizeof(*this);
  return sizeof(*this) + sizeof(detail::CurveData) +
         (data_->coefficients.capacity() + data_->contact_storage.capacity()) * sizeof(double) +
         data_->directory.capacity() * sizeof(detail::FastBinade) + data_->outside.memory_bytes();
}

double Curve::log_value_outside(int twice_order, double separation) const noexcept {
  return data_->outside.log_value(twice_order, separation);
}


void Curve::log_values(double separation, double out[order_count]) const noexcept {
  log_values(separation, 0, order_count - 1, out);
}

// One position on the grid for every order asked: the cost of several orders is one lookup
// plus a quintic each.
void Curve::log_values(double separation, int first, int last, double* out) const noexcept {
  if (first < 0 || last >= order_count || first > last) return;
  if (!data_) {
    for (int k = first; k <= last; ++k) out[k - first] = not_a_number;
    return;
  }
  detail::FastPosition at;
  if (!detail::fast_position(lookup().grid, separation, at)) {
    data_->outside.log_values(separation, first, last, out);
    return;
  }
  for (int k = first; k <= last; ++k) {
    const double* c = lookup().order_coefficients[k];
    out[k - first] = c ? detail::fast_quintic(c, at.interval * detail::fast_stride, at.y) : not_a_number;
  }
}

// One position, then the four orders' quintics and exps as one 4-lane vector from the contact
// records; without them (or off the grid), log_values and four independent exps.
void Curve::contact_orders(double separation, double log_out[4], double value_out[4]) const noexcept {
  if (!data_) {
    for (int k = 0; k < 4; ++k) log_out[k] = value_out[k] = not_a_number;
    return;
  }
  detail::FastPosition at;
  if (lookup().contact_records && __builtin_expect(detail::fast_position(lookup().grid, separation, at), 1)) {
    double log2s[4];
    data_->kernels->contact4(lookup().contact_records + at.interval * detail::contact_record_size, at.y, log2s,
                             value_out);
    detail::contact_logs_of(log2s, log_out);
    return;
  }
  log_values(separation, 0, 3, log_out);
  for (int k = 0; k < 4; ++k) value_out[k] = detail::fast_exp(log_out[k]);
}

void Curve::value_batch(int twice_order, const double* separations, double* out, std::size_t count,
                        InstructionSet isa) const noexcept {
  batch(twice_order, separations, out, count, isa, false);
}

void Curve::log_value_batch(int twice_order, const double* separations, double* out, std::size_t count,
                            InstructionSet isa) const noexcept {
  batch(twice_order, separations, out, count, isa, true);
}

void Curve::batch(int twice_order, const double* separations, double* out, std::size_t count, InstructionSet isa,
                  bool log_output) const noexcept {
  if (!has_order(twice_order)) {
    for (std::size_t i = 0; i < count; ++i) out[i] = not_a_number;
    return;
  }
  const detail::CurveData& data = *data_;
  const detail::Kernels& kernels = isa == InstructionSet::automatic ? *data.kernels : detail::kernels_for(isa);
  const double* coefficients = lookup().order_coefficients[twice_order];
  int rest[detail::batch_block];
  // out may be separations (curve.hpp: no partial overlap): then each block is copied first,
  // since its outputs are written before the queries off the grid are answered; apart, the
  // copy is skipped (Curve::batch, mostly this copy, was 3% of asperity_eval_batch's samples:
  // perf on bench_lookup BM_BatchCApi)
  double block_copy[detail::batch_block];
  const bool in_place = out == separations;
  // a grid that covers nothing (CurveOptions' separations beside the table) has no directory
  // and no record for the kernels' off-grid lanes to read: every query is answered outside it
  const bool empty_grid = lookup().grid.intervals == 0;
  for (std::size_t start = 0; start < count; start += detail::batch_block) {
    const int block = static_cast<int>(count - start < detail::batch_block ? count - start : detail::batch_block);
    const double* block_separations = separations + start;
    if (in_place) {
      for (int j = 0; j < block; ++j) block_copy[j] = separations[start + j];
      block_separations = block_copy;
    }
    int rest_count = block;
    if (empty_grid)
      for (int j = 0; j < block; ++j) rest[j] = j;
    else
      rest_count = kernels.block(lookup().grid, coefficients, block_separations, out + start, block, log_output, rest);
    for (int r = 0; r < rest_count; ++r) {
      const double log_value = data.outside.log_value(twice_order, block_separations[rest[r]]);
      out[start + rest[r]] = log_output ? log_value : std::exp(log_value);
    }
  }
}

}  // namespace asperity
