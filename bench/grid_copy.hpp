// The lookup grid of a table's curve, built again by the benchmarks from public parts only
// (CompactCurve and build_fast_grid, as Curve does for a grid shape: runtime/core/curve.cpp),
// so that kernels written outside the runtime (Highway, other record layouts) read the same
// data as Curve. bench_lookup --check verifies that the copy answers bit for bit like Curve.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "asperity/detail/fast_grid_build.hpp"
#include "asperity/table.hpp"

namespace asperity::bench {

struct GridCopy {
  detail::FastGrid grid;                  // its directory points into `directory`
  std::vector<detail::FastBinade> directory;
  std::vector<double> coefficients;  // [held order][interval][fast_stride], as Curve holds them
  std::array<std::int64_t, order_count> order_offset{};
  const double* order(int twice_order) const { return coefficients.data() + order_offset[twice_order]; }
  GridCopy() = default;
  GridCopy(GridCopy&&) = default;  // moves keep the directory where grid points
  GridCopy& operator=(GridCopy&&) = default;
  GridCopy(const GridCopy&) = delete;
  GridCopy& operator=(const GridCopy&) = delete;
};

// The grid of the table's curve at a grid shape (the Gaussian ignores shape), all six orders.
inline GridCopy copy_grid(const Table& table, Distribution distribution, Side side, double shape) {
  const CurveSet& set = *table.find(distribution, side);
  std::size_t index = 0;
  if (distribution == Distribution::gaussian) shape = 2.0;  // as Table::curve
  else
    while (set.shapes[index] != shape) ++index;  // the benchmarks ask for grid shapes only
  const CurveOptions options = set.curve_options(index);
  detail::CompactCurve compact(distribution, side, shape, set.layout, &set.knots[index * set.curve_stride()],
                               Curve::all_orders);
  detail::GridReference reference;
  reference.log_values = [&compact](double separation, double* out) {
    compact.log_values(separation, 0, order_count - 1, out);
  };
  detail::describe_grid(reference, compact, options.grid_min_separation, options.grid_max_separation);
  detail::FastGridBuild build = detail::build_fast_grid(reference, options.grid_tolerance, options.grid_far_factor);
  GridCopy copy;
  copy.grid = build.grid;
  copy.directory = std::move(build.directory);  // a move: copy.grid.directory still points into it
  copy.coefficients = std::move(build.coefficients);
  copy.order_offset = build.order_offset;
  return copy;
}

}  // namespace asperity::bench
