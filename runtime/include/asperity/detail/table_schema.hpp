// The table file format, defined once for the writer (tablegen) and the reader (runtime).
//
// A table file is an HDF5 file created with a 512-byte user block (which HDF5 skips) holding
// the integrity header, checked with plain file reads before HDF5 sees a byte
// (docs/reliability.md):
//
//   offset  size  field
//        0    16  magic: 0x89 "asperity" CR LF 0x1A LF and three zero bytes
//       16     4  format version (unsigned, little-endian) = version below
//       20     4  header size (unsigned, little-endian) = 512
//       24     8  payload size (unsigned, little-endian): the file's size - 512
//       32    32  SHA-256 of the payload (bytes 512 to the end)
//       64   448  zero
//
// The HDF5 file after it (scalar attributes, fixed datatypes: strings, int32, IEEE float64):
//
//   /                       attributes: schema, schema_version, generator, generator_options,
//                                       conventions (plain text, readable with h5dump),
//                                       exact_shapes (int, optional: 1 in a scene table, whose
//                                       shapes are served exactly and never interpolated)
//   /<distribution>_<side>  one group per curve set: weibull_tail, weibull_bounded, gaussian_tail
//       attributes  distribution, side, definition
//       shapes          [S]          grid of Weibull shapes, ascending (the Gaussian: one, 2)
//       shape_range     [2]          the shapes served (the grid extends past it)
//       orders          [6]          0, 1/2, 1, 3/2, 2, 5/2
//       segment_kind    [G] int32    asperity::SegmentKind
//       segment_knots   [G] int32
//       segment_p0      [G], segment_p1 [G]
//       knots           [S][6][K][3] H, dH/du, d2H/du2 at each knot (K = sum of segment_knots),
//                                    H = ln X - offset(u) (see layout.hpp)
//       max_rel_error   [S][6]       the generator's measured max relative error per curve, as
//                                    served (the runtime's lookup grid included)
//       grid_tolerance  [S]          optional (scene tables): the tolerance of the runtime's
//                                    lookup grid for the curve (CurveOptions; 1e-13 if absent)
//       grid_separations [S][2]      optional (scene tables): the separations the curve serves
//                                    (its scene's range), which the grid covers; outside them a
//                                    lookup answers NaN (X = 0 on the bounded side, s >= 0, excepted)
//
// A second kind of table, contact curves against separation (ContactCurvesData,
// contact_curves_data.hpp), has the same header and root attributes and, at the root, the text
// attribute kind = "contact-curves" (absent: the Greenwood-Williamson integrals above), with one
// group and no curve sets:
//
//   /contact_curves          attributes: source (what the curves are of: "exact-contact", the
//                                        exact elastic contact of a measured map), description
//                                        (the map, its grid, the solver and its options),
//                                        separation_datum (the datum of the separation, in words),
//                                        definition (the quantities and their units)
//       separation      [N]  m, strictly ascending: the nodes (the mean gap, from the datum);
//                            with a tensile part, a separation may be repeated once (a break:
//                            an adhesive law's withdrawal, where the stiffness jumps as summits
//                            start to detach), inside the range, with the same pressure, tensile
//                            pressure, area fraction and count at both: the stiffnesses left and right
//       pressure        [N]  Pa, mean nominal pressure, > 0, strictly descending
//       stiffness       [N]  Pa/m, -dp/d(separation), > 0
//       area_fraction   [N]  real contact area / nominal area, in (0, 1], never rising
//       max_rel_error   [3]  the stored bound of the served pressure, stiffness and area fraction
//                            (relative): measured_rel_error times safety_factor
//       measured_rel_error [3]  the largest relative error measured against independent solves
//                            between the nodes (check_points of them)
//                            attribute bound_method (text, optional): how they were measured, a
//                            token of ContactBoundMethod (contact_curves_data.hpp, where each
//                            is defined); absent (tables before it): "unstated"; a token the
//                            reader does not know is refused (a newer table)
//       check_points    [1] int32, safety_factor [1], solver_tolerance [1] (the solves' relative
//                            residual), contact_modulus [1] Pa, nominal_area [1] m^2
//       mean_summit_height [1], max_height [1]  optional: m above the separation's datum (the
//                            GW curves' datum; first contact)
//       tensile_pressure [N], tensile_stiffness [N]  optional, together (an adhesive contact law's
//                            curves): the tensile part p_t of the pressure, > 0, never
//                            rising, and its k_t = -dp_t/du, >= 0. Then `pressure` and
//                            `stiffness` hold the compressive part p_c, k_c; the pressure served is
//                            p_c - p_t (negative: tension), the stiffness k_c - k_t, and
//                            max_rel_error[0], [1] bound the served error relative to the gross
//                            p_c + p_t and k_c + k_t. Absent: p_t = 0 (every other table)
//       summit_count    [N]  optional: summits in contact per m^2 of nominal area, > 0, never rising
//       summit_count_max_rel_error [1]  with summit_count: its stored bound (relative)
//       approach_separation [1]  optional, only with a tensile part: m, at or below the first
//                            node: the curves are an adhesive law's withdrawal (unloading, fixed
//                            grips) branch after an approach to it; absent: the approach branch
//   Served between the first and last node (outside: NaN); between nodes by a cubic Hermite in
//   ln p with the stored stiffness as slope (-k/p), limited to stay monotone (Fritsch-Carlson),
//   and by Steffen's monotone cubic in ln(area fraction); the stiffness is -p d(ln p)/du of the
//   interpolant. The tensile part like the pressure (ln p_t by cubic Hermite, slopes -k_t/p_t),
//   the summit count like the area fraction (Steffen in ln). A break ends one piece and starts
//   the next: each piece's cubics are its own (Steffen's slopes from its own nodes); the break's
//   separation is served from the piece on its right.
#pragma once
#include <cstddef>
#include <cstdint>

