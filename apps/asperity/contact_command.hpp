// `asperity contact`: forward and inverse contact of a physical surface (CSV out), and its
// pressure-overclosure law for FE codes (pressure_overclosure.hpp).
#pragma once

namespace CLI {
class App;
}

namespace asperity::cli {

void add_contact_command(CLI::App& app);

// Above this real-area fraction the command warns: GW's asperities are independent Hertz
// contacts, which holds only while contacts are sparse.
inline constexpr double gw_area_fraction_limit = 0.1;

}  // namespace asperity::cli
