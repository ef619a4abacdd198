// ContactCurves: the interpolants of a contact-curves table (contact_curves.hpp) built once, and
// the lookups that never allocate or throw.
#include "asperity/contact_curves.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "asperity/error.hpp"

namespace asperity {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// One interval [u0, u0 + h] of both cubic Hermites in t = (u - u0) / h: values at its ends and
// slopes times h.
struct Interval {
  double u0, u1, inverse_h;
  double y0, y1, m0, m1;  // ln p
  double a0, a1, b0, b1;  // ln(area fraction)
  double z0, z1, n0, n1;  // ln p_t, the tensile part (adhesive curves; else unused)
  double c0, c1, d0, d1;  // ln(summit count) (where stored; else unused)
};

double hermite(double t, double y0, double y1, double m0, double m1) noexcept {
  const double s = 1 - t;
  return s * s * ((1 + 2 * t) * y0 + t * m0) + t * t * ((3 - 2 * t) * y1 - s * m1);
}
// d/dt of hermite()
double hermite_slope(double t, double y0, double y1, double m0, double m1) noexcept {
  return 6 * t * (t - 1) * (y0 - y1) + (1 - t) * (1 - 3 * t) * m0 + t * (3 * t - 2) * m1;
}

double sign(double x) { return x > 0 ? 1.0 : x < 0 ? -1.0 : 0.0; }

// The Hermite slopes (times h) of a falling ln p between y0 and y1 from the nodes' stiffness
// k0, k1 and pressure p0, p1 (d ln p/du = -k/p), limited to keep the cubic monotone
// (Fritsch-Carlson: alpha^2 + beta^2 <= 9, alpha, beta the end slopes over the secant, both
// >= 0 here: p falls and k > 0). True where limited.
bool monotone_log_slopes(double h, double y0, double y1, double p0, double p1, double k0, double k1, double& m0,
                         double& m1) {
  m0 = -k0 / p0 * h;
  m1 = -k1 / p1 * h;
  const double secant = y1 - y0;  // < 0, or 0 where two pressures a few ulp apart share a log
  const double alpha = m0 / secant, beta = m1 / secant, radius = alpha * alpha + beta * beta;
  if (!(secant < 0)) {
    m0 = m1 = 0;  // flat: the one monotone cubic between equal values
    return true;
  }
  if (radius > 9) {
    const double tau = 3 / std::sqrt(radius);
    m0 = tau * alpha * secant;
    m1 = tau * beta * secant;
    return true;
  }
  return false;
}

// Steffen's (1990) slopes of a monotone cubic through (x, y): never an overshoot.
std::vector<double> steffen_slopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> h(n - 1), s(n - 1), slope(n);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = x[i + 1] - x[i];
    s[i] = (y[i + 1] - y[i]) / h[i];
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double p = (s[i - 1] * h[i] + s[i] * h[i - 1]) / (h[i - 1] + h[i]);
    slope[i] = (sign(s[i - 1]) + sign(s[i])) * std::min({std::fabs(s[i - 1]), std::fabs(s[i]), 0.5 * std::fabs(p)});
  }
  const auto end = [](double s0, double s1, double h0, double h1) {
    const double p = s0 * (1 + h0 / (h0 + h1)) - s1 * h0 / (h0 + h1);
    if (p * s0 <= 0) return 0.0;
    if (std::fabs(p) > 2 * std::fabs(s0)) return 2 * s0;
    return p;
  };
  slope[0] = end(s[0], s[1], h[0], h[1]);
  slope[n - 1] = end(s[n - 2], s[n - 3], h[n - 2], h[n - 3]);  // n >= 3 (validated)
  return slope;
}

