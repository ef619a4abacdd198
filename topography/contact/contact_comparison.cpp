#include "asperity/topography/contact_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "asperity/contact_scales.hpp"
#include "asperity/error.hpp"
#include "asperity/generator/scene_table.hpp"
#include "asperity/scene.hpp"
#include "asperity/surface.hpp"
#include "asperity/table.hpp"
#include "asperity/topography/persson_contact.hpp"
#include "asperity/topography/summit_contact.hpp"

namespace asperity::topography {
namespace {

std::string shape_text(double shape) {
  std::ostringstream text;
  text.precision(4);
  text << shape;
  return text.str();
}

void fill_curves(ModelContact& model, const ContactModel& contact, const ContactComparison& comparison) {
  // a table answers NaN outside what it serves: no curve rather than a curve of NaN
  const auto state = [&](double p) {
    const PhysicalState s = contact.at_pressure(p);
    if (std::isnan(s.stiffness) || std::isnan(s.mean_separation))
      throw Error("the table gives no value at " + shape_text(p) + " Pa");
    return s;
  };
  for (double p : curve_pressures(comparison)) model.curve.push_back(state(p));
  for (double p : comparison.pressures) model.at_pressures.push_back(state(p));
  model.served = true;
}

// A comparison's curve of that kind, named
ModelContact model_of(ContactModelKind kind) {
  ModelContact model;
  model.kind = kind;
  return model;
}

// A reference's state at nominal pressure p over the comparison's nominal area A0.
PhysicalState reference_state(double p, double mean_gap, double area_fraction, double stiffness_per_area,
                              double count, double mean_summit_height, double area) {
  PhysicalState state{};
  state.separation = mean_gap;
  state.mean_separation = mean_gap - mean_summit_height;
  state.count = count;
  state.area_fraction = area_fraction;
  state.real_area = area_fraction * area;
  state.pressure = p;
  state.load = p * area;
  state.stiffness = stiffness_per_area * area;
  state.stiffness_over_load = stiffness_per_area / p;
  return state;
}

void conclude_against_exact(ContactComparison& comparison) {
  comparison.closest_to_exact.reset();
  comparison.exact_headline.clear();
  const ModelContact* exact = comparison.find(ContactModelKind::exact);
  const std::size_t points = comparison.map_nx * comparison.map_ny;
  if (!exact && points > 0 && !exact_contact_wanted(comparison.options, points)) {
    if (comparison.options.exact_auto) {  // left out for the map's size alone: said, with how to ask
      std::ostringstream text;
      text << "The exact elastic contact of the map, the referee of every curve, is not solved: " << comparison.map_nx
           << " x " << comparison.map_ny << " points is over the " << exact_auto_max_points
           << " solved by default (--exact, or ContactOptions(exact=True), solves it: seconds to minutes)";
      comparison.exact_headline = text.str();
    }
    return;
  }
  for (ModelContact& model : comparison.models) {
    model.stiffness_over_exact.clear();
    model.area_over_exact.clear();
    model.separation_minus_exact.clear();
  }
  if (!exact || !exact->served) return;
  double best = std::numeric_limits<double>::infinity();
  const ModelContact* closest = nullptr;
  for (ModelContact& model : comparison.models) {
    if (!model.served || model.kind == ContactModelKind::exact) continue;
    double worst = 0;
    for (std::size_t k = 0; k < comparison.pressures.size(); ++k) {
      const PhysicalState &m = model.at_pressures[k], &e = exact->at_pressures[k];
      model.stiffness_over_exact.push_back(m.stiffness / e.stiffness);
      model.area_over_exact.push_back(m.real_area / e.real_area);
      model.separation_minus_exact.push_back(m.mean_separation - e.mean_separation);
      worst = std::max(worst, std::fabs(std::log(model.stiffness_over_exact.back())));
    }
    if (model.kind != ContactModelKind::measured_summits_own_radii && worst < best) {  // NaN never wins
      best = worst;
      closest = &model;
      comparison.closest_to_exact = model.kind;
    }
  }
  std::ostringstream text;
  text.precision(3);
  const auto describe = [&](const ModelContact& m) {
    text << m.label() << ": stiffness ";
    for (std::size_t k = 0; k < comparison.pressures.size(); ++k) text << (k ? ", " : "") << m.stiffness_over_exact[k] << "x";
    text << ", real area ";
    for (std::size_t k = 0; k < comparison.pressures.size(); ++k) text << (k ? ", " : "") << m.area_over_exact[k] << "x";
    text << ", mean separation ";
    for (std::size_t k = 0; k < comparison.pressures.size(); ++k)
      text << (k ? ", " : "") << m.separation_minus_exact[k] << " m";
  };
  text << "Against the exact elastic contact of the map at ";
  for (std::size_t k = 0; k < comparison.pressures.size(); ++k) text << (k ? ", " : "") << comparison.pressures[k];
  text << " Pa: ";
  if (!closest) {
    text << "no other curve to compare";
  } else {
    text << "closest ";
    describe(*closest);
    for (ContactModelKind kind : {ContactModelKind::measured_summits, ContactModelKind::persson}) {
      const ModelContact* m = comparison.find(kind);
      if (m && m->served && m != closest) {
        text << "; ";
        describe(*m);
      }
    }
    if (best > std::log(1.25)) text << "; no curve is within 25% in stiffness at every pressure";
  }
  comparison.exact_headline = text.str();
}

}  // namespace

void add_reference_contact(ContactComparison& comparison, const HeightMap& map, double mean_summit_height,
                           const ExactProgress& progress) {
  const ContactOptions& options = comparison.options;
  const double area = comparison.nominal_area;
  const bool exact_wanted = exact_contact_wanted(options, map.nx * map.ny);
  if (exact_wanted && (options.exact_points < min_exact_points || options.exact_points > max_exact_points))
    throw Error("contact: exact_points must be from " + std::to_string(min_exact_points) + " to " +
                std::to_string(max_exact_points) + ", not " + std::to_string(options.exact_points));
  if (options.persson) {
    ModelContact model = model_of(ContactModelKind::persson);
    model.mean_summit_height = mean_summit_height;
    try {
      const RadialPowerSpectrum spectrum = radial_power_spectrum(map, SpectrumEdges::periodic_component);
      const PerssonContact persson(spectrum, options.contact_modulus);
      const auto state = [&](double p) {
        const PerssonState s = persson.at_pressure(p);
        return reference_state(p, s.mean_gap, s.area_fraction, s.stiffness_per_area, NAN, mean_summit_height, area);
      };
      for (double p : curve_pressures(comparison)) model.curve.push_back(state(p));
      for (double p : comparison.pressures) model.at_pressures.push_back(state(p));
      model.served = true;
      std::ostringstream note;
      note.precision(3);
      note << "Persson's theory (2007; Yang-Persson gamma " << yang_persson_gamma << ") from the map's power spectrum ("
           << spectrum.density.size() << " annuli, q " << spectrum.edges.front() << " to " << spectrum.edges.back()
           << " 1/m; periodic component, " << 100 * spectrum.variance / spectrum.map_variance
           << "% of the height variance): no summits";
      model.note = note.str();
    } catch (const Error& error) {
      model.curve.clear();
      model.at_pressures.clear();
      model.note = std::string("no curve: ") + error.what();
    }
    comparison.models.push_back(std::move(model));
  }
  comparison.map_nx = map.nx, comparison.map_ny = map.ny;
  if (exact_wanted) {
    ModelContact model = model_of(ContactModelKind::exact);
    model.mean_summit_height = mean_summit_height;
    try {
      ExactContactOptions solve;
      solve.contact_modulus = options.contact_modulus;
      solve.boundary = options.exact_boundary;
      solve.kernel = options.exact_kernel;
      solve.tolerance = options.exact_tolerance;
      solve.threads = options.threads;
      ExactContact exact(map, solve);
      // the curve's pressures and the pressures of interest, solved upwards (each from the last)
      std::vector<double> pressures = comparison.pressures;
      const double lo = std::log(comparison.pressure_min), hi = std::log(comparison.pressure_max);
      for (int k = 0; k < options.exact_points; ++k)
        pressures.push_back(std::exp(lo + (hi - lo) * k / (options.exact_points - 1)));
      std::sort(pressures.begin(), pressures.end());
      pressures.erase(std::unique(pressures.begin(), pressures.end()), pressures.end());
      int iterations = 0, most = 0;
      double residual = 0;
      for (std::size_t k = 0; k < pressures.size(); ++k) {
        const ContactStep step = exact.at_pressure(pressures[k]);
        iterations += step.iterations;
        most = std::max(most, step.iterations);
        residual = std::max(residual, step.residual);
        // the pressure asked (the step's own is its pressures' mean, equal to rounding)
        const PhysicalState state = reference_state(pressures[k], step.mean_gap, step.area_fraction, step.stiffness_per_area,
                                                    static_cast<double>(step.clusters), mean_summit_height, area);
        model.curve.push_back(state);
        if (progress) progress(k + 1, pressures.size());
      }
      for (double p : comparison.pressures)  // each is in `pressures`, solved
        model.at_pressures.push_back(
            model.curve[static_cast<std::size_t>(std::lower_bound(pressures.begin(), pressures.end(), p) - pressures.begin())]);
      model.served = true;
      std::ostringstream method;
      method.precision(3);
      method << "boundary elements on FFTs (Polonsky-Keer constrained conjugate gradient), " << exact.nx() << " x "
             << exact.ny() << " points, " << contact_boundary_name(options.exact_boundary) << " boundary, "
             << contact_kernel_name(options.exact_kernel) << " kernel, tolerance " << options.exact_tolerance << "; "
             << pressures.size() << " load steps, " << iterations << " iterations (at most " << most
             << " a step), largest residual " << residual;
      comparison.exact_method = method.str();
      model.note = "the exact elastic contact of the map: " + comparison.exact_method + "; summits in contact: the contact "
                   "clusters";
    } catch (const Error& error) {
      model.curve.clear();
      model.at_pressures.clear();
      model.note = std::string("no curve: ") + error.what();
    }
    comparison.models.push_back(std::move(model));
  }
}

std::vector<double> curve_pressures(const ContactComparison& comparison) {
  const int points = comparison.options.curve_points;
  const double lo = std::log(comparison.pressure_min), hi = std::log(comparison.pressure_max);
  std::vector<double> pressures;
  for (int k = 0; k < points; ++k) pressures.push_back(std::exp(lo + (hi - lo) * k / (points - 1)));
  return pressures;
}

std::vector<double> contact_pressures(const ContactOptions& options) {
  std::vector<double> pressures = options.pressures;
  if (pressures.empty())
    for (double f : {1e-5, 1e-4, 1e-3}) pressures.push_back(f * options.contact_modulus);
  for (double p : pressures)
    if (!(p > 0) || !std::isfinite(p)) throw Error("contact: pressures must be positive numbers");
  std::sort(pressures.begin(), pressures.end());
  return pressures;
}

namespace {

// "1 measured summit", "27 measured summits"
std::string summits_text(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " measured summit" : " measured summits");
}

// The headline against the measured summits: the closest fitted model (nullptr: none) at the
// pressures compared, and at each pressure not compared why not.
std::string measured_headline(const ContactComparison& comparison, const ModelContact* closest, double worst) {
  std::ostringstream text;
  text.precision(3);
  const std::vector<double>& pressures = comparison.pressures;
  std::vector<std::size_t> compared, too_few;
  for (std::size_t k = 0; k < pressures.size(); ++k) (comparison.compared_at(k) ? compared : too_few).push_back(k);
  const auto why_not = [&] {
    for (std::size_t n = 0; n < too_few.size(); ++n) {
      const std::size_t k = too_few[n];
      text << (n ? ", " : "") << "at " << pressures[k] << " Pa only "
           << summits_text(k < comparison.measured_summits_in_contact.size() ? comparison.measured_summits_in_contact[k] : 0)
           << " in contact";
    }
    text << ": too few to compare models (at least " << min_summits_to_compare
         << ": below that the answer rests on a handful of summits, its sampling spread ~1/sqrt(n) above 20%)";
  };
  if (compared.empty()) {
    text << "No model is named closest to GW on the measured summits: ";
    why_not();
    return text.str();
  }
  if (!closest) return "no fitted model has contact curves to compare with the measured summits";
  text << "Closest to GW on the measured summits (no law fitted): " << closest->label() << ", stiffness ";
  for (std::size_t n = 0; n < compared.size(); ++n) {
    const std::size_t k = compared[n];
    text << (n ? ", " : "") << closest->stiffness_over_measured[k] << "x";
    if (k < comparison.measured_stiffness_spread.size()) text << " (+-" << 100 * comparison.measured_stiffness_spread[k] << "%)";
    text << " at " << pressures[k] << " Pa (" << summits_text(comparison.measured_summits_in_contact[k]) << " in contact)";
  }
  text << "; mean separation ";
  for (std::size_t n = 0; n < compared.size(); ++n) text << (n ? ", " : "") << closest->separation_minus_measured[compared[n]] << " m";
  text << " from the measured summits'";
  if (!comparison.measured_stiffness_spread.empty())
    text << " (the +- is the measured-summit answer's spread over the surrogate ensemble)";
  if (worst > std::log(1.25))
    text << "; no fitted model is within 25% at every pressure" << (too_few.empty() ? "" : " compared");
  if (!too_few.empty()) {
    text << "; " << (too_few.size() == 1 ? "one pressure is" : "some pressures are") << " not compared: ";
    why_not();
  }
  return text.str();
}

}  // namespace

