// `asperity surface FILE ...`: a measured surface to its statistics, summits, fitted height
// distributions with the evidence, and the contact curves of each fit (docs/surfaces.md).
#pragma once

namespace CLI {
class App;
}

namespace asperity::cli {

void add_surface_command(CLI::App& app);

}  // namespace asperity::cli