// Equal bins over ascending keys (the nodes' separations, or their -ln p): bin b starts in the
// interval holding its left edge, so a query searches only the intervals its bin overlaps (one
// or two for keys about evenly spread, four bins an interval; a bisection among them otherwise).
class Directory {
 public:
  void build(const std::vector<double>& keys) {
    const std::size_t n = keys.size(), bins = 4 * (n - 1);
    low_ = keys.front();
    const double span = keys.back() - low_;
    scale_ = static_cast<double>(bins) / span;  // inf or NaN for a degenerate span: find() then bisects
    entries_.resize(bins + 1);
    std::size_t interval = 0;
    for (std::size_t b = 0; b <= bins; ++b) {
      const double edge = b == bins ? keys.back() : low_ + span * static_cast<double>(b) / static_cast<double>(bins);
      while (interval + 1 < n - 1 && keys[interval + 1] <= edge) ++interval;
      entries_[b] = static_cast<std::uint32_t>(interval);
    }
  }
  // The interval i (0 to keys.size() - 2) with keys[i] <= x < keys[i + 1] (the last: <=), for x
  // in [keys.front(), keys.back()].
  std::size_t find(const std::vector<double>& keys, double x) const noexcept {
    const std::size_t bins = entries_.size() - 1, intervals = keys.size() - 1;
    const double position = (x - low_) * scale_;
    const std::size_t b = position < static_cast<double>(bins) ? static_cast<std::size_t>(position) : bins - 1;
    const std::size_t first = entries_[b], last = entries_[b + 1];
    std::size_t i = first;
    if (last > first)
      i = static_cast<std::size_t>(std::upper_bound(keys.begin() + first + 1, keys.begin() + last + 1, x) -
                                   keys.begin()) - 1;
    // where rounding put x in a neighbouring bin (or the span is degenerate): the whole search
    if (!(x >= keys[i] && (x < keys[i + 1] || i + 1 == intervals))) {
      i = static_cast<std::size_t>(std::upper_bound(keys.begin(), keys.end(), x) - keys.begin());
      i = i == 0 ? 0 : std::min(i - 1, intervals - 1);
    }
    return i;
  }

 private:
  std::vector<std::uint32_t> entries_;  // bins + 1
  double low_ = 0, scale_ = 0;
};

}  // namespace

struct ContactCurves::Impl {
  ContactCurvesData data;
  std::vector<double> nodes;          // separations
  std::vector<double> minus_log_pressures;  // -ln p at the nodes, ascending (the compressive part's)
  std::vector<Interval> intervals;
  std::size_t limited = 0;
  Directory by_separation, by_pressure;
  bool tension = false, count = false;
  // Adhesive curves: the stable branch served by the inverse runs from the first node to
  // stable_end (the pull-off, where the net stiffness crosses 0, or the last node); the net
  // pressures at the nodes before it and at it, negated (ascending), bracket an inverse.
  double stable_end = 0, pull_off_separation = nan, pull_off_pressure = nan;
  std::size_t stable_nodes = 0;            // nodes before stable_end
  std::vector<double> minus_net_pressures;  // stable_nodes + 1 values

  // The interval holding u (inside the range), and t in it.
  const Interval& locate(double u, double& t) const noexcept {
    const Interval& interval = intervals[by_separation.find(nodes, u)];
    t = (u - interval.u0) * interval.inverse_h;
    return interval;
  }
  bool served(double u) const noexcept { return u >= nodes.front() && u <= nodes.back(); }
  // exp(ln p) within the stored end pressures: at the end nodes rounding could put it a hair
  // outside the pressures served, which the inverse would refuse
  double clamped(double p) const noexcept { return std::min(std::max(p, data.pressure.back()), data.pressure.front()); }
  double clamped_tension(double p) const noexcept {
    return std::min(std::max(p, data.tensile_pressure.back()), data.tensile_pressure.front());
  }
  // The served net pressure and stiffness in interval i at t (the compressive part alone without tension).
  // `gross`: the parts' sum, the scale of the net's rounding.
  void net(const Interval& i, double t, double& pressure, double& stiffness, double* gross = nullptr) const noexcept {
    const double p = std::exp(hermite(t, i.y0, i.y1, i.m0, i.m1));
    pressure = clamped(p);
    stiffness = -p * hermite_slope(t, i.y0, i.y1, i.m0, i.m1) * i.inverse_h;
    if (gross) *gross = pressure;
    if (!tension) return;
    const double q = std::exp(hermite(t, i.z0, i.z1, i.n0, i.n1));
    pressure -= clamped_tension(q);
    stiffness += q * hermite_slope(t, i.z0, i.z1, i.n0, i.n1) * i.inverse_h;
    if (gross) *gross += clamped_tension(q);
  }
  void net_at(double u, double& pressure, double& stiffness) const noexcept {
    double t;
    const Interval& i = locate(u, t);
    net(i, t, pressure, stiffness);
  }