void conclude_contact(ContactComparison& comparison) {
  conclude_against_exact(comparison);
  const ModelContact* measured = comparison.find(ContactModelKind::measured_summits);
  if (!measured || !measured->served) return;
  for (ModelContact& model : comparison.models) {
    model.stiffness_over_measured.clear();
    model.separation_minus_measured.clear();
    if (!model.served) continue;
    for (std::size_t k = 0; k < comparison.pressures.size(); ++k) {
      model.stiffness_over_measured.push_back(model.at_pressures[k].stiffness / measured->at_pressures[k].stiffness);
      model.separation_minus_measured.push_back(model.at_pressures[k].mean_separation -
                                                measured->at_pressures[k].mean_separation);
    }
  }
  // the fitted model whose worst stiffness ratio over the pressures compared (enough measured
  // summits in contact: compared_at) is nearest 1; none where no pressure is compared
  double best = std::numeric_limits<double>::infinity();
  comparison.closest.reset();
  const ModelContact* closest_model = nullptr;
  for (const ModelContact& model : comparison.models) {
    if (!model.served || !is_fitted(model.kind)) continue;
    double worst = 0;
    bool any = false;
    for (std::size_t k = 0; k < model.stiffness_over_measured.size(); ++k)
      if (comparison.compared_at(k)) {
        worst = std::max(worst, std::fabs(std::log(model.stiffness_over_measured[k])));
        any = true;
      }
    if (any && worst < best) {
      best = worst;
      closest_model = &model;
      comparison.closest = model.kind;
    }
  }
  comparison.headline = measured_headline(comparison, closest_model, best);
}

