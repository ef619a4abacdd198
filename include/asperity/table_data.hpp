// A table file's contents in memory (CurveSet, TableData) and the readers that make them
// from a file; Table (table.hpp) serves curves from them. Public: it is what the generator
// makes (generator/generate.hpp, scene_table.hpp), what the writer writes (table_writer.hpp)
// and what Table::data() shows (Python's asperity.CurveSet). The file format's own names and
// limits are the library's (not installed).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "asperity/curve.hpp"
#include "asperity/layout.hpp"
#include "asperity/integrals.hpp"

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
  // Optional (scene tables; empty otherwise): per shape, the lookup grid's tolerance and the
  // separations the curve serves [shape][2], which its grid covers (CurveOptions): outside them
  // a lookup answers NaN.
  std::vector<double> grid_tolerance;
  std::vector<double> grid_separations;
  CurveOptions curve_options(std::size_t shape_index) const;
  // `asked`, its served separations narrowed to the curve's own; throws Error where they do not meet.
  CurveOptions curve_options(std::size_t shape_index, const CurveOptions& asked) const;

  int total_knots() const;
  std::size_t curve_stride() const { return static_cast<std::size_t>(order_count) * total_knots() * 3; }
  // Throws Error if sizes, ordering or values are inconsistent, or beyond the table format's
  // limits (which the writer keeps too).
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

}  // namespace asperity
