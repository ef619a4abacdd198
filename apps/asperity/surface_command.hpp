// `asperity surface FILE ...`: a measured surface to its statistics, summits, fitted height
// distributions with the evidence, and the contact curves of each fit (docs/surfaces.md).
#pragma once
#include <iosfwd>

namespace asperity::cli {

// argv[0] is "surface"; returns the exit status (0 ok, 2 bad usage, input or file). Writes the
// summary (or the JSON with --json) to `out`, messages to `err`.
int surface_command(int argc, char** argv, std::ostream& out, std::ostream& err);
int surface_command(int argc, char** argv);

}  // namespace asperity::cli
