// A measured surface as a table: its exact contact curves (exact_contact.hpp) at nodes, with an
// error bound measured against independent solves between them (docs/exact-contact.md, "A
// measured surface as a table"). The runtime serves the table (asperity/contact_curves.hpp); it
// never depends on this.
//
// The nodes are solves at the pressures asked (ascending: each starts from the last); between
// each two neighbours one more solve, at their geometric mean pressure, gives an exact point
// (u, p, k, a) at which the curves as served (the table's own interpolants) are compared: the
// largest relative errors of pressure, stiffness and area fraction are stored, and the bound the
// table states is those times `safety_factor`.
#pragma once
#include <string>
#include <vector>

#include "asperity/contact_curves_data.hpp"
#include "asperity/topography/exact_contact.hpp"

namespace asperity::topography {

inline constexpr double default_table_safety_factor = 2;

struct ExactContactTable {
  ContactCurvesData data;
  std::vector<ContactStep> nodes;     // ascending in pressure
  std::vector<ContactStep> checks;    // the solves between them
  std::size_t limited_intervals = 0;  // ContactCurves::limited_intervals()
};

// From the nodes (solves by `solver`, stiffness on, at least 3, ascending in pressure) solves the
// checks with the same solver and measures the bound. `description` and `generator_options` go into the
// table as text. Throws asperity::Error, before the checks are solved, for a description or
// generator_options longer than a table's text may be (schema::max_text_bytes), nodes out of
// order or too few, a solver without
// stiffness, a step in full contact (infinite stiffness: the table stops before it), curves
// that do not fall strictly with the separation (give pressures further apart, or a smaller
// tolerance), or a failed solve.
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

ExactContactTable measure_exact_contact_table(ExactContact& solver, const std::vector<ContactStep>& nodes,
                                              const std::string& description, const std::string& generator_options,
                                              double safety_factor = default_table_safety_factor);

}  // namespace asperity::topography
