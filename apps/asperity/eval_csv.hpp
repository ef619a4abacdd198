// `asperity eval`: CSV in (dist,side,shape,sep), CSV out (values and logs of the six orders).
#pragma once
#include <iosfwd>

#include "asperity/table.hpp"

namespace asperity::cli {

// Processes every row; a bad row is reported on `errors` with its line number and skipped.
// Returns the number of bad rows (a bad or missing header counts as one and stops).
int eval_csv(const Table& table, std::istream& input, std::ostream& output, std::ostream& errors);

}  // namespace asperity::cli
