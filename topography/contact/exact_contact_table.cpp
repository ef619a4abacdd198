#include "asperity/topography/exact_contact_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "asperity/contact_curves.hpp"
#include "asperity/error.hpp"
#include "asperity/number_text.hpp"
#include "asperity/detail/table_schema.hpp"

namespace asperity::topography {
namespace {

double relative(double served, double exact) { return std::fabs(served - exact) / std::fabs(exact); }

std::string at_pressure(double pressure) {
  std::ostringstream text;
  text << pressure << " Pa";
  return text.str();
}

void check_text(const std::string& text, const char* name) {
  if (text.size() > schema::max_text_bytes)
    throw Error(std::string("the table's ") + name + " would hold " + std::to_string(text.size()) +
                " bytes, more than a table's text may have (" + std::to_string(schema::max_text_bytes) + ")");
}

}  // namespace

void check_exact_contact_table_text(const std::string& description, const std::string& generator_options) {
  check_text(description, "description");
  check_text(generator_options, "generator_options");
}

void check_exact_contact_table_nodes(const std::vector<double>& pressures) {
  const std::size_t n = pressures.size();
  if (n < static_cast<std::size_t>(schema::min_contact_curve_nodes) ||
      n > static_cast<std::size_t>(schema::max_contact_curve_nodes))
    throw Error("a contact-curves table needs " + std::to_string(schema::min_contact_curve_nodes) + " to " +
                std::to_string(schema::max_contact_curve_nodes) + " nodes, not " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    if (!(std::isfinite(pressures[i]) && pressures[i] > 0))
      throw Error("a contact-curves table needs its nodes at positive finite pressures, not " +
                  format_double(pressures[i]) + " Pa (node " + std::to_string(i + 1) + ")");
    if (i > 0 && !(pressures[i] > pressures[i - 1]))
      throw Error("a contact-curves table needs its nodes' pressures in ascending order: " +
                  format_double(pressures[i]) + " Pa follows " + format_double(pressures[i - 1]) + " Pa");
  }
}

std::string exact_contact_table_generator_options(const std::string& prefix, const std::vector<double>& pressures) {
  const std::string checks = "; checks at their neighbours' geometric means";
  std::string listed = prefix + "nodes at pressures [Pa]:";
  for (double p : pressures) {
    listed += " " + format_double(p);
    if (listed.size() > schema::max_text_bytes / 4) break;
  }
  if (listed.size() <= schema::max_text_bytes / 4) return listed + checks;
  // too many to list: the pressure dataset holds them, exactly
  return prefix + std::to_string(pressures.size()) + " nodes at pressures from " +
         format_double(pressures.empty() ? 0.0 : pressures.front()) + " to " +
         format_double(pressures.empty() ? 0.0 : pressures.back()) +
         " Pa (each one in the table's pressure dataset)" + checks;
}

ExactContactTable measure_exact_contact_table(ExactContact& solver, const std::vector<ContactStep>& nodes,
                                              const std::string& description, const std::string& generator_options,
                                              double safety_factor) {
  check_exact_contact_table_text(description, generator_options);  // before the checks' solves, not after them
  if (nodes.size() < 3) throw Error("a contact-curves table needs at least 3 nodes");
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (!(std::isfinite(nodes[i].pressure) && nodes[i].pressure > 0) ||
        (i > 0 && !(nodes[i].pressure > nodes[i - 1].pressure)))
      throw Error("a contact-curves table needs its nodes at positive pressures in ascending order");
  if (!solver.options().stiffness) throw Error("a contact-curves table needs the stiffness (the incremental solves)");
  if (!(safety_factor >= 1 && safety_factor <= 1e3)) throw Error("the safety factor must be from 1 to 1000");
  const auto check_step = [](const ContactStep& step) {
    if (!std::isfinite(step.stiffness_per_area) || !(step.stiffness_per_area > 0))
      throw Error("at " + at_pressure(step.pressure) +
                  " the map is in full contact (or the stiffness is not positive): the table must stop below it");
    if (!(step.area_fraction > 0)) throw Error("at " + at_pressure(step.pressure) + " nothing touches");
  };
  ExactContactTable table;
  table.nodes = nodes;
  for (const ContactStep& step : nodes) check_step(step);
  ContactCurvesData& data = table.data;
  // ascending in separation: the highest pressure first
  for (auto step = table.nodes.rbegin(); step != table.nodes.rend(); ++step) {
    data.separation.push_back(step->mean_gap);
    data.pressure.push_back(step->pressure);
    data.stiffness.push_back(step->stiffness_per_area);
    data.area_fraction.push_back(step->area_fraction);
  }
  for (std::size_t i = 1; i < data.separation.size(); ++i)
    if (!(data.separation[i] > data.separation[i - 1]))
      throw Error("the mean gap does not fall strictly with the pressure between " + at_pressure(data.pressure[i]) +
                  " and " + at_pressure(data.pressure[i - 1]) +
                  ": give pressures further apart, or a smaller --tolerance");
  data.generator = "asperity " ASPERITY_TOPOGRAPHY_VERSION " exact-contact";
  data.generator_options = generator_options;
  data.source = "exact-contact";
  data.description = description;
  data.separation_datum =
      "the mean gap: the separation of the flat from the mean plane of the map (the exact solver's mean_gap_m)";
  data.safety_factor = safety_factor;
  data.solver_tolerance = solver.options().tolerance;
  data.contact_modulus = solver.options().contact_modulus;
  data.nominal_area = solver.nominal_area();
  data.mean_summit_height = std::isfinite(solver.mean_summit_height()) ? solver.mean_summit_height() : NAN;
  data.max_height = solver.max_height();
  // the curves as served, before the bound is known
  const ContactCurves served(data);
  table.limited_intervals = served.limited_intervals();
  double worst[3] = {0, 0, 0};
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const ContactStep check = solver.at_pressure(std::sqrt(nodes[i].pressure * nodes[i + 1].pressure));
    check_step(check);
    table.checks.push_back(check);
    const ContactCurvesState state = served.at_separation(check.mean_gap);
    const double errors[3] = {relative(state.pressure, check.pressure),
                              relative(state.stiffness, check.stiffness_per_area),
                              relative(state.area_fraction, check.area_fraction)};
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(errors[k]))
        throw Error("a check between the nodes at " + at_pressure(check.pressure) +
                    " falls outside the curves (the mean gap is not monotone there): give a smaller --tolerance");
      worst[k] = std::max(worst[k], errors[k]);
    }
  }
  for (int k = 0; k < 3; ++k) {
    data.measured_rel_error[k] = worst[k];
    data.max_rel_error[k] = worst[k] * safety_factor;
  }
  data.check_points = static_cast<int>(table.checks.size());
  data.validate("the exact contact curves");
  return table;
}

}  // namespace asperity::topography
