// ContactCurvesData::validate: what a contact-curves table may hold (table_schema.hpp's limits),
// checked by the reader after it reads and by the writer before it writes.
#include <cmath>
#include <string>

#include "asperity/contact_curves_data.hpp"
#include "asperity/error.hpp"
#include "asperity/detail/table_schema.hpp"

namespace asperity {

namespace {

struct BoundMethodEntry {
  ContactBoundMethod method;
  const char* token;
  const char* meaning;
};
constexpr BoundMethodEntry bound_methods[] = {
#define ASPERITY_CONTACT_BOUND_METHOD_ENTRY(id, token, meaning) {ContactBoundMethod::id, token, meaning},
    ASPERITY_CONTACT_BOUND_METHODS(ASPERITY_CONTACT_BOUND_METHOD_ENTRY)
#undef ASPERITY_CONTACT_BOUND_METHOD_ENTRY
};

const BoundMethodEntry* find_bound_method(ContactBoundMethod method) noexcept {
  for (const BoundMethodEntry& entry : bound_methods)
    if (entry.method == method) return &entry;
  return nullptr;
}

}  // namespace

const char* to_string(ContactBoundMethod method) noexcept {
  const BoundMethodEntry* entry = find_bound_method(method);
  return entry ? entry->token : "?";
}

const char* bound_method_meaning(ContactBoundMethod method) noexcept {
  const BoundMethodEntry* entry = find_bound_method(method);
  return entry ? entry->meaning : "?";
}

bool parse_contact_bound_method(const std::string& token, ContactBoundMethod& method) noexcept {
  for (const BoundMethodEntry& entry : bound_methods)
    if (token == entry.token) {
      method = entry.method;
      return true;
    }
  return false;
}

void ContactCurvesData::validate(const std::string& context) const {
  const auto fail = [&](const std::string& what) { throw Error(context + ": " + what); };
  const auto text = [&](const std::string& value, const char* name) {
    if (value.size() > schema::max_text_bytes) fail(std::string("'") + name + "' is too long");
  };
  text(generator, "generator");
  text(generator_options, "generator_options");
  text(source, "source");
  text(description, "description");
  text(separation_datum, "separation_datum");
  if (source.empty()) fail("the curves need a source (what they are of)");
  const std::size_t n = separation.size();
  if (n < static_cast<std::size_t>(schema::min_contact_curve_nodes) ||
      n > static_cast<std::size_t>(schema::max_contact_curve_nodes))
    fail("contact curves need " + std::to_string(schema::min_contact_curve_nodes) + " to " +
         std::to_string(schema::max_contact_curve_nodes) + " nodes, not " + std::to_string(n));
  if (pressure.size() != n || stiffness.size() != n || area_fraction.size() != n)
    fail("separation, pressure, stiffness and area_fraction must have one value per node");
  const auto in_range = [](double x) { return x >= schema::min_contact_value && x <= schema::max_contact_value; };
  for (std::size_t i = 0; i < n; ++i) {
    const std::string at = " at node " + std::to_string(i);
    if (!(std::fabs(separation[i]) <= schema::max_contact_separation)) fail("a separation is not finite or too large" + at);
    if (!in_range(pressure[i])) fail("a pressure is not positive and finite (or beyond the limits)" + at);
    if (!in_range(stiffness[i])) fail("a stiffness is not positive and finite (or beyond the limits)" + at);
    if (!(area_fraction[i] >= schema::min_contact_value && area_fraction[i] <= 1))
      fail("an area fraction is not in (0, 1]" + at);
  }
  if (tensile_pressure.size() != tensile_stiffness.size())
    fail("tensile_pressure and tensile_stiffness come together (both or neither)");
  if (!tensile_pressure.empty()) {
    if (tensile_pressure.size() != n) fail("tensile_pressure and tensile_stiffness must have one value per node");
    for (std::size_t i = 0; i < n; ++i) {
      const std::string at = " at node " + std::to_string(i);
      if (!in_range(tensile_pressure[i])) fail("a tensile pressure is not positive and finite (or beyond the limits)" + at);
      // 0 where every summit is in contact already and the tension no longer grows (DMT on a
      // Weibull tail below its origin)
      if (!(tensile_stiffness[i] == 0 || in_range(tensile_stiffness[i])))
        fail("a tensile stiffness is not >= 0 and finite (or beyond the limits)" + at);
      if (i > 0 && !(tensile_pressure[i] <= tensile_pressure[i - 1]))
        fail("the tensile pressure must never rise with the separation between nodes " + std::to_string(i - 1) +
             " and " + std::to_string(i));
    }
  }
  if (!summit_count.empty()) {
    if (summit_count.size() != n) fail("summit_count must have one value per node");
    for (std::size_t i = 0; i < n; ++i) {
      const std::string at = " at node " + std::to_string(i);
      if (!in_range(summit_count[i])) fail("a summit count is not positive and finite (or beyond the limits)" + at);
      if (i > 0 && !(summit_count[i] <= summit_count[i - 1]))
        fail("the summit count must never rise with the separation between nodes " + std::to_string(i - 1) + " and " +
             std::to_string(i));
    }
    if (!(summit_count_max_rel_error >= 0 && summit_count_max_rel_error <= schema::max_contact_rel_error))
      fail("the summit count's error bound is not finite and >= 0 (or beyond 1e3)");
  }
  const double span = separation[n - 1] - separation[0];
  for (std::size_t i = 1; i < n; ++i) {
    const std::string at = " between nodes " + std::to_string(i - 1) + " and " + std::to_string(i);
    if (separation[i] == separation[i - 1] && span > 0) {
      // a break (an adhesive withdrawal's: the stiffness jumps there): the values continuous
      if (tensile_pressure.empty()) fail("a separation repeats (a break) in curves without a tensile part" + at);
      if (i < 2 || i + 2 > n || (i >= 2 && separation[i - 2] == separation[i - 1]))
        fail("a break (a repeated separation) must be inside the range, one node apart from another" + at);
      if (!(pressure[i] == pressure[i - 1] && tensile_pressure[i] == tensile_pressure[i - 1] &&
            area_fraction[i] == area_fraction[i - 1] &&
            (summit_count.empty() || summit_count[i] == summit_count[i - 1])))
        fail("at a break (a repeated separation) the pressures, area fraction and count must be the same" + at);
      continue;
    }
    if (!(separation[i] - separation[i - 1] >= schema::min_contact_node_spacing * span) || !(span > 0))
      fail("the separations must ascend strictly (nodes apart by at least 1e-12 of their span; a break repeats "
           "one)" + at);
    if (!(pressure[i] < pressure[i - 1])) fail("the pressure must fall strictly as the separation grows" + at);
    if (!(area_fraction[i] <= area_fraction[i - 1])) fail("the area fraction must never rise with the separation" + at);
  }
  for (int i = 0; i < 3; ++i)
    if (!(max_rel_error[i] >= 0 && max_rel_error[i] <= schema::max_contact_rel_error &&
          measured_rel_error[i] >= 0 && measured_rel_error[i] <= schema::max_contact_rel_error))
      fail("an error bound is not finite and >= 0 (or beyond 1e3)");
  if (!(check_points >= 0)) fail("check_points must be >= 0");
  if (!find_bound_method(bound_method)) fail("the bound's method is not one of ContactBoundMethod's");
  if (!(safety_factor >= 1 && safety_factor <= 1e3)) fail("the safety factor must be from 1 to 1000");
  if (!(solver_tolerance >= 0 && solver_tolerance <= 1)) fail("the solver tolerance must be from 0 to 1");
  if (!in_range(contact_modulus)) fail("the contact modulus is not positive and finite");
  if (!(nominal_area > 0 && nominal_area <= 1e150)) fail("the nominal area is not positive and finite");
  if (!std::isnan(mean_summit_height) && !(std::fabs(mean_summit_height) <= schema::max_contact_separation))
    fail("the mean summit height is not finite (or too large)");
  if (!std::isnan(max_height) && !(std::fabs(max_height) <= schema::max_contact_separation))
    fail("the highest point is not finite (or too large)");
  if (withdrawal() && (tensile_pressure.empty() || !(approach_separation <= separation[0]) ||
                       !(std::fabs(approach_separation) <= schema::max_contact_separation)))
    fail("the approach separation (a withdrawal branch's) goes with a tensile part and must be finite, at or below "
         "the first separation");
}

}  // namespace asperity