const ModelContact* ContactComparison::find(ContactModelKind kind) const {
  for (const ModelContact& m : models)
    if (m.kind == kind) return &m;
  return nullptr;
}

const ModelContact* ContactComparison::find(const std::string& label) const {
  ContactModelKind kind;
  return parse_contact_model_kind(label, kind) ? find(kind) : nullptr;
}

namespace {
// The kinds' names, once, in ContactModelKind's order; the fitted height models' are HeightModel's
// (nullptr here: to_string(HeightModel), distribution_fit.cpp)
constexpr const char* contact_model_kind_names[] = {
    "measured-summits", "measured-summits-own-radii", "gaussian-moments", nullptr, nullptr, nullptr, "persson", "exact"};
}  // namespace

std::string contact_model_name(const std::optional<ContactModelKind>& kind) { return kind ? to_string(*kind) : ""; }

const char* to_string(ContactModelKind kind) {
  switch (kind) {
    case ContactModelKind::gaussian: return to_string(HeightModel::gaussian);
    case ContactModelKind::weibull_tail: return to_string(HeightModel::weibull_tail);
    case ContactModelKind::weibull_bounded: return to_string(HeightModel::weibull_bounded);
    default: break;
  }
  const auto k = static_cast<std::size_t>(kind);
  return k < std::size(contact_model_kind_names) && contact_model_kind_names[k] ? contact_model_kind_names[k] : "?";
}