namespace asperity::schema {

inline constexpr const char* name = "asperity-table";
// 2: the integrity header (version 1 had none; such tables are refused: regenerate them).
inline constexpr int version = 2;

// The integrity header (see above).
inline constexpr std::size_t header_bytes = 512;
inline constexpr unsigned char header_magic[16] = {0x89, 'a', 's', 'p', 'e', 'r', 'i', 't',
                                                   'y',  '\r', '\n', 0x1A, '\n', 0, 0, 0};
inline constexpr std::size_t header_version_offset = 16, header_size_offset = 20,
                             header_payload_size_offset = 24, header_digest_offset = 32, header_digest_bytes = 32,
                             header_used_bytes = 64;

// What a reader accepts (and a writer may write): bounds that keep a table's memory and a
// load's work in proportion to the file, far above what the generator makes (the default
// table: 90 shapes, at most 1153 knots in a segment, |H| <= 56, |dH/du| <= 13, |d2H/du2| <= 68).
inline constexpr std::uint64_t max_file_bytes = std::uint64_t(1) << 30;   // 1 GiB
inline constexpr int max_shapes = 4096;                                   // per curve set
inline constexpr int max_segment_knots = 65536;
inline constexpr std::uint64_t max_set_values = std::uint64_t(1) << 26;  // knot values per set: 512 MiB
inline constexpr double max_expansion = 64;  // knot values in memory / bytes of the file holding them
inline constexpr double max_knot_value = 1e4;  // |H|, |dH/du|, |d2H/du2|
inline constexpr double min_shape = 0.05, max_shape = 1000;  // Weibull shapes in a table
inline constexpr std::size_t max_text_bytes = 60000;  // a text attribute (HDF5's compact limit is 64 KiB)

inline constexpr const char* attr_schema = "schema";
inline constexpr const char* attr_schema_version = "schema_version";
inline constexpr const char* attr_generator = "generator";
inline constexpr const char* attr_generator_options = "generator_options";
inline constexpr const char* attr_conventions = "conventions";  // its text: table_writer.cpp
inline constexpr const char* attr_exact_shapes = "exact_shapes";
inline constexpr const char* attr_distribution = "distribution";
inline constexpr const char* attr_side = "side";
inline constexpr const char* attr_definition = "definition";

inline constexpr const char* set_shapes = "shapes";
inline constexpr const char* set_shape_range = "shape_range";
inline constexpr const char* set_orders = "orders";
inline constexpr const char* set_segment_kind = "segment_kind";
inline constexpr const char* set_segment_knots = "segment_knots";
inline constexpr const char* set_segment_p0 = "segment_p0";
inline constexpr const char* set_segment_p1 = "segment_p1";
inline constexpr const char* set_knots = "knots";
inline constexpr const char* set_max_rel_error = "max_rel_error";
inline constexpr const char* set_grid_tolerance = "grid_tolerance";
inline constexpr const char* set_grid_separations = "grid_separations";

// The kind of a table (root attribute `kind`; absent: integrals).
inline constexpr const char* attr_kind = "kind";
inline constexpr const char* kind_integrals = "gw-integrals";
inline constexpr const char* kind_contact_curves = "contact-curves";

// Contact curves against separation (see above).
inline constexpr const char* group_contact_curves = "contact_curves";
inline constexpr const char* attr_source = "source";
inline constexpr const char* attr_description = "description";
inline constexpr const char* attr_separation_datum = "separation_datum";
inline constexpr const char* set_separation = "separation";
inline constexpr const char* set_pressure = "pressure";
inline constexpr const char* set_stiffness = "stiffness";
inline constexpr const char* set_area_fraction = "area_fraction";
inline constexpr const char* set_measured_rel_error = "measured_rel_error";
inline constexpr const char* set_check_points = "check_points";
inline constexpr const char* attr_bound_method = "bound_method";
inline constexpr const char* set_safety_factor = "safety_factor";
inline constexpr const char* set_solver_tolerance = "solver_tolerance";
inline constexpr const char* set_contact_modulus = "contact_modulus";
inline constexpr const char* set_nominal_area = "nominal_area";
inline constexpr const char* set_mean_summit_height = "mean_summit_height";
inline constexpr const char* set_max_height = "max_height";
inline constexpr const char* set_tensile_pressure = "tensile_pressure";
inline constexpr const char* set_tensile_stiffness = "tensile_stiffness";
inline constexpr const char* set_summit_count = "summit_count";
inline constexpr const char* set_summit_count_max_rel_error = "summit_count_max_rel_error";
inline constexpr const char* set_approach_separation = "approach_separation";
// What a reader accepts: bounds that keep every served quantity and its logarithm's slope
// finite, far beyond a physical surface's (separations of micrometres, pressures of kPa to GPa).
inline constexpr int min_contact_curve_nodes = 3, max_contact_curve_nodes = 65536;
inline constexpr double max_contact_separation = 1e3;  // |separation| [m]
inline constexpr double min_contact_value = 1e-150, max_contact_value = 1e150;  // pressure [Pa], stiffness [Pa/m]
inline constexpr double min_contact_node_spacing = 1e-12;  // relative to the separations' span
inline constexpr double max_contact_rel_error = 1e3;     // a stored bound beyond this is refused

inline constexpr const char* contact_curves_definition =
    "Contact curves against separation u [m]: the mean nominal pressure p(u) [Pa] (load over the\n"
    "nominal area), the normal stiffness per area k(u) = -dp/du [Pa/m] and the real contact area\n"
    "fraction a(u) (real area / nominal area). Stored at nodes; served between the first and last\n"
    "node (NaN outside): ln p by cubic Hermite with slope -k/p at the nodes (Fritsch-Carlson limited\n"
    "to stay monotone), k = -p d(ln p)/du of that interpolant, ln a by Steffen's monotone cubic.\n"
    "max_rel_error: the measured largest relative error of the served values against independent\n"
    "solves between the nodes (measured_rel_error) times safety_factor; the attribute bound_method\n"
    "names how they were measured (absent: unstated).\n"
    "Optional tensile_pressure p_t and tensile_stiffness k_t (adhesion): pressure and stiffness are\n"
    "then the compressive parts p_c, k_c; served p = p_c - p_t (negative: tension), k = k_c - k_t,\n"
    "ln p_t like ln p_c; the pressure and stiffness bounds are relative to p_c + p_t and k_c + k_t.\n"
    "Optional summit_count: summits in contact per m^2 [1/m^2], ln by Steffen's cubic, bounded by\n"
    "summit_count_max_rel_error.";

}  // namespace asperity::schema
