// Building the fast grid (fast_grid.hpp) from a curve's compact form.
#include "asperity/detail/fast_grid_build.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

#include "asperity/error.hpp"

namespace asperity::detail {
namespace {

constexpr double zero_zone = 8.470329472543003e-22;  // 2^-70: below it the compact curve answers
constexpr double log_of_1e_minus_100 = -230.25850929940457;
constexpr double largest_knots_per_binade = 65536;
// A binade's error falls ~64x per doubling of its knots (at least 8,700x over four doublings
// from above 16x the tolerance, measured over every curve of the default table and the points
// between its shapes). Where it stalls, more knots would not help: the error is at the
// rounding of ln X (up to ~1.5x the tolerance at shapes 0.34-0.4), or the table's pieces meet
// only to its own error (a coarse table) or not at all (a crafted one); the cheapest try
// within 1.5x of the best is kept and its error reported.
// The work a grid may take, in intervals fitted (tries included): measured at most ~3,100 over
// the default table's curves and ~7,600 over shapes 0.34-35 (tail); a table that would take
// more is refused in bounded time (a crafted one could otherwise hold a lookup for minutes).
constexpr std::int64_t largest_fitted_intervals = std::int64_t(1) << 17;
constexpr double least_gain_over_four_doublings = 16;

// The six Chebyshev-Lobatto points of an interval in y = x - 1/2, and where the interpolation
// error peaks between them (the middle three gaps: |prod (y - y_k)| is largest there).
struct Nodes {
  std::array<double, 6> y;
  std::array<double, 3> check;
  std::array<std::array<double, 6>, 6> inverse;  // power-basis coefficients = inverse * values
  Nodes() {
    const long double pi = 3.141592653589793238462643383279502884L;
    for (int k = 0; k < 6; ++k) y[k] = static_cast<double>((1 - std::cos(pi * k / 5)) / 2 - 0.5L);
    y[0] = -0.5;
    y[5] = 0.5;
    for (int g = 0; g < 3; ++g) check[g] = 0.5 * (y[g + 1] + y[g + 2]);
    // invert the Vandermonde matrix V[k][j] = y_k^j (Gauss-Jordan in long double)
    long double a[6][12];
    for (int k = 0; k < 6; ++k)
      for (int j = 0; j < 12; ++j)
        a[k][j] = j < 6 ? std::pow(static_cast<long double>(y[k]), j) : (j - 6 == k ? 1.0L : 0.0L);
    for (int column = 0; column < 6; ++column) {
      int pivot = column;
      for (int row = column + 1; row < 6; ++row)
        if (std::fabs(a[row][column]) > std::fabs(a[pivot][column])) pivot = row;
      for (int j = 0; j < 12; ++j) std::swap(a[column][j], a[pivot][j]);
      const long double scale = a[column][column];
      for (int j = 0; j < 12; ++j) a[column][j] /= scale;
      for (int row = 0; row < 6; ++row)
        if (row != column) {
          const long double factor = a[row][column];
          for (int j = 0; j < 12; ++j) a[row][j] -= factor * a[column][j];
        }
    }
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) inverse[j][k] = static_cast<double>(a[j][6 + k]);
  }
};

const Nodes& nodes() {
  static const Nodes instance;
  return instance;
}

// The quintic through values at the nodes, in the power basis of y. Differences from the
// mean of the end values keep the rounding relative to the variation in the interval.
void fit_quintic(const double* values, double* out) {
  const Nodes& n = nodes();
  const double reference = 0.5 * (values[0] + values[5]);
  for (int j = 0; j < 6; ++j) {
    double sum = 0;
    for (int k = 0; k < 6; ++k) sum += n.inverse[j][k] * (values[k] - reference);
    out[j] = sum;
  }
  out[0] += reference;
}

struct Builder {
  const GridReference& reference;
  double tolerance;
  double far_tolerance;  // where X < 1e-100
  std::array<int, order_count> orders{};  // the held orders
  int held = 0;
  double achieved = 0;
  // per order, per side (0: s > 0, 1: s < 0): below this |s| the grid answers at_zero
  std::array<std::array<double, 2>, order_count> first_contact_zone{};

