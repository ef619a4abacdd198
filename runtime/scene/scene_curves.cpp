#include "asperity/scene_curves.hpp"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "asperity/error.hpp"

namespace asperity {
namespace {
constexpr double between_grid_bound = 1e-10;  // docs/accuracy.md, tests/test_accuracy.cpp
}

double separation_at_load(const Curve& curve, double load) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!curve.has_order(orders::load) || !(load > 0) || !std::isfinite(load)) return nan;
  const double target = std::log(load);
  // ln X_3/2 falls as s grows: bracket the root, then TOMS 748 (Boost.Math)
  auto excess = [&](double separation) { return curve.log_value(orders::load, separation) - target; };
  // brackets within the separations the curve serves (a scene table's range)
  const double range_min = curve.served_min_separation(), range_max = curve.served_max_separation();
  double lo = std::max(-1.0, range_min), hi = std::min(curve.side() == Side::bounded ? -1e-300 : 1.0, range_max);
  if (!(lo < hi)) lo = range_min, hi = range_max;  // a range beside [-1, 1]
  for (int i = 0; !(excess(lo) > 0); ++i) {
    if (i > 1100 || lo == range_min) return nan;
    lo = std::max(lo < 0 ? lo * 2 : lo - (hi - lo), range_min);
  }
  for (int i = 0; !(excess(hi) < 0); ++i) {
    if (i > 2000 || curve.side() == Side::bounded || hi == range_max) return nan;
    hi = std::min(hi < 1 ? 1 : hi * 1.5, range_max);
  }
  boost::uintmax_t iterations = 200;
  try {
    const auto bracket = boost::math::tools::toms748_solve(excess, lo, hi, boost::math::tools::eps_tolerance<double>(50),
                                                          iterations);
    return 0.5 * (bracket.first + bracket.second);
  } catch (...) {
    return nan;
  }
}

std::vector<SceneCurveView> serve_scene(const Table& table, const Scene& scene) {
  std::vector<SceneCurveView> views;
  for (const SceneCurve& spec : scene.curves) {
    unsigned mask = 0;
    for (int twice_order : spec.twice_orders) mask |= order_bit(twice_order);
    const std::string label = spec.name.empty() ? "curve at line " + std::to_string(spec.line) : "curve '" + spec.name + "'";
    const CurveSet* set = table.find(spec.distribution, spec.side);
    if (!set) throw Error("scene " + scene.source + ": the table has no " + to_string(spec.distribution) + " " +
                          to_string(spec.side) + " curves (" + label + ")");
    // by_load needs X_3/2 even when the scene does not ask for it
    Curve curve = table.curve(spec.distribution, spec.side, spec.shape, spec.by_load ? mask | order_bit(orders::load) : mask);
    SceneCurveView view{spec, curve, spec.range_min, spec.range_max, between_grid_bound};
    if (spec.by_load) {
      view.separation_min = separation_at_load(curve, spec.range_max);
      view.separation_max = separation_at_load(curve, spec.range_min);
      if (std::isnan(view.separation_min) || std::isnan(view.separation_max))
        throw Error("scene " + scene.source + ": " + label + ": its load range is not reached on this curve");
      if (!(mask & order_bit(orders::load))) view.curve = table.curve(spec.distribution, spec.side, spec.shape, mask);
    }
    for (std::size_t i = 0; i < set->shapes.size(); ++i)
      if (set->shapes[i] == spec.shape || spec.distribution == Distribution::gaussian) {  // a node: its own error
        double stored = 0;
        if (!set->max_rel_error.empty())
          for (int twice_order : spec.twice_orders)
            stored = std::max(stored, set->max_rel_error[i * order_count + twice_order]);
        view.error_bound = stored;
        break;
      }
    if (view.error_bound > spec.max_rel_error) {
      std::ostringstream message;
      message << "scene " << scene.source << ": " << label << " asks for " << spec.max_rel_error
              << " but this table guarantees " << view.error_bound
              << " at that shape: generate a scene table (tablegen --scene)";
      throw Error(message.str());
    }
    views.push_back(std::move(view));
  }
  return views;
}

}  // namespace asperity
