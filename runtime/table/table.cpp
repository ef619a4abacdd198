#include "asperity/table.hpp"

#include <cmath>
#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <sstream>

#include "asperity/detail/compact_curve.hpp"
#include "table_state.hpp"
#include "asperity/detail/segment_map.hpp"
#include "asperity/error.hpp"
#include "asperity/detail/table_schema.hpp"

namespace asperity {
namespace {
// In messages: the shortest text that reads back to the same double (0.4999999 is not "0.5").
std::string shortest(double value) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}
}  // namespace

double shape_grid_variable(double shape) { return std::log(shape) - 1 / shape; }

int CurveSet::total_knots() const {
  int total = 0;
  for (const SegmentSpec& segment : layout) total += segment.knots;
  return total;
}

void CurveSet::validate(const std::string& context) const {
  const std::string where = context + " " + to_string(distribution) + "_" + to_string(side) + ": ";
  if (shapes.empty() || shapes.size() > static_cast<std::size_t>(schema::max_shapes))
    throw Error(where + "a curve set has 1 to " + std::to_string(schema::max_shapes) + " shapes");
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    if (!(std::isfinite(shapes[i]) && shapes[i] > 0)) throw Error(where + "a shape is not a positive number");
    if (i > 0 && !(shapes[i] > shapes[i - 1])) throw Error(where + "shapes are not strictly ascending");
  }
  if (distribution == Distribution::gaussian && !(shapes.size() == 1 && shapes[0] == 2))
    throw Error(where + "the Gaussian set has the one shape 2");
  if (!(shapes.front() >= schema::min_shape && shapes.back() <= schema::max_shape)) {
    std::ostringstream message;
    message << where << "shapes must lie in [" << schema::min_shape << ", " << schema::max_shape << "]";
    throw Error(message.str());
  }
  if (!(shape_min >= shapes.front() && shape_max <= shapes.back() && shape_min <= shape_max))
    throw Error(where + "shape_range is not inside the shape grid");
  if (layout.empty() || layout.size() > static_cast<std::size_t>(max_segments))
    throw Error(where + "the layout must have 1 to " + std::to_string(max_segments) + " segments");
  for (const SegmentSpec& segment : layout) {
    if (segment.knots < 2 || segment.knots > schema::max_segment_knots)
      throw Error(where + "a segment has a bad knot count (2 to " + std::to_string(schema::max_segment_knots) + ")");
    if (!detail::is_segment_kind(static_cast<int>(segment.kind)))
      throw Error(where + "unknown segment kind");
    if (!std::isfinite(segment.p0) || !std::isfinite(segment.p1)) throw Error(where + "a segment bound is not finite");
  }
  if (layout.front().kind != SegmentKind::reciprocal) throw Error(where + "the first segment must be reciprocal");
  for (double shape : shapes) {
    std::vector<detail::SegmentMap> maps;
    try {
      maps = detail::SegmentMap::resolve(layout, distribution, side, distribution == Distribution::gaussian ? 2.0 : shape);
    } catch (const Error& error) {
      throw Error(where + error.what());
    }
    // What a lookup divides by and maps with must be finite numbers.
    for (std::size_t i = 0; i < maps.size(); ++i) {
      const detail::SegmentMap& map = maps[i];
      const double inverse_step = (layout[i].knots - 1) / (map.u_hi - map.u_lo);
      if (!std::isfinite(map.u_lo) || !std::isfinite(map.u_hi) || !std::isfinite(inverse_step) ||
          std::isnan(map.s_lo) || std::isnan(map.s_hi) || !std::isfinite(map.span) || !std::isfinite(map.power))
        throw Error(where + "the layout maps to non-finite numbers at shape " + std::to_string(shape));
    }
  }
  const double expected = static_cast<double>(shapes.size()) * static_cast<double>(curve_stride());
  if (expected > static_cast<double>(schema::max_set_values))
    throw Error(where + "more knot values than a table may hold (" + std::to_string(schema::max_set_values) + ")");
  if (knots.size() != shapes.size() * curve_stride())
    throw Error(where + "knot data has " + std::to_string(knots.size()) + " values, expected " +
                std::to_string(shapes.size() * curve_stride()));
  for (double value : knots)
    if (!(std::fabs(value) <= schema::max_knot_value)) {
      std::ostringstream message;
      message << where << "knot data holds " << value << ", not a number of magnitude at most "
              << schema::max_knot_value;
      throw Error(message.str());
    }
  if (!max_rel_error.empty() && max_rel_error.size() != shapes.size() * order_count)
    throw Error(where + "max_rel_error has the wrong size");
  for (double error : max_rel_error)
    if (!(error >= 0 && error <= 1e300)) throw Error(where + "max_rel_error holds a value that is not a finite error");
  if (!grid_tolerance.empty()) {
    if (grid_tolerance.size() != shapes.size() || grid_separations.size() != 2 * shapes.size())
      throw Error(where + "grid_tolerance and grid_separations need one entry (a pair) per shape");
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      if (!(grid_tolerance[i] >= 1e-14 && grid_tolerance[i] <= 1e-2))
        throw Error(where + "grid_tolerance must lie in [1e-14, 1e-2]");
      const double lo = grid_separations[2 * i], hi = grid_separations[2 * i + 1];
      if (std::isnan(lo) || std::isnan(hi) || !(lo < hi)) throw Error(where + "grid_separations must be intervals");
    }
  } else if (!grid_separations.empty()) {
    throw Error(where + "grid_separations without grid_tolerance");
  }
}

