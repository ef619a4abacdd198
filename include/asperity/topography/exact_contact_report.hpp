// The exact contact's results written out, as `asperity exact-contact` prints them: the JSON
// document (schema exact_contact_json_schema), made here as the surface's JSON is
// (surface_report.hpp), its steps from ContactStep's list (exact_contact.hpp). The CSV's header and
// rows are that list's too: csv_header<ContactStep>() and csv_row(step) (asperity/record_fields.hpp).
#pragma once
#include <string>
#include <vector>

#include "asperity/topography/exact_contact.hpp"
#include "asperity/topography/height_map.hpp"

namespace asperity::topography {

// The JSON's schema (its "schema" member; the command's --json help names it).
inline constexpr const char* exact_contact_json_schema = "asperity-exact-contact/1";

// The solved steps with what was solved: the map (leveled or not), the solver's statistics of it,
// its options and what drove the steps (pressures, or mean gaps). JSON has no NaN or infinity:
// null for those (a stiffness in full contact).
std::string exact_contact_json(const HeightMap& map, bool leveled, const ExactContact& solver,
                               const ExactContactOptions& options, bool by_pressure,
                               const std::vector<ContactStep>& steps);

}  // namespace asperity::topography
