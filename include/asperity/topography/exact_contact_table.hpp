// A measured surface as a table: its exact contact curves (exact_contact.hpp) at nodes, with an
// error bound measured against independent solves between them (docs/exact-contact.md, "A
// measured surface as a table"). The runtime serves the table (asperity/contact_curves.hpp); it
// never depends on this.
//
// The nodes are solves at the pressures asked (ascending: each starts from the last). Between
// them more solves, the checks, give exact points (u, p, k, a) at which the curves as served (the
// table's own interpolants) are compared. One check an interval is not enough on a pixelated
// map: its exact stiffness and area jump where a pixel enters the contact, so the error at one
// point says little of the error elsewhere in the interval (the AFM map's 9-node table stored
// 7.9% for the stiffness, measured at one point an interval, and served 12.6% between them).
// So each interval's error is estimated twice, by 2 checks (at 1/3 and 2/3 of it in ln p) and
// by 5 (1/6 to 5/6 by sixths), and where the second estimate's largest error of p, k or a is
// more than table_settle_factor times the first (and above table_error_floor) the interval is
// checked finer, the points halved each level (level L: every multiple of 1/(3 2^L) inside,
// 3 2^L - 1 checks), until two levels agree or the cap (max_checks an interval) is reached.
// The largest relative errors at any check are stored, and the bound the table states is those
// times `safety_factor`, with the method (ContactBoundMethod::checks_until_settled).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "asperity/contact_curves_data.hpp"
#include "asperity/topography/exact_contact.hpp"

namespace asperity::topography {

inline constexpr double default_table_safety_factor = 2;
// An interval's error estimate has settled when a finer level raised none of its largest errors
// by more than this factor.
inline constexpr double table_settle_factor = 1.25;
// Errors below this are not refined (a hundred times the solves' own tolerance: their noise).
constexpr double table_error_floor(double solver_tolerance) { return 100 * solver_tolerance; }
// The checks an interval has after level L (3 2^L - 1: 2, 5, 11, 23, 47, ...), and the last
// level within `max_checks` of them.
constexpr std::size_t table_checks_at_level(int level) { return (std::size_t(3) << level) - 1; }
int table_check_levels(std::size_t max_checks);
// Throws asperity::Error for max_checks below table_checks_at_level(1) = 5 (two estimates needed).
void check_exact_contact_table_max_checks(std::size_t max_checks);
inline constexpr std::size_t default_table_max_checks = 47;  // level 4

struct ExactContactTable {
  ContactCurvesData data;
  std::vector<ContactStep> nodes;          // ascending in pressure
  std::vector<ContactStep> checks;         // the solves between them, ascending in pressure
  std::size_t limited_intervals = 0;       // ContactCurves::limited_intervals()
  std::size_t unsettled_intervals = 0;     // whose estimate still rose at the cap
  int deepest_level = 0;                   // of any interval
};

// What a table with nodes at these pressures must be, checked before any solve: 3 to
// schema::max_contact_curve_nodes of them, finite, positive and ascending. Throws asperity::Error
// naming the first that is not.
void check_exact_contact_table_nodes(const std::vector<double>& pressures);

// The table's generator_options text for nodes at these pressures, after `prefix` (what made
// it): each pressure listed while the text stays within a quarter of a table's text attribute
// (schema::max_text_bytes), else their count and range (the table's pressure dataset holds every
// one exactly). Always within the limit for a prefix of up to 1000 bytes, whatever the count.
std::string exact_contact_table_generator_options(const std::string& prefix, const std::vector<double>& pressures);

// The table's text attributes within schema::max_text_bytes: throws asperity::Error naming the
// one that is not (what measure_exact_contact_table checks first; callers check it earlier).
void check_exact_contact_table_text(const std::string& description, const std::string& generator_options);

// From the nodes (solves by `solver`, stiffness on, at least 3, ascending in pressure) solves the
// checks with the same solver, finer until settled (at most `max_checks` an interval, at least
// 5) and measures the bound. `description` and
// `generator_options` go into the table as text. Throws asperity::Error, before the checks are
// solved, for a description or generator_options longer than a table's text may be
// (schema::max_text_bytes), nodes out of order or too few, max_checks below 5, a solver without stiffness, a step in
// full contact (infinite stiffness: the table stops before it), curves that do not fall strictly
// with the separation (give pressures further apart, or a smaller tolerance), or a failed solve.
ExactContactTable measure_exact_contact_table(ExactContact& solver, const std::vector<ContactStep>& nodes,
                                              const std::string& description, const std::string& generator_options,
                                              double safety_factor = default_table_safety_factor,
                                              std::size_t max_checks = default_table_max_checks);

}  // namespace asperity::topography
