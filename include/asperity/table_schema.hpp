// The HDF5 table schema, defined once for the writer (tablegen) and the reader (runtime).
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

inline constexpr const char* conventions =
    "Greenwood-Williamson asperity integrals, see MODEL.md of the asperity project.\n"
    "Weibull summit heights phi_a(z) = a z^(a-1) exp(-z^a), z >= 0 (unit scale sigma_s);\n"
    "Gaussian phi(z) = exp(-z^2/2)/sqrt(2 pi) (unit rms summit height sigma).\n"
    "tail side:    J_n(s) = integral_{z > max(s,0)} (z - s)^n phi(z) dz, every real s.\n"
    "bounded side: K_n(s) = integral_0^{max(-s,0)} (-s - z)^n phi(z) dz; 0 for s >= 0.\n"
    "Orders n = 0, 1/2, 1, 3/2, 2, 5/2. Separation s from the Weibull origin (Gaussian: from\n"
    "the mean), in units of sigma_s (Gaussian: sigma). dX_n/ds = -n X_(n-1).\n"
    "Stored: H = ln X - offset(u) and dH/du, d2H/du2 on knots uniform in u per segment.\n"
    "Segment kinds (p0, p1 from segment_p0/p1; t = s^a, or s^2/2 for the Gaussian):\n"
    "0 reciprocal   s <= s1 (start of the next segment), u = sqrt(s1/s), offset n ln(-s)\n"
    "1 linear       p0 <= s <= p1, u = s, offset 0\n"
    "2 graded       s = p0 + (p1 - p0) u^6, offset -s^a on the Weibull tail for s > 0, else 0\n"
    "3 log_exponent s >= p0 and t <= p1, u = ln t, offset -t\n"
    "4 log_tau      tau = (-s)^a in [p0, p1], u = ln tau, offset (n + a) ln(-s)\n"
    "5 log_distance p0 <= s <= p1 < 0, u = ln(-s), offset 0\n"
    "6 bounded_far  -s = d0 exp(L u^2), d0 = p0^(1/a), L = ln((d0 + p1)/d0), offset 0\n"
    "7 gaussian_linear p0 <= s <= p1, u = s, offset -s^2/2 (Gaussian only)\n"
    "Shapes between grid nodes: Lagrange in q = ln a - 1/a over the 12 nearest nodes.";

}  // namespace asperity::schema