CurveOptions CurveSet::curve_options(std::size_t shape_index) const {
  CurveOptions options;
  if (shape_index < grid_tolerance.size()) {  // a scene table: its tolerance everywhere in its range
    options.grid_tolerance = grid_tolerance[shape_index];
    options.grid_far_factor = 1;
    options.grid_min_separation = options.served_min_separation = grid_separations[2 * shape_index];
    options.grid_max_separation = options.served_max_separation = grid_separations[2 * shape_index + 1];
  }
  return options;
}

CurveOptions CurveSet::curve_options(std::size_t shape_index, const CurveOptions& asked) const {
  const CurveOptions own = curve_options(shape_index);
  CurveOptions options = asked;
  options.served_min_separation = std::max(asked.served_min_separation, own.served_min_separation);
  options.served_max_separation = std::min(asked.served_max_separation, own.served_max_separation);
  if (!(options.served_min_separation < options.served_max_separation)) {
    std::ostringstream message;
    message << "the separations asked to be served, [" << shortest(asked.served_min_separation) << ", "
            << shortest(asked.served_max_separation) << "], lie outside the curve's own, ["
            << shortest(own.served_min_separation) << ", " << shortest(own.served_max_separation) << "]";
    throw Error(message.str());
  }
  return options;
}

namespace detail {

// Each node's view costs its segments' maps, series and values at 0 (about 1.5 us): the whole
// default table's 217 in about 0.3 ms, once.
TableState::TableState(TableData table) : data(std::move(table)) {
  nodes.resize(data.sets.size());
  grid_variable.resize(data.sets.size());
  for (std::size_t k = 0; k < data.sets.size(); ++k) {
    const CurveSet& set = data.sets[k];
    const std::size_t stride = set.curve_stride();
    const std::size_t count = set.distribution == Distribution::gaussian ? 1 : set.shapes.size();
    for (std::size_t i = 0; i < count && (i + 1) * stride <= set.knots.size(); ++i) {
      const double shape = set.distribution == Distribution::gaussian ? 2.0 : set.shapes[i];
      nodes[k].push_back(CompactCurve::borrowing(set.distribution, set.side, shape, set.layout,
                                                 &set.knots[i * stride], Curve::all_orders));
      grid_variable[k].push_back(set.distribution == Distribution::gaussian ? 0.0 : shape_grid_variable(shape));
    }
  }
}

}  // namespace detail

Table::Table(TableData data, Validated) : state_(std::make_shared<const detail::TableState>(std::move(data))) {}