  // Where the net stiffness first turns <= 0 from the first node: the pull-off (greatest tension)
  void find_pull_off() {
    stable_end = nodes.back();
    stable_nodes = nodes.size() - 1;
    if (!tension) return;
    const std::size_t n = nodes.size();
    std::size_t crossing = n;
    for (std::size_t k = 0; k < n; ++k)
      if (!(data.stiffness[k] - data.tensile_stiffness[k] > 0)) {
        crossing = k;
        break;
      }
    if (crossing == 0) {
      stable_end = nodes.front();  // the curves start beyond the pull-off: no stable branch in them
      stable_nodes = 0;
    } else if (crossing < n) {
      // the served net stiffness falls through 0 in [nodes[crossing - 1], nodes[crossing]]: bisection
      double lo = nodes[crossing - 1], hi = nodes[crossing];
      for (int iteration = 0; iteration < 200 && hi - lo > 0; ++iteration) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        double p, k;
        net_at(mid, p, k);
        (k > 0 ? lo : hi) = mid;
      }
      stable_end = lo;
      stable_nodes = crossing;  // nodes 0 .. crossing - 1 lie before it
      double k;
      net_at(stable_end, pull_off_pressure, k);
      pull_off_separation = stable_end;
    }
    for (std::size_t k = 0; k < stable_nodes; ++k) {
      double p, stiffness;
      net_at(nodes[k], p, stiffness);
      minus_net_pressures.push_back(-p);
    }
    double p, stiffness;
    net_at(stable_end, p, stiffness);
    minus_net_pressures.push_back(-p);
    // The inverse needs the net pressure not to rise along the branch: a table whose stored
    // stiffnesses disagree with its pressures (never one the generator wrote) has its stable
    // branch end at the last node before the net pressure stops falling, and no pull-off
    for (std::size_t k = 1; k < minus_net_pressures.size(); ++k)
      if (!(minus_net_pressures[k] >= minus_net_pressures[k - 1])) {
        stable_nodes = k - 1;
        stable_end = nodes[k - 1];
        minus_net_pressures.resize(k);
        pull_off_separation = pull_off_pressure = nan;
        break;
      }
  }
};

ContactCurves::ContactCurves(ContactCurvesData data) {
  data.validate("contact curves");
  auto impl = std::make_shared<Impl>();
  const std::size_t n = data.separation.size();
  impl->nodes = data.separation;
  impl->tension = data.has_tension();
  impl->count = !data.summit_count.empty();
  std::vector<double> log_area(n), log_count(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    impl->minus_log_pressures.push_back(-std::log(data.pressure[i]));
    log_area[i] = std::log(data.area_fraction[i]);
    if (impl->count) log_count[i] = std::log(data.summit_count[i]);
  }
  const std::vector<double> area_slopes = steffen_slopes(impl->nodes, log_area);
  const std::vector<double> count_slopes = steffen_slopes(impl->nodes, log_count);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double h = impl->nodes[i + 1] - impl->nodes[i];
    Interval interval{};
    interval.u0 = impl->nodes[i];
    interval.u1 = impl->nodes[i + 1];
    interval.inverse_h = 1 / h;
    interval.y0 = -impl->minus_log_pressures[i];
    interval.y1 = -impl->minus_log_pressures[i + 1];
    // the nodes' own slopes of ln p, -k/p, times h
    if (monotone_log_slopes(h, interval.y0, interval.y1, data.pressure[i], data.pressure[i + 1], data.stiffness[i],
                            data.stiffness[i + 1], interval.m0, interval.m1))
      ++impl->limited;
    interval.a0 = log_area[i];
    interval.a1 = log_area[i + 1];
    interval.b0 = area_slopes[i] * h;
    interval.b1 = area_slopes[i + 1] * h;
    if (impl->tension) {
      interval.z0 = std::log(data.tensile_pressure[i]);
      interval.z1 = std::log(data.tensile_pressure[i + 1]);
      if (monotone_log_slopes(h, interval.z0, interval.z1, data.tensile_pressure[i], data.tensile_pressure[i + 1],
                              data.tensile_stiffness[i], data.tensile_stiffness[i + 1], interval.n0, interval.n1))
        ++impl->limited;
    }
    interval.c0 = log_count[i];
    interval.c1 = log_count[i + 1];
    interval.d0 = count_slopes[i] * h;
    interval.d1 = count_slopes[i + 1] * h;
    impl->intervals.push_back(interval);
  }
  impl->by_separation.build(impl->nodes);
  impl->by_pressure.build(impl->minus_log_pressures);
  impl->data = std::move(data);
  impl->find_pull_off();
  impl_ = std::move(impl);
}

