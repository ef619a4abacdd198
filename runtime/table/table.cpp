#include "asperity/table.hpp"

#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "asperity/error.hpp"

namespace asperity {

double shape_grid_variable(double shape) { return std::log(shape) - 1 / shape; }

int CurveSet::total_knots() const {
  int total = 0;
  for (const SegmentSpec& segment : layout) total += segment.knots;
  return total;
}

void CurveSet::validate(const std::string& context) const {
  const std::string where = context + " " + to_string(distribution) + "_" + to_string(side) + ": ";
  if (shapes.empty()) throw Error(where + "no shapes");
  if (!(shape_min >= shapes.front() && shape_max <= shapes.back() && shape_min <= shape_max))
    throw Error(where + "shape_range is not inside the shape grid");
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    if (!(std::isfinite(shapes[i]) && shapes[i] > 0)) throw Error(where + "a shape is not a positive number");
    if (i > 0 && !(shapes[i] > shapes[i - 1])) throw Error(where + "shapes are not strictly ascending");
  }
  if (layout.empty() || layout.size() > static_cast<std::size_t>(max_segments))
    throw Error(where + "the layout must have 1 to " + std::to_string(max_segments) + " segments");
  if (layout.front().kind != SegmentKind::reciprocal) throw Error(where + "the first segment must be reciprocal");
  for (double shape : shapes) {
    try {
      SegmentMap::resolve(layout, distribution, side, distribution == Distribution::gaussian ? 2.0 : shape);
    } catch (const Error& error) {
      throw Error(where + error.what());
    }
  }
  for (const SegmentSpec& segment : layout) {
    if (segment.knots < 2 || segment.knots > 1000000) throw Error(where + "a segment has a bad knot count");
    if (!is_segment_kind(static_cast<int>(segment.kind)))
      throw Error(where + "unknown segment kind");
    if (!std::isfinite(segment.p0) || !std::isfinite(segment.p1)) throw Error(where + "a segment bound is not finite");
  }
  if (knots.size() != shapes.size() * curve_stride())
    throw Error(where + "knot data has " + std::to_string(knots.size()) + " values, expected " +
                std::to_string(shapes.size() * curve_stride()));
  for (double value : knots)
    if (!std::isfinite(value)) throw Error(where + "knot data holds a value that is not finite");
  if (!max_rel_error.empty() && max_rel_error.size() != shapes.size() * order_count)
    throw Error(where + "max_rel_error has the wrong size");
}

Table::Table(TableData data) : data_(std::move(data)) {
  for (const CurveSet& set : data_.sets) set.validate("table");
}

Table Table::open(const std::string& path) { return Table(read_table_file(path)); }

std::string Table::default_path() {
  if (const char* path = std::getenv("ASPERITY_TABLE"); path && *path) return path;
  return ASPERITY_DEFAULT_TABLE;
}

Table Table::open_default() { return open(default_path()); }

const CurveSet* Table::find(Distribution distribution, Side side) const noexcept {
  for (const CurveSet& set : data_.sets)
    if (set.distribution == distribution && set.side == side) return &set;
  return nullptr;
}

Curve Table::curve(Distribution distribution, Side side, double shape, unsigned order_mask) const {
  const CurveSet* set = find(distribution, side);
  if (!set) {
    if (distribution == Distribution::gaussian && side == Side::bounded)
      throw Error("the Gaussian has no bounded side (its heights are unbounded)");
    throw Error(std::string("this table has no ") + to_string(distribution) + " " + to_string(side) + " curves");
  }
  if (distribution == Distribution::gaussian) return Curve(distribution, side, 2.0, set->layout, set->knots.data(), order_mask);
  if (data_.exact_shapes && std::none_of(set->shapes.begin(), set->shapes.end(), [&](double node) {
        return std::fabs(shape - node) <= 1e-12 * shape;
      })) {
    std::ostringstream message;
    message << "this scene table serves only its own " << to_string(distribution) << " " << to_string(side)
            << " shapes (";
    for (std::size_t i = 0; i < set->shapes.size(); ++i) message << (i ? ", " : "") << set->shapes[i];
    message << "), exactly; asked for " << shape;
    throw Error(message.str());
  }
  const double lo = set->shape_min, hi = set->shape_max;
  if (!std::isfinite(shape) || shape < lo * (1 - 1e-12) || shape > hi * (1 + 1e-12)) {
    std::ostringstream message;
    message << "shape " << shape << " is outside the table's range [" << lo << ", " << hi << "]";
    throw Error(message.str());
  }
  const std::size_t count = set->shapes.size(), stride = set->curve_stride();
  // A grid shape: its knots as they are.
  for (std::size_t i = 0; i < count; ++i)
    if (std::fabs(shape - set->shapes[i]) <= 1e-12 * shape)
      return Curve(distribution, side, set->shapes[i], set->layout, &set->knots[i * stride], order_mask);

  // Between grid shapes: Lagrange in q over the shape_stencil nearest nodes, centred.
  std::size_t upper = 1;
  while (upper < count - 1 && set->shapes[upper] < shape) ++upper;
  const std::size_t points = std::min<std::size_t>(count, shape_stencil);
  std::size_t first = upper >= points / 2 ? upper - points / 2 : 0;
  if (first + points > count) first = count - points;
  std::vector<double> weights(points);
  const double x = shape_grid_variable(shape);
  for (std::size_t i = 0; i < points; ++i) {
    double weight = 1;
    const double xi = shape_grid_variable(set->shapes[first + i]);
    for (std::size_t j = 0; j < points; ++j)
      if (j != i) {
        const double xj = shape_grid_variable(set->shapes[first + j]);
        weight *= (x - xj) / (xi - xj);
      }
    weights[i] = weight;
  }
  // The all-touching segment (below the table) from the knot data blended with the same
  // weights: its variable u = sqrt(s1/s) does not depend on the shape.
  std::vector<double> blended(stride, 0.0);
  ShapeBlend blend;
  for (std::size_t i = 0; i < points; ++i) {
    const double* source = &set->knots[(first + i) * stride];
    for (std::size_t k = 0; k < stride; ++k) blended[k] += weights[i] * source[k];
    blend.shapes.push_back(set->shapes[first + i]);
    blend.knot_data.push_back(source);
    blend.weights.push_back(weights[i]);
  }
  return Curve(distribution, side, shape, set->layout, blended.data(), blend, order_mask);
}

}  // namespace asperity
