// `asperity eval`'s contract: CSV in (dist,side,shape,sep), CSV out (the values and logs of the
// six orders), numbers in the shortest form that reads back to the same double.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>

#include "asperity/integrals.hpp"
#include "asperity/table.hpp"

namespace asperity::cli {

// Processes every row; a bad row is reported on `errors` with its line number and skipped: one
// the table cannot parse or resolve, or whose separation lies outside what the curve serves (a
// scene table's range: Curve::serves), named with that range.
// Lines end with LF, CRLF or a lone CR; a line longer than max_line_bytes is a bad row.
// Returns the number of bad rows (a bad or missing header counts as one and stops). Stops early
// when `output` fails (the caller reports the write error). Throws asperity::Error when reading
// `input` fails.
// Each shape's curve answers from the table's shape nodes (Table::direct_curve: microseconds a
// shape), or with lookup_grid from a lookup grid built for it (Table::curve: milliseconds a shape
// between nodes, nanoseconds a row); the two agree within 2e-13 of ln X.
std::uint64_t eval_csv(const Table& table, std::istream& input, std::ostream& output, std::ostream& errors,
                       bool lookup_grid = false);

inline constexpr std::size_t max_line_bytes = 65536;

// The output's columns, in the order eval_csv writes each row: the input's four, then X_n at each
// order of the list (twice_order 0 .. order_count - 1), then ln X_n at each:
// dist,side,shape,sep,I0,I1_2,I1,I3_2,I2,I5_2,lnI0,...,lnI5_2.
inline constexpr const char* eval_input_columns[] = {"dist", "side", "shape", "sep"};
inline std::string eval_order_column(int twice_order) {  // "I0", "I1_2", "I1", ...
  return "I" + (twice_order % 2 ? std::to_string(twice_order) + "_2" : std::to_string(twice_order / 2));
}
inline std::string eval_csv_header() {
  std::string header;
  for (const char* column : eval_input_columns) header += (header.empty() ? "" : ",") + std::string(column);
  for (int k = 0; k < order_count; ++k) header += "," + eval_order_column(k);
  for (int k = 0; k < order_count; ++k) header += ",ln" + eval_order_column(k);
  return header;
}

}  // namespace asperity::cli
