// Contact curves against separation, served: the pressure, stiffness and real area fraction of
// one surface against a flat at any separation between a contact-curves table's nodes (a
// measured map's exact elastic contact: asperity exact-contact --table), and the separation at a
// pressure. The table's format and its stored error bound: table_schema.hpp,
// contact_curves_data.hpp; docs/exact-contact.md, "A measured surface as a table".
//
// A ContactCurves is a small handle over immutable shared data: copies share it, and any number
// of threads may query one at once. Queries never allocate, lock or throw: NaN for a NaN
// separation or pressure, or one outside the range served (the first to the last node: nothing
// is extrapolated). A query finds its interval through a directory of equal bins over the range
// (four an interval: O(1) for nodes about evenly spread, a bisection among a bin's intervals
// otherwise), then evaluates the interval's cubics (ln of each quantity, written as the contact
// kernel's record: one 4-lane call gives every exp); the inverse bisects the nodes'
// pressures and solves the cubic by safeguarded Newton.
//
// Interpolation (fixed by the format, so that the stored bound is the bound of what is served):
// ln p by cubic Hermite with the nodes' own slopes d(ln p)/du = -k/p (the stiffness the solver
// gives at each node), limited where needed to keep it monotone (Fritsch and Carlson 1980:
// limited_intervals() says how many); the stiffness is -p d(ln p)/du of that interpolant, so it
// equals the node's at a node; ln a by Steffen's monotone cubic (1990). At the nodes the served
// values are the stored ones to rounding; between them within the stored max_rel_error.
//
// Adhesive curves (a table with a tensile part: ContactCurvesData::has_tension) serve the net
// pressure p_c - p_t (negative: tension) and stiffness k_c - k_t, each part interpolated like
// the pressure above; the stored bound is then relative to the gross p_c + p_t (k_c + k_t), so
// near the net pressure's zero crossing a relative error of the net means nothing. The inverse
// serves the stable branch only: from the first node up to the pull-off (where the net
// stiffness first falls to 0: the greatest tension), or the last node if the curves end before
// it; beyond it, NaN. The summit count, where stored, by Steffen's cubic in ln like the area.
//
// A break (a separation stored twice, table_schema.hpp: an adhesive law's withdrawal, where
// summits start to detach and the stiffness jumps) ends one piece of cubics and starts the next;
// the break's separation is served from the piece on its right. The pull-off may be at a break
// (the net stiffness jumping from > 0 to <= 0 there).
#pragma once
#include <cstddef>
#include <memory>
#include <string>

#include "asperity/contact_curves_data.hpp"
#include "asperity/record_fields.hpp"

namespace asperity {

// Contact curves at one separation; its fields, defined once (a record's list, record_fields.hpp):
// the C API's asperity_contact_curves_state, the Fortran type and `asperity contact`'s CSV columns
// are made from or checked against it.
#define ASPERITY_CONTACT_CURVES_STATE_FIELDS(X)                                                             \
  X(double, separation, "separation_m", "[m], from the table's datum (ContactCurvesData::separation_datum)") \
  X(double, pressure, "nominal_pressure_Pa", "[Pa], mean nominal pressure")                                 \
  X(double, stiffness, "stiffness_per_area_N_per_m3", "-dp/d(separation) [N/m^3 = Pa/m]")                           \
  X(double, area_fraction, "area_fraction", "real contact area / nominal area")

struct ContactCurvesState {
  ASPERITY_CONTACT_CURVES_STATE_FIELDS(ASPERITY_RECORD_MEMBER_ZERO)
};
ASPERITY_DEFINE_RECORD(ContactCurvesState, ASPERITY_CONTACT_CURVES_STATE_FIELDS)

// A row of `asperity contact`'s CSV of contact curves (ContactCurves::row): the state with the
// separation from the mean summit height too and, for a law's curves, the summits in contact
// (a measured surface's table has no such column: the writer leaves the last out)
#define ASPERITY_CONTACT_CURVES_ROW_FIELDS(X)                                                                   \
  X(double, separation, "separation_m", "[m], from the table's datum (ContactCurvesData::separation_datum)")     \
  X(double, separation_from_mean_summit, "separation_from_mean_summit_m", "[m], from the mean summit height")   \
  X(double, pressure, "nominal_pressure_Pa", "[Pa], mean nominal pressure")                                     \
  X(double, stiffness, "stiffness_per_area_N_per_m3", "-dp/d(separation) [N/m^3 = Pa/m]")                               \
  X(double, area_fraction, "area_fraction", "real contact area / nominal area")                                 \
  X(double, summits_in_contact, "summits_in_contact_per_m2", "summits in contact per m^2 of nominal area (NaN: not stored)")

struct ContactCurvesRow {
  ASPERITY_CONTACT_CURVES_ROW_FIELDS(ASPERITY_RECORD_MEMBER_ZERO)
};
ASPERITY_DEFINE_RECORD(ContactCurvesRow, ASPERITY_CONTACT_CURVES_ROW_FIELDS)

class ContactCurves {
 public:
  // Validates the data (ContactCurvesData::validate) and builds the interpolants; throws Error.
  explicit ContactCurves(ContactCurvesData data);
  // Reads a contact-curves table (read_contact_curves_file); throws TableFileError.
  static ContactCurves open(const std::string& path);