  // ln X of the held orders at a point of the binade [base, 2 base) of |s| (the zone is whole
  // binades: both ends of one answer alike)
  void evaluate(double separation, double base, double* out) const {
    double all[order_count];
    reference.log_values(separation, all);
    const int side = separation < 0;
    for (int k = 0; k < held; ++k) {
      if (base < first_contact_zone[orders[k]][side]) all[orders[k]] = reference.next_to_zero[side][orders[k]];
      out[k] = all[orders[k]];
      if (!std::isfinite(out[k]))
        throw Error("the table gives ln X_" + std::to_string(order_of(orders[k])) + " = " + std::to_string(out[k]) +
                    " at s = " + std::to_string(separation) + ", inside the curve's range");
    }
  }

  // One binade's intervals first..last (of `knots`) at |s| = base (1 + (i + 1/2 + y)/knots):
  // appends their coefficients [held order][interval][6] to `block` and returns the largest
  // error at the check points relative to what is allowed there: the three where the
  // interpolation error of a smooth curve peaks, or (dense) sixteen across each interval, for a
  // binade whose error stalled (where the table's pieces do not meet, the error is not a
  // smooth curve's, and the three would understate what it reports).
  double fit_binade(double sign, double base, double knots, std::int64_t first, std::int64_t last,
                    std::vector<double>& block, bool dense = false) const {
    const Nodes& n = nodes();
    std::vector<double> check_y(n.check.begin(), n.check.end());
    if (dense) {
      check_y.clear();
      for (int g = 0; g < 16; ++g) check_y.push_back((g + 0.5) / 16 - 0.5);
    }
    const int check_count = static_cast<int>(check_y.size());
    const std::int64_t count = last - first + 1;
    block.assign(static_cast<std::size_t>(count) * held * 6, 0.0);
    double worst = 0;
    std::vector<double> values(static_cast<std::size_t>(6) * held),
        checks(static_cast<std::size_t>(check_count) * held);
    std::vector<double> left(held);
    for (std::int64_t i = first; i <= last; ++i) {
      auto at = [&](double y) { return sign * base * (1 + (static_cast<double>(i) + 0.5 + y) / knots); };
      for (int k = 0; k < 6; ++k) {
        if (k == 0 && i > first) {  // the previous interval's right end
          for (int o = 0; o < held; ++o) values[o * 6] = left[o];
          continue;
        }
        double point[order_count];
        evaluate(at(n.y[k]), base, point);
        for (int o = 0; o < held; ++o) values[o * 6 + k] = point[o];
      }
      for (int o = 0; o < held; ++o) left[o] = values[o * 6 + 5];
      for (int g = 0; g < check_count; ++g) {
        double point[order_count];
        evaluate(at(check_y[g]), base, point);
        for (int o = 0; o < held; ++o) checks[o * check_count + g] = point[o];
      }
      for (int o = 0; o < held; ++o) {
        double* c = &block[(static_cast<std::size_t>(o) * count + (i - first)) * 6];
        fit_quintic(&values[o * 6], c);
        for (int g = 0; g < check_count; ++g) {
          const double truth = checks[o * check_count + g];
          // what is asked, plus four units in the last place of ln X (the rounding of the
          // reference and of the quintic: a relative error |ln X| eps that no method escapes)
          double allowed = (truth >= log_of_1e_minus_100 ? tolerance : far_tolerance) +
                           8.8817841970012523e-16 * std::fabs(truth);
          // the Weibull order 0 where -s^a is below the tolerance: relative (find_first_contact_zones)
          if (orders[o] == orders::count && reference.exact_order_zero && truth != 0)
            allowed = std::min(allowed, 1e-3 * std::fabs(truth));
          // a subnormal ln X_0 (X_0 = 1 to the last bit) makes `allowed` 0: exact is no error
          const double miss = std::fabs(fast_quintic(c, 0, check_y[g]) - truth);
          const double error = miss == 0 ? 0 : miss / allowed;
          worst = std::max(worst, std::isnan(error) ? std::numeric_limits<double>::infinity() : error);
        }
      }
    }
    return worst;
  }
};

int biased_exponent(double magnitude) {
  std::uint64_t bits;
  std::memcpy(&bits, &magnitude, sizeof bits);
  return static_cast<int>((bits >> 52) & 0x7ff);
}

}  // namespace

