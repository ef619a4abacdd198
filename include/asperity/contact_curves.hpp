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
// otherwise), then evaluates a cubic and an exp per quantity; the inverse bisects the nodes'
// pressures and solves the cubic by safeguarded Newton.
//
// Interpolation (fixed by the format, so that the stored bound is the bound of what is served):
// ln p by cubic Hermite with the nodes' own slopes d(ln p)/du = -k/p (the stiffness the solver
// gives at each node), limited where needed to keep it monotone (Fritsch and Carlson 1980:
// limited_intervals() says how many); the stiffness is -p d(ln p)/du of that interpolant, so it
// equals the node's at a node; ln a by Steffen's monotone cubic (1990). At the nodes the served
// values are the stored ones to rounding; between them within the stored max_rel_error.
#pragma once
#include <cstddef>
#include <memory>
#include <string>

#include "asperity/contact_curves_data.hpp"

namespace asperity {

struct ContactCurvesState {
  double separation = 0;     // m, from the table's datum (ContactCurvesData::separation_datum)
  double pressure = 0;       // Pa, mean nominal pressure
  double stiffness = 0;      // Pa/m, -dp/d(separation)
  double area_fraction = 0;  // real contact area / nominal area
};

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
  double min_pressure() const noexcept;  // at max_separation()
  double max_pressure() const noexcept;  // at min_separation()
  // Intervals whose Hermite slopes were limited to keep ln p monotone (0 for smooth data).
  std::size_t limited_intervals() const noexcept;

  // The hot path: NaN outside [min_separation(), max_separation()] or for NaN.
  double pressure(double separation) const noexcept;
  double stiffness(double separation) const noexcept;
  double area_fraction(double separation) const noexcept;
  ContactCurvesState at_separation(double separation) const noexcept;
  // The separation where the served pressure is `pressure` (the inverse of pressure(), to a few
  // ulp); NaN outside [min_pressure(), max_pressure()] or for NaN.
  double separation_at_pressure(double pressure) const noexcept;
  ContactCurvesState at_pressure(double pressure) const noexcept;

  struct Impl;

 private:
  std::shared_ptr<const Impl> impl_;
};

}  // namespace asperity