bool parse_contact_model_kind(const std::string& name, ContactModelKind& kind) noexcept {
  for (ContactModelKind candidate : all_contact_model_kinds)
    if (name == to_string(candidate)) {
      kind = candidate;
      return true;
    }
  return false;
}

ContactModelKind contact_model_kind(HeightModel model) noexcept {
  switch (model) {
    case HeightModel::gaussian: return ContactModelKind::gaussian;
    case HeightModel::weibull_tail: return ContactModelKind::weibull_tail;
    case HeightModel::weibull_bounded: return ContactModelKind::weibull_bounded;
  }
  return ContactModelKind::gaussian;
}

bool is_fitted(ContactModelKind kind) noexcept {
  return kind == ContactModelKind::gaussian_moments || kind == ContactModelKind::gaussian ||
         kind == ContactModelKind::weibull_tail || kind == ContactModelKind::weibull_bounded;
}

ContactComparison compare_contact(const SampleAssessment& summit_fit, const Summits& summits,
                                  const SpectralMoments& moments, double measured_area, const ContactOptions& options) {
  if (!(options.contact_modulus > 0) || !std::isfinite(options.contact_modulus))
    throw Error("contact: the contact modulus E* must be a positive number (--modulus)");
  if (options.curve_points < min_curve_points || options.curve_points > max_curve_points)
    throw Error("contact: curve_points must be from " + std::to_string(min_curve_points) + " to " +
                std::to_string(max_curve_points) + ", not " + std::to_string(options.curve_points));
  if (summits.list.empty() || !(summits.radius > 0)) throw Error("contact: no summits with a positive mean curvature");
  ContactComparison comparison;
  comparison.options = options;
  comparison.nominal_area = options.nominal_area > 0 ? options.nominal_area : measured_area;
  if (!(comparison.nominal_area > 0) || !std::isfinite(comparison.nominal_area)) throw Error("contact: bad nominal area");
  comparison.pressures = contact_pressures(options);
  comparison.pressure_min = comparison.pressures.front() / 10;
  comparison.pressure_max = comparison.pressures.back() * 3;

  const Table default_table = options.table_path.empty() ? Table::open_default() : Table::open(options.table_path);
  const double e_star = options.contact_modulus, area = comparison.nominal_area;

  // GW on the measured summits, no law: with GW's one radius, and with each summit's own
  for (const bool own_radii : {false, true}) {
    ModelContact model =
        model_of(own_radii ? ContactModelKind::measured_summits_own_radii : ContactModelKind::measured_summits);
    try {
      const SummitContact contact(summits, e_star, area, own_radii);
      model.mean_summit_height = contact.mean_summit_height();
      for (double p : curve_pressures(comparison)) model.curve.push_back(contact.at_pressure(p));
      for (double p : comparison.pressures) {
        model.at_pressures.push_back(contact.at_pressure(p));
        if (!own_radii) comparison.measured_summits_in_contact.push_back(contact.in_contact(model.at_pressures.back().separation));
      }
      model.served = true;
      model.surface.summit_radius = summits.radius;
      model.surface.summit_density = summits.density;
      model.surface.nominal_area = area;
      model.surface.contact_modulus = e_star;
      model.note = std::to_string(summits.list.size()) + " measured summits, " +
                   (own_radii ? "each with its own radius 1/kappa_m" : "GW's one radius 1/<kappa_m>") + ", no law fitted";
    } catch (const Error& error) {
      model.at_pressures.clear();
      model.curve.clear();
      if (!own_radii) comparison.measured_summits_in_contact.clear();
      model.note = std::string("no curve: ") + error.what();
    }
    comparison.models.push_back(std::move(model));
  }

  // the Gaussian from the spectral moments (Nayak-McCool)
  {
    ModelContact model = model_of(ContactModelKind::gaussian_moments);
    try {
      model.surface = gaussian_surface_from_moments(moments.m0, moments.m2, moments.m4, area, e_star);
      model.mean_summit_height = 0;
      const ContactModel contact(default_table, model.surface);
      fill_curves(model, contact, comparison);
      model.note = "Nayak-McCool from m0, m2, m4 (alpha " + shape_text(moments.alpha) + "), " +
                   (options.table_path.empty() ? Table::default_path() : options.table_path);
    } catch (const Error& error) {
      model.note = std::string("no curve: ") + error.what();
    }
    comparison.models.push_back(std::move(model));
  }

  for (HeightModel height_model : all_height_models) {
    const HeightDistribution& fit = summit_fit.model(height_model).fit.distribution;
    ModelContact model = model_of(contact_model_kind(height_model));
    model.mean_summit_height = fit.mean();
    RoughSurface& surface = model.surface;
    surface.distribution = height_model == HeightModel::gaussian ? Distribution::gaussian : Distribution::weibull;
    surface.side = height_model == HeightModel::weibull_bounded ? Side::bounded : Side::tail;
    surface.shape = height_model == HeightModel::gaussian ? 2 : fit.shape;
    surface.height_scale = fit.scale;
    surface.summit_radius = summits.radius;
    surface.summit_density = summits.density;
    surface.nominal_area = area;
    surface.contact_modulus = e_star;
    try {
      if (height_model == HeightModel::gaussian || !options.table_path.empty()) {
        const ContactModel contact(default_table, surface);
        fill_curves(model, contact, comparison);
        model.note = options.table_path.empty() ? "default table" : "table " + options.table_path;
        if (height_model != HeightModel::gaussian) model.note += " (shape interpolated between grid shapes)";
      } else {
        if (!(fit.shape >= weibull_shape_min && fit.shape <= weibull_shape_max))
          throw Error("the fitted shape " + shape_text(fit.shape) + " is outside the shapes scene tables serve (" +
                      shape_text(weibull_shape_min) + " to " + shape_text(weibull_shape_max) + ")");
        // an exact-shape scene table over the loads the curves visit (X_3/2, dimensionless)
        // P/A0 per unit X_3/2: the load factor per unit nominal area (contact_scales.hpp)
        const double load_unit = detail::contact_scales_of(summits.density, summits.radius, fit.scale, e_star).load;
        Scene scene;
        scene.name = std::string("asperity surface: ") + model.label();
        scene.source = "asperity surface";
        SceneCurve curve;
        curve.name = model.label();
        curve.distribution = Distribution::weibull;
        curve.side = surface.side;
        curve.shape = fit.shape;
        curve.twice_orders = {0, 1, 2, 3};
        curve.by_load = true;
        curve.range_min = comparison.pressure_min / load_unit / 2;
        curve.range_max = comparison.pressure_max / load_unit * 2;
        curve.max_rel_error = options.scene_tolerance;
        scene.curves.push_back(curve);
        generator::SceneResult generated = generator::generate_scene_table(scene, options.threads);
        const double achieved = generated.curves.front().achieved_error;
        const Table scene_table(std::move(generated.table));
        const ContactModel contact(scene_table, surface);
        fill_curves(model, contact, comparison);
        std::ostringstream note;
        note.precision(2);
        note << "exact-shape scene table at a = " << shape_text(fit.shape) << " (max relative error " << achieved
             << " measured against quadrature)";
        model.note = note.str();
      }
    } catch (const Error& error) {
      model.served = false;
      model.curve.clear();
      model.at_pressures.clear();
      model.note = std::string("no curve: ") + error.what();
    }
    comparison.models.push_back(std::move(model));
  }
  conclude_contact(comparison);
  return comparison;
}

}  // namespace asperity::topography