  const ContactCurvesData& data() const noexcept;
  // The range served: the first and last node's separations, and their pressures.
  double min_separation() const noexcept;
  double max_separation() const noexcept;
  // The pressures the inverse serves: adhesive curves from the net pressure at
  // stable_branch_end() (the greatest tension where the pull-off is in the range) to the net
  // pressure at min_separation(); otherwise at max_separation() and min_separation().
  double min_pressure() const noexcept;
  double max_pressure() const noexcept;
  // Adhesive curves (a tensile part stored); pull_off_pressure() is the greatest tension (< 0 Pa)
  // and pull_off_separation() where (the net stiffness 0), both NaN where the curves have no
  // tension or the pull-off is not inside their range. stable_branch_end(): the last separation
  // the inverse serves (max_separation() without tension).
  bool has_tension() const noexcept;
  double pull_off_pressure() const noexcept;
  double pull_off_separation() const noexcept;
  double stable_branch_end() const noexcept;
  // Intervals whose Hermite slopes were limited to keep ln p monotone (0 for smooth data).
  std::size_t limited_intervals() const noexcept;

  // The hot path: NaN outside [min_separation(), max_separation()] or for NaN.
  double pressure(double separation) const noexcept;
  double stiffness(double separation) const noexcept;
  double area_fraction(double separation) const noexcept;
  // The tensile part alone: p_t [Pa] and k_t = -dp_t/du [Pa/m] as served (0 and 0 for curves
  // without tension; NaN outside the range); its area_fraction is NaN. The compressive part is
  // the net plus it.
  ContactCurvesState tensile_part(double separation) const noexcept;
  // Summits in contact per m^2 of nominal area; NaN where the table stores no count (a measured
  // surface's exact contact) or outside the range.
  double summit_count(double separation) const noexcept;
  ContactCurvesState at_separation(double separation) const noexcept;
  // The separation where the served pressure is `pressure` (the inverse of pressure(), to a few
  // ulp; adhesive curves: on the stable branch); NaN outside [min_pressure(), max_pressure()] or
  // for NaN. Adhesive curves serve a pressure a few ulp of that range's span past an end (one
  // computed from the two, which straddle 0 Pa, rounds there) as that end's separation.
  double separation_at_pressure(double pressure) const noexcept;
  ContactCurvesState at_pressure(double pressure) const noexcept;
  // The CSV row of a state these curves answered: its separation from the mean summit height
  // (ContactCurvesData::mean_summit_height) and the summits in contact (NaN where not stored)
  ContactCurvesRow row(const ContactCurvesState& state) const noexcept;
  // Whether the table stores the summits in contact (a law's curves): the CSV's last column
  bool counts_summits() const noexcept;

  struct Impl;

 private:
  std::shared_ptr<const Impl> impl_;
};

}  // namespace asperity
