#include "asperity/topography/contact_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "asperity/error.hpp"
#include "asperity/scene.hpp"
#include "asperity/surface.hpp"
#include "asperity/table.hpp"
#include "asperity/topography/summit_contact.hpp"
#include "asperity/generator/scene_table.hpp"

namespace asperity::topography {
namespace {

std::string shape_text(double shape) {
  std::ostringstream text;
  text.precision(4);
  text << shape;
  return text.str();
}

void fill_curves(ModelContact& model, const ContactModel& contact, const ContactComparison& comparison) {
  const int points = comparison.options.curve_points;  // checked by compare_contact
  const double lo = std::log(comparison.pressure_min), hi = std::log(comparison.pressure_max);
  for (int k = 0; k < points; ++k)
    model.curve.push_back(contact.at_pressure(std::exp(lo + (hi - lo) * k / (points - 1))));
  for (double p : comparison.pressures) model.at_pressures.push_back(contact.at_pressure(p));
  model.served = true;
}

}  // namespace

std::vector<double> contact_pressures(const ContactOptions& options) {
  std::vector<double> pressures = options.pressures;
  if (pressures.empty())
    for (double f : {1e-5, 1e-4, 1e-3}) pressures.push_back(f * options.contact_modulus);
  for (double p : pressures)
    if (!(p > 0) || !std::isfinite(p)) throw Error("contact: pressures must be positive numbers");
  std::sort(pressures.begin(), pressures.end());
  return pressures;
}

void conclude_contact(ContactComparison& comparison) {
  const ModelContact* measured = comparison.find("measured-summits");
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
  // the fitted model whose worst stiffness ratio over the pressures is nearest 1
  double best = std::numeric_limits<double>::infinity();
  comparison.closest.clear();
  for (const ModelContact& model : comparison.models) {
    if (!model.served || model.label.rfind("measured-summits", 0) == 0) continue;
    double worst = 0;
    for (double ratio : model.stiffness_over_measured) worst = std::max(worst, std::fabs(std::log(ratio)));
    if (worst < best) {
      best = worst;
      comparison.closest = model.label;
    }
  }
  std::ostringstream text;
  text.precision(3);
  if (comparison.closest.empty()) {
    text << "no fitted model has contact curves to compare with the measured summits";
  } else {
    const ModelContact& closest = *comparison.find(comparison.closest);
    text << "Closest to GW on the measured summits (no law fitted): " << closest.label << ", stiffness ";
    for (std::size_t k = 0; k < comparison.pressures.size(); ++k) {
      text << (k ? ", " : "") << closest.stiffness_over_measured[k] << "x";
      if (k < comparison.measured_stiffness_spread.size())
        text << " (+-" << 100 * comparison.measured_stiffness_spread[k] << "%)";
      text << " at " << comparison.pressures[k] << " Pa";
    }
    text << "; mean separation ";
    for (std::size_t k = 0; k < comparison.pressures.size(); ++k)
      text << (k ? ", " : "") << closest.separation_minus_measured[k] << " m";
    text << " from the measured summits' (the +- is the measured-summit answer's spread over the surrogate ensemble)";
  }
  comparison.headline = text.str();
}

const ModelContact* ContactComparison::find(const std::string& label) const {
  for (const ModelContact& m : models)
    if (m.label == label) return &m;
  return nullptr;
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
    ModelContact model;
    model.label = own_radii ? "measured-summits-own-radii" : "measured-summits";
    try {
      const SummitContact contact(summits, e_star, area, own_radii);
      model.mean_summit_height = contact.mean_summit_height();
      const int points = comparison.options.curve_points;
      const double lo = std::log(comparison.pressure_min), hi = std::log(comparison.pressure_max);
      for (int k = 0; k < points; ++k) model.curve.push_back(contact.at_pressure(std::exp(lo + (hi - lo) * k / (points - 1))));
      for (double p : comparison.pressures) model.at_pressures.push_back(contact.at_pressure(p));
      model.served = true;
      model.surface.summit_radius = summits.radius;
      model.surface.summit_density = summits.density;
      model.surface.nominal_area = area;
      model.surface.contact_modulus = e_star;
      model.note = std::to_string(summits.list.size()) + " measured summits, " +
                   (own_radii ? "each with its own radius 1/kappa_m" : "GW's one radius 1/<kappa_m>") + ", no law fitted";
    } catch (const Error& error) {
      model.note = std::string("no curve: ") + error.what();
    }
    comparison.models.push_back(std::move(model));
  }

  // the Gaussian from the spectral moments (Nayak-McCool)
  {
    ModelContact model;
    model.label = "gaussian-moments";
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
    ModelContact model;
    model.label = to_string(height_model);
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
        if (!(fit.shape >= scene_shape_min && fit.shape <= scene_shape_max))
          throw Error("the fitted shape " + shape_text(fit.shape) + " is outside the shapes scene tables serve (" +
                      shape_text(scene_shape_min) + " to " + shape_text(scene_shape_max) + ")");
        // an exact-shape scene table over the loads the curves visit (X_3/2, dimensionless)
        const double load_unit = (4.0 / 3.0) * summits.density * e_star * std::sqrt(summits.radius) *
                                 std::pow(fit.scale, 1.5);  // P/A0 per unit X_3/2
        Scene scene;
        scene.name = "asperity surface: " + model.label;
        scene.source = "asperity surface";
        SceneCurve curve;
        curve.name = model.label;
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
