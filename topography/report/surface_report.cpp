#include "asperity/topography/surface_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "asperity/error.hpp"
#include "asperity/integrals.hpp"
#include "asperity/number_text.hpp"
#include "asperity/topography/next_steps.hpp"
#include "asperity/topography/surrogates.hpp"
#include "input/reader_support.hpp"
#include "record_json.hpp"
#include "svg_plot.hpp"

namespace asperity::topography {
namespace {
using nlohmann::ordered_json;

// JSON has no NaN or infinity: null
ordered_json number(double v) { return std::isfinite(v) ? ordered_json(v) : ordered_json(nullptr); }

std::string g(double v, int digits = 4) {
  if (!std::isfinite(v)) return "–";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
  return buffer;
}

// a physical state as its record's list keys it (physical_state_fields.hpp)
ordered_json state_json(const PhysicalState& s) { return record_json<ordered_json>(s); }

ordered_json assessment_json(const SampleAssessment& a) {
  ordered_json models = ordered_json::array();
  for (const ModelAssessment& m : a.models) {
    const HeightDistribution& d = m.fit.distribution;
    // the distribution's parameters and what follows from them, the fit's, then the assessment's
    // fields (each from its record's list, record_fields.hpp) and its intervals as [lo, hi]
    ordered_json mj = record_json<ordered_json>(d);
    mj["description"] = describe(d.model);
    mj["mean_m"] = number(d.mean());
    mj["standard_deviation_m"] = number(d.standard_deviation());
    mj["estimator"] = d.model == HeightModel::gaussian ? "maximum likelihood" : "maximum product of spacings";
    add_record_json(mj, m.fit);
    add_record_json(mj, m);
    mj["interval_location_m"] = {number(m.location.lo), number(m.location.hi)};
    mj["interval_scale_m"] = {number(m.scale.lo), number(m.scale.hi)};
    mj["interval_shape"] = {number(m.shape.lo), number(m.shape.hi)};
    models.push_back(std::move(mj));
  }
  // the sample's fields (its verdict's object among them), its options', how it was tested, its models
  ordered_json sample = record_json<ordered_json>(a);
  add_record_json(sample, a.options);
  sample["null_distributions"] =
      "from surrogate surfaces of the map's own spectrum with each model's marginal, every statistic computed on them "
      "as on the map";
  sample["intervals"] = interval_method(a.model(HeightModel::weibull_tail).shape_interval);
  sample["models"] = models;
  return sample;
}

ordered_json histogram_json(const HeightMap& map, int bins) {
  double lo = INFINITY, hi = -INFINITY;
  std::size_t n = 0;
  for (double h : map.heights)
    if (!std::isnan(h)) {
      lo = std::min(lo, h);
      hi = std::max(hi, h);
      ++n;
    }
  std::vector<double> density(static_cast<std::size_t>(bins), 0.0);
  const double width = (hi - lo) / bins;
  if (width > 0)
    for (double h : map.heights)
      if (!std::isnan(h)) density[std::min<std::size_t>(static_cast<std::size_t>((h - lo) / width), bins - 1)] += 1;
  for (double& d : density) d = width > 0 ? d / (static_cast<double>(n) * width) : 0;
  return ordered_json{{"lo_m", lo}, {"hi_m", hi}, {"density_per_m", density}};
}

// the ratio of a model's prediction to the Gaussian fit's at each pressure of interest
double ratio(double a, double b) { return (std::isfinite(a) && std::isfinite(b) && b != 0) ? a / b : NAN; }

// how many measured summits carry the answer at pressure k, and whether models are compared there
std::string in_contact_text(const ContactComparison& c, std::size_t k) {
  if (k >= c.measured_summits_in_contact.size()) return "measured summits in contact: not known";
  const std::size_t n = c.measured_summits_in_contact[k];
  return std::to_string(n) + (n == 1 ? " measured summit" : " measured summits") + " in contact" +
         (c.compared_at(k) ? "" : ": too few to compare models");
}

// The unit of the plots' heights: nm for sub-micrometre roughness, else um
struct HeightUnit {
  const char* name;
  double per_metre;
};
HeightUnit height_unit(const SurfaceAnalysis& a) {
  return a.statistics.rms < 1e-6 ? HeightUnit{"nm", 1e9} : HeightUnit{"\xC2\xB5m", 1e6};
}

// Each curve's colour and legend in the plots
const char* colour_of(ContactModelKind kind) {
  switch (kind) {
    case ContactModelKind::measured_summits: return "#2ca02c";
    case ContactModelKind::measured_summits_own_radii: return "#98df8a";
    case ContactModelKind::gaussian_moments: return "#8c8c8c";
    case ContactModelKind::gaussian: return "#000000";
    case ContactModelKind::weibull_tail: return "#1f77b4";
    case ContactModelKind::weibull_bounded: return "#d62728";
    case ContactModelKind::persson: return "#ff7f0e";
    case ContactModelKind::exact: return "#7b3294";
  }
  return "#d62728";
}
const char* legend_of(ContactModelKind kind) {
  switch (kind) {
    case ContactModelKind::measured_summits: return "GW on the measured summits (no law)";
    case ContactModelKind::measured_summits_own_radii: return "measured summits, their own radii";
    case ContactModelKind::gaussian_moments: return "Gaussian from m0, m2, m4 (Nayak-McCool)";
    case ContactModelKind::gaussian: return "Gaussian fit";
    case ContactModelKind::weibull_tail: return "Weibull, tail up";
    case ContactModelKind::weibull_bounded: return "Weibull mirrored (bounded)";
    case ContactModelKind::persson: return "Persson's theory (the map's spectrum)";
    case ContactModelKind::exact: return "exact elastic contact (boundary elements)";
  }
  return "Weibull mirrored (bounded)";
}

std::string p_label(const ModelAssessment& m) {
  if (!(m.bootstrap > 0) || !std::isfinite(m.anderson_darling_p)) return "";
  return " (AD " + p_value_text(m.anderson_darling_p, m.p_at_floor) + ")";
}

// A histogram (density) of values, and the fitted densities over the same span.
detail::PlotPanel density_panel(const std::vector<double>& values, const SampleAssessment& fits, const HeightUnit& unit,
                                const std::string& what, const std::string& title) {
  detail::PlotPanel panel;
  panel.title = title;
  panel.x_label = what + " [" + unit.name + "]";
  panel.y_label = std::string("density [1/") + unit.name + "]";
  if (values.empty()) return panel;
  const auto [lo_it, hi_it] = std::minmax_element(values.begin(), values.end());
  const double lo = *lo_it, hi = *hi_it;
  const std::size_t bins = std::clamp<std::size_t>(values.size() / 25, 10, 60);
  const double width = (hi - lo) / static_cast<double>(bins);
  std::vector<double> counts(bins, 0.0);
  if (width > 0)
    for (double v : values) counts[std::min(bins - 1, static_cast<std::size_t>((v - lo) / width))] += 1;
  panel.bars.label = what + "s (n = " + std::to_string(values.size()) + ")";
  for (std::size_t k = 0; k <= bins; ++k) panel.bars.edges.push_back((lo + width * static_cast<double>(k)) * unit.per_metre);
  for (double c : counts)
    panel.bars.heights.push_back(width > 0 ? c / (static_cast<double>(values.size()) * width * unit.per_metre) : 0);
  const double pad = 0.15 * (hi - lo);
  for (const ModelAssessment& m : fits.models) {
    detail::PlotSeries series;
    series.label = std::string(legend_of(contact_model_kind(m.fit.distribution.model))) + p_label(m);
    series.colour = colour_of(contact_model_kind(m.fit.distribution.model));
    for (int k = 0; k <= 400; ++k) {
      const double x = lo - pad + (hi - lo + 2 * pad) * k / 400.0;
      series.x.push_back(x * unit.per_metre);
      series.y.push_back(std::exp(m.fit.distribution.log_pdf(x)) / unit.per_metre);
    }
    panel.series.push_back(std::move(series));
  }
  return panel;
}

std::string fits_svg(const SurfaceAnalysis& a) {
  const HeightUnit unit = height_unit(a);
  std::vector<double> heights;
  for (const Summit& s : a.summits.list) heights.push_back(s.height);
  std::sort(heights.begin(), heights.end());
  std::vector<detail::PlotPanel> panels;
  panels.push_back(density_panel(heights, a.summit_heights, unit, "summit height", "summit heights and the three fits"));
  detail::PlotPanel qq;
  qq.title = "quantile-quantile: on the line = fits";
  qq.x_label = std::string("model quantile [") + unit.name + "]";
  qq.y_label = std::string("observed summit height [") + unit.name + "]";
  for (const ModelAssessment& m : a.summit_heights.models) {
    detail::PlotSeries series;
    series.label = legend_of(contact_model_kind(m.fit.distribution.model));
    series.colour = colour_of(contact_model_kind(m.fit.distribution.model));
    series.points = true;
    const std::size_t n = heights.size(), step = std::max<std::size_t>(1, n / 2000);  // at most ~2000 markers
    for (std::size_t k = 0; k < n; k += step) {
      series.x.push_back(m.fit.distribution.quantile((static_cast<double>(k) + 0.5) / static_cast<double>(n)) * unit.per_metre);
      series.y.push_back(heights[k] * unit.per_metre);
    }
    qq.series.push_back(std::move(series));
  }
  if (!heights.empty()) {
    detail::PlotSeries line;
    line.colour = "#808080";
    line.dashed = true;
    line.x = line.y = {heights.front() * unit.per_metre, heights.back() * unit.per_metre};
    qq.series.push_back(line);
  }
  panels.push_back(std::move(qq));
  if (a.heights) {
    std::vector<double> all;
    for (double h : a.map.heights)
      if (!std::isnan(h)) all.push_back(h);
    panels.push_back(density_panel(all, *a.heights, unit, "height",
                                   "heights (fits on n = " + std::to_string(a.heights->n) + ", thinned)"));
  }
  return detail::svg_figure(panels);
}

// The contact plots' three panels: load-separation, area-load, stiffness-load, each curve drawn
// on all three, the pressures of interest marked.
struct ContactPanels {
  detail::PlotPanel load, area, stiffness;
  HeightUnit unit;
  double nominal_area;

