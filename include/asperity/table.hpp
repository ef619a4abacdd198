// A loaded table: the curve sets of one HDF5 file, and curves resolved from them.
//
// Opening checks the file's integrity header (SHA-256) before HDF5 reads it, then validates
// everything (schema, version, datatypes, shapes, sizes, bounded knots) and throws
// asperity::TableFileError (an asperity::Error, table_file.hpp) with a message naming the file
// and the problem, and the problem as a value. The trust model: docs/reliability.md. Shapes between grid shapes
// are resolved once, when the curve is made, by 12-point Lagrange interpolation in the grid
// variable q = ln(a) - 1/a (see shape_grid_variable) of the knot data at corresponding
// knots; queries on the resulting Curve cost the same as on a grid shape.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "asperity/curve.hpp"
#include "asperity/layout.hpp"
#include "asperity/model.hpp"

namespace asperity {

// One (distribution, side) group of a table file, in memory.
struct CurveSet {
  Distribution distribution = Distribution::weibull;
  Side side = Side::tail;
  std::vector<double> shapes;        // ascending; the grid runs a few nodes past the range
  double shape_min = 0, shape_max = 0;  // the range served (interpolation stays centred in it)
  std::vector<SegmentSpec> layout;
  std::vector<double> knots;         // [shape][order][knot][3]
  std::vector<double> max_rel_error; // [shape][order], measured by the generator

  int total_knots() const;
  std::size_t curve_stride() const { return static_cast<std::size_t>(order_count) * total_knots() * 3; }
  // Throws Error if sizes, ordering or values are inconsistent, or beyond the limits of
  // table_schema.hpp (which the writer keeps too).
  void validate(const std::string& context) const;
};

struct TableData {
  std::string generator;
  std::string generator_options;
  bool exact_shapes = false;  // a scene table: only its own shapes, never interpolated
  std::vector<CurveSet> sets;
};

// The variable in which shape grids are uniform and shapes are interpolated: q = ln(a) - 1/a.
// It puts nodes closer at small a, where the integrals depend on a most strongly.
double shape_grid_variable(double shape);
inline constexpr int shape_stencil = 12;

// Reads and validates a table file (HDF5, schema asperity::schema). Throws TableFileError.
TableData read_table_file(const std::string& path);
// The same from a whole file's bytes in memory; `name` names them in messages.
TableData read_table_bytes(const void* bytes, std::size_t size, const std::string& name);

class Table {
 public:
  explicit Table(TableData data);
  static Table open(const std::string& path);
  // ASPERITY_TABLE from the environment if set, else the shipped default table.
  static Table open_default();
  static std::string default_path();

  const TableData& data() const noexcept { return data_; }
  const CurveSet* find(Distribution distribution, Side side) const noexcept;
  // Throws Error: no such set, shape not finite, or outside the grid. The Gaussian ignores shape.
  // order_mask (bit 1 << twice_order) keeps only the orders a program needs (less memory).
  Curve curve(Distribution distribution, Side side, double shape, unsigned order_mask = Curve::all_orders) const;

 private:
  TableData data_;
};

}  // namespace asperity
