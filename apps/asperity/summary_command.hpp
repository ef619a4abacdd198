// `asperity summary`: count, area, load and stiffness of a unit surface for a few shapes.
#pragma once

namespace CLI {
class App;
}

namespace asperity::cli {

void add_summary_command(CLI::App& app);

}  // namespace asperity::cli