Table::Table(TableData data) {
  for (const CurveSet& set : data.sets) set.validate("table");
  state_ = std::make_shared<const detail::TableState>(std::move(data));
}

const TableData& Table::data() const noexcept { return state_->data; }

Table Table::open(const std::string& path) { return Table(read_table_file(path), Validated{}); }

const CurveSet* Table::find(Distribution distribution, Side side) const noexcept {
  for (const CurveSet& set : state_->data.sets)
    if (set.distribution == distribution && set.side == side) return &set;
  return nullptr;
}

Curve Table::curve(Distribution distribution, Side side, double shape, unsigned order_mask) const {
  return make_curve(distribution, side, shape, order_mask, nullptr);
}

Curve Table::curve(Distribution distribution, Side side, double shape, unsigned order_mask,
                   const CurveOptions& options) const {
  return make_curve(distribution, side, shape, order_mask, &options);
}

namespace {

// The curve set a curve is asked of, and the shape checked against it (throws Error)
const CurveSet& checked_set(const Table& table, Distribution distribution, Side side, double shape) {
  const CurveSet* set = table.find(distribution, side);
  if (!set) {
    if (distribution == Distribution::gaussian && side == Side::bounded)
      throw Error("the Gaussian has no bounded side (its heights are unbounded)");
    throw Error(std::string("this table has no ") + to_string(distribution) + " " + to_string(side) + " curves");
  }
  if (distribution == Distribution::gaussian) return *set;
  // A shape is a grid node only when it is that double: one a hair off it is interpolated (in
  // the far tail ln X moves by t ln t da/a, 1e-9 at t = 700 for da/a = 1e-12), and a scene
  // table, which cannot interpolate, refuses it.
  if (table.data().exact_shapes && std::none_of(set->shapes.begin(), set->shapes.end(), [&](double node) {
        return shape == node;
      })) {
    std::ostringstream message;
    message << "this scene table serves only its own " << to_string(distribution) << " " << to_string(side)
            << " shapes (";
    for (std::size_t i = 0; i < set->shapes.size(); ++i) message << (i ? ", " : "") << shortest(set->shapes[i]);
    message << "), exactly; asked for " << shortest(shape);
    throw Error(message.str());
  }
  const double lo = set->shape_min, hi = set->shape_max;
  if (!(shape >= lo && shape <= hi)) {  // also NaN
    std::ostringstream message;
    message << "shape " << shortest(shape) << " is outside the table's range [" << shortest(lo) << ", "
            << shortest(hi) << "]";
    throw Error(message.str());
  }
  return *set;
}

// The set's place in the table's list (the state's per-set views are in the same order)
std::size_t set_index(const Table& table, const CurveSet& set) {
  return static_cast<std::size_t>(&set - table.data().sets.data());
}

// The grid node that is this shape, or -1
std::ptrdiff_t node_of(const CurveSet& set, double shape) {
  for (std::size_t i = 0; i < set.shapes.size(); ++i)
    if (shape == set.shapes[i]) return static_cast<std::ptrdiff_t>(i);
  return -1;
}

// Between grid shapes: Lagrange in q over the shape_stencil nearest nodes, centred
struct Stencil {
  std::size_t first = 0;
  std::vector<double> weights;
};

Stencil shape_stencil_of(const CurveSet& set, const std::vector<double>& grid_variable, double shape) {
  const std::size_t count = set.shapes.size();
  std::size_t upper = 1;
  while (upper < count - 1 && set.shapes[upper] < shape) ++upper;
  const std::size_t points = std::min<std::size_t>(count, shape_stencil);
  Stencil stencil;
  stencil.first = upper >= points / 2 ? upper - points / 2 : 0;
  if (stencil.first + points > count) stencil.first = count - points;
  stencil.weights.resize(points);
  const double x = shape_grid_variable(shape);
  const double* q = &grid_variable[stencil.first];
  for (std::size_t i = 0; i < points; ++i) {
    double weight = 1;
    for (std::size_t j = 0; j < points; ++j)
      if (j != i) weight *= (x - q[j]) / (q[i] - q[j]);
    stencil.weights[i] = weight;
  }
  return stencil;
}

}  // namespace

