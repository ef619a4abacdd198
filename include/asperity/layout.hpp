// The knot layout of a tabulated curve: which segments cover the separation axis, each with
// its kind, knot count and ends. Public because public signatures name it: a Curve is built
// from a layout (curve.hpp), a table's curve set carries one (CurveSet::layout, table_data.hpp)
// and the generator integrates on one (generator/chain_ode.hpp). What a kind means (its map
// from separation s to the segment variable u, its offset, its schema text) is the table
// format's, defined once in the library (runtime/include/asperity/detail/segment_kind.hpp).
#pragma once
#include <vector>

#include "asperity/integrals.hpp"

namespace asperity {

// A segment's kind. The numbers are the table format (a file stores them): never reuse one.
// The library's list of kinds (detail/segment_kind.hpp) checks that it matches this enum.
enum class SegmentKind : int {
  reciprocal = 0,       // s <= s1 (the next segment's start), u = sqrt(s1/s)
  linear = 1,           // p0 <= s <= p1, u = s
  graded = 2,           // s = p0 + (p1 - p0) u^q (version 1 tables)
  log_exponent = 3,     // s >= p0 and t <= p1, u = ln t (t = s^a, or s^2/2 for the Gaussian)
  log_tau = 4,          // tau = (-s)^a in [p0, p1], u = ln tau
  log_distance = 5,     // p0 <= s <= p1 < 0, u = ln(-s)
  bounded_far = 6,      // -s = d0 exp(L u^2): the bounded side past the bulk
  gaussian_linear = 7,  // p0 <= s <= p1, u = s (Gaussian only)
  graded_bare = 8,      // s = p0 + (p1 - p0) u^6
};

// The kind's name in the schema ("reciprocal", ...); "unknown" for a number that names none.
const char* to_string(SegmentKind kind) noexcept;

// A layout has 1 to max_segments segments (the loader refuses more).
inline constexpr int max_segments = 8;

struct SegmentSpec {
  SegmentKind kind;
  int knots;  // >= 2, uniform in u including both ends
  double p0;
  double p1;
};

// The default layouts (knot counts chosen by measurement, see docs/accuracy.md).
std::vector<SegmentSpec> default_layout(Distribution distribution, Side side);

// The same layout with every segment's knot count scaled by `density` (knots - 1 intervals
// become round(density * (knots - 1)), at least 2): a cheaper table for a stated error, or a
// denser one. Throws asperity::Error for a density that is not positive and finite.
std::vector<SegmentSpec> scale_knot_density(const std::vector<SegmentSpec>& layout, double density);

}  // namespace asperity
