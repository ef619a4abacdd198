#include "asperity/generator/scene_table.hpp"

#include "asperity/detail/parallel_for.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <random>
#include <sstream>
#include <thread>

#include "asperity/curve.hpp"
#include "asperity/detail/quintic_hermite.hpp"
#include "asperity/detail/segment_map.hpp"
#include "asperity/error.hpp"
#include "asperity/generator/chain_ode.hpp"
#include "asperity/generator/quadrature.hpp"
#include "asperity/interrupt.hpp"
#include "asperity/number_text.hpp"

namespace asperity::generator {

double separation_at_load(Distribution distribution, Side side, double shape, double load) {
  const CurveId id{distribution, side, shape};
  const double target = std::log(load);
  // ln X_3/2 falls as s grows (and is -inf on the bounded side from s = 0 on)
  auto excess = [&](double separation) { return log_integral(id, 1.5, separation) - target; };
  double lo = -1, hi = side == Side::bounded ? -1e-300 : 1;
  for (int i = 0; excess(lo) < 0; ++i) {
    if (i > 60) throw Error("scene: a load is larger than X_3/2 reaches");
    lo *= 2;
  }
  for (int i = 0; excess(hi) > 0; ++i) {
    if (i > 200 || side == Side::bounded) throw Error("scene: a load is smaller than X_3/2 reaches");
    hi = hi < 1 ? 1 : hi * 1.5;
  }
  boost::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(excess, lo, hi, boost::math::tools::eps_tolerance<double>(50),
                                                        iterations);
  return 0.5 * (bracket.first + bracket.second);
}

namespace {

struct Requirement {  // one scene curve, on its shape's data
  std::size_t report;  // index in the result's curves
  std::vector<int> twice_orders;
  double separation_min, separation_max;
  double tolerance;
};

struct Shape {
  double shape;
  std::vector<Requirement> requirements;
  std::vector<double> fine;  // knot data on the fine layout
  // What the table serves at this shape (the file holds all six orders, and Table::curve serves
  // them): every order over the hull of its curves' separations, to the strictest tolerance they
  // ask; nothing outside (Curve::serves). Set by serve_hull.
  double served_min = 0, served_max = 0, tolerance = 1;
};

struct Group {
  Distribution distribution;
  Side side;
  std::vector<Shape> shapes;  // ascending
};

// A curve given by its loads is served a little past the separations they resolve to (by
// quadrature): the table's own X_3/2, within its tolerance of the integral, reaches the loads
// inside what it serves (serve_scene resolves them again on it).
constexpr double load_range_margin = 1e-3;

void serve_hull(Shape& shape, const std::vector<SceneCurveReport>& reports) {
  shape.served_min = std::numeric_limits<double>::infinity();
  shape.served_max = -shape.served_min;
  shape.tolerance = 1;
  for (const Requirement& requirement : shape.requirements) {
    double lo = requirement.separation_min, hi = requirement.separation_max;
    if (reports[requirement.report].curve.by_load) {
      const double margin = load_range_margin * (hi - lo);
      lo -= margin;
      hi += margin;
    }
    shape.served_min = std::min(shape.served_min, lo);
    shape.served_max = std::max(shape.served_max, hi);
    shape.tolerance = std::min(shape.tolerance, requirement.tolerance);
  }
}

bool overlaps(double a_lo, double a_hi, double b_lo, double b_hi) { return a_hi >= b_lo && a_lo <= b_hi; }

double group_tolerance(const Group& group) {
  double tolerance = 1;
  for (const Shape& shape : group.shapes) tolerance = std::min(tolerance, shape.tolerance);
  return tolerance;
}

using detail::parallel_for;
using detail::SegmentMap;

// The largest error in H of the quintic through every factor-th fine knot of a segment, at the
// fine knots it drops, where the shape is served (every order, its separations).
double thinning_error(const Shape& shape, const SegmentMap& map, int first_knot, int knots, int total_knots,
                      int factor) {
  double worst = 0;
  const double fine_step = (map.u_hi - map.u_lo) / (knots - 1), coarse_step = fine_step * factor;
  auto separation_at = [&](int j) {
    double separation, unused1, unused2;
    map.s_of_u(map.u_lo + fine_step * j, separation, unused1, unused2);
    return separation;
  };
  for (int twice_order = 0; twice_order < order_count; ++twice_order) {
    const double* data = &shape.fine[(static_cast<std::size_t>(twice_order) * total_knots + first_knot) * 3];
    for (int start = 0; start + factor <= knots - 1; start += factor) {
      const double s_a = separation_at(start), s_b = separation_at(start + factor);
      if (!overlaps(std::min(s_a, s_b), std::max(s_a, s_b), shape.served_min, shape.served_max)) continue;
      const double* left_knot = data + start * 3;
      const double* right_knot = data + (start + factor) * 3;
      const double left[3] = {left_knot[0], left_knot[1] * coarse_step, left_knot[2] * coarse_step * coarse_step};
      const double right[3] = {right_knot[0], right_knot[1] * coarse_step, right_knot[2] * coarse_step * coarse_step};
      for (int m = 1; m < factor; ++m) {
        const double separation = separation_at(start + m);
        if (separation < shape.served_min || separation > shape.served_max) continue;
        const double x = static_cast<double>(m) / factor;
        const double error = std::fabs(detail::quintic_hermite(left, right, x) - data[(start + m) * 3]);
        worst = std::max(worst, std::isnan(error) ? 1.0 : error);
      }
    }
  }
  return worst;
}

std::vector<double> thin(const std::vector<double>& fine, const std::vector<SegmentSpec>& fine_layout,
                         const std::vector<int>& factors) {
  int fine_total = 0, coarse_total = 0;
  for (std::size_t i = 0; i < fine_layout.size(); ++i) {
    fine_total += fine_layout[i].knots;
    coarse_total += (fine_layout[i].knots - 1) / factors[i] + 1;
  }
  std::vector<double> coarse(static_cast<std::size_t>(order_count) * coarse_total * 3);
  for (int order = 0; order < order_count; ++order) {
    int fine_first = 0, coarse_index = 0;
    for (std::size_t i = 0; i < fine_layout.size(); ++i) {
      for (int j = 0; j < fine_layout[i].knots; j += factors[i], ++coarse_index)
        for (int c = 0; c < 3; ++c)
          coarse[(static_cast<std::size_t>(order) * coarse_total + coarse_index) * 3 + c] =
              fine[(static_cast<std::size_t>(order) * fine_total + fine_first + j) * 3 + c];
      fine_first += fine_layout[i].knots;
    }
  }
  return coarse;
}

// How a scene curve is served (CurveOptions, stored with the table): the lookup grid over the
// separations it serves, and only those, to a tenth of its tolerance there, X < 1e-100 included.
CurveOptions grid_options(const Shape& shape) {
  CurveOptions options;
  options.grid_tolerance = std::max(1e-14, 0.1 * shape.tolerance);
  options.grid_far_factor = 1;
  options.grid_min_separation = options.served_min_separation = shape.served_min;
  options.grid_max_separation = options.served_max_separation = shape.served_max;
  return options;
}

// Where a served curve is checked: at every interval of its layout inside what it serves, where
// a quintic Hermite interpolant's error peaks (x^3 (1 - x)^3 h^6 H^(6)/720: the middle; and a
// quarter from each end; eighths in the two intervals at each end of a segment, where H^(6) may
// change fastest), uniform and random over the range, log-spaced toward both of its ends and
// toward every segment end, toward s = 0 down to the smallest doubles, and past the table's end
// (the series) log-spaced: the places a stored bound would otherwise miss the peak (issue #28).
std::vector<double> check_points(const Shape& shape, const std::vector<SegmentSpec>& layout,
                                 const std::vector<SegmentMap>& maps, std::mt19937_64& rng) {
  const double lo = shape.served_min, hi = shape.served_max;
  const double width = std::isfinite(hi - lo) ? hi - lo : 0.0;
  std::vector<double> points;
  const int uniform_points = 96;
  for (int i = 0; i <= uniform_points; ++i) points.push_back(lo + width * i / uniform_points);
  std::uniform_real_distribution<double> pick(lo, lo + width);
  for (int i = 0; i < 64; ++i) points.push_back(pick(rng));
  for (std::size_t g = 0; g < maps.size(); ++g) {
    const SegmentMap& map = maps[g];
    const int intervals = layout[g].knots - 1;
    const double step = (map.u_hi - map.u_lo) / intervals;
    for (int j = 0; j < intervals; ++j) {
      const double s_a = map.separation_of_u(map.u_lo + step * j), s_b = map.separation_of_u(map.u_lo + step * (j + 1));
      if (!overlaps(std::min(s_a, s_b), std::max(s_a, s_b), lo, hi)) continue;
      const int parts = j < 2 || j >= intervals - 2 ? 8 : 4;
      for (int k = 1; k < parts; ++k) points.push_back(map.separation_of_u(map.u_lo + step * (j + double(k) / parts)));
    }
  }
  std::vector<double> ends = {lo, hi};
  for (const SegmentMap& map : maps) ends.insert(ends.end(), {map.s_lo, map.s_hi});
  for (double end : ends) {
    if (!std::isfinite(end)) continue;
    for (int k = 1; k <= 15; ++k) {
      const double offset = std::max(std::fabs(end), 1e-3) * std::pow(10.0, -k);
      points.insert(points.end(), {end - offset, end + offset});
    }
  }
  for (int k = 4; k <= 80; ++k) {  // 1e-1 down to 1e-20, four a decade; then every ten decades
    const double magnitude = std::pow(10.0, -k / 4.0);
    points.insert(points.end(), {magnitude, -magnitude});
  }
  for (double magnitude = 1e-30; magnitude > 1e-305; magnitude *= 1e-10) points.insert(points.end(), {magnitude, -magnitude});
  // the lookup grid's binades end at powers of two, and so does its first-contact zone, where
  // it answers X_n(0) and is farthest from the truth just below its end
  for (int k = -10; k <= 72; ++k) {
    const double binade = std::ldexp(1.0, -k), below = std::nextafter(binade, 0.0);
    points.insert(points.end(), {binade, -binade, below, -below});
  }
  points.insert(points.end(), {0.0, 4.9406564584124654e-324, -4.9406564584124654e-324});
  const double table_max = maps.back().s_hi;
  if (table_max > 0 && hi > table_max)  // the series past the table, log-spaced
    for (int k = 1; k <= 48; ++k) points.push_back(table_max * std::pow(hi / table_max, k / 48.0));
  std::vector<double> inside;
  for (double point : points)
    if (point >= lo && point <= hi) inside.push_back(point);
  std::sort(inside.begin(), inside.end());
  inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
  return inside;
}

// Checks a thinned curve as it is served (its lookup grid included) against quadrature at
// check_points. Returns, per order, the largest error found plus the grid's own largest
// difference from the table (where the points may fall beside the grid's peaks): the bound the
// file stores. Marks the segments where an order's bound there exceeds the shape's tolerance,
// and gives each requirement's bound (its orders, its separations).
std::vector<double> verify(const Group& group, const Shape& shape, const std::vector<SegmentSpec>& layout,
                           const std::vector<double>& data, std::vector<char>& failed_segments,
                           std::vector<double>& requirement_error) {
  const Curve curve(group.distribution, group.side, shape.shape, layout, data.data(), Curve::all_orders,
                    grid_options(shape));
  const double grid_error = curve.grid_error();
  const std::vector<SegmentMap> maps = SegmentMap::resolve(layout, group.distribution, group.side, shape.shape);
  const CurveId id{group.distribution, group.side, shape.shape};
  std::vector<double> errors(order_count, 0.0);
  requirement_error.assign(shape.requirements.size(), 0.0);
  std::mt19937_64 rng(97);
  for (double separation : check_points(shape, layout, maps, rng)) {
    poll_interrupt();  // a quadrature per order
    std::size_t segment = 0;
    while (segment + 1 < maps.size() && separation > maps[segment].s_hi) ++segment;
    for (int twice_order = 0; twice_order < order_count; ++twice_order) {
      const double reference = log_integral(id, order_of(twice_order), separation);
      const double value = curve.log_value(twice_order, separation);
      double error;
      if (std::isinf(reference) && reference < 0) error = value == reference ? 0 : 1;
      else error = std::fabs(std::expm1(value - reference)) + grid_error;
      if (std::isnan(error)) error = 1;
      errors[twice_order] = std::max(errors[twice_order], error);
      if (error > shape.tolerance) failed_segments[segment] = 1;
      for (std::size_t r = 0; r < shape.requirements.size(); ++r) {
        const Requirement& requirement = shape.requirements[r];
        if (separation >= requirement.separation_min && separation <= requirement.separation_max &&
            std::find(requirement.twice_orders.begin(), requirement.twice_orders.end(), twice_order) !=
                requirement.twice_orders.end())
          requirement_error[r] = std::max(requirement_error[r], error);
      }
    }
  }
  for (double& error : errors) error = std::max(error, grid_error);
  return errors;
}

// Segments parameterized by separation itself (linear, gaussian_linear, log_distance) are cut at
// the scene's range (with a small margin), so that the knots the range needs are not spread
// over the whole segment: the pieces outside are thinned to three knots. Each piece keeps the
// segment's knot spacing, in multiples of 16 intervals (the thinning halves them).
std::vector<SegmentSpec> split_for_range(const std::vector<SegmentSpec>& layout, double lo, double hi) {
  std::vector<SegmentSpec> out;
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const SegmentSpec& spec = layout[i];
    const bool by_separation = spec.kind == SegmentKind::linear || spec.kind == SegmentKind::gaussian_linear ||
                               spec.kind == SegmentKind::log_distance;
    const std::size_t room = static_cast<std::size_t>(max_segments) - (layout.size() - 1 - i) - out.size();
    if (!by_separation || room < 2 || !(hi > spec.p0 && lo < spec.p1)) {
      out.push_back(spec);
      continue;
    }
    const bool logarithmic = spec.kind == SegmentKind::log_distance;  // u = ln(-s)
    auto u_of = [&](double s) { return logarithmic ? std::log(-s) : s; };
    const double margin = 0.02 * (spec.p1 - spec.p0);
    std::vector<double> cuts = {spec.p0};
    const double a = std::max(spec.p0, lo - margin), b = std::min(spec.p1, hi + margin);
    if (a - spec.p0 > 4 * margin && cuts.size() + 1 < room) cuts.push_back(a);
    if (spec.p1 - b > 4 * margin && cuts.size() < room) cuts.push_back(b);
    cuts.push_back(spec.p1);
    if (cuts.size() == 2) {
      out.push_back(spec);
      continue;
    }
    const double per_u = (spec.knots - 1) / std::fabs(u_of(spec.p1) - u_of(spec.p0));
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double intervals = per_u * std::fabs(u_of(cuts[k + 1]) - u_of(cuts[k]));
      const int rounded = std::max(16, 16 * static_cast<int>(std::ceil(intervals / 16)));
      out.push_back({spec.kind, rounded + 1, cuts[k], cuts[k + 1]});
    }
  }
  return out;
}

}  // namespace

