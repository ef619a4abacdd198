// `asperity exact-contact FILE ...`: the exact elastic contact of a measured height map with a
// flat (boundary elements on FFTs, topography/exact_contact.hpp; docs/exact-contact.md) at the
// pressures or mean gaps asked, as CSV or JSON; optionally the pressure and gap fields as images
// and the curve as a CalculiX/Abaqus pressure-overclosure card.
#pragma once

namespace CLI {
class App;
}

namespace asperity::cli {

void add_exact_contact_command(CLI::App& app);

}  // namespace asperity::cli