ContactCurves ContactCurves::open(const std::string& path) { return ContactCurves(read_contact_curves_file(path)); }

const ContactCurvesData& ContactCurves::data() const noexcept { return impl_->data; }
double ContactCurves::min_separation() const noexcept { return impl_->nodes.front(); }
double ContactCurves::max_separation() const noexcept { return impl_->nodes.back(); }
double ContactCurves::min_pressure() const noexcept {
  return impl_->tension ? -impl_->minus_net_pressures.back() : impl_->data.pressure.back();
}
double ContactCurves::max_pressure() const noexcept {
  return impl_->tension ? -impl_->minus_net_pressures.front() : impl_->data.pressure.front();
}
std::size_t ContactCurves::limited_intervals() const noexcept { return impl_->limited; }
bool ContactCurves::has_tension() const noexcept { return impl_->tension; }
double ContactCurves::stable_branch_end() const noexcept { return impl_->stable_end; }
double ContactCurves::pull_off_separation() const noexcept { return impl_->pull_off_separation; }
double ContactCurves::pull_off_pressure() const noexcept { return impl_->pull_off_pressure; }

double ContactCurves::pressure(double separation) const noexcept {
  if (!impl_->served(separation)) return nan;
  double t;
  const Interval& i = impl_->locate(separation, t);
  if (impl_->tension) {
    double p, k;
    impl_->net(i, t, p, k);
    return p;
  }
  return impl_->clamped(std::exp(hermite(t, i.y0, i.y1, i.m0, i.m1)));
}

double ContactCurves::stiffness(double separation) const noexcept {
  if (!impl_->served(separation)) return nan;
  double t;
  const Interval& i = impl_->locate(separation, t);
  if (impl_->tension) {
    double p, k;
    impl_->net(i, t, p, k);
    return k;
  }
  return -std::exp(hermite(t, i.y0, i.y1, i.m0, i.m1)) * hermite_slope(t, i.y0, i.y1, i.m0, i.m1) * i.inverse_h;
}

double ContactCurves::area_fraction(double separation) const noexcept {
  if (!impl_->served(separation)) return nan;
  double t;
  const Interval& i = impl_->locate(separation, t);
  return std::exp(hermite(t, i.a0, i.a1, i.b0, i.b1));
}

ContactCurvesState ContactCurves::tensile_part(double separation) const noexcept {
  if (!impl_->served(separation)) return {separation, nan, nan, nan};
  if (!impl_->tension) return {separation, 0, 0, nan};
  double t;
  const Interval& i = impl_->locate(separation, t);
  const double q = std::exp(hermite(t, i.z0, i.z1, i.n0, i.n1));
  return {separation, impl_->clamped_tension(q), -q * hermite_slope(t, i.z0, i.z1, i.n0, i.n1) * i.inverse_h, nan};
}

double ContactCurves::summit_count(double separation) const noexcept {
  if (!impl_->count || !impl_->served(separation)) return nan;
  double t;
  const Interval& i = impl_->locate(separation, t);
  return std::exp(hermite(t, i.c0, i.c1, i.d0, i.d1));
}

ContactCurvesState ContactCurves::at_separation(double separation) const noexcept {
  if (!impl_->served(separation)) return {separation, nan, nan, nan};
  double t;
  const Interval& i = impl_->locate(separation, t);
  ContactCurvesState state{separation, 0, 0, std::exp(hermite(t, i.a0, i.a1, i.b0, i.b1))};
  impl_->net(i, t, state.pressure, state.stiffness);
  return state;
}