  ContactPanels(const SurfaceAnalysis& a, const std::string& load_title, const std::string& stiffness_title)
      : unit(height_unit(a)), nominal_area(a.contact->nominal_area) {
    load.title = load_title;
    load.x_label = std::string("separation from the mean summit height [") + unit.name + "]";
    load.y_label = "nominal pressure [Pa]";
    load.log_y = true;
    area.title = "area-load";
    area.x_label = stiffness.x_label = "nominal pressure [Pa]";
    area.y_label = "real area / nominal area";
    area.log_x = area.log_y = stiffness.log_x = stiffness.log_y = true;
    stiffness.title = stiffness_title;
    stiffness.y_label = "normal stiffness per nominal area [N/m\xC2\xB3]";
    load.y_marks = area.x_marks = stiffness.x_marks = a.contact->pressures;
  }
  void add(const std::vector<PhysicalState>& curve, const std::string& label, const char* colour, bool points = false,
           bool dashed = false) {
    detail::PlotSeries l, r, k;
    l.label = r.label = k.label = label;
    l.colour = r.colour = k.colour = colour;
    l.points = r.points = k.points = points;
    l.dashed = r.dashed = k.dashed = dashed;
    for (const PhysicalState& s : curve) {
      l.x.push_back(s.mean_separation * unit.per_metre);
      l.y.push_back(s.pressure);
      r.x.push_back(s.pressure);
      r.y.push_back(s.area_fraction);
      k.x.push_back(s.pressure);
      k.y.push_back(s.stiffness / nominal_area);
    }
    load.series.push_back(std::move(l));
    area.series.push_back(std::move(r));
    stiffness.series.push_back(std::move(k));
  }
  std::string svg() const { return detail::svg_figure({load, area, stiffness}); }
};

std::string contact_svg(const SurfaceAnalysis& a) {
  char title[96];
  std::snprintf(title, sizeof title, "stiffness-load (E* = %.3g Pa)", a.contact->options.contact_modulus);
  ContactPanels panels(a, "load-separation", title);
  for (const ModelContact& m : a.contact->models)
    if (m.served)  // the exact contact's solved steps as markers, Persson dashed
      panels.add(m.curve, legend_of(m.kind), colour_of(m.kind), m.kind == ContactModelKind::exact,
                 m.kind == ContactModelKind::persson);
  return panels.svg();
}

// The law's curves next to the same fit's elastic ones.
std::string law_svg(const SurfaceAnalysis& a) {
  const LawContact& law = *a.law;
  ContactPanels panels(a, law.law + " and elastic: load-separation", "stiffness-load");
  const ModelContact* elastic = a.contact->find(contact_model_kind(law.fit));
  if (elastic && elastic->served)
    panels.add(elastic->curve, std::string("elastic (Hertz), ") + legend_of(contact_model_kind(law.fit)), "#1f77b4");
  panels.add(law.curve, law.law + ", " + legend_of(contact_model_kind(law.fit)), "#d62728");
  return panels.svg();
}

// the map as read and analysed: its grid, noise floor, leveling, statistics, spectral moments,
// correlation, summits, their sampling dependence, the height histogram and the ensemble
void describe_surface(const SurfaceAnalysis& a, ordered_json& j) {
  const HeightMap& map = a.map;
  j["surface"] = {{"source", map.source},   {"format", map.format},     {"nx", map.nx},
                  {"ny", map.ny},           {"dx_m", map.dx},           {"dy_m", map.dy},
                  {"width_m", map.width()}, {"length_m", map.length()}, {"notes", map.notes}};
  // each object a record's fields (its list, record_fields.hpp: SurfaceAnalysis's written records
  // are in j already) and the keys composed around them
  j["noise_floor"]["rule"] = "Sq under 10 times the rms of rounding to the heights' quantization step (q / sqrt(12))";
  j["leveling"] = {{"leveled", a.leveled},
                   {"method", a.leveled ? "least-squares plane subtracted" : "none: the heights as read"},
                   {"offset_m", a.plane.offset},
                   {"slope_x", a.plane.slope_x},
                   {"slope_y", a.plane.slope_y}};
  ordered_json moments{
      {"method",
       "slopes by forward differences, curvatures by second differences (one discrete wavenumber); m2, m4 "
       "the equivalent isotropic moments, geometric means along the principal directions (McCool 1986)"}};
  add_record_json(moments, a.moments);
  moments["isotropic"] = a.moments.anisotropy <= max_isotropic_anisotropy;
  moments["isotropy_limit"] = max_isotropic_anisotropy;
  j["spectral_moments"] = moments;
  j["correlation"]["lag_x_m"] = static_cast<double>(a.correlation.x) * map.dx;
  j["correlation"]["lag_y_m"] = static_cast<double>(a.correlation.y) * map.dy;
  const Summits& su = a.summits;
  ordered_json summits{
      {"definition", su.options.window == 1 ? "higher than its 8 neighbours" : "highest within the window"},
      {"window_points", su.options.window},
      {"min_drop_m", su.options.min_drop},
      {"count", su.list.size()}};
  add_record_json(summits, su);
  summits["radius_method"] = "1 / mean over summits of -(h_xx + h_yy)/2 (3-point second differences)";
  j["summits"] = summits;
  j["height_histogram"] = histogram_json(map, 60);
  j["ensemble"] = {{"surrogates", a.surrogates},
                   {"padded_grid", {a.padded_nx, a.padded_ny}},
                   {"method", surrogate_method()}};
}

// the verdict's fields (its list), the rules it applied and the models it names
ordered_json verdict_json(const SurfaceVerdict& v) {
  ordered_json verdict = record_json<ordered_json>(v);
  verdict["rule"] =
      "each sample's Gaussian test that speaks at the significance shared among them (Bonferroni: half each when "
      "both speak)";
  verdict["summit_test_min_summits"] = min_summits_to_test;
  verdict["summit_test_rule"] = summit_test_rule();
  verdict["heights_orientation"] = v.orientation == HeightModel::gaussian ? "none" : to_string(v.orientation);
  verdict["side_rule"] = side_rule();
  verdict["model_for_contact"] = v.named ? to_string(v.model) : "none";
  return verdict;
}

// a model's states at the pressures of interest (its record's at_pressures, written from its list)
// given their stiffness per area and their ratios to the Gaussian fit, the measured summits and the
// exact contact
void add_ratios(ordered_json& at, const ModelContact& mc, const ContactComparison& c) {
  const ModelContact* gaussian = c.find(ContactModelKind::gaussian);
  for (std::size_t k = 0; k < mc.at_pressures.size(); ++k) {
    ordered_json& sj = at[k];
    sj["stiffness_per_area_N_per_m3"] = number(mc.at_pressures[k].stiffness / c.nominal_area);
    if (gaussian && gaussian->served && k < gaussian->at_pressures.size()) {
      const PhysicalState& ref = gaussian->at_pressures[k];
      sj["stiffness_over_gaussian"] = number(ratio(mc.at_pressures[k].stiffness, ref.stiffness));
      sj["area_over_gaussian"] = number(ratio(mc.at_pressures[k].real_area, ref.real_area));
      sj["mean_separation_minus_gaussian_m"] = number(mc.at_pressures[k].mean_separation - ref.mean_separation);
    }
    if (k < mc.stiffness_over_measured.size()) {
      sj["stiffness_over_measured_summits"] = number(mc.stiffness_over_measured[k]);
      sj["mean_separation_minus_measured_summits_m"] = number(mc.separation_minus_measured[k]);
    }
    if (k < mc.stiffness_over_exact.size()) {
      sj["stiffness_over_exact"] = number(mc.stiffness_over_exact[k]);
      sj["area_over_exact"] = number(mc.area_over_exact[k]);
      sj["mean_separation_minus_exact_m"] = number(mc.separation_minus_exact[k]);
    }
  }
}

// which tables served the fitted models' curves, as compare_contact chooses them
std::string tables_text(const ContactOptions& options) {
  if (!options.table_path.empty())
    return "every fitted model (gaussian-moments, gaussian, weibull-tail, weibull-bounded): the given table " +
           options.table_path + " (a Weibull between its grid shapes by interpolation)";
  return "gaussian-moments and gaussian: the default table; each Weibull: an exact-shape scene table at the fitted "
         "shape (shapes " + format_double(weibull_shape_min) + "-" + format_double(weibull_shape_max) + ")";
}

// the contact comparison: its record's written fields (every model's object among them, their
// states at the pressures of interest given their ratios) and the keys composed from the others
ordered_json contact_json(const ContactComparison& c) {
  ordered_json contact{{"contact_modulus_Pa", c.options.contact_modulus}};
  add_record_json(contact, c);
  for (std::size_t m = 0; m < c.models.size(); ++m) add_ratios(contact["models"][m]["at_pressures"], c.models[m], c);
  // at each pressure: enough measured summits in contact to name a closest model there
  std::vector<bool> compared;
  for (std::size_t k = 0; k < c.pressures.size(); ++k) compared.push_back(c.compared_at(k));
  contact["compared_at_pressures"] = compared;
  contact["min_measured_summits_to_compare"] = min_summits_to_compare;
  contact["pressure_range_Pa"] = {c.pressure_min, c.pressure_max};
  contact["tables"] = tables_text(c.options);
  contact["measured_summits_spread"] = {
      {"meaning",
       "relative standard deviation of the measured-summit stiffness, and the standard deviation of its mean "
       "separation [m], over the surrogate ensemble: the uncertainty of every ratio to it"},
      {"stiffness_relative", c.measured_stiffness_spread},
      {"mean_separation_m", c.measured_separation_spread}};
  contact["references"] = {{"persson", c.options.persson},
                           {"exact", c.find(ContactModelKind::exact) != nullptr},
                           {"exact_method", c.exact_method},
                           {"closest_to_exact", contact_model_name(c.closest_to_exact)},
                           {"exact_headline", c.exact_headline}};
  return contact;
}

// the contact law's curves beside the elastic ones of the same fit (its plasticity or adhesion)
// The law's parameters as the registry names them (contact_law_registry.hpp), in the law's order:
// each its key (the scene's and Python's), symbol, value (a choice: its text) and unit.
ordered_json law_parameters_json(const LawContact& law) {
  ordered_json parameters = ordered_json::array();
  for (const LawParameterValue& p : law.parameters) {
    const LawParameterInfo& info = law_parameter_info(p.parameter);
    const bool choice = info.choices[0] && p.value >= 0 && p.value < 3 && info.choices[static_cast<int>(p.value)];
    parameters.push_back({{"key", info.key},
                          {"symbol", info.symbol},
                          {"value", choice ? ordered_json(info.choices[static_cast<int>(p.value)]) : number(p.value)},
                          {"unit", info.unit}});
  }
  return parameters;
}

ordered_json law_json(const LawContact& law, const ContactComparison& c) {
  ordered_json at = ordered_json::array();
  for (std::size_t k = 0; k < law.at_pressures.size(); ++k) {
    ordered_json lj = state_json(law.at_pressures[k]), ej = state_json(law.elastic_at_pressures[k]);
    lj["stiffness_per_area_N_per_m3"] = number(law.at_pressures[k].stiffness / c.nominal_area);
    ej["stiffness_per_area_N_per_m3"] = number(law.elastic_at_pressures[k].stiffness / c.nominal_area);
    at.push_back({{"pressure_Pa", c.pressures[k]},
                  {"law", lj},
                  {"elastic", ej},
                  {"mean_separation_minus_elastic_m", number(law.separation_minus_elastic[k])},
                  {"area_over_elastic", number(law.area_over_elastic[k])},
                  {"stiffness_over_elastic", number(law.stiffness_over_elastic[k])}});
  }
  // its record's written fields (law, model, model_reason, served, note, nodes, curve, warnings),
  // then the nested objects composed from the others
  ordered_json j = record_json<ordered_json>(law);
  j["parameters"] = law_parameters_json(law);
  j["plasticity"] = {
      {"summit_height_standard_deviation_m", number(law.summit_height_sd)},
      {"summit_radius_m", number(law.summit_radius)},
      {"contact_modulus_Pa", number(law.contact_modulus)},
      {"hardness_Pa", number(law.hardness)},
      {"critical_interference_m", number(law.critical_interference)},
      {"valid_up_to_m", number(law.valid_up_to)},
      {"psi", number(law.plasticity_index)},
      {"psi_definition",
       "(sigma_s / omega_c)^1/2 with the law's omega_c (Kogut-Etsion 2003's with the CEB/KE "
       "omega_c; Jackson-Green's with theirs)"},
      {"psi_gw", number(law.gw_plasticity_index)},
      {"psi_gw_definition",
       "(E*/H)(sigma_s/R)^1/2 (Greenwood-Williamson 1966; H: the law's hardness, "
       "Kogut-Etsion's 2.8 Y)"},
      {"regime", law.regime}};
  j["adhesion"] = law.adhesive
                      ? ordered_json{{"adhesion_parameter", number(law.adhesion_parameter)},
                                     {"adhesion_parameter_definition",
                                      "sigma_s / delta_c, delta_c = (3/4)(pi^2 dgamma^2 R / E*^2)^1/3 (Fuller-Tabor 1975)"},
                                     {"length_scale_m", number(law.adhesion_length)},
                                     {"branch", std::isnan(law.approach_separation)
                                                    ? std::string("approach (loading)")
                                                    : "withdrawal (unloading, fixed grips) after an approach to s0 = " +
                                                          format_double(law.approach_separation)},
                                     {"approach_separation", number(law.approach_separation)},
                                     {"pull_off_pressure_Pa", number(law.pull_off_pressure)},
                                     {"pull_off_mean_separation_m", number(law.pull_off_mean_separation)}}
                      : ordered_json(nullptr);
  j["separation_range"] = {number(law.separation_min), number(law.separation_max)};
  j["max_rel_error"] = {{"pressure", number(law.max_rel_error[0])},
                        {"stiffness", number(law.max_rel_error[1])},
                        {"area_fraction", number(law.max_rel_error[2])}};
  j["at_pressures"] = at;
  return j;
}

}  // namespace

std::string analysis_json(const SurfaceAnalysis& a) {
  ordered_json j;
  j["schema"] = surface_json_schema;
  add_record_json(j, a);  // its written records (noise_floor, statistics, correlation, sampling_dependence)
  describe_surface(a, j);
  j["fits"]["summit_heights"] = assessment_json(a.summit_heights);
  j["fits"]["summits_fitted"] = a.summits_fitted;
  if (a.heights) j["fits"]["heights"] = assessment_json(*a.heights);
  j["verdict"] = verdict_json(a.verdict);
  if (a.contact) {
    j["contact"] = contact_json(*a.contact);
    if (a.law) j["contact"]["law"] = law_json(*a.law, *a.contact);
  }
  j["next_steps"] = record_json<ordered_json>(next_steps(a));
  // a source or note that is not UTF-8 (a path's bytes) is replaced, not an exception
  return j.dump(1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

std::string analysis_summary(const SurfaceAnalysis& a) {
  std::ostringstream out;
  const HeightMap& map = a.map;
  out << map.source << " (" << map.format << "): " << map.nx << " x " << map.ny << " points, " << g(map.dx) << " x "
      << g(map.dy) << " m";
  if (a.statistics.missing_points) out << ", " << a.statistics.missing_points << " missing";
  out << "\n";
  out << "  Sq " << g(a.statistics.rms) << " m, Ssk " << g(a.statistics.skewness, 3) << ", Sku "
      << g(a.statistics.kurtosis, 3) << (a.leveled ? " (plane subtracted)" : " (not leveled)") << "\n";
  if (a.noise_floor.reached) {
    out << "  noise floor: " << a.noise_floor.text << "\n";
    return out.str();
  }
  out << "  m0 " << g(a.moments.m0) << " m^2, m2 " << g(a.moments.m2) << ", m4 " << g(a.moments.m4)
      << " 1/m^2, alpha " << g(a.moments.alpha, 3) << ", anisotropy " << g(a.moments.anisotropy, 3)
      << (a.moments.anisotropy > max_isotropic_anisotropy ? " (not isotropic: Nayak-McCool's moments do not hold)" : "")
      << "\n";
  out << "  summits " << a.summits.list.size() << ", density " << g(a.summits.density) << " 1/m^2, radius "
      << g(a.summits.radius) << " m\n";
  out << "  " << a.verdict.text << "\n";
  if (a.contact) {
    const ContactComparison& c = *a.contact;
    const ModelContact* gaussian = c.find(ContactModelKind::gaussian);
    for (std::size_t k = 0; k < c.pressures.size(); ++k) {
      out << "  at " << g(c.pressures[k]) << " Pa (" << in_contact_text(c, k)
          << "): stiffness per area [N/m^3] (x the measured summits')";
      for (const ModelContact& mc : c.models) {
        if (mc.kind == ContactModelKind::measured_summits_own_radii) continue;
        out << "  " << mc.label() << " ";
        if (!mc.served) {
          out << "(none)";
          continue;
        }
        out << g(mc.at_pressures[k].stiffness / c.nominal_area);
        if (k < mc.stiffness_over_measured.size() && mc.kind != ContactModelKind::measured_summits)
          out << " (" << g(mc.stiffness_over_measured[k], 3) << "x)";
      }
      (void)gaussian;
      out << "\n";
    }
    for (const ModelContact& mc : c.models)
      if (!mc.served) out << "  " << mc.label() << ": " << mc.note << "\n";
    if (!c.exact_headline.empty()) out << "  " << c.exact_headline << "\n";
  }
  if (a.law) {
    const LawContact& law = *a.law;
    out << "  law " << law.law << " on the " << to_string(law.fit) << " fit (" << law.model_reason << "): "
        << (law.parameters_text.empty() ? "" : law.parameters_text + ", ") << "sigma_s " << g(law.summit_height_sd)
        << " m, R " << g(law.summit_radius) << " m, ";
    if (law.adhesive)
      out << "length scale " << g(law.adhesion_length) << " m, adhesion parameter sigma_s/delta_c " << g(law.adhesion_parameter, 3)
          << (std::isfinite(law.pull_off_pressure) ? ", pull-off " + g(law.pull_off_pressure) + " Pa at mean separation " +
                                                          g(law.pull_off_mean_separation) + " m\n"
                                                    : std::string(", no measurable pull-off\n"));
    else
      out << "omega_c " << g(law.critical_interference) << " m, psi = (sigma_s/omega_c)^1/2 " << g(law.plasticity_index, 3)
          << ", GW's psi = (E*/H)(sigma_s/R)^1/2 " << g(law.gw_plasticity_index, 3) << "\n";
    out << "  " << law.regime << "\n";
    const ContactComparison& c = *a.contact;
    for (std::size_t k = 0; k < law.at_pressures.size(); ++k) {
      const PhysicalState &l = law.at_pressures[k], &e = law.elastic_at_pressures[k];
      out << "  at " << g(c.pressures[k]) << " Pa under " << law.law << " (elastic; law/elastic): mean separation "
          << g(l.mean_separation) << " m (" << g(e.mean_separation) << " m; " << g(law.separation_minus_elastic[k], 3)
          << " m), area fraction " << g(l.area_fraction) << " (" << g(e.area_fraction) << "; "
          << g(law.area_over_elastic[k], 3) << "x), stiffness per area " << g(l.stiffness / c.nominal_area) << " N/m^3 ("
          << g(e.stiffness / c.nominal_area) << "; " << g(law.stiffness_over_elastic[k], 3) << "x)\n";
    }
    if (!law.served) out << "  " << law.law << ": " << law.note << "\n";
    for (const std::string& warning : law.warnings) out << "  " << law.law << ": " << warning << "\n";
  }
  const NextSteps next = next_steps(a);
  if (!next.contact_command.empty()) {
    out << "  next, " << next.why << ":\n    " << next.contact_command << "\n    " << next.card_command << "\n";
  } else if (!next.exact_command.empty()) {
    out << "  next: " << next.why << "; use instead " << next.instead << ":\n";
  } else {
    out << "  " << next.text << "\n";
  }
  if (!next.exact_command.empty()) out << "    " << next.exact_command << "\n";
  return out.str();
}

namespace {

// the map as read and its statistics
void markdown_surface(std::ostream& md, const SurfaceAnalysis& a) {
  const HeightMap& map = a.map;
  md << "# Surface report: " << detail::printable(std::filesystem::path(map.source).filename().string(), 200) << "\n\n";
  md << "Written by `asperity surface`. Every number below is in `report.json`; the curves are in `curves.csv`, "
        "the summits in `summits.csv`.\n\n";
  md << "## The surface\n\n| | |\n|---|---|\n";
  md << "| file | `" << detail::printable(map.source, 4096) << "` (" << map.format << ") |\n";
  md << "| grid | " << map.nx << " x " << map.ny << " points, sampling " << g(map.dx) << " m x " << g(map.dy) << " m (" << g(map.width())
     << " m x " << g(map.length()) << " m) |\n";
  md << "| missing points | " << a.statistics.missing_points << " |\n";
  md << "| leveling | " << (a.leveled ? "least-squares plane subtracted (slopes " + g(a.plane.slope_x) + ", " + g(a.plane.slope_y) + ")" : "none") << " |\n";
  for (const std::string& note : map.notes) md << "| note | " << note << " |\n";
  md << "\n## Statistics\n\n| Sq [m] | Sa [m] | Ssk | Sku | m0 [m²] | m2 | m4 [1/m²] | Nayak α |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  md << "| " << g(a.statistics.rms) << " | " << g(a.statistics.mean_absolute) << " | " << g(a.statistics.skewness, 3) << " | "
     << g(a.statistics.kurtosis, 3) << " | " << g(a.moments.m0) << " | " << g(a.moments.m2) << " | " << g(a.moments.m4) << " | "
     << g(a.moments.alpha, 3) << " |\n\n";
}

// the spectral moments, the summits and their dependence on the sampling interval
void markdown_summits(std::ostream& md, const SurfaceAnalysis& a) {
  md << "Spectral moments at the file's sampling interval by one consistent scheme (slopes by forward differences, "
        "curvatures by second differences); m2 and m4 are the equivalent isotropic moments (geometric means along the "
        "principal directions, McCool 1986). Anisotropy (ratio of the principal slope variances) "
     << g(a.moments.anisotropy, 3) << ", steepest at " << g(a.moments.principal_angle * 57.29577951308232, 3)
     << "° from x"
     << (a.moments.anisotropy > max_isotropic_anisotropy
             ? ": **not isotropic** (above " + g(max_isotropic_anisotropy, 2) +
                   "): Nayak-McCool's Gaussian from the moments assumes an isotropic surface and does not hold here"
             : "")
     << ". They grow as the sampling interval shrinks on a rough surface, see below.\n\n";
  md << "## Summits\n\n" << a.summits.list.size() << " summits (" << (a.summits.options.window == 1 ? "8-neighbour maxima" : "maxima within " + std::to_string(a.summits.options.window) + " points")
     << (a.summits.options.min_drop > 0 ? ", at least " + g(a.summits.options.min_drop) + " m above the mean of their neighbours" : "")
     << "): density " << g(a.summits.density) << " /m², radius R = 1/⟨κ_m⟩ = " << g(a.summits.radius)
     << " m (mean curvature −(h_xx + h_yy)/2 from 3-point second differences, averaged over the summits).\n\n";
  md << "Dependence on the sampling interval (every k-th point):\n\n| k | dx [m] | summits | density [1/m²] | R [m] | m2 | m4 [1/m²] | α | anisotropy |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const SamplingRow& r : a.sampling)
    md << "| " << r.factor << " | " << g(r.dx) << " | " << r.summits << " | " << g(r.density) << " | " << g(r.radius) << " | "
       << g(r.m2) << " | " << g(r.m4) << " | " << g(r.alpha, 3) << " | " << g(r.anisotropy, 3) << " |\n";
}

// a sample's fits: each model's parameters, shape interval, tests and AIC
void markdown_fits_table(std::ostream& md, const SampleAssessment& s) {
  md << "\n| model | location [m] | scale [m] | shape [" << g(100 * s.options.confidence, 3) << "% interval] | A² | AD p | KS D | KS p | AIC | ΔAIC | Akaike weight |\n"
     << "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
  // a bound with three digits: two could round it below 1/(B + 1)
  const auto p_cell = [](double p, bool bound) { return std::isfinite(p) ? (bound ? "≤ " + g(p, 3) : g(p, 2)) : std::string("–"); };
  for (const ModelAssessment& m : s.models) {
    const HeightDistribution& d = m.fit.distribution;
    std::string shape = "–";
    if (d.model != HeightModel::gaussian) {
      shape = g(d.shape, 3);
      if (!m.shape_identified) shape += " (not identified)";
      else if (std::isfinite(m.shape.lo)) shape += " [" + g(m.shape.lo, 3) + ", " + g(m.shape.hi, 3) + "]";
    }
    md << "| " << describe(d.model) << " | " << g(d.location) << " | " << g(d.scale) << " | " << shape << " | "
       << g(m.anderson_darling, 3) << " | " << p_cell(m.anderson_darling_p, m.p_at_floor) << " | "
       << g(m.kolmogorov_smirnov, 3) << " | " << p_cell(m.kolmogorov_smirnov_p, m.kolmogorov_smirnov_p_at_floor) << " | " << g(m.aic, 6) << " | "
       << g(m.delta_aic, 3) << " | " << g(m.akaike_weight, 3) << " |\n";
  }
}

// the verdict, the fits of both samples and how they were tested
void markdown_fits(std::ostream& md, const SurfaceAnalysis& a, bool plots) {
  md << "\n## Is it Gaussian? Which Weibull?\n\n**Verdict.** " << a.verdict.text << "\n";
  md << "\nThe summit heights (what the asperity model integrates; a Gaussian surface's summit heights are not "
        "Gaussian themselves, which the surrogates account for):\n";
  markdown_fits_table(md, a.summit_heights);
  if (a.heights) {
    md << "\nThe heights (a fixed random sample of " << a.heights->n << " points: the marginal of the whole surface, "
          "whose bound a wear process makes):\n";
    markdown_fits_table(md, *a.heights);
  }
  md << "\nMethod: the Gaussian by maximum likelihood; each three-parameter Weibull by maximum product of spacings "
        "(well-posed for every shape, including shapes below 1 where maximum likelihood diverges). The null "
        "distribution of every statistic and the shape intervals come from "
     << a.surrogates << " surrogate surfaces (seed " << a.summit_heights.options.seed << "): " << surrogate_method()
     << "; on each every statistic is computed exactly as on the map (summits found the same way), so the tests carry "
        "the surface's correlation. A p-value shown as ≤ is at its floor 1/(B + 1). Intervals of the summit heights: "
     << interval_method(a.summit_heights.model(HeightModel::weibull_tail).shape_interval) << ".";
  if (a.heights)
    md << " Intervals of the heights: " << interval_method(a.heights->model(HeightModel::weibull_tail).shape_interval) << ".";
  md << " A shape whose interval reaches the fit's bounds (0.05, 100) or with over a tenth of its refits there is not "
        "identified. Akaike weights over all three models.\n";
  if (plots) md << "\n![fits](fits.svg)\n";
}

// each model against the exact contact of the map, where it was solved
void markdown_exact(std::ostream& md, const ContactComparison& c) {
  const ModelContact* exact = c.find(ContactModelKind::exact);
  if (exact && exact->served) {
    md << "\n### Each model against the exact contact of this map\n\nThe exact elastic contact: " << c.exact_method
       << ". It neglects neither the summits' coalescence nor their elastic interaction: what every model is judged "
          "against.\n\n**" << c.exact_headline << ".**\n\n| model | nominal pressure [Pa] | mean separation − exact's [m] | "
          "real area / exact's | stiffness / exact's |\n|---|---:|---:|---:|---:|\n";
    for (const ModelContact& mc : c.models) {
      if (!mc.served || mc.kind == ContactModelKind::exact || mc.stiffness_over_exact.empty()) continue;
      for (std::size_t k = 0; k < c.pressures.size(); ++k)
        md << "| " << mc.label() << " | " << g(c.pressures[k]) << " | " << g(mc.separation_minus_exact[k], 3) << " | "
           << g(mc.area_over_exact[k], 3) << " | " << g(mc.stiffness_over_exact[k], 3) << " |\n";
    }
  } else if (exact) {
    md << "\nThe exact contact: " << exact->note << ".\n";
  }
}

// the contact law's curves beside the elastic ones
void markdown_law(std::ostream& md, const LawContact& law, const ContactComparison& c, bool plots) {
  md << "\n### Under the contact law: " << law.law << "\n\nThe law's rough-surface curves on the " << to_string(law.fit)
     << " fit (" << law.model_reason << "), with the measured summit density and radius, next to the same fit's "
        "elastic (Hertz) curves above.\n\n| | |\n|---|---|\n";
  md << "| σs: standard deviation of the measured summit heights | " << g(law.summit_height_sd) << " m |\n";
  md << "| R: the measured summit radius | " << g(law.summit_radius) << " m |\n";
  md << "| E* | " << g(law.contact_modulus) << " Pa |\n";
  md << "| the law's parameters | " << (law.parameters_text.empty() ? "none beyond R and E*" : law.parameters_text)
     << " |\n";
  if (!law.adhesive) {  // an adhesive law is elastic: no hardness, no ω_c, no plasticity index
    // a figure the law does not define says so, and why (Hertz: none of them; Jackson-Green: no H)
    const auto cell = [](double value, const std::string& unit, int digits, const char* why) {
      return std::isfinite(value) ? g(value, digits) + unit : std::string("not used: ") + why;
    };
    md << "| H (GW's ψ) | " << cell(law.hardness, " Pa", 4, "the law has no hardness") << " |\n";
    md << "| ω_c (the law's, at R) | " << cell(law.critical_interference, " m", 4, "the law does not yield") << " |\n";
    md << "| ψ = (σs/ω_c)^½ (the law's: Kogut–Etsion 2003's with the CEB/KE ω_c) | "
       << cell(law.plasticity_index, "", 3, "no ω_c") << " |\n";
    md << "| ψ = (E*/H)(σs/R)^½ (Greenwood–Williamson 1966's) | " << cell(law.gw_plasticity_index, "", 3, "no H")
       << " |\n";
  }
  md << "| the law's source range | " << (std::isfinite(law.valid_up_to) ? "ω up to " + g(law.valid_up_to) + " m" : "every ω") << " |\n";
  if (law.adhesive) {
    md << "| adhesion parameter σs/δc (Fuller–Tabor 1975) | " << g(law.adhesion_parameter, 3) << " |\n";
    md << "| the law's length scale | " << g(law.adhesion_length) << " m |\n";
    md << "| pull-off: greatest tension of the "
       << (std::isnan(law.approach_separation) ? std::string("approach branch")
                                               : "withdrawal after an approach to s0 = " + g(law.approach_separation))
       << " | "
       << (std::isfinite(law.pull_off_pressure)
               ? g(law.pull_off_pressure) + " Pa at mean separation " + g(law.pull_off_mean_separation) + " m"
               : std::string("none measurable (see the warning below)"))
       << " |\n";
  }
  md << "| its curves | " << law.note << " |\n\n**" << law.regime << ".**\n";
  if (law.served) {
    md << "\n| nominal pressure [Pa] | mean separation, elastic [m] | under the law [m] | law − elastic [m] | area "
          "fraction, elastic | under the law | law / elastic | stiffness / A0, elastic [N/m³] | under the law | law / "
          "elastic |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (std::size_t k = 0; k < law.at_pressures.size(); ++k) {
      const PhysicalState &l = law.at_pressures[k], &e = law.elastic_at_pressures[k];
      md << "| " << g(c.pressures[k]) << " | " << g(e.mean_separation) << " | " << g(l.mean_separation) << " | "
         << g(law.separation_minus_elastic[k], 3) << " | " << g(e.area_fraction, 3) << " | " << g(l.area_fraction, 3)
         << " | " << g(law.area_over_elastic[k], 3) << " | " << g(e.stiffness / c.nominal_area) << " | "
         << g(l.stiffness / c.nominal_area) << " | " << g(law.stiffness_over_elastic[k], 3) << " |\n";
    }
  }
  for (const std::string& warning : law.warnings) md << "\n**Warning:** " << warning << ".\n";
  if (plots && law.served) md << "\n![law](law.svg)\n";
}

// the contact with a rigid flat: each model's states at the asked pressures
void markdown_contact(std::ostream& md, const SurfaceAnalysis& a, bool plots) {
  const ContactComparison& c = *a.contact;
  md << "\n## What it changes: contact with a rigid flat\n\nE* = " << g(c.options.contact_modulus) << " Pa, nominal area A0 = "
     << g(c.nominal_area) << " m². Separations from each model's mean summit height; stiffness per nominal area. "
        "An asperity model is a statistical statement: where only a few summits are in contact over A0, its "
        "prediction rests on the few highest summits measured, not on the fitted law.\n\n";
  if (!c.headline.empty()) md << "**" << c.headline << ".**\n\n";
  md << "| model | table |\n|---|---|\n";
  for (const ModelContact& mc : c.models) md << "| " << mc.label() << " | " << mc.note << " |\n";
  const ModelContact* gaussian = c.find(ContactModelKind::gaussian);
  for (std::size_t k = 0; k < c.pressures.size(); ++k) {
    md << "\nAt a nominal pressure of " << g(c.pressures[k]) << " Pa (" << in_contact_text(c, k)
       << (c.compared_at(k) || k >= c.measured_summits_in_contact.size() ? "" : "; the ratios below are that handful's")
       << "):\n\n| model | summits in contact | mean separation [m] | area fraction | stiffness / A0 [N/m³] | K/P [1/m] | stiffness / measured summits' | stiffness / Gaussian fit's |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const ModelContact& mc : c.models) {
      if (!mc.served) {
        md << "| " << mc.label() << " | – | – | – | – | – | – | – |\n";
        continue;
      }
      const PhysicalState& s = mc.at_pressures[k];
      std::string versus = k < mc.stiffness_over_measured.size() ? g(mc.stiffness_over_measured[k], 3) : "–";
      if (mc.kind == ContactModelKind::measured_summits && k < c.measured_stiffness_spread.size())
        versus = "1 (±" + g(100 * c.measured_stiffness_spread[k], 2) + "%)";
      md << "| " << mc.label() << " | " << g(s.count, 3) << " | " << g(s.mean_separation) << " | " << g(s.area_fraction, 3) << " | "
         << g(s.stiffness / c.nominal_area) << " | " << g(s.stiffness_over_load) << " | " << versus << " | "
         << (gaussian && gaussian->served ? g(ratio(s.stiffness, gaussian->at_pressures[k].stiffness), 3) : "–") << " |\n";
    }
  }
  if (!c.sampling.empty()) {
    md << "\nGW on the measured summits at a coarser sampling (every k-th point), its stiffness over the answer at the "
          "file's sampling, at each pressure: ";
    for (const SamplingContact& r : c.sampling) {
      md << "k = " << r.factor << ":";
      for (double ratio_k : r.stiffness_over_finest) md << " " << g(ratio_k, 3);
      md << (&r == &c.sampling.back() ? ".\n" : "; ");
    }
  }
  if (!c.measured_stiffness_spread.empty())
    md << "\n± on the measured summits: the relative standard deviation of their stiffness over the surrogate "
          "ensemble (surfaces of the same statistics), the uncertainty of each ratio to them.\n";
  markdown_exact(md, c);
  if (plots) md << "\n![contact](contact.svg)\n";
  if (a.law) markdown_law(md, *a.law, c, plots);
}

// what to do next: the named model's command, Python call and card, the map's exact contact
void markdown_next_steps(std::ostream& md, const NextSteps& next) {
  md << "\n## What to do next\n\n";
  if (next.contact_command.empty() && next.exact_command.empty()) {
    md << next.text << "\n";
    return;
  }
  md << (next.contact_command.empty() ? "No model: " + next.why + ". Use instead " + next.instead + ":\n"
                                      : "The model: " + next.why + ". Its curves in your code (separations from its "
                                        "mean summit height):\n");
  if (!next.contact_command.empty())
    md << "\n```sh\n" << next.contact_command << "\n```\n\n```python\n" << next.python
       << "\n```\n\nIts pressure-overclosure card for CalculiX (or `asperity surface ... --card FILE`):\n\n```sh\n"
       << next.card_command << "\n```\n\nThe map's own exact contact, what every model is judged against, as a table "
       << "`asperity contact --table` serves and as a card:\n";
  md << "\n```sh\n" << next.exact_command << "\n```\n";
}

std::string markdown_report(const SurfaceAnalysis& a, const ReportOutcome& outcome) {
  std::ostringstream md;
  markdown_surface(md, a);
  if (a.noise_floor.reached) {
    md << "**Noise floor.** " << a.noise_floor.text << ".\n";
  } else {
    markdown_summits(md, a);
    markdown_fits(md, a, outcome.plots);
    if (a.contact) markdown_contact(md, a, outcome.plots);
  }
  if (!outcome.plots) md << "\n_" << outcome.plot_note << "._\n";
  markdown_next_steps(md, next_steps(a));
  return md.str();
}

// summits.csv: every summit's position, height and curvatures
std::string summits_csv(const SurfaceAnalysis& a) {
  std::ostringstream summits;
  summits << "i,j,x_m,y_m,height_m,mean_curvature_per_m,kappa1_per_m,kappa2_per_m\n";
  for (const Summit& s : a.summits.list)  // numbers in shortest round-trip form, as every CSV of the project
    summits << s.i << ',' << s.j << ',' << format_double(static_cast<double>(s.i) * a.map.dx) << ','
            << format_double(static_cast<double>(s.j) * a.map.dy) << ',' << format_double(s.height) << ','
            << format_double(s.mean_curvature) << ',' << format_double(s.kappa1) << ',' << format_double(s.kappa2)
            << '\n';
  return summits.str();
}

// curves.csv: each model's curve, a row a physical state (its record's columns, as `asperity
// contact` writes them) and its stiffness per nominal area; the law's rows are model "law:NAME"
// (the fit it is on: report.json's contact.law.model)
std::string curves_csv(const SurfaceAnalysis& a) {
  const ContactComparison& c = *a.contact;
  std::string csv = "model," + csv_header<PhysicalState>() + ",stiffness_per_area_N_per_m3\n";
  const auto rows = [&](const std::string& model, const std::vector<PhysicalState>& curve) {
    for (const PhysicalState& s : curve)
      csv += model + "," + csv_row(s) + "," + format_double(s.stiffness / c.nominal_area) + "\n";
  };
  for (const ModelContact& mc : c.models) rows(mc.label(), mc.curve);
  if (a.law) rows("law:" + a.law->law, a.law->curve);
  return csv;
}

}  // namespace

OutputPlan report_plan(const std::string& directory, const std::string& input, bool overwrite) {
  OutputPlan plan(overwrite);
  if (!input.empty()) plan.input(input);
  std::vector<FolderEntry> entries;
  for (const char* name : report_file_names) entries.push_back({name, &output_kinds::report_file});
  plan.folder("report folder", directory, std::move(entries));
  plan.check();
  return plan;
}

ReportOutcome write_report(const SurfaceAnalysis& a, const std::string& directory, bool overwrite) {
  // the report's files: staged, renamed into place together; a file of an earlier report that
  // this one does not write is removed (only if it is a report file of ours)
  OutputTransaction folder(report_plan(directory, a.map.source, overwrite));
  const auto write = [&](const char* name, const std::string& bytes) {
    folder.stage(directory, name, bytes);
    return (std::filesystem::path(directory) / name).string();
  };
  ReportOutcome outcome;
  outcome.files.push_back(write("report.json", analysis_json(a)));
  outcome.files.push_back(write("summits.csv", summits_csv(a)));
  if (a.contact) outcome.files.push_back(write("curves.csv", curves_csv(a)));
  // plots, drawn here (svg_plot.hpp): nothing is run
  if (!a.noise_floor.reached) {
    outcome.files.push_back(write("fits.svg", fits_svg(a)));
    if (a.contact) outcome.files.push_back(write("contact.svg", contact_svg(a)));
    if (a.contact && a.law && a.law->served) outcome.files.push_back(write("law.svg", law_svg(a)));
    outcome.plots = true;
  } else {
    outcome.plot_note = "no plots: " + a.noise_floor.text;
  }
  outcome.files.insert(outcome.files.begin(), write("report.md", markdown_report(a, outcome)));
  folder.commit();
  return outcome;
}

}  // namespace asperity::topography