// Next to s = 0 the grid answers what the closed forms give just inside |s| = 2^-70 (X_n(0);
// not the Weibull order 0, whose closed form the grid fits), for |s| < z. With D the larger of the
// tolerance and how far the table's value at 2^-69 is from that, past z (at every power of two
// up to 2^-10) ln X_n has moved the right way by more than 2 D and monotonely, so the grid's
// values (within the tolerance) lie beyond the zone's on their side: monotone across s = 0.
// The table's own value wanders next to s = 0 at small shapes; the zone also covers that
// wander where it stays within 20 D. Inside the zone the answer is within ~5 D of the truth,
// farthest from it at the zone's end (a power of two), where a check should look.
void find_first_contact_zones(Builder& builder, double upper_limit, int side) {
  const GridReference& reference = builder.reference;
  const double sign = side ? -1.0 : 1.0;
  double near[order_count], previous[order_count], moved[order_count], allowed[order_count];
  reference.log_values(sign * 2 * zero_zone, near);
  for (int k = 0; k < order_count; ++k) {
    const double closed_form = reference.next_to_zero[side][k];
    const double difference = std::max(std::fabs(near[k] - closed_form),
                                       builder.tolerance + 64 * 2.220446049250313e-16 * std::fabs(closed_form));
    const bool applies = std::isfinite(difference) && std::isfinite(closed_form) && (reference.order_mask >> k & 1u);
    allowed[k] = applies ? 2 * difference : 0;
    builder.first_contact_zone[k][side] = applies ? 4 * zero_zone : 0;
    previous[k] = near[k];
  }
  // The Weibull order 0 is its closed form ln J_0 = -s^a: held at its value at 2^-70 only while
  // s^a <= 2^-60 (J_0 to 1e-18), and followed from there on (fit_binade: to 1e-3 of s^a where s^a
  // is below the tolerance, so that it stays below 0 and falls). Held until it had moved by the
  // tolerance's width instead, it was off by s^a there: 5e-11 at a = 0.5, s = 2^-67; 2e-12 at
  // a = 3.54, s = 2^-11 (issue #28).
  const bool exact_zero = reference.exact_order_zero && allowed[orders::count] > 0;
  if (exact_zero) {
    allowed[orders::count] = 0;
    builder.first_contact_zone[orders::count][side] = zero_zone;  // no binade held ...
    for (double top = 2 * zero_zone; top <= std::min(upper_limit, 1.0); top *= 2) {  // ... but these
      reference.log_values(sign * top, moved);
      if (!(std::fabs(moved[orders::count]) <= 8.673617379884035e-19)) break;  // 2^-60
      builder.first_contact_zone[orders::count][side] = top;
    }
  }
  const double last = std::min(upper_limit, 1.0 / 1024);
  for (double top = 4 * zero_zone; top <= last; top *= 2) {
    reference.log_values(sign * top, moved);
    for (int k = 0; k < order_count; ++k) {
      if (allowed[k] == 0) continue;
      // ln X_n falls with s: down on s > 0, up on s < 0
      const double away = sign * (near[k] - moved[k]), step = sign * (previous[k] - moved[k]);
      const bool clear = away > allowed[k] && step >= 0;
      if (!clear && std::fabs(away) <= 10 * allowed[k]) builder.first_contact_zone[k][side] = 2 * top;
      previous[k] = moved[k];
    }
  }
}