namespace {
// The separation in [lo, hi] (inside interval `index`) where the served net pressure is
// `pressure`; it falls from `p_lo` at lo to `p_hi` at hi on the stable branch. Newton in the
// interval's t from the secant's guess, kept inside the bracket by bisection.
double solve_net(const ContactCurves::Impl& impl, std::size_t index, double pressure, double lo_u, double hi_u,
                 double p_lo, double p_hi) noexcept {
  const Interval& i = impl.intervals[index];
  double lo = std::max(0.0, (lo_u - i.u0) * i.inverse_h), hi = std::min(1.0, (hi_u - i.u0) * i.inverse_h);
  double t = p_lo > p_hi ? lo + (hi - lo) * (p_lo - pressure) / (p_lo - p_hi) : 0.5 * (lo + hi);
  if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 100; ++iteration) {
    double p, k, gross;
    impl.net(i, t, p, k, &gross);
    const double f = p - pressure;  // falls with t
    // within rounding of the parts (the net is their difference: its own digits end there)
    if (std::fabs(f) <= 4e-16 * gross) break;
    if (f > 0) lo = t;
    else if (f < 0) hi = t;
    else break;
    // dp/dt = -k h
    double next = k > 0 ? t + f * i.inverse_h / k : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - t) <= 1e-16 || hi - lo <= 1e-16) {
      t = next;
      break;
    }
    t = next;
  }
  return std::min(std::max(i.u0 + t / i.inverse_h, lo_u), hi_u);
}
}  // namespace

double ContactCurves::separation_at_pressure(double pressure) const noexcept {
  const Impl& impl = *impl_;
  if (impl.tension) {
    // the stable branch: the first node to stable_end, where the net pressure falls
    const std::vector<double>& keys = impl.minus_net_pressures;
    if (!(-pressure >= keys.front() && -pressure <= keys.back())) return nan;
    if (keys.size() == 1 || -pressure == keys.back()) return impl.stable_end;
    std::size_t k = static_cast<std::size_t>(std::upper_bound(keys.begin(), keys.end(), -pressure) - keys.begin());
    k = k == 0 ? 0 : std::min(k - 1, keys.size() - 2);
    if (-pressure == keys[k]) return k < impl.stable_nodes ? impl.nodes[k] : impl.stable_end;
    const double lo = impl.nodes[k], hi = k + 1 < impl.stable_nodes ? impl.nodes[k + 1] : impl.stable_end;
    return solve_net(impl, k, pressure, lo, hi, -keys[k], -keys[k + 1]);
  }
  if (!(pressure >= impl.data.pressure.back() && pressure <= impl.data.pressure.front())) return nan;
  const double y = std::log(pressure);
  // the interval whose ln p brackets y (ln p descends along the nodes)
  const Interval& i = impl.intervals[impl.by_pressure.find(impl.minus_log_pressures, -y)];
  if (y >= i.y0) return i.u0;
  if (y <= i.y1) return i.u1;
  // Newton on the monotone cubic, kept inside the bracket [lo, hi] by bisection
  double lo = 0, hi = 1, t = (y - i.y0) / (i.y1 - i.y0);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double f = hermite(t, i.y0, i.y1, i.m0, i.m1) - y;  // falls with t
    if (f > 0) lo = t;
    else if (f < 0) hi = t;
    else break;
    const double slope = hermite_slope(t, i.y0, i.y1, i.m0, i.m1);
    double next = slope < 0 ? t - f / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - t) <= 1e-16 || hi - lo <= 1e-16) {
      t = next;
      break;
    }
    t = next;
  }
  return std::min(i.u0 + t / i.inverse_h, i.u1);  // t < 1, but its rounding must not pass the node
}

ContactCurvesState ContactCurves::at_pressure(double pressure) const noexcept {
  const double u = separation_at_pressure(pressure);
  if (std::isnan(u)) return {nan, nan, nan, nan};
  ContactCurvesState state = at_separation(u);
  state.pressure = pressure;  // what was asked; the curve gives it back to a few ulp
  return state;
}

}  // namespace asperity
