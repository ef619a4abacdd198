// What a Table holds (table.hpp), shared with the curves that borrow from it: the data and, for
// each curve set, each shape node's curve over its own knots (borrowed from the data, so made
// once, when the table is) and its grid variable: Table::direct_curve blends these.
#pragma once
#include <vector>

#include "asperity/detail/compact_curve.hpp"
#include "asperity/table_data.hpp"

namespace asperity::detail {

struct TableState {
  explicit TableState(TableData table);
  TableState(const TableState&) = delete;  // nodes borrow from data
  TableState& operator=(const TableState&) = delete;
  TableData data;
  std::vector<std::vector<CompactCurve>> nodes;    // [set][shape]: empty for a set with no shapes
  std::vector<std::vector<double>> grid_variable;  // [set][shape]: shape_grid_variable
};

}  // namespace asperity::detail
