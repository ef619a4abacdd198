#include "asperity/topography/law_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "asperity/contact_curves.hpp"
#include "asperity/contact_law.hpp"
#include "asperity/error.hpp"
#include "asperity/generator/law_curves.hpp"

namespace asperity::topography {
namespace {

std::string g(double value, int digits = 3) {
  std::ostringstream text;
  text.precision(digits);
  text << value;
  return text.str();
}

// GW 1966's ranges of their psi, said of whichever psi is given (`which` names it)
std::string regime_text(double psi, const std::string& which) {
  std::string text = which + " = " + g(psi) + ": ";
  if (psi < 0.6) text += "below 0.6, elastic (plastic contacts only at impractically high pressures)";
  else if (psi <= 1) text += "between 0.6 and 1, elastic at light loads, plastic contacts growing with the load";
  else text += "above 1, plastic contacts at practically every load";
  return text + " (Greenwood & Williamson 1966's ranges, on their psi = (E*/H)(sigma_s/R)^1/2)";
}

// The law's state at nominal pressure p from its served curves, as every model's (over A0).
PhysicalState law_state(const ContactCurves& curves, double p, double area) {
  const ContactCurvesState s = curves.at_pressure(p);
  if (std::isnan(s.separation) || std::isnan(s.stiffness) || std::isnan(s.area_fraction))
    throw Error("the law's curves give no value at " + g(p) + " Pa");
  PhysicalState state{};
  state.separation = s.separation;
  state.mean_separation = s.separation - curves.data().mean_summit_height;
  state.count = curves.summit_count(s.separation) * area;  // NaN: a table without the count
  state.area_fraction = s.area_fraction;
  state.real_area = s.area_fraction * area;
  state.pressure = p;
  state.load = p * area;
  state.stiffness = s.stiffness * area;
  state.stiffness_over_load = s.stiffness / p;
  return state;
}

}  // namespace

LawContact compare_law(const ContactComparison& comparison, const Summits& summits, HeightModel model,
                       const std::string& model_reason, const LawSceneMaker& make, double approach_separation) {
  const ModelContact* elastic = comparison.find(to_string(model));
  if (!elastic || !elastic->served || elastic->at_pressures.size() != comparison.pressures.size())
    throw Error(std::string("contact law: the ") + to_string(model) + " fit has no elastic curves to set the law beside");
  if (summits.list.size() < 2) throw Error("contact law: too few summits for their heights' standard deviation");
  LawContact out;
  out.fit = model;
  out.model_reason = model_reason;
  out.surface = elastic->surface;
  out.elastic_at_pressures = elastic->at_pressures;
  out.summit_radius = summits.radius;
  out.contact_modulus = comparison.options.contact_modulus;
  double mean = 0, squares = 0;
  for (const Summit& s : summits.list) mean += s.height;
  mean /= static_cast<double>(summits.list.size());
  for (const Summit& s : summits.list) squares += (s.height - mean) * (s.height - mean);
  out.summit_height_sd = std::sqrt(squares / static_cast<double>(summits.list.size() - 1));

  // the separations (dimensionless, origin convention) of the elastic curve at its pressure range
  const RoughSurface& surface = out.surface;
  const double scale = surface.height_scale;
  double s_lo = elastic->curve.back().separation / scale, s_hi = elastic->curve.front().separation / scale;
  out.separation_min = s_lo;
  out.separation_max = s_hi;
  const double nan = std::numeric_limits<double>::quiet_NaN(), s0 = approach_separation;
  const bool withdrawal = !std::isnan(s0);
  SceneLaw law = make(surface, s_lo, s_hi, nan);  // the material's errors, before any work
  // and the approach separation's: the law's refusal without adhesion, then s0's own (finite, below 0
  // on the bounded side) over a range it starts; whether the approach reaches the pressures is the
  // curves' question (below)
  if (withdrawal && !is_adhesive(law.law.kind)) make(surface, s_lo, s_hi, s_lo);
  if (withdrawal && s0 < s_hi) make(surface, s0, s_hi, s0);
  out.approach_separation = s0;
  out.law = contact_law_name(law.law.kind);
  if (const ContactLawDescriptor* descriptor = find_contact_law(law.law.kind))
    for (int k = 0; k < descriptor->parameter_count; ++k) {
      const LawParameter parameter = descriptor->parameters[k].parameter;
      out.parameters.push_back({parameter, law_parameter_value(law.law, parameter)});
    }
  out.parameters_text = law_parameters_text(law.law);
  out.valid_up_to = law.law.valid_up_to;
  out.plasticity_index = plasticity_index(law.law, out.summit_height_sd);
  // omega_c of first yield only (an adhesive law's critical_interference is its length scale)
  if (std::isfinite(out.plasticity_index)) out.critical_interference = law.law.critical_interference;
  if (law.law.hardness > 0) out.hardness = law.law.hardness;
  out.gw_plasticity_index =
      greenwood_williamson_plasticity_index(out.contact_modulus, out.hardness, out.summit_height_sd, out.summit_radius);
  out.adhesive = is_adhesive(law.law.kind);
  if (out.adhesive) {
    out.adhesion_parameter = adhesion_parameter(law.law, out.summit_height_sd);
    out.adhesion_length = law.law.critical_interference;
    out.regime = "adhesive (" + out.law + ", " +
                 (withdrawal ? "the withdrawal branch after an approach to s0 = " + g(s0, 6) : "the approach branch") +
                 "): Fuller-Tabor's adhesion parameter sigma_s/delta_c = " + g(out.adhesion_parameter) +
                 " (Fuller & Tabor 1975: the larger, the less of the smooth surfaces' adhesion survives the roughness; "
                 "docs/contact-laws.md section 5)";
  } else if (std::isfinite(out.gw_plasticity_index))
    out.regime = regime_text(out.gw_plasticity_index, "GW's psi");
  else if (std::isfinite(out.plasticity_index))
    out.regime = regime_text(out.plasticity_index, "no hardness for GW's psi (" + out.law +
                                                       " takes the yield strength); the law's psi");
  else
    out.regime = out.law + " has no critical interference: every contact is elastic, no plasticity index";

  // Widen the range until the law's pressure covers the comparison's (the law is softer or
  // stiffer than Hertz past omega_c): its exact pressure by the generator's own quadrature
  const double density = surface.summit_density, p_min = comparison.pressure_min, p_max = comparison.pressure_max;
  SceneLaw branch = law;  // the curves' branch: the approach, or the withdrawal after s0 (from s0 on)
  const auto pressure = [&](double s) { return density * generator::law_means(branch, s).load; };
  const bool bounded = surface.distribution == Distribution::weibull && surface.side == Side::bounded;
  try {
    double step = 0.02 * std::max(s_hi - s_lo, 0.05);
    for (int k = 0; k < 80 && !(pressure(s_hi) < p_min * (1 - 1e-3)); ++k, step *= 1.5)
      s_hi = bounded ? s_hi + std::min(step, -s_hi / 2) : s_hi + step;
    step = 0.02 * std::max(s_hi - s_lo, 0.05);
    for (int k = 0; k < 80 && !(pressure(s_lo) > p_max * (1 + 1e-3)) && s_lo > -1e3; ++k, step *= 1.5) s_lo -= step;
    if (withdrawal) {
      // the withdrawal starts at s0 with the approach's pressure there, and falls from it
      const double reached = pressure(s0);
      if (s0 > s_lo && !(reached > p_max))
        throw Error("the approach to s0 = " + g(s0, 6) + " reaches " + g(reached) + " Pa, not the " + g(p_max) +
                    " Pa the curves are compared up to: approach further (a lower approach separation) or ask lower "
                    "pressures");
      s_lo = std::max(s_lo, s0);  // below s_hi: the pressure there is above p_max, at s_hi below p_min
      branch = make(surface, s0, s_hi, s0);
      // the withdrawal's tension lowers the pressure: from s_lo down towards s0 until it covers p_max
      step = 0.02 * std::max(s_hi - s_lo, 0.05);
      for (int k = 0; k < 80 && s_lo > s0 && !(pressure(s_lo) > p_max * (1 + 1e-3)); ++k, step *= 1.5)
        s_lo = std::max(s0, s_lo - step);
    }
    if (out.adhesive) {
      // on past the greatest tension: the net pressure falls below 0 and rises back towards it
      // (only while the pressure stays within a table's range: where the tension shows only
      // among pressures that small, the roughness has removed the adhesion, and no pull-off is given)
      double step = 0.02 * std::max(s_hi - s_lo, 0.05), previous = pressure(s_hi);
      for (int k = 0; k < 80; ++k, step *= 1.3) {
        const double next_s = bounded ? s_hi + std::min(step, -s_hi / 2) : s_hi + step;
        if (!(next_s < 1e3)) break;
        const double next = pressure(next_s);
        if (!(std::fabs(next) > 1e-140)) break;
        s_hi = next_s;
        if (previous < 0 && next > previous) break;
        previous = next;
      }
    }
    out.separation_min = std::max(s_lo, -1e3);
    out.separation_max = s_hi;
    if (!(pressure(out.separation_min) > p_max) || !(pressure(out.separation_max) < p_min))
      throw Error("no separation within a scene's range [-1e3, 1e3] gives the law's pressures " + g(p_min) + " to " +
                  g(p_max) + " Pa");
    law = make(surface, out.separation_min, out.separation_max, withdrawal ? s0 : nan);
    const generator::LawCurvesResult result = generator::generate_law_curves(law, "asperity surface --law");
    out.nodes = result.nodes;
    for (int k = 0; k < 3; ++k) out.max_rel_error[k] = result.data.max_rel_error[k];
    const ContactCurves curves(result.data);
    const double area = comparison.nominal_area;
    for (double p : curve_pressures(comparison)) out.curve.push_back(law_state(curves, p, area));
    for (double p : comparison.pressures) out.at_pressures.push_back(law_state(curves, p, area));
    if (out.adhesive) {
      out.pull_off_pressure = curves.pull_off_pressure();
      out.pull_off_mean_separation = curves.pull_off_separation() - curves.data().mean_summit_height;
      if (!std::isfinite(out.pull_off_pressure))
        out.warnings.push_back("the tension of the law's curves has no greatest value while their pressures stay above "
                               "1e-140 Pa: no pull-off reported (the roughness leaves no measurable adhesion)");
    }
    out.served = true;
    std::ostringstream note;
    note.precision(2);
    note << "law scene table" << (withdrawal ? " (the withdrawal after an approach to s0 = " + g(s0, 6) + ")" : "")
         << ": separations s = " << g(out.separation_min, 4) << " to " << g(out.separation_max, 4)
         << " (origin convention, in units of the fit's scale " << g(scale) << " m), " << result.nodes
         << " nodes, stored relative error bound " << out.max_rel_error[0] << " (pressure), " << out.max_rel_error[1]
         << " (stiffness), " << out.max_rel_error[2] << " (area fraction)";
    out.note = note.str();
  } catch (const Error& error) {
    // the law's own limits (its source's interferences, an area fraction past 1, ...): stated
    out.curve.clear();
    out.at_pressures.clear();
    out.note = "no curves over the pressures " + g(p_min) + " to " + g(p_max) + " Pa (a tenth of the least pressure "
               "of interest to three times the largest): " + error.what();
    return out;
  }
  for (std::size_t k = 0; k < comparison.pressures.size(); ++k) {
    const PhysicalState &l = out.at_pressures[k], &e = out.elastic_at_pressures[k];
    out.area_over_elastic.push_back(l.real_area / e.real_area);
    out.stiffness_over_elastic.push_back(l.stiffness / e.stiffness);
    out.separation_minus_elastic.push_back(l.mean_separation - e.mean_separation);
    if (l.area_fraction > gw_area_fraction_limit)
      out.warnings.push_back("at " + g(comparison.pressures[k]) + " Pa the real area fraction under the law is " +
                             g(l.area_fraction) + " (above " + g(gw_area_fraction_limit) +
                             "): GW's asperity contacts are sparse and independent only below it");
  }
  return out;
}

}  // namespace asperity::topography
