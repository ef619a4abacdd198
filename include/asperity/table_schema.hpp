// The HDF5 table schema, defined once for the writer (tablegen) and the reader (runtime).
//
//   /                       attributes: schema, schema_version, generator, generator_options,
//                                       conventions (plain text, readable with h5dump)
//   /<distribution>_<side>  one group per curve set: weibull_tail, weibull_bounded, gaussian_tail
//       attributes  distribution, side, definition
//       shapes          [S]          grid of Weibull shapes, ascending (the Gaussian: one, 2)
//       orders          [6]          0, 1/2, 1, 3/2, 2, 5/2
//       segment_kind    [G] int32    asperity::SegmentKind
//       segment_knots   [G] int32
//       segment_p0      [G], segment_p1 [G]
//       knots           [S][6][K][3] H, dH/du, d2H/du2 at each knot (K = sum of segment_knots),
//                                    H = ln X - offset(u) (see layout.hpp)
//       max_rel_error   [S][6]       the generator's measured max relative error per curve
#pragma once

namespace asperity::schema {

inline constexpr const char* name = "asperity-table";
inline constexpr int version = 1;

inline constexpr const char* attr_schema = "schema";
inline constexpr const char* attr_schema_version = "schema_version";
inline constexpr const char* attr_generator = "generator";
inline constexpr const char* attr_generator_options = "generator_options";
inline constexpr const char* attr_conventions = "conventions";
inline constexpr const char* attr_distribution = "distribution";
inline constexpr const char* attr_side = "side";
inline constexpr const char* attr_definition = "definition";

inline constexpr const char* set_shapes = "shapes";
inline constexpr const char* set_orders = "orders";
inline constexpr const char* set_segment_kind = "segment_kind";
inline constexpr const char* set_segment_knots = "segment_knots";
inline constexpr const char* set_segment_p0 = "segment_p0";
inline constexpr const char* set_segment_p1 = "segment_p1";
inline constexpr const char* set_knots = "knots";
inline constexpr const char* set_max_rel_error = "max_rel_error";

inline constexpr const char* conventions =
    "Greenwood-Williamson asperity integrals, see MODEL.md of the asperity project.\n"
    "Weibull summit heights phi_a(z) = a z^(a-1) exp(-z^a), z >= 0 (unit scale sigma_s);\n"
    "Gaussian phi(z) = exp(-z^2/2)/sqrt(2 pi) (unit rms summit height sigma).\n"
    "tail side:    J_n(s) = integral_{z > max(s,0)} (z - s)^n phi(z) dz, every real s.\n"
    "bounded side: K_n(s) = integral_0^{max(-s,0)} (-s - z)^n phi(z) dz; 0 for s >= 0.\n"
    "Orders n = 0, 1/2, 1, 3/2, 2, 5/2. Separation s from the Weibull origin (Gaussian: from\n"
    "the mean), in units of sigma_s (Gaussian: sigma). dX_n/ds = -n X_(n-1).\n"
    "Stored: H = ln X - offset(u) and dH/du, d2H/du2 on knots uniform in u per segment;\n"
    "segment kinds: 0 reciprocal u=p0/s, 1 linear u=s, 2 graded s=p0+(p1-p0)u^6,\n"
    "3 log_exponent u=ln t (t = s^a or s^2/2, offset -t), 4 log_tau u=ln((-s)^a),\n"
    "offset (n+a)ln(-s). The reciprocal offset is n ln(-s); graded on the Weibull tail for\n"
    "s > 0 has offset -s^a.";

}  // namespace asperity::schema