SceneResult generate_scene_table(const Scene& scene, int threads,
                                 const std::function<void(const std::string&)>& progress) {
  std::mutex progress_mutex;
  auto report = [&](const std::string& step) {
    if (!progress) return;
    std::lock_guard<std::mutex> lock(progress_mutex);
    progress(step);
  };
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  SceneResult result;
  // Resolve the ranges and group the curves by (distribution, side) and exact shape.
  std::vector<Group> groups;
  for (const SceneCurve& curve : scene.curves) {
    SceneCurveReport report;
    report.curve = curve;
    if (curve.by_load) {
      report.separation_min = separation_at_load(curve.distribution, curve.side, curve.shape, curve.range_max);
      report.separation_max = separation_at_load(curve.distribution, curve.side, curve.shape, curve.range_min);
    } else {
      report.separation_min = curve.range_min;
      report.separation_max = curve.range_max;
    }
    result.curves.push_back(report);
    auto group = std::find_if(groups.begin(), groups.end(), [&](const Group& g) {
      return g.distribution == curve.distribution && g.side == curve.side;
    });
    if (group == groups.end()) {
      groups.push_back({curve.distribution, curve.side, {}});
      group = groups.end() - 1;
    }
    auto shape = std::find_if(group->shapes.begin(), group->shapes.end(),
                              [&](const Shape& s) { return s.shape == curve.shape; });
    if (shape == group->shapes.end()) {
      group->shapes.push_back({curve.shape, {}, {}});
      shape = group->shapes.end() - 1;
    }
    shape->requirements.push_back({result.curves.size() - 1, curve.twice_orders, report.separation_min,
                                   report.separation_max, curve.max_rel_error});
  }
  for (Group& group : groups)
    for (Shape& shape : group.shapes) serve_hull(shape, result.curves);

  std::ostringstream options;
  options.precision(12);
  options << "scene=" << (scene.name.empty() ? scene.source : scene.name) << " curves=" << scene.curves.size();
  result.table.generator = "asperity tablegen --scene (Boost.odeint runge_kutta_fehlberg78, Boost.Math quadrature)";
  result.table.exact_shapes = true;

  for (Group& group : groups) {
    std::sort(group.shapes.begin(), group.shapes.end(), [](const Shape& a, const Shape& b) { return a.shape < b.shape; });
    double range_lo = std::numeric_limits<double>::infinity(), range_hi = -range_lo;
    for (const Shape& shape : group.shapes) {
      range_lo = std::min(range_lo, shape.served_min);
      range_hi = std::max(range_hi, shape.served_max);
    }
    const std::vector<SegmentSpec> base =
        split_for_range(default_layout(group.distribution, group.side), range_lo, range_hi);
    const double tolerance = group_tolerance(group);
    double density = tolerance >= 1e-9 ? 0.5 : tolerance >= 5e-12 ? 1.0 : 2.0;
    for (;;) {  // until the fine layout itself is good enough
      const std::vector<SegmentSpec> fine_layout = scale_knot_density(base, density);
      int total_knots = 0;
      for (const SegmentSpec& spec : fine_layout) total_knots += spec.knots;
      std::ostringstream step;
      step << to_string(group.distribution) << " " << to_string(group.side) << ", " << group.shapes.size()
           << " shape(s): ";
      const std::string group_name = step.str();
      report(group_name + "integrating at knot density " + format_double(density) + " (" +
             std::to_string(total_knots) + " knots a curve)");
      parallel_for(group.shapes.size(), threads, [&](std::size_t i) {
        group.shapes[i].fine = integrate_curve({group.distribution, group.side, group.shapes[i].shape}, fine_layout,
                                               ChainOptions{});
        report(group_name + "shape " + format_double(group.shapes[i].shape) + " integrated");
      });
      report(group_name + "thinning the knots, segment by segment (" + std::to_string(fine_layout.size()) +
             " segments)");
      // The coarsest thinning per segment that every shape's requirements accept.
      std::vector<int> factors(fine_layout.size(), 1);
      for (std::size_t segment = 0; segment < fine_layout.size(); ++segment) {
        const int intervals = fine_layout[segment].knots - 1;
        int first_knot = 0;
        for (std::size_t k = 0; k < segment; ++k) first_knot += fine_layout[k].knots;
        int factor = 1;
        while (intervals % (factor * 2) == 0 && intervals / (factor * 2) >= 2) factor *= 2;
        // Half the (strictest) tolerance at the dropped knots: the check that follows looks between them.
        for (; factor > 1; factor /= 2) {
          poll_interrupt();
          double worst = 0;
          for (const Shape& shape : group.shapes) {
            const auto maps = SegmentMap::resolve(fine_layout, group.distribution, group.side, shape.shape);
            worst = std::max(worst, thinning_error(shape, maps[segment], first_knot, fine_layout[segment].knots,
                                                   total_knots, factor));
          }
          if (worst <= 0.5 * tolerance) break;
        }
        factors[segment] = factor;
      }
      // Thin, verify, refine where a check fails.
      bool fine_failed = false;
      for (int attempt = 0; attempt < 12; ++attempt) {
        std::vector<SegmentSpec> layout = fine_layout;
        for (std::size_t i = 0; i < layout.size(); ++i) layout[i].knots = (fine_layout[i].knots - 1) / factors[i] + 1;
        std::vector<char> failed(layout.size(), 0);
        std::vector<std::vector<double>> thinned(group.shapes.size()), errors(group.shapes.size()),
            requirement_errors(group.shapes.size());
        std::vector<std::vector<char>> shape_failed(group.shapes.size(), std::vector<char>(layout.size(), 0));
        report(group_name + "checking the thinned curves against the quadrature (pass " + std::to_string(attempt + 1) +
               ")");
        parallel_for(group.shapes.size(), threads, [&](std::size_t i) {
          thinned[i] = thin(group.shapes[i].fine, fine_layout, factors);
          errors[i] = verify(group, group.shapes[i], layout, thinned[i], shape_failed[i], requirement_errors[i]);
        });
        for (const auto& flags : shape_failed)
          for (std::size_t k = 0; k < flags.size(); ++k) failed[k] |= flags[k];
        bool refined = false, stuck = false;
        for (std::size_t k = 0; k < failed.size(); ++k)
          if (failed[k]) {
            if (factors[k] > 1) {
              factors[k] /= 2;
              refined = true;
            } else {
              stuck = true;
            }
          }
        if (stuck) {
          fine_failed = true;
          break;
        }
        if (refined) continue;
        // Passed: record it.
        CurveSet set;
        set.distribution = group.distribution;
        set.side = group.side;
        for (const Shape& shape : group.shapes) set.shapes.push_back(shape.shape);
        set.shape_min = set.shapes.front();
        set.shape_max = set.shapes.back();
        set.layout = layout;
        for (std::size_t i = 0; i < group.shapes.size(); ++i) {
          set.knots.insert(set.knots.end(), thinned[i].begin(), thinned[i].end());
          set.max_rel_error.insert(set.max_rel_error.end(), errors[i].begin(), errors[i].end());
          const CurveOptions served = grid_options(group.shapes[i]);
          set.grid_tolerance.push_back(served.grid_tolerance);
          set.grid_separations.insert(set.grid_separations.end(),
                                      {served.grid_min_separation, served.grid_max_separation});
          for (std::size_t r = 0; r < group.shapes[i].requirements.size(); ++r) {
            const Requirement& requirement = group.shapes[i].requirements[r];
            unsigned mask = 0;
            for (int twice_order : requirement.twice_orders) mask |= order_bit(twice_order);
            // in memory as serve_scene gives it: the asked orders only
            const Curve curve(group.distribution, group.side, group.shapes[i].shape, layout, thinned[i].data(), mask,
                              grid_options(group.shapes[i]));
            SceneCurveReport& report = result.curves[requirement.report];
            report.achieved_error = requirement_errors[i][r];
            report.knots = set.total_knots();
            report.memory_bytes = curve.memory_bytes();
          }
        }
        options << " " << to_string(group.distribution) << "_" << to_string(group.side) << ":density=" << density;
        result.fine_density = std::max(result.fine_density, density);
        result.table.sets.push_back(std::move(set));
        break;
      }
      if (!fine_failed && !result.table.sets.empty() && result.table.sets.back().distribution == group.distribution &&
          result.table.sets.back().side == group.side)
        break;
      if (density >= 8) {
        std::ostringstream message;
        message << "scene: " << to_string(group.distribution) << " " << to_string(group.side)
                << " curves cannot reach max_rel_error " << tolerance << " even at 8x the default knot density";
        throw Error(message.str());
      }
      density *= 2;
    }
  }
  std::size_t total_bytes = 0;
  for (const SceneCurveReport& report : result.curves) total_bytes += report.memory_bytes;
  if (scene.memory_budget_bytes > 0 && total_bytes > scene.memory_budget_bytes) {
    std::ostringstream message;
    message << "scene: the table needs " << (total_bytes + 1023) / 1024 << " KiB in memory, over the budget of "
            << scene.memory_budget_bytes / 1024 << " KiB (loosen max_rel_error or narrow the ranges)";
    throw Error(message.str());
  }
  result.table.generator_options = options.str();
  for (const CurveSet& set : result.table.sets) set.validate("scene table");
  return result;
}

}  // namespace asperity::generator