Curve Table::make_curve(Distribution distribution, Side side, double shape, unsigned order_mask,
                        const CurveOptions* options) const {
  const CurveSet& set = checked_set(*this, distribution, side, shape);
  if (distribution == Distribution::gaussian)
    return Curve(distribution, side, 2.0, set.layout, set.knots.data(), order_mask,
                 options ? set.curve_options(0, *options) : set.curve_options(0));
  const std::size_t stride = set.curve_stride();
  // A grid shape: its knots as they are.
  if (const std::ptrdiff_t node = node_of(set, shape); node >= 0) {
    const auto i = static_cast<std::size_t>(node);
    return Curve(distribution, side, set.shapes[i], set.layout, &set.knots[i * stride], order_mask,
                 options ? set.curve_options(i, *options) : set.curve_options(i));
  }
  const Stencil stencil = shape_stencil_of(set, state_->grid_variable[set_index(*this, set)], shape);
  const std::size_t first = stencil.first, points = stencil.weights.size();
  const std::vector<double>& weights = stencil.weights;
  // The all-touching segment (below the table) from the knot data blended with the same
  // weights: its variable u = sqrt(s1/s) does not depend on the shape.
  std::vector<double> blended(stride, 0.0);
  ShapeBlend blend;
  CurveOptions between;  // a table that gives its grid shapes' tolerances: the largest of the stencil's
  if (!set.grid_tolerance.empty()) {
    between.grid_tolerance = 0;
    for (std::size_t i = 0; i < points; ++i)
      between.grid_tolerance = std::max(between.grid_tolerance, set.grid_tolerance[first + i]);
  }
  for (std::size_t i = 0; i < points; ++i) {
    const double* source = &set.knots[(first + i) * stride];
    for (std::size_t k = 0; k < stride; ++k) blended[k] += weights[i] * source[k];
    blend.shapes.push_back(set.shapes[first + i]);
    blend.knot_data.push_back(source);
    blend.weights.push_back(weights[i]);
  }
  return Curve(distribution, side, shape, set.layout, blended.data(), blend, order_mask,
               options ? *options : between);
}

Curve Table::direct_curve(Distribution distribution, Side side, double shape, unsigned order_mask) const {
  const CurveSet& set = checked_set(*this, distribution, side, shape);
  const std::size_t index = set_index(*this, set);
  const std::vector<detail::CompactCurve>& views = state_->nodes[index];
  const std::ptrdiff_t node = distribution == Distribution::gaussian ? 0 : node_of(set, shape);
  std::vector<double> shapes, weights;
  std::vector<const detail::CompactCurve*> nodes;
  double own_shape = shape;
  CurveOptions served;
  if (node >= 0) {  // a node (the Gaussian's one curve): its own knots
    const auto i = static_cast<std::size_t>(node);
    own_shape = views[i].shape();
    shapes = {own_shape};
    nodes = {&views[i]};
    weights = {1.0};
    served = set.curve_options(i);  // a scene table's range
  } else {
    Stencil stencil = shape_stencil_of(set, state_->grid_variable[index], shape);
    for (std::size_t i = 0; i < stencil.weights.size(); ++i) {
      shapes.push_back(set.shapes[stencil.first + i]);
      nodes.push_back(&views[stencil.first + i]);
    }
    weights = std::move(stencil.weights);
  }
  auto blend = std::make_shared<const detail::NodeBlend>(distribution, side, own_shape, std::move(shapes),
                                                        std::move(nodes), std::move(weights), state_);
  auto answer = detail::CompactCurve::blending(distribution, side, own_shape, set.layout, std::move(blend), order_mask);
  answer.serve_only(served.served_min_separation, served.served_max_separation);
  return Curve::without_grid(std::move(answer));
}

}  // namespace asperity
