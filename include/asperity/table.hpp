// A loaded table: the curve sets of one HDF5 file, and curves resolved from them.
//
// Opening checks the file's integrity header (SHA-256) before HDF5 reads it, then validates
// everything (schema, version, datatypes, shapes, sizes, bounded knots) and throws
// asperity::TableFileError (an asperity::Error, table_file.hpp) with a message naming the file
// and the problem, and the problem as a value. The trust model: docs/reliability.md. Shapes
// between grid shapes are resolved once, when the curve is made, by 12-point Lagrange
// interpolation in the grid variable q = ln(a) - 1/a (shape_grid_variable) of the nodes' curves
// at the same separation (ShapeBlend, curve.hpp); queries on the resulting Curve cost the same
// as on a grid shape. Table::direct_curve answers the same blend without a grid: microseconds
// to make, a microsecond a query.
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "asperity/curve.hpp"
#include "asperity/layout.hpp"
#include "asperity/integrals.hpp"
#include "asperity/table_data.hpp"

namespace asperity {
namespace detail {
struct TableState;
}

class Table {
 public:
  // Validates the data (CurveSet::validate) and throws Error for what it refuses.
  explicit Table(TableData data);
  static Table open(const std::string& path);
  // The default table: $ASPERITY_TABLE if set, else the table installed with the library
  // (share/asperity/asperity-default.h5 beside its lib/ or bin/, wherever the installed tree
  // is), else the build tree's (runtime/table/default_table.cpp).
  static Table open_default();
  // The first of default_search_paths() that is a file; throws Error naming every place
  // looked at when none is.
  static std::string default_path();
  // Where default_path() looks, in order ($ASPERITY_TABLE alone when it is set).
  static std::vector<std::string> default_search_paths();

  const TableData& data() const noexcept;
  const CurveSet* find(Distribution distribution, Side side) const noexcept;
  // Throws Error: no such set, shape not finite, or outside the grid. The Gaussian ignores shape.
  // order_mask (bit 1 << twice_order) keeps only the orders a program needs (less memory).
  Curve curve(Distribution distribution, Side side, double shape, unsigned order_mask = Curve::all_orders) const;
  // The same with the lookup grid's options (curve.hpp) given, instead of the table's own (1e-13
  // over the whole range, or a scene table's tolerance and range).
  Curve curve(Distribution distribution, Side side, double shape, unsigned order_mask,
              const CurveOptions& options) const;
  // A curve answered from the table's shape nodes directly, without a lookup grid: made in
  // microseconds where curve() between nodes builds its grid in 2-60 ms, each query costing about
  // a microsecond (the 12 nearest nodes' knots) instead of nanoseconds. Its answers are the
  // blend curve()'s grid is fitted to (so within that grid's tolerance of curve()'s), a node's own
  // knots at a node. For a stream of distinct shapes or a few queries each (asperity eval);
  // curve() for many queries at one shape. Shares the table's data (valid after the Table is
  // gone). Throws as curve() does.
  Curve direct_curve(Distribution distribution, Side side, double shape,
                     unsigned order_mask = Curve::all_orders) const;

 private:
  struct Validated {};
  Table(TableData data, Validated);  // from read_table_file, which has validated it
  Curve make_curve(Distribution distribution, Side side, double shape, unsigned order_mask,
                   const CurveOptions* options) const;  // options null: the table's
  // the data and each shape node's view of its knots, shared with the curves that borrow them
  // (direct_curve)
  std::shared_ptr<const detail::TableState> state_;
};

}  // namespace asperity
