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

// the bytes the measurement appends to generator_options (what the checks found: two counts)
constexpr std::size_t checks_note_bytes = 100;

void check_text(const std::string& text, const char* name, std::size_t reserved) {
  if (text.size() + reserved > schema::max_text_bytes)
    throw Error(std::string("the table's ") + name + " would hold " + std::to_string(text.size()) +
                " bytes, more than a table's text may have (" + std::to_string(schema::max_text_bytes - reserved) +
                ")");
}

}  // namespace

void check_exact_contact_table_text(const std::string& description, const std::string& generator_options) {
  check_text(description, "description", 0);
  check_text(generator_options, "generator_options", checks_note_bytes);
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
  const std::string checks = "; the bound measured by checks between the nodes, finer until settled "
                             "(bound_method checks-until-settled)";
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

namespace {

double pressure_between(double low, double high, double fraction) {
  return std::exp(std::log(low) + fraction * (std::log(high) - std::log(low)));
}

void check_step(const ContactStep& step) {
  if (!std::isfinite(step.stiffness_per_area) || !(step.stiffness_per_area > 0))
    throw Error("at " + at_pressure(step.pressure) +
                " the map is in full contact (or the stiffness is not positive): the table must stop below it");
  if (!(step.area_fraction > 0)) throw Error("at " + at_pressure(step.pressure) + " nothing touches");
}

// An interval between two neighbouring nodes (ascending in pressure) and its checks so far.
struct Interval {
  int level = -1;              // the last level checked (table_checks_at_level)
  double before[3] = {0, 0, 0};  // the largest errors of p, k, a up to the level before it
  double now[3] = {0, 0, 0};     // ... up to it
  bool settled = false;
};

// The nodes as the table's curves: ascending in separation (the highest pressure first).
void fill_nodes(ContactCurvesData& data, const std::vector<ContactStep>& nodes) {
  for (auto step = nodes.rbegin(); step != nodes.rend(); ++step) {
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
}

void describe_solver(ContactCurvesData& data, const ExactContact& solver, const std::string& description,
                     const std::string& generator_options, double safety_factor) {
  data.generator = "asperity " ASPERITY_TOPOGRAPHY_VERSION " exact-contact";
  data.generator_options = generator_options;
  data.source = "exact-contact";
  data.description = description;
  data.separation_datum =
      "the mean gap: the separation of the flat from the mean plane of the map (the exact solver's mean_gap_m)";
  data.safety_factor = safety_factor;
  data.bound_method = ContactBoundMethod::checks_until_settled;
  data.solver_tolerance = solver.options().tolerance;
  data.contact_modulus = solver.options().contact_modulus;
  data.nominal_area = solver.nominal_area();
  data.mean_summit_height = std::isfinite(solver.mean_summit_height()) ? solver.mean_summit_height() : NAN;
  data.max_height = solver.max_height();
}

// The checks a level adds to an interval, at fractions of it in ln p: level 0 at 1/3 and 2/3,
// level L >= 1 at the odd multiples of 1/(3 2^L) (the midpoints between the points so far and
// the nodes), so that after level L the checks are every multiple of 1/(3 2^L) inside.
std::vector<double> level_fractions(int level) {
  if (level == 0) return {1.0 / 3, 2.0 / 3};
  const double step = 1.0 / (3.0 * std::ldexp(1.0, level));
  std::vector<double> fractions;
  for (int m = 1; m < 3 << level; m += 2) fractions.push_back(m * step);
  return fractions;
}

// Solves the next level's checks of every interval listed (ascending in pressure: each solve
// warm starts the next) and measures them against the curves as served.
void check_next_level(ExactContact& solver, const ContactCurves& served, const std::vector<ContactStep>& nodes,
                      std::vector<Interval>& intervals, const std::vector<std::size_t>& which,
                      std::vector<ContactStep>& checks) {
  for (std::size_t i : which) {
    Interval& interval = intervals[i];
    ++interval.level;
    std::copy(interval.now, interval.now + 3, interval.before);
    for (double fraction : level_fractions(interval.level)) {
      const ContactStep check = solver.at_pressure(pressure_between(nodes[i].pressure, nodes[i + 1].pressure, fraction));
      check_step(check);
      checks.push_back(check);
      const ContactCurvesState state = served.at_separation(check.mean_gap);
      const double errors[3] = {relative(state.pressure, check.pressure),
                                relative(state.stiffness, check.stiffness_per_area),
                                relative(state.area_fraction, check.area_fraction)};
      for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(errors[k]))
          throw Error("a check between the nodes at " + at_pressure(check.pressure) +
                      " falls outside the curves (the mean gap is not monotone there): give a smaller --tolerance");
        interval.now[k] = std::max(interval.now[k], errors[k]);
      }
    }
  }
}

// Whether the last level left each largest error (those above `floor`) within
// table_settle_factor of the one before it.
bool settled(const Interval& interval, double floor) {
  for (int k = 0; k < 3; ++k)
    if (interval.now[k] > floor && interval.now[k] > table_settle_factor * interval.before[k]) return false;
  return true;
}

}  // namespace

