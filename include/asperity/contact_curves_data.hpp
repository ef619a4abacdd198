// A table of contact curves against separation in memory (ContactCurvesData), and the reader and
// writer of its file: the table format of table_schema.hpp (the same integrity header and root
// attributes as every table, kind "contact-curves"). ContactCurves (contact_curves.hpp) serves it.
//
// The curves are those of one surface against a flat: today the exact elastic contact of a
// measured height map (asperity exact-contact --table; topography/exact_contact_table.hpp makes
// them), generic enough for any source that gives pressure, stiffness and real area at
// separations (a contact law's curves): `source` and `description` say what they are of.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace asperity {

// How a table's stored bound was measured (the attribute bound_method of its contact_curves
// group; table_schema.hpp): the token written and read, and what it means, defined once here.
// A table written before the attribute has none: unstated (still served). A token this runtime
// does not know is refused by the reader, naming it (a newer table: update asperity).
#define ASPERITY_CONTACT_BOUND_METHODS(X)                                                                            \
  X(unstated, "unstated",                                                                                           \
    "not stated (a table written before the method was stored; an exact-contact table then compared the served "    \
    "curves with one solve an interval, at its nodes' geometric-mean pressure)")                                     \
  X(checks_until_settled, "checks-until-settled",                                                                   \
    "solves between the nodes at fractions of each interval in ln p, 2 (1/3, 2/3) then 5 (sixths), then finer "    \
    "(the points halved each level) where the largest error of p, k or a rose by more than 1.25 times, until "      \
    "two levels agree or a cap of checks an interval; the bound is the largest error at any check times "           \
    "safety_factor")                                                                                                \
  X(checks_split_to_tolerance, "checks-split-to-tolerance",                                                         \
    "three evaluations of the exact law an interval (its middle and the two Gauss-Legendre points), intervals "     \
    "halved until every one is within half the asked max_rel_error; the bound is the largest error times "          \
    "safety_factor")

enum class ContactBoundMethod {
#define ASPERITY_CONTACT_BOUND_METHOD_ENUM(id, token, meaning) id,
  ASPERITY_CONTACT_BOUND_METHODS(ASPERITY_CONTACT_BOUND_METHOD_ENUM)
#undef ASPERITY_CONTACT_BOUND_METHOD_ENUM
};

// The token written in a table ("two-checks-refined") and what it means, in words.
const char* to_string(ContactBoundMethod method) noexcept;
const char* bound_method_meaning(ContactBoundMethod method) noexcept;
// The method of a token; false for a token this runtime does not know.
bool parse_contact_bound_method(const std::string& token, ContactBoundMethod& method) noexcept;

struct ContactCurvesData {
  std::string generator;          // the program that wrote it ("asperity 0.2.0 exact-contact")
  std::string generator_options;  // its options, as text
  std::string source;             // what the curves are of: "exact-contact"
  std::string description;        // the map, its grid, the solver and its options
  std::string separation_datum;   // the separation's datum, in words
  // The nodes, ascending in separation [m]: pressure [Pa] (descending), stiffness -dp/du [Pa/m],
  // real area fraction (never rising).
  std::vector<double> separation, pressure, stiffness, area_fraction;
  // The stored error bounds (relative) of the served pressure, stiffness and area fraction:
  // measured_rel_error (the largest against check_points independent solves between the nodes)
  // times safety_factor.
  double max_rel_error[3] = {0, 0, 0};
  double measured_rel_error[3] = {0, 0, 0};
  int check_points = 0;
  double safety_factor = 1;
  ContactBoundMethod bound_method = ContactBoundMethod::unstated;  // how measured_rel_error was measured
  double solver_tolerance = 0;  // the solves' own convergence tolerance (relative residual)
  double contact_modulus = 0;   // E* [Pa]
  double nominal_area = 0;      // [m^2]
  // Optional (NaN: not known): above the separation's datum [m], the mean summit height (the
  // datum of the GW curves and of the FE cards) and the highest point (first contact).
  double mean_summit_height = 0.0 / 0.0;
  double max_height = 0.0 / 0.0;
  // Optional, both or neither (an adhesive law's curves; table_schema.hpp): the tensile part of
  // the pressure [Pa] (> 0, never rising) and its stiffness -dp_t/du [Pa/m] (>= 0). Then
  // `pressure` and `stiffness` are the compressive parts, the net pressure is pressure -
  // tensile_pressure, and max_rel_error[0], [1] are relative to the gross pressure and stiffness.
  std::vector<double> tensile_pressure, tensile_stiffness;
  // Optional (empty: not known): summits in contact per m^2 of nominal area (> 0, never rising),
  // and its stored relative bound.
  std::vector<double> summit_count;
  double summit_count_max_rel_error = 0;
  // Optional (NaN: not stated), only with a tensile part: an adhesive law's withdrawal (unloading,
  // fixed grips) branch after an approach to this separation [m], at or below the first node
  // (docs/contact-laws.md section 8); NaN: the approach (loading) branch, or no law's curves.
  double approach_separation = 0.0 / 0.0;

  bool has_tension() const noexcept { return !tensile_pressure.empty(); }
  bool withdrawal() const noexcept { return approach_separation == approach_separation; }

  // Throws Error (naming `context`) for sizes, order, values or text beyond table_schema.hpp's
  // limits: what the reader refuses and the writer never writes.
  void validate(const std::string& context) const;
};

// The whole file's bytes (validated first; throws Error).
std::vector<unsigned char> contact_curves_file_bytes(const ContactCurvesData& data);
// Written with the atomic replace of every table (a crash never leaves half a file).
void write_contact_curves_file(const ContactCurvesData& data, const std::string& path, bool overwrite = false);

// Reads and validates a contact-curves table. Throws TableFileError (table_file.hpp): the
// statuses of every table file, other_schema for a table of another kind.
ContactCurvesData read_contact_curves_file(const std::string& path);
ContactCurvesData read_contact_curves_bytes(const void* bytes, std::size_t size, const std::string& name);

}  // namespace asperity
