// `asperity contact`: forward and inverse contact of a physical surface (CSV out), and its
// pressure-overclosure law for FE codes (pressure_overclosure.hpp).
#pragma once

namespace CLI {
class App;
}

namespace asperity::cli {

void add_contact_command(CLI::App& app);

}  // namespace asperity::cli