void check_exact_contact_table_max_checks(std::size_t max_checks) {
  if (max_checks < table_checks_at_level(1))
    throw Error("a table's intervals need at least " + std::to_string(table_checks_at_level(1)) +
                " checks each (two estimates of the error to compare), not " + std::to_string(max_checks));
}

int table_check_levels(std::size_t max_checks) {
  int level = 0;
  while (table_checks_at_level(level + 1) <= max_checks && level < 20) ++level;
  return level;
}

ExactContactTable measure_exact_contact_table(ExactContact& solver, const std::vector<ContactStep>& nodes,
                                              const std::string& description, const std::string& generator_options,
                                              double safety_factor, std::size_t max_checks) {
  check_exact_contact_table_text(description, generator_options);  // before the checks' solves, not after them
  if (nodes.size() < 3) throw Error("a contact-curves table needs at least 3 nodes");
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (!(std::isfinite(nodes[i].pressure) && nodes[i].pressure > 0) ||
        (i > 0 && !(nodes[i].pressure > nodes[i - 1].pressure)))
      throw Error("a contact-curves table needs its nodes at positive pressures in ascending order");
  if (!solver.options().stiffness) throw Error("a contact-curves table needs the stiffness (the incremental solves)");
  if (!(safety_factor >= 1 && safety_factor <= 1e3)) throw Error("the safety factor must be from 1 to 1000");
  check_exact_contact_table_max_checks(max_checks);
  for (const ContactStep& step : nodes) check_step(step);
  ExactContactTable table;
  table.nodes = nodes;
  ContactCurvesData& data = table.data;
  describe_solver(data, solver, description, generator_options, safety_factor);
  fill_nodes(data, table.nodes);
  const ContactCurves served(data);  // the curves as served: the nodes never change
  table.limited_intervals = served.limited_intervals();
  std::vector<Interval> intervals(nodes.size() - 1);
  std::vector<std::size_t> all(intervals.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  // two estimates of every interval's error (2 checks, then 5), then finer where they differ
  check_next_level(solver, served, nodes, intervals, all, table.checks);
  check_next_level(solver, served, nodes, intervals, all, table.checks);
  const int last_level = table_check_levels(max_checks);
  const double floor = table_error_floor(solver.options().tolerance);
  for (;;) {
    std::vector<std::size_t> unsettled;
    for (std::size_t i = 0; i < intervals.size(); ++i)
      if (!settled(intervals[i], floor) && intervals[i].level < last_level) unsettled.push_back(i);
    if (unsettled.empty()) break;
    check_next_level(solver, served, nodes, intervals, unsettled, table.checks);
  }
  double worst[3] = {0, 0, 0};
  for (const Interval& interval : intervals) {
    if (!settled(interval, floor)) ++table.unsettled_intervals;
    table.deepest_level = std::max(table.deepest_level, interval.level);
    for (int k = 0; k < 3; ++k) worst[k] = std::max(worst[k], interval.now[k]);
  }
  std::sort(table.checks.begin(), table.checks.end(),
            [](const ContactStep& a, const ContactStep& b) { return a.pressure < b.pressure; });
  for (int k = 0; k < 3; ++k) {
    data.measured_rel_error[k] = worst[k];
    data.max_rel_error[k] = worst[k] * safety_factor;
  }
  data.check_points = static_cast<int>(table.checks.size());
  // what the checks found, beside the nodes asked (within the text limit: see the header)
  data.generator_options += "; at most " + std::to_string(table_checks_at_level(last_level)) +
                            " checks an interval, " + std::to_string(table.unsettled_intervals) +
                            " intervals not settled there";
  data.validate("the exact contact curves");
  return table;
}

}  // namespace asperity::topography