void describe_grid(GridReference& reference, const CompactCurve& compact, double grid_min, double grid_max) {
  reference.order_mask = compact.order_mask();
  reference.table_min = compact.table_min();
  reference.table_max = compact.table_max();
  reference.grid_min = grid_min;
  reference.grid_max = grid_max;
  if (compact.side() == Side::bounded) {  // X_n -> 0 like d^(n+a): no value at 0 to meet
    for (auto& side : reference.next_to_zero) side.fill(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  const double inside_zero_zone = std::nextafter(zero_zone, 0.0);  // the compact curve's closed forms
  compact.log_values(inside_zero_zone, 0, order_count - 1, reference.next_to_zero[0].data());
  compact.log_values(-inside_zero_zone, 0, order_count - 1, reference.next_to_zero[1].data());
  reference.exact_order_zero = compact.distribution() == Distribution::weibull;
}

FastGridBuild build_fast_grid(const GridReference& reference, double tolerance, double far_factor) {
  if (!(tolerance > 0)) throw Error("the lookup grid's tolerance must be positive");
  if (!(far_factor >= 1 && far_factor <= 1e6)) throw Error("the lookup grid's far factor must lie in [1, 1e6]");
  Builder builder{reference, tolerance, far_factor * tolerance};
  for (int order = 0; order < order_count; ++order)
    if (reference.order_mask >> order & 1u) builder.orders[builder.held++] = order;

  FastGridBuild build;
  FastGrid& grid = build.grid;
  // entry 0: the batch passes' entry for a query off the grid (fast_grid.hpp)
  build.directory.push_back(FastBinade::make(0, 0));
  // Per held order, the intervals in the order they are made; coefficients gathered at the end.
  std::vector<std::vector<double>> per_order(builder.held);
  const double table_min = reference.table_min, table_max = reference.table_max;
  std::int64_t fitted = 0;  // intervals fitted, tries included
  for (int sign_bit = 0; sign_bit < 2; ++sign_bit) {
    const double sign = sign_bit ? -1.0 : 1.0;
    FastSide& side = grid.sides[sign_bit];
    // |s| covered on this side: the table's range cut to the asked range, never below 2^-70
    const double lo = std::max(table_min, reference.grid_min), hi = std::min(table_max, reference.grid_max);
    double lower, upper;
    if (sign_bit) {
      lower = std::max(zero_zone, -hi);
      upper = -lo;
    } else {
      lower = std::max(zero_zone, lo);
      upper = hi;
    }
    if (!(upper >= lower) || !std::isfinite(upper)) continue;  // not covered
    side.lower = lower;
    side.upper = upper;
    find_first_contact_zones(builder, upper, sign_bit);
    const int e_lo = biased_exponent(lower), e_hi = biased_exponent(upper);
    side.offset = static_cast<std::int32_t>(build.directory.size()) - e_lo;
    build.directory.resize(build.directory.size() + (e_hi - e_lo + 1));
    double knots = 1;
    std::vector<double> block;
    // From the top binade down: the knots a binade needs shrink toward s = 0.
    for (int e = e_hi; e >= e_lo; --e) {
      const double base = std::ldexp(1.0, e - 1023);
      const double from = std::max(lower, base), to = std::min(upper, 2 * base);
      knots = std::max(1.0, knots / 4);
      std::int64_t first = 0, last = 0;
      auto fit = [&](double knots_in_binade, bool dense = false) {  // the worst at the check points, relative
        first = static_cast<std::int64_t>(std::floor((from / base - 1) * knots_in_binade));
        last = std::min(static_cast<std::int64_t>(knots_in_binade) - 1,
                        static_cast<std::int64_t>(std::floor((to / base - 1) * knots_in_binade)));
        fitted += last - first + 1;
        if (fitted > largest_fitted_intervals) {
          std::ostringstream message;
          message << "the table's curve is not smooth near s = " << sign * from
                  << ": its lookup grid would take more than 2^17 intervals";
          throw Error(message.str());
        }
        return builder.fit_binade(sign, base, knots_in_binade, first, last, block, dense);
      };
      struct Try { double knots, worst; };
      std::vector<Try> tries;
      double worst;
      for (;;) {
        worst = fit(knots);
        tries.push_back({knots, worst});
        if (worst <= 1 || knots >= largest_knots_per_binade) break;
        if (tries.size() > 4 && !(worst * least_gain_over_four_doublings <= tries[tries.size() - 5].worst)) {
          // stalled: more knots bought nothing; the cheapest try within 1.5x of the best
          double best = worst;
          for (const Try& t : tries) best = std::min(best, t.worst);
          for (const Try& t : tries)
            if (t.worst <= 1.5 * best) {
              knots = t.knots;
              break;
            }
          worst = fit(knots, true);  // what it reports, from dense checks
          break;
        }
        knots *= 2;
      }
      builder.achieved = std::max(builder.achieved, worst * tolerance);
      const std::int64_t count = last - first + 1;
      build.directory[side.offset + e] = FastBinade::make(grid.intervals - first, std::ilogb(knots));
      grid.intervals += static_cast<std::int32_t>(count);
      for (int o = 0; o < builder.held; ++o)
        per_order[o].insert(per_order[o].end(), block.begin() + static_cast<std::ptrdiff_t>(o) * count * 6,
                            block.begin() + static_cast<std::ptrdiff_t>(o + 1) * count * 6);
    }
  }
  build.order_offset.fill(-1);
  for (int o = 0; o < builder.held; ++o) {
    build.order_offset[builder.orders[o]] = static_cast<std::int64_t>(build.coefficients.size());
    build.coefficients.insert(build.coefficients.end(), per_order[o].begin(), per_order[o].end());
  }
  build.achieved = builder.achieved;
  grid.directory = build.directory.empty() ? nullptr : build.directory.data();
  return build;
}

}  // namespace asperity::detail
