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
#include "asperity/detail/contact_kernel.hpp"
#include "asperity/detail/fast_math.hpp"

namespace asperity {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// One interval [u0, u0 + h]: t = (u - u0) / h. Its cubics are the Impl's record k.
struct Interval {
  double u0, u1, inverse_h;
};

// One cubic Hermite in t on an interval: ln X at its ends and its slopes d(ln X)/dt there.
struct HermiteCubic {
  double y0 = 0, y1 = 0, m0 = 0, m1 = 0;
};

// The served cubics of an interval are written as the contact kernel's record (kernels.hpp: rows
// of the coefficients of t^j, four lanes of log2 X), so that one call of the kernel (one 4-lane
// vector on x86: the polynomials and their exps at once, as contact_at's) gives every quantity
// of a query (faster than a cubic and a scalar exp per quantity: bench_lookup BM_LawCurvesForward,
// docs/contact-laws.md section 8). The kernel's outputs, in its order:
enum Output : int { compressive = 0, tensile = 1, area = 2, count = 3 };
// the record's lane that comes out as `output`
constexpr int record_lane(int output) noexcept {
  int lane = 0;
  while (detail::contact_lane_orders[lane] != output) ++lane;
  return lane;
}
constexpr int compressive_lane = record_lane(compressive), tensile_lane = record_lane(tensile);

// The Hermite cubic in the power basis, in log2 (each coefficient from the ln ones in long
// double, rounded once), into the record's lane
void write_cubic(const HermiteCubic& c, int output, double* record) noexcept {
  constexpr long double log2_e = 1.44269504088896340735992468100189214L;
  const long double y0 = c.y0, y1 = c.y1, m0 = c.m0, m1 = c.m1;
  const long double power[4] = {y0, m0, 3 * (y1 - y0) - 2 * m0 - m1, 2 * (y0 - y1) + m0 + m1};
  for (int j = 0; j < 4; ++j) record[4 * j + record_lane(output)] = static_cast<double>(log2_e * power[j]);
}
// A lane's cubic (log2 X) and its slope d(log2 X)/dt at t (Horner)
double record_cubic(const double* record, int lane, double t) noexcept {
  return record[lane] + t * (record[4 + lane] + t * (record[8 + lane] + t * record[12 + lane]));
}
double record_slope(const double* record, int lane, double t) noexcept {
  return record[4 + lane] + t * (2 * record[8 + lane] + 3 * t * record[12 + lane]);
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

// Steffen's slopes piece by piece: a break (a repeated separation, contact_curves_data.hpp) ends
// one piece and starts the next, each its own monotone cubic (a piece of two nodes: the secant)
std::vector<double> piecewise_steffen_slopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> slope(n, 0.0);
  std::size_t first = 0;
  for (std::size_t end = 1; end <= n; ++end) {
    if (end < n && x[end] != x[end - 1]) continue;
    const std::vector<double> px(x.begin() + first, x.begin() + end), py(y.begin() + first, y.begin() + end);
    if (px.size() == 2) {
      slope[first] = slope[first + 1] = (py[1] - py[0]) / (px[1] - px[0]);
    } else if (px.size() > 2) {
      const std::vector<double> piece = steffen_slopes(px, py);
      std::copy(piece.begin(), piece.end(), slope.begin() + first);
    }
    first = end;
  }
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
  std::vector<double> minus_log2_pressures;  // -log2 p at the nodes as the records hold them, ascending (the compressive part's)
  std::vector<Interval> intervals;
  std::vector<double> record_storage;         // the records, from a 64-byte boundary inside it
  const double* records = nullptr;
  detail::Contact4 contact4 = nullptr;
  std::size_t limited = 0;
  Directory by_separation, by_pressure;
  bool tension = false, count = false;
  // Adhesive curves: the stable branch served by the inverse runs from the first node to
  // stable_end (the pull-off, where the net stiffness crosses 0, or the last node); the net
  // pressures at the nodes before it and at it, negated (ascending), bracket an inverse.
  double stable_end = 0, pull_off_separation = nan, pull_off_pressure = nan;
  std::size_t stable_nodes = 0;            // nodes before stable_end
  std::vector<double> minus_net_pressures;  // stable_nodes + 1 values
  // How far past an end of the net pressures served the inverse still serves that end: a
  // pressure computed from them (min + (max - min) * 1) rounds up to an ulp of their span past
  // it, as the range straddles 0 Pa (a few ulp of the span, never a pressure the curves miss)
  double pressure_slack = 0;

  // The interval holding u (inside the range), and t in it.
  std::size_t locate(double u, double& t) const noexcept {
    const std::size_t k = by_separation.find(nodes, u);
    t = (u - intervals[k].u0) * intervals[k].inverse_h;
    return k;
  }
  const double* record(std::size_t k) const noexcept { return records + k * detail::contact_record_size; }
  // Every quantity's value at t in interval k (the kernel's outputs)
  void values_at(std::size_t k, double t, double values[4]) const noexcept {
    double log2s[4];
    contact4(record(k), t, log2s, values);
  }
  // -dX/du of a part (compressive or tensile) from its value X at t: -X ln 2 d(log2 X)/dt / h
  double part_stiffness(std::size_t k, int lane, double t, double value) const noexcept {
    return -value * detail::ln_2 * record_slope(record(k), lane, t) * intervals[k].inverse_h;
  }
  bool served(double u) const noexcept { return u >= nodes.front() && u <= nodes.back(); }
  // exp(ln p) within the stored end pressures: at the end nodes rounding could put it a hair
  // outside the pressures served, which the inverse would refuse
  double clamped(double p) const noexcept { return std::min(std::max(p, data.pressure.back()), data.pressure.front()); }
  double clamped_tension(double p) const noexcept {
    return std::min(std::max(p, data.tensile_pressure.back()), data.tensile_pressure.front());
  }
  // The served net pressure and stiffness in interval k at t from the kernel's values there
  // (the compressive part alone without tension). `gross`: the parts' sum, the scale of the
  // net's rounding.
  void net(std::size_t k, double t, const double values[4], double& pressure, double& stiffness,
           double* gross = nullptr) const noexcept {
    const double p = values[compressive];
    pressure = clamped(p);
    stiffness = part_stiffness(k, compressive_lane, t, p);
    if (gross) *gross = pressure;
    if (!tension) return;
    const double q = values[tensile];
    pressure -= clamped_tension(q);
    stiffness -= part_stiffness(k, tensile_lane, t, q);
    if (gross) *gross += clamped_tension(q);
  }
  void net_at(double u, double& pressure, double& stiffness) const noexcept {
    double t, values[4];
    const std::size_t k = locate(u, t);
    values_at(k, t, values);
    net(k, t, values, pressure, stiffness);
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
    pressure_slack = 4 * std::numeric_limits<double>::epsilon() * (minus_net_pressures.back() - minus_net_pressures.front());
  }
};

ContactCurves::ContactCurves(ContactCurvesData data) {
  data.validate("contact curves");
  auto impl = std::make_shared<Impl>();
  const std::size_t n = data.separation.size(), count = n - 1;
  impl->nodes = data.separation;
  impl->tension = data.has_tension();
  impl->count = !data.summit_count.empty();
  std::vector<double> log_pressure(n), log_area(n), log_count(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    log_pressure[i] = std::log(data.pressure[i]);
    log_area[i] = std::log(data.area_fraction[i]);
    if (impl->count) log_count[i] = std::log(data.summit_count[i]);
  }
  const std::vector<double> area_slopes = piecewise_steffen_slopes(impl->nodes, log_area);
  const std::vector<double> count_slopes = piecewise_steffen_slopes(impl->nodes, log_count);
  constexpr std::size_t line = 64 / sizeof(double);  // room to start on a cache line (the kernel's aligned loads)
  impl->record_storage.assign(count * detail::contact_record_size + line, 0.0);
  double* records = impl->record_storage.data();
  while (reinterpret_cast<std::uintptr_t>(records) % 64 != 0) ++records;
  for (std::size_t i = 0; i < count; ++i) {
    const double h = impl->nodes[i + 1] - impl->nodes[i];
    double* record = records + i * detail::contact_record_size;
    if (h == 0) {
      // a break: never located (the directory finds the piece on its right); constant cubics of
      // the node's values, so that its record's pressure is the node's like every record's
      impl->intervals.push_back({impl->nodes[i], impl->nodes[i + 1], 0});
      write_cubic({log_pressure[i], log_pressure[i]}, compressive, record);
      if (impl->tension) {
        const double q = std::log(data.tensile_pressure[i]);
        write_cubic({q, q}, tensile, record);
      }
      write_cubic({log_area[i], log_area[i]}, area, record);
      write_cubic({log_count[i], log_count[i]}, Output::count, record);
      impl->minus_log2_pressures.push_back(-record[compressive_lane]);
      continue;
    }
    impl->intervals.push_back({impl->nodes[i], impl->nodes[i + 1], 1 / h});
    // ln p with the nodes' own slopes, -k/p, times h (limited to stay monotone)
    HermiteCubic pressure{log_pressure[i], log_pressure[i + 1]};
    if (monotone_log_slopes(h, pressure.y0, pressure.y1, data.pressure[i], data.pressure[i + 1], data.stiffness[i],
                            data.stiffness[i + 1], pressure.m0, pressure.m1))
      ++impl->limited;
    write_cubic(pressure, compressive, record);
    // without tension its lane is 0 (2^0 = 1: a value the kernel's fast path takes, never served)
    HermiteCubic tension;
    if (impl->tension) {
      tension = {std::log(data.tensile_pressure[i]), std::log(data.tensile_pressure[i + 1])};
      if (monotone_log_slopes(h, tension.y0, tension.y1, data.tensile_pressure[i], data.tensile_pressure[i + 1],
                              data.tensile_stiffness[i], data.tensile_stiffness[i + 1], tension.m0, tension.m1))
        ++impl->limited;
    }
    write_cubic(tension, tensile, record);
    write_cubic({log_area[i], log_area[i + 1], area_slopes[i] * h, area_slopes[i + 1] * h}, area, record);
    write_cubic({log_count[i], log_count[i + 1], count_slopes[i] * h, count_slopes[i + 1] * h}, Output::count, record);
    impl->minus_log2_pressures.push_back(-record[compressive_lane]);
  }
  // the last node's, rounded as the records' constant terms are
  constexpr long double log2_e = 1.44269504088896340735992468100189214L;
  impl->minus_log2_pressures.push_back(-static_cast<double>(log2_e * static_cast<long double>(log_pressure[n - 1])));
  impl->records = records;
  impl->contact4 = detail::best_contact4();
  impl->by_separation.build(impl->nodes);
  impl->by_pressure.build(impl->minus_log2_pressures);
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
  return at_separation(separation).pressure;
}

double ContactCurves::stiffness(double separation) const noexcept {
  return at_separation(separation).stiffness;
}

double ContactCurves::area_fraction(double separation) const noexcept {
  return at_separation(separation).area_fraction;
}

ContactCurvesState ContactCurves::tensile_part(double separation) const noexcept {
  const Impl& impl = *impl_;
  if (!impl.served(separation)) return {separation, nan, nan, nan};
  if (!impl.tension) return {separation, 0, 0, nan};
  double t, values[4];
  const std::size_t k = impl.locate(separation, t);
  impl.values_at(k, t, values);
  const double q = values[tensile];
  return {separation, impl.clamped_tension(q), impl.part_stiffness(k, tensile_lane, t, q), nan};
}

double ContactCurves::summit_count(double separation) const noexcept {
  const Impl& impl = *impl_;
  if (!impl.count || !impl.served(separation)) return nan;
  double t, values[4];
  const std::size_t k = impl.locate(separation, t);  // before t is read
  impl.values_at(k, t, values);
  return values[Output::count];
}

ContactCurvesRow ContactCurves::row(const ContactCurvesState& state) const noexcept {
  return {state.separation, state.separation - data().mean_summit_height, state.pressure, state.stiffness,
          state.area_fraction, summit_count(state.separation)};
}

bool ContactCurves::counts_summits() const noexcept { return impl_->count; }

ContactCurvesState ContactCurves::at_separation(double separation) const noexcept {
  const Impl& impl = *impl_;
  if (!impl.served(separation)) return {separation, nan, nan, nan};
  double t, values[4];
  const std::size_t k = impl.locate(separation, t);
  impl.values_at(k, t, values);
  ContactCurvesState state{separation, 0, 0, values[area]};
  impl.net(k, t, values, state.pressure, state.stiffness);
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
  double values[4];
  double t = p_lo > p_hi ? lo + (hi - lo) * (p_lo - pressure) / (p_lo - p_hi) : 0.5 * (lo + hi);
  if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 100; ++iteration) {
    double p, k, gross;
    impl.values_at(index, t, values);
    impl.net(index, t, values, p, k, &gross);
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
    if (!(-pressure >= keys.front() - impl.pressure_slack && -pressure <= keys.back() + impl.pressure_slack))
      return nan;
    if (-pressure < keys.front()) return impl.nodes.front();  // within the slack past max_pressure()
    if (keys.size() == 1 || -pressure >= keys.back()) return impl.stable_end;  // or within the slack past it
    std::size_t k = static_cast<std::size_t>(std::upper_bound(keys.begin(), keys.end(), -pressure) - keys.begin());
    k = k == 0 ? 0 : std::min(k - 1, keys.size() - 2);
    if (-pressure == keys[k]) return k < impl.stable_nodes ? impl.nodes[k] : impl.stable_end;
    const double lo = impl.nodes[k], hi = k + 1 < impl.stable_nodes ? impl.nodes[k + 1] : impl.stable_end;
    return solve_net(impl, k, pressure, lo, hi, -keys[k], -keys[k + 1]);
  }
  if (!(pressure >= impl.data.pressure.back() && pressure <= impl.data.pressure.front())) return nan;
  const double y = std::log2(pressure);
  // the interval whose log2 p brackets y (log2 p descends along the nodes)
  const std::size_t k = impl.by_pressure.find(impl.minus_log2_pressures, -y);
  const Interval& i = impl.intervals[k];
  const double* record = impl.record(k);
  const double y0 = -impl.minus_log2_pressures[k], y1 = -impl.minus_log2_pressures[k + 1];
  if (y >= y0) return i.u0;
  if (y <= y1) return i.u1;
  // Newton on the monotone cubic (the record's, as served), kept inside the bracket [lo, hi] by bisection
  double lo = 0, hi = 1, t = (y - y0) / (y1 - y0);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double f = record_cubic(record, compressive_lane, t) - y;  // falls with t
    if (f > 0) lo = t;
    else if (f < 0) hi = t;
    else break;
    const double slope = record_slope(record, compressive_lane, t);
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
