#include "asperity/generator/law_curves.hpp"

#include <boost/math/policies/error_handling.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <algorithm>
#include <cmath>
#include <exception>
#include <new>
#include <stdexcept>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <sstream>
#include <vector>

#include "asperity/contact_curves.hpp"
#include "asperity/contact_law_registry.hpp"
#include "asperity/error.hpp"
#include "asperity/integrals.hpp"
#include "asperity/interrupt.hpp"
#include "asperity/number_text.hpp"
#include "asperity/plausibility.hpp"
#include "asperity/detail/parallel_for.hpp"
#include "asperity/detail/table_schema.hpp"

namespace asperity::generator {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double quadrature_tolerance = 1e-13;
// The integrand beyond exp(-60) of its start is dropped (below 1e-26 of the integral)
constexpr double density_cutoff = 60;
constexpr int max_nodes = 8192;
constexpr double min_interval = 1e-9;  // of the separation range
constexpr double safety_factor = 2;
// Where each interval is checked: its midpoint (where a cubic Hermite interpolant's error peaks)
// and 1/2 -+ 1/(2 sqrt 3) (where its derivative's does: the served stiffness is the derivative
// of the ln p interpolant, whose error vanishes at the midpoint to leading order)
constexpr double check_fractions[] = {0.21132486540518713, 0.5, 0.78867513459481287};

double density(const SceneLaw& law, double z) {
  if (law.distribution == Distribution::gaussian) return std::exp(-0.5 * z * z) / std::sqrt(2 * pi);
  if (!(z > 0)) return 0;
  const double a = law.shape, t = std::pow(z, a);
  return a * t / z * std::exp(-t);
}

// The heights z a piece is cut at: the density's mass from the lower end `from` outward
// (Weibull: in t = z^a, where its mass lies; Gaussian: in units of its decay length)
void mass_cuts(const SceneLaw& law, double from, std::vector<double>& cuts) {
  static const double steps[] = {1e-3, 1e-2, 0.1, 0.3, 1, 2, 4, 8, 16, 32};
  if (law.distribution == Distribution::gaussian) {
    for (int z = -8; z <= 8; ++z) cuts.push_back(z);
    const double length = 1 / std::max(from, 1.0);
    for (double step : steps) cuts.push_back(from + step * length);
    return;
  }
  const double a = law.shape, t0 = from > 0 ? std::pow(from, a) : 0;
  for (double step : steps) {
    cuts.push_back(std::pow(step, 1 / a));
    cuts.push_back(std::pow(t0 + step, 1 / a));
  }
}

// The ranges the laws' curves are computed over (checked at their corners, docs/reliability.md):
// E* as plausibility.hpp's, H/E* and Y/E* (below, omega_c = R (pi K H / 2 E*)^2 underflows; the
// laws' formulas divide by it), Maugis' lambda (beyond, Maugis-Dugdale is JKR: --law jkr)
constexpr double material_ratio_min = 1e-6, material_ratio_max = 10;
constexpr double maugis_parameter_max = 1e6;

// The inputs of a law scene a failed quadrature points at: each parameter outside the range
// above, with its value and that range; where none is, every parameter of the law and surface.
std::string law_inputs_at_fault(const SceneLaw& scene) {
  const ContactLaw& law = scene.law;
  std::ostringstream out;
  const auto outside = [&](const std::string& what, double value, const char* unit, double lo, double hi,
                           const std::string& note = "") {
    if (value >= lo && value <= hi) return;
    const std::string units = *unit ? std::string(" ") + unit : "";
    out << (out.tellp() > 0 ? "; " : "") << what << " " << value << units << " is outside " << lo << " to " << hi
        << units << note;
  };
  const double modulus = law.modulus;
  outside("the contact modulus E*", modulus, "Pa", plausible_contact_modulus.min, plausible_contact_modulus.max);
  const ContactLawDescriptor* descriptor = find_contact_law(law.kind);
  for (int k = 0; descriptor && k < descriptor->parameter_count; ++k) {
    // a strength set against E* (below, omega_c underflows; the laws' formulas divide by it)
    const LawParameterInfo& p = law_parameter_info(descriptor->parameters[k].parameter);
    if (!p.strength) continue;
    const double material = law_parameter_value(law, p.id);
    const std::string meaning = p.meaning;  // "hardness H [Pa]": the name without its unit
    outside("the " + meaning.substr(0, meaning.find(" [")), material, p.unit, material_ratio_min * modulus, material_ratio_max * modulus,
            std::string(" (") + p.symbol + "/E* " + format_double(material_ratio_min) + " to " +
                format_double(material_ratio_max) + " with E* " + format_double(modulus) + " Pa)");
    if (!(law.critical_interference > 0))
      out << (out.tellp() > 0 ? "; " : "") << "the critical interference omega_c it gives is "
          << law.critical_interference << " m (the law divides by it)";
  }
  if (descriptor && law_parameter_use(*descriptor, LawParameter::maugis_parameter))
    outside("Maugis' parameter lambda", law.maugis_parameter, "", 0, maugis_parameter_max,
            " (beyond, Maugis-Dugdale is JKR: law jkr)");
  outside("the height scale sigma_s", scene.height_scale, "m", plausible_height_scale.min, plausible_height_scale.max);
  outside("the summit radius R", scene.summit_radius, "m", plausible_summit_radius.min, plausible_summit_radius.max);
  if (out.tellp() > 0) return out.str();
  out << "none of its inputs is outside the ranges tested (E* " << plausible_contact_modulus.min << " to "
      << plausible_contact_modulus.max << " Pa, H/E* and Y/E* " << material_ratio_min << " to " << material_ratio_max
      << ", sigma_s and R plausible): the law's parameters are E* " << modulus << " Pa";
  if (descriptor && descriptor->parameter_count > 0) out << ", " << law_parameters_text(law);
  out << ", sigma_s " << scene.height_scale << " m, R " << scene.summit_radius << " m";
  return out.str();
}

// A failure inside Boost.Math (or an allocation) while the law's means at s are integrated,
// as an Error naming the law, s, what failed and the inputs at fault. Called in a catch block.
[[noreturn]] void throw_law_failure(const SceneLaw& scene, double s) {
  std::string what;
  try {
    throw;
  } catch (const std::bad_alloc&) {
    what = "memory ran out";
  } catch (const boost::math::evaluation_error&) {
    what = "the quadrature over the summit heights met a law response that is not a finite number";
  } catch (const std::domain_error&) {
    what = "a function of the law was evaluated outside its domain";
  } catch (const std::overflow_error&) {
    what = "a value of the law overflowed";
  } catch (const std::exception& error) {
    what = error.what();
  }
  std::ostringstream message;
  message << (scene.name.empty() ? std::string("the law") : "law '" + scene.name + "'") << " ("
          << contact_law_name(scene.law.kind) << "): its curves cannot be computed at s = " << s << ": " << what
          << ": " << law_inputs_at_fault(scene);
  throw Error(message.str());
}

using Integrator = boost::math::quadrature::tanh_sinh<double>;
LawMeans integrate_law_means(const SceneLaw& scene, double s, Integrator& finite);

// Boost.Math's errors (and an allocation's) named by the law's inputs; asperity::Error (and
// Interrupted) as they are
LawMeans checked_law_means(const SceneLaw& scene, double s, Integrator& finite) {
  try {
    return integrate_law_means(scene, s, finite);
  } catch (const Error&) {
    throw;
  } catch (...) {
    throw_law_failure(scene, s);
  }
}

}  // namespace

double withdrawal_kink(const SceneLaw& law) noexcept {
  if (!law.withdrawal()) return std::numeric_limits<double>::quiet_NaN();
  return law.approach_separation - law.law.lowest_interference / law.height_scale;
}

LawMeans law_means(const SceneLaw& scene, double s) {
  Integrator finite;  // its abscissae: a few hundred microseconds (the generator keeps a pool)
  return checked_law_means(scene, s, finite);
}

namespace {
// Where the summits in contact at s end, in the height z (before the density's support clips
// it): on the tail side those above it, on the bounded side those below. Approach: first contact,
// omega = 0. Withdrawal after an approach to s0 (SceneLaw::approach_separation): the summits that
// touched at s0 and have not reached their law's lowest interference omega_min; `detaching` where
// that end is omega_min (s >= s0 - omega_min / sigma_s: it moves with s), not the fixed z of s0.
double contact_edge(const SceneLaw& scene, double s, bool& detaching) {
  const bool tail = scene.side == Side::tail;
  detaching = false;
  if (!scene.withdrawal()) return tail ? s : -s;
  const double s0 = scene.approach_separation, omega_min = scene.law.lowest_interference;
  detaching = s >= withdrawal_kink(scene);
  const double attached = omega_min / scene.height_scale;  // z - s on the tail side at omega_min
  return tail ? std::max(s0, s + attached) : std::min(-s0, -s - attached);
}

// Beyond the interference its source supports (Jackson-Green: a = R) the law is not used: the
// summits there must be negligible (their share of the count below 1e-3 of the tolerance;
// their load share is within a power of the interference of that). Narrows [lo, hi] to them.
void clip_to_validity(const SceneLaw& scene, double s, double z_valid, double& lo, double& hi) {
  const bool tail = scene.side == Side::tail, weibull = scene.distribution == Distribution::weibull;
  const bool beyond = tail ? z_valid < hi : z_valid > lo;  // tail: above it; bounded: below it
  if (!beyond) return;
  auto survival = [&](double z) {  // the density's mass above z
    return weibull ? std::exp(-std::pow(std::max(z, 0.0), scene.shape)) : 0.5 * std::erfc(z / std::sqrt(2.0));
  };
  const double total = tail ? survival(lo) : 1 - survival(hi);
  const double share = tail ? survival(z_valid) / total : (1 - survival(z_valid)) / total;
  if (!(share < 1e-3 * scene.max_rel_error)) {
    std::ostringstream message;
    message << contact_law_name(scene.law.kind) << ": at s = " << s << " a share " << share
            << " of the summits in contact is beyond the interference its source supports (" << scene.law.valid_up_to
            << " m): narrow the separation range";
    throw Error(message.str());
  }
  (tail ? hi : lo) = z_valid;
}

// The stiffness a load jump at a moving height adds (docs/contact-laws.md section 8): where the
// law switches (omega_k), and an adhesive law's edge of contact: first contact on approach (its
// load jumps there from 0), the detaching edge on withdrawal (its load at omega_min drops to 0;
// kept apart in `out` too, for the break at the kink)
void add_jumps(const SceneLaw& scene, double s, double lo, double hi, bool detaching, double& compressive_stiffness,
               LawMeans& out) {
  const ContactLaw& law = scene.law;
  const double sigma = scene.height_scale;
  const bool tail = scene.side == Side::tail;
  auto z_of = [&](double omega) { return tail ? s + omega / sigma : -s - omega / sigma; };
  const double inf = std::numeric_limits<double>::infinity();
  const SwitchPoints points = switch_points(law);
  for (int k = 0; k < points.count; ++k) {
    const double omega = points.interference[k], z = z_of(omega);
    if (!(z > lo && z < hi)) continue;
    if (scene.withdrawal() && omega <= law.lowest_interference) continue;  // the edge's, below
    const AsperityLoadSplit above = asperity_load_split(law, std::nextafter(omega, inf));
    const AsperityLoadSplit below = asperity_load_split(law, std::nextafter(omega, -inf));
    compressive_stiffness += (above.compressive - below.compressive) * density(scene, z) / sigma;
    out.tensile_stiffness += (above.tensile - below.tensile) * density(scene, z) / sigma;
  }
  if (!is_adhesive(law.kind) || (scene.withdrawal() && !detaching)) return;
  const double omega = scene.withdrawal() ? law.lowest_interference : 0.0, z = z_of(omega);
  if (!(z >= lo && z <= hi)) return;
  const AsperityLoadSplit edge = asperity_load_split(law, omega);
  const double compressive = edge.compressive * density(scene, z) / sigma;
  const double tensile = edge.tensile * density(scene, z) / sigma;
  compressive_stiffness += compressive;
  out.tensile_stiffness += tensile;
  if (scene.withdrawal()) out.detach_compressive_stiffness = compressive, out.detach_tensile_stiffness = tensile;
}

LawMeans integrate_law_means(const SceneLaw& scene, double s, Integrator& finite) {
  const ContactLaw& law = scene.law;
  const double sigma = scene.height_scale;
  const bool tail = scene.side == Side::tail;
  const bool weibull = scene.distribution == Distribution::weibull;
  const bool withdrawal = scene.withdrawal();
  // interference at height z, and the height of interference omega
  auto omega_of = [&](double z) { return sigma * (tail ? z - s : -s - z); };
  auto z_of = [&](double omega) { return tail ? s + omega / sigma : -s - omega / sigma; };
  bool detaching = false;
  const double edge = contact_edge(scene, s, detaching);
  double lo, hi;
  if (tail) {
    lo = weibull ? std::max(edge, 0.0) : edge;
    const double t_lo = weibull ? std::pow(std::max(lo, 0.0), scene.shape) : 0.5 * lo * lo * (lo > 0);
    hi = weibull ? std::pow(t_lo + density_cutoff, 1 / scene.shape) : std::sqrt(2 * (t_lo + density_cutoff));
    hi = std::max(hi, lo + 1e-3);
  } else {
    lo = 0;
    hi = edge;
  }
  LawMeans out;
  if (!(hi > lo)) return out;
  if (std::isfinite(law.valid_up_to)) {
    clip_to_validity(scene, s, z_of(law.valid_up_to), lo, hi);
    if (!(hi > lo)) return out;
  }
  std::vector<double> cuts{lo, hi};
  const SwitchPoints points = switch_points(law);
  for (int k = 0; k < points.count; ++k) cuts.push_back(z_of(points.interference[k]));
  if (withdrawal) cuts.push_back(z_of(0.0));  // first contact: negative interferences on one side
  mass_cuts(scene, lo, cuts);
  cuts.erase(std::remove_if(cuts.begin(), cuts.end(), [&](double z) { return !(z >= lo && z <= hi); }), cuts.end());
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  // Withdrawal: the interference from a piece's end plus the distance to it, given exactly (the
  // detaching edge's is omega_min itself), never at or below omega_min, where JKR's dP/domega is
  // -inf and the response 0 one double below: the stiffness's (omega - omega_min)^(-1/2) there
  // is integrated from its exact distance
  const double omega_min = law.lowest_interference;
  const double above_min = std::nextafter(omega_min, std::numeric_limits<double>::infinity());
  const double direction = tail ? 1 : -1;
  auto end_omega = [&](double z) { return detaching && z == edge ? omega_min : omega_of(z); };
  auto density_slope = [&](double z) {  // d phi / dz
    if (!weibull) return -z * density(scene, z);
    const double phi = density(scene, z), a = scene.shape;
    return phi == 0 ? 0.0 : phi * ((a - 1) / z - a * std::pow(z, a - 1));
  };
  // `load`, given (a stiffness: quantity = d load / d omega), takes the edge's piece by parts
  auto integrate_parts = [&](auto quantity, auto load, bool by_parts) {
    double total = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      poll_interrupt();  // a quadrature of an adhesive law's response takes milliseconds
      const double a = cuts[i], b = cuts[i + 1];
      if (!(b > a)) continue;
      const double omega_a = end_omega(a), omega_b = end_omega(b);
      if (withdrawal && (tail ? a == edge : b == edge)) {
        // the piece at the contact's edge in x = v^2 from it: the law's (omega - omega_min)^(1/2)
        // there (JKR, MD at a turning point) becomes smooth in v. A stiffness by parts,
        // (1/(sigma dz/domega-sign)) ([X phi] - int X phi' dz): its (omega - omega_min)^(-1/2) is
        // solved from omega where D is flat in t, to about half the digits (MD at lambda = 3: no
        // quadrature converged on it), the load X is not
        const double omega_edge = tail ? omega_a : omega_b;
        const double integral = finite.integrate(
            [&](double v, double) {
              const double x = v * v, z = tail ? a + x : b - x;
              const double phi = by_parts ? density_slope(z) : density(scene, z);
              const double w = std::max(omega_edge + sigma * x, above_min);
              return phi == 0 ? 0.0 : (by_parts ? load(w) : quantity(w)) * phi * 2 * v;
            },
            0.0, std::sqrt(b - a), quadrature_tolerance);
        if (!by_parts) {
          total += integral;
        } else {
          // at omega_min exactly the law gives its branch end's state (in contact)
          const double ends = load(std::max(omega_b, omega_min)) * density(scene, b) -
                              load(std::max(omega_a, omega_min)) * density(scene, a);
          total += direction / sigma * (ends - integral);
        }
        continue;
      }
      // x from a; the complement from b given exactly, so that an end's distance is exact
      total += finite.integrate(
          [&](double x, double complement) {
            const bool near_a = x < 0.5 * (b - a);
            const double z = near_a ? a + x : b - complement;
            const double phi = density(scene, z);
            if (phi == 0) return 0.0;
            if (!withdrawal) return quantity(omega_of(z)) * phi;
            const double omega = near_a ? omega_a + direction * sigma * x : omega_b - direction * sigma * complement;
            return quantity(std::max(omega, above_min)) * phi;
          },
          0.0, b - a, quadrature_tolerance);
    }
    return total;
  };
  auto integrate = [&](auto quantity) { return integrate_parts(quantity, quantity, false); };
  // the fraction in contact in closed form (the quadrature's rounding could make it rise where
  // it is 1 to rounding): Gaussian z >= edge; Weibull tail z >= max(edge, 0); bounded z <= edge
  if (!weibull) out.count = 0.5 * std::erfc(edge / std::sqrt(2.0));
  else if (tail) out.count = std::exp(-std::pow(std::max(edge, 0.0), scene.shape));
  else out.count = -std::expm1(-std::pow(std::max(edge, 0.0), scene.shape));
  double compressive = 0, compressive_stiffness = 0;
  if (is_adhesive(law.kind)) {
    // An adhesive law's response solves for its state (Maugis-Dugdale: a root per interference):
    // each interference's is kept, so the five integrals, whose quadratures visit the same
    // abscissae, solve it once
    struct Split {
      double area;
      AsperityLoadSplit load;
    };
    std::unordered_map<double, Split> solved;
    const auto split = [&](double omega) -> const Split& {
      auto found = solved.find(omega);
      if (found == solved.end())
        found = solved.emplace(omega, Split{asperity_response(law, omega).area, asperity_load_split(law, omega)}).first;
      return found->second;
    };
    out.area = integrate([&](double omega) { return split(omega).area; });
    compressive = integrate([&](double omega) { return split(omega).load.compressive; });
    out.tensile_load = integrate([&](double omega) { return split(omega).load.tensile; });
    compressive_stiffness = integrate_parts([&](double omega) { return split(omega).load.compressive_stiffness; },
                                            [&](double omega) { return split(omega).load.compressive; }, withdrawal);
    out.tensile_stiffness = integrate_parts([&](double omega) { return split(omega).load.tensile_stiffness; },
                                            [&](double omega) { return split(omega).load.tensile; }, withdrawal);
  } else {
    out.area = integrate([&](double omega) { return asperity_response(law, omega).area; });
    compressive = integrate([&](double omega) { return asperity_response(law, omega).load; });
    compressive_stiffness = integrate([&](double omega) { return asperity_response(law, omega).stiffness; });
  }
  add_jumps(scene, s, lo, hi, detaching, compressive_stiffness, out);
  out.load = compressive - out.tensile_load;
  out.stiffness = compressive_stiffness - out.tensile_stiffness;
  return out;
}
}  // namespace

namespace {

// The exact means at separations s, computed once each (law_means). compute(wanted) computes those
// not yet known on the machine's threads (an s a job: the results do not depend on the threads), in
// chunks; a failure is the lowest s's, as one thread would meet it. Given per_interval (a pass's
// check points: that many an interval, in order), progress is reported between the chunks.
class ExactMeans {
 public:
  ExactMeans(const SceneLaw& law, const std::function<void(const LawCurvesProgress&)>& progress)
      : law_(law), progress_(progress) {}
  const LawMeans& at(double s) {
    auto found = means_.find(s);
    if (found == means_.end()) found = means_.emplace(s, means_at(s)).first;
    return found->second;
  }
  std::size_t size() const { return means_.size(); }
  void next_pass(std::size_t nodes) { ++pass_, nodes_ = nodes; }
  void compute(std::vector<double> wanted, std::size_t per_interval = 0) {
    wanted.erase(std::remove_if(wanted.begin(), wanted.end(), [&](double s) { return means_.count(s) > 0; }),
                 wanted.end());
    std::sort(wanted.begin(), wanted.end());
    wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
    const std::size_t chunk = 64;
    for (std::size_t first = 0; first < wanted.size(); first += chunk) {
      const std::size_t count = std::min(chunk, wanted.size() - first);
      std::vector<LawMeans> means(count);
      std::vector<std::exception_ptr> failures(count);
      detail::parallel_for(count, 0, [&](std::size_t i) {
        try {
          means[i] = means_at(wanted[first + i]);
        } catch (const Interrupted&) {
          throw;
        } catch (...) {
          failures[i] = std::current_exception();
        }
      });
      for (std::size_t i = 0; i < count; ++i) {
        if (failures[i]) std::rethrow_exception(failures[i]);
        means_.emplace(wanted[first + i], means[i]);
      }
      if (progress_ && per_interval > 0 && nodes_ > 1) {
        const std::size_t intervals = nodes_ - 1, done = (first + count) / per_interval;
        progress_({pass_, static_cast<int>(nodes_), static_cast<int>(std::clamp<std::size_t>(done, 1, intervals)),
                   static_cast<int>(intervals), static_cast<int>(means_.size())});
      }
    }
  }

 private:
  // The means at s with an integrator of the pool (made once each, one per thread at a time: not
  // thread_local, whose destructors at a worker's exit ThreadSanitizer cannot order with glibc's
  // reuse of the thread's TLS block)
  LawMeans means_at(double s) {
    std::unique_ptr<Integrator> integrator;
    {
      std::lock_guard<std::mutex> lock(pool_mutex_);
      if (!pool_.empty()) integrator = std::move(pool_.back()), pool_.pop_back();
    }
    if (!integrator) integrator = std::make_unique<Integrator>();
    struct Return {  // the integrator back to the pool, also when the means throw
      ExactMeans& owner;
      std::unique_ptr<Integrator>& integrator;
      ~Return() {
        std::lock_guard<std::mutex> lock(owner.pool_mutex_);
        owner.pool_.push_back(std::move(integrator));
      }
    } back{*this, integrator};
    return checked_law_means(law_, s, *integrator);
  }

  const SceneLaw& law_;
  const std::function<void(const LawCurvesProgress&)>& progress_;
  std::mutex pool_mutex_;
  std::vector<std::unique_ptr<Integrator>> pool_;
  std::map<double, LawMeans> means_;  // by s
  int pass_ = 0;
  std::size_t nodes_ = 0;
};

// The first nodes: uniform, and knots where the integrals are not smooth (a Weibull density's edge)
std::vector<double> starting_nodes(const SceneLaw& law) {
  const double sigma = law.height_scale;
  std::vector<double> nodes;
  const int uniform = 9;
  for (int i = 0; i + 1 < uniform; ++i)
    nodes.push_back(law.range_min + (law.range_max - law.range_min) * i / (uniform - 1));
  nodes.push_back(law.range_max);  // exactly: the range's end is served
  std::vector<double> knots;
  if (law.distribution == Distribution::weibull) {
    knots.push_back(0.0);
    const SwitchPoints points = switch_points(law.law);
    for (int k = 0; k < points.count; ++k) knots.push_back(-points.interference[k] / sigma);
    // withdrawal: where the detaching edge (omega_min) meets the density's edge z = 0
    if (law.withdrawal()) knots.push_back(-law.law.lowest_interference / sigma);
  }
  // withdrawal: the kink, where summits start to detach (the stiffness jumps: a break)
  if (law.withdrawal()) knots.push_back(withdrawal_kink(law));
  for (double knot : knots)
    if (knot > law.range_min && knot < law.range_max) nodes.push_back(knot);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

// Why the curves are singular near s, for the refusal: the knot nearest s, where the Weibull
// density's edge (z^(a-1) there) meets first contact or the law's switch point omega_k (a load
// or a slope that jumps at omega_k). A jump J in the asperity's load there puts J phi(z_k) / sigma_s
// into the stiffness, z_k the edge's distance, linear in s: a power |s - s_k|^(a-1), unbounded for
// a < 1, a jump at a = 1 (the density's edge is 1 there), with an infinite slope for a < 2, which
// no cubic Hermite interval resolves. The text ends with what may be done: at a load jump with
// a <= 1 no tolerance helps (the stiffness is unbounded, or jumps by a share no cubic follows).
std::string singular_point(const SceneLaw& law, double s) {
  std::ostringstream text;
  text.precision(6);
  const double kink = withdrawal_kink(law);
  if (law.withdrawal() && std::fabs(s - kink) < 1e-6 * (law.range_max - law.range_min)) {
    text << "at s = " << kink << " the withdrawal's kink, where summits start to leave at the law's lowest "
         << "interference (the stiffness jumps there, and varies as (s_k - s)^(1/2) on its left); exclude it from "
            "the separation range or ask a larger tolerance";
    return text.str();
  }
  if (law.distribution != Distribution::weibull) {
    text << "the curves have a singular point there; exclude it from the separation range or ask a larger tolerance";
    return text.str();
  }
  double knot = 0;  // first contact at the density's edge
  int nearest = -1;
  const SwitchPoints points = switch_points(law.law);
  for (int k = 0; k < points.count; ++k) {
    const double at = -points.interference[k] / law.height_scale;
    if (std::fabs(at - s) < std::fabs(knot - s)) knot = at, nearest = k;
  }
  text << "at s = " << knot << " the Weibull density's edge, where it behaves as z^(a-1) with a = " << law.shape
       << ", meets ";
  bool load_jumps = nearest < 0 && is_adhesive(law.law.kind) && !law.withdrawal();
  if (nearest < 0) {
    text << "first contact" << (load_jumps ? ", where each summit's load jumps from 0 (adhesion)" : "");
  } else {
    const double omega = points.interference[nearest], inf = std::numeric_limits<double>::infinity();
    const double above = asperity_response(law.law, std::nextafter(omega, inf)).load;
    const double below = asperity_response(law.law, std::nextafter(omega, -inf)).load;
    load_jumps = std::fabs(above - below) > 1e-9 * std::max(std::fabs(above), std::fabs(below));
    text << "the law's switch point omega_" << nearest + 1 << " = " << omega << " m (s = -omega / sigma_s), where its "
         << (load_jumps ? "load" : "slope") << " jumps";
  }
  text << ": the curves vary as a power of |s - " << knot << "| there";
  if (load_jumps && law.shape < 1)
    text << ", the stiffness unbounded (a load jump on a density that is infinite at its edge): no tolerance "
            "resolves it; exclude it from the separation range";
  else if (load_jumps && law.shape == 1)
    text << ", the stiffness jumping (a load jump on the density's edge value 1): a tolerance resolves it only "
            "above the jump's share of the stiffness; exclude it from the separation range";
  else
    text << "; exclude it from the separation range or ask a larger tolerance";
  return text.str();
}

// The curves' provenance and conventions: generator, source, description, datum, scales
void describe(const SceneLaw& law, const std::string& generator_options, ContactCurvesData& data) {
  const double sigma = law.height_scale, eta = law.summit_density;
  data.generator = std::string("asperity ") + ASPERITY_VERSION_STRING + " tablegen";
  data.generator_options = generator_options;
  data.source = std::string("contact-law ") + contact_law_name(law.law.kind);
  {
    std::ostringstream text;  // numbers in shortest round-trip form (0.3, not 0.29999999999999999)
    const auto n = [](double value) { return format_double(value); };
    const ContactLaw& l = law.law;
    text << contact_law_name(l.kind) << ": E* = " << n(l.modulus) << " Pa";
    if (find_contact_law(l.kind)->parameter_count > 0) text << ", " << law_parameters_text(l);
    if (is_adhesive(l.kind))
      text << ", length scale d_s = " << n(l.critical_interference) << " m";
    else if (std::isfinite(l.critical_interference))
      text << ", omega_c = " << n(l.critical_interference) << " m";
    text << "; summits " << to_string(law.distribution);
    if (law.distribution == Distribution::weibull)
      text << " a = " << n(law.shape) << " " << to_string(law.side) << " side";
    text << ", sigma_s = " << n(sigma) << " m, R = " << n(law.summit_radius) << " m, density = " << n(eta)
         << " /m^2, A0 = " << n(law.nominal_area) << " m^2; separations s in [" << n(law.range_min) << ", "
         << n(law.range_max) << "] (dimensionless)";
    if (is_adhesive(l.kind) && law.withdrawal()) {
      text << "; the withdrawal (unloading, fixed grips) branch after an approach to s0 = " << n(law.approach_separation)
           << ": a summit that touched at s0 stays in contact down to its law's lowest interference omega_min = "
           << n(l.lowest_interference) << " m";
      if (l.lowest_interference < 0)
        text << ", from s = s0 - omega_min / sigma_s = " << n(withdrawal_kink(law))
             << " on leaving there (the stiffness jumps: a break of the curves)";
      else
        text << " (0: the same curves as the approach branch)";
      text << " (pressure = compressive - tensile part, negative: tension; the stored pressure and stiffness bounds "
              "are relative to the gross, compressive + tensile)";
    } else if (is_adhesive(l.kind)) {
      text << "; the approach (loading) branch: a summit touches at omega = 0 and follows its law's stable branch "
              "(pressure = compressive - tensile part, negative: tension; the stored pressure and stiffness bounds "
              "are relative to the gross, compressive + tensile)";
    }
    if (!law.name.empty()) text << "; scene law '" << law.name << "'";
    data.description = text.str();
  }
  data.separation_datum = law.distribution == Distribution::gaussian
                              ? "the mean summit height"
                              : law.side == Side::tail ? "the Weibull origin (the lowest summit)"
                                                       : "the Weibull origin (the highest summit)";
  data.solver_tolerance = quadrature_tolerance;
  data.safety_factor = safety_factor;
  data.contact_modulus = law.law.modulus;
  data.nominal_area = law.nominal_area;
  // the branch as asked (DMT's withdrawal too, whose curves are its approach's): stated in the table
  if (is_adhesive(law.law.kind) && law.withdrawal()) data.approach_separation = sigma * law.approach_separation;
  if (law.distribution == Distribution::gaussian) {
    data.mean_summit_height = 0;
  } else {
    data.mean_summit_height = (law.side == Side::tail ? 1 : -1) * sigma * weibull_mean(law.shape);
    if (law.side == Side::bounded) data.max_height = 0;
  }
}

}  // namespace

namespace {

// The table's nodes from the exact means at the nodes s (adhesive laws: `pressure` and `stiffness`
// hold the compressive parts, the tensile ones their own). At a withdrawal's kink, a break: the
// node twice, the stiffness from the left (without the detaching edge's share) then the right.
template <typename At>
void fill_nodes(const SceneLaw& law, const std::vector<double>& nodes, double kink, At&& at, ContactCurvesData& data) {
  const double sigma = law.height_scale, eta = law.summit_density;
  const std::string name = law.name.empty() ? std::string("the law") : "law '" + law.name + "'";
  const bool adhesive = is_adhesive(law.law.kind);
  for (auto* column : {&data.separation, &data.pressure, &data.stiffness, &data.area_fraction, &data.tensile_pressure,
                       &data.tensile_stiffness, &data.summit_count})
    column->clear();
  for (double s : nodes) {
    const LawMeans& m = at(s);
    const double pressure = eta * (m.load + m.tensile_load), area_fraction = eta * m.area;
    if (!(area_fraction <= 1)) {
      std::ostringstream message;
      message << name << ": the real area fraction reaches " << area_fraction << " at s = " << s
              << ": beyond 1 Greenwood-Williamson does not hold; raise the separation range's lower end";
      throw Error(message.str());
    }
    if (!(pressure >= schema::min_contact_value) || (adhesive && !(eta * m.tensile_load >= schema::min_contact_value))) {
      std::ostringstream message;
      message << name << ": the pressure" << (adhesive ? " (or its tensile part)" : "") << " falls to " << pressure
              << " Pa at s = " << s
              << ", below what a contact-curves table holds (1e-150 Pa); lower the separation range's upper end";
      throw Error(message.str());
    }
    const double compressive_stiffness = m.stiffness + m.tensile_stiffness;
    for (int side = s == kink ? 0 : 1; side < 2; ++side) {  // the break: left (0), then right (1)
      data.separation.push_back(sigma * s);
      data.pressure.push_back(pressure);
      data.stiffness.push_back(eta * (compressive_stiffness - (side == 0 ? m.detach_compressive_stiffness : 0)));
      data.area_fraction.push_back(area_fraction);
      if (adhesive) {
        data.tensile_pressure.push_back(eta * m.tensile_load);
        data.tensile_stiffness.push_back(eta * (m.tensile_stiffness - (side == 0 ? m.detach_tensile_stiffness : 0)));
      }
      data.summit_count.push_back(eta * m.count);
    }
  }
}

}  // namespace

LawCurvesResult generate_law_curves(const SceneLaw& asked, const std::string& generator_options,
                                    const std::function<void(const LawCurvesProgress&)>& progress) {
  // DMT's lowest interference is 0: its withdrawal is its approach (tabulated as such, described as asked)
  SceneLaw law = asked;
  if (law.withdrawal() && !(law.law.lowest_interference < 0)) law.approach_separation = std::numeric_limits<double>::quiet_NaN();
  const double sigma = law.height_scale, eta = law.summit_density;
  const double tolerance = law.max_rel_error;
  const std::string name = law.name.empty() ? std::string("the law") : "law '" + law.name + "'";
  ExactMeans exact(law, progress);
  const auto at = [&](double s) -> const LawMeans& { return exact.at(s); };
  std::vector<double> nodes = starting_nodes(law);
  // withdrawal: the kink's stiffness jumps (a break); from its left the stiffness varies as
  // sqrt(kink - s) (the summits at s0 near omega_min, where dP/domega ~ (omega - omega_min)^(-1/2)):
  // the interval ending there is halved down to the smallest interval and its error stored, not refused
  const double kink = law.withdrawal() && withdrawal_kink(law) > law.range_min && withdrawal_kink(law) < law.range_max
                          ? withdrawal_kink(law)
                          : std::numeric_limits<double>::quiet_NaN();

  LawCurvesResult result;
  ContactCurvesData& data = result.data;
  describe(asked, generator_options, data);

  const bool adhesive = is_adhesive(law.law.kind);
  int checks = 0, pass = 0;
  for (;;) {
    ++pass;
    exact.next_pass(nodes.size());
    exact.compute(nodes);
    fill_nodes(law, nodes, kink, at, data);
    const ContactCurves curves(data);
    std::vector<double> halves;
    // pressure, stiffness, area, count. With a tensile part (adhesion) the served net pressure
    // and stiffness and each part are measured relative to the gross (compressive + tensile):
    // relative to the net, meaningless where it crosses 0; relative to a part, unreachable where
    // that part is a rounding of the other (DMT's tension where every summit touches already)
    double worst[4] = {0, 0, 0, 0};
    checks = 0;
    {
      std::vector<double> points;
      for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
        for (double fraction : check_fractions) points.push_back(nodes[i] + fraction * (nodes[i + 1] - nodes[i]));
      exact.compute(std::move(points), std::size(check_fractions));
    }
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
      const double h = nodes[i + 1] - nodes[i];
      const bool smallest = h < min_interval * (law.range_max - law.range_min);
      const bool cusp = smallest && nodes[i + 1] == kink;  // its error stored (above)
      bool split = false;
      double errors[4] = {0, 0, 0, 0};
      for (double fraction : check_fractions) {
        const double s = nodes[i] + fraction * h;
        const LawMeans& m = at(s);
        const double u = sigma * s;
        const ContactCurvesState served = curves.at_separation(u);
        const double count = curves.summit_count(u);
        // the compressive part as served: the net plus the tensile part
        double served_tension = 0, served_tension_stiffness = 0;
        if (adhesive) {
          const ContactCurvesState part = curves.tensile_part(u);
          served_tension = part.pressure;
          served_tension_stiffness = part.stiffness;
        }
        struct Check {
          int bound;
          double value, truth, scale;
        };
        const double pc = eta * (m.load + m.tensile_load), pt = eta * m.tensile_load;
        const double kc = eta * (m.stiffness + m.tensile_stiffness), kt = eta * m.tensile_stiffness;
        const double gross_p = pc + pt, gross_k = std::fabs(kc) + std::fabs(kt);
        const Check list[] = {
            {0, served.pressure, pc - pt, gross_p},
            {0, served.pressure + served_tension, pc, gross_p},
            {0, served_tension, pt, gross_p},
            {1, served.stiffness, kc - kt, gross_k},
            {1, served.stiffness + served_tension_stiffness, kc, gross_k},
            {1, served_tension_stiffness, kt, gross_k},
            {2, served.area_fraction, eta * m.area, eta * m.area},
            {3, count, eta * m.count, eta * m.count},
        };
        for (const Check& c : list) {
          const double error = std::fabs(c.value - c.truth) / c.scale;
          // the count is measured and its bound stored, but does not place nodes: ln count has an
          // infinite slope at first contact on a Weibull density with a < 1 (-s^a), where the
          // pressure, stiffness and area are tabulable
          if (!(c.bound == 3 || error <= 0.5 * tolerance)) split = true;
          errors[c.bound] = std::max(errors[c.bound], std::isnan(error) ? HUGE_VAL : error);
        }
        ++checks;
      }
      if (split && cusp) split = false;
      if (split && smallest) {
        std::ostringstream message;
        message << name << ": the curves are not smooth enough near s = " << nodes[i]
                << " to be tabulated to max_rel_error " << tolerance << " (intervals of 1e-9 of the range still miss it: "
                << singular_point(law, nodes[i]) << ")";
        throw Error(message.str());
      }
      if (split) halves.push_back(nodes[i] + 0.5 * h);
      else
        for (int k = 0; k < 4; ++k) worst[k] = std::max(worst[k], errors[k]);
      if (progress)
        progress({pass, static_cast<int>(nodes.size()), static_cast<int>(i + 1), static_cast<int>(nodes.size() - 1),
                  static_cast<int>(exact.size())});
    }
    if (halves.empty()) {
      for (int k = 0; k < 3; ++k) {
        data.measured_rel_error[k] = worst[k];
        data.max_rel_error[k] = worst[k] * safety_factor;
      }
      data.summit_count_max_rel_error = worst[3] * safety_factor;
      data.check_points = checks;
      data.bound_method = ContactBoundMethod::checks_split_to_tolerance;
      break;
    }
    nodes.insert(nodes.end(), halves.begin(), halves.end());
    std::sort(nodes.begin(), nodes.end());
    if (nodes.size() > static_cast<std::size_t>(max_nodes)) {
      std::ostringstream message;
      message << name << ": more than " << max_nodes << " nodes would be needed for max_rel_error " << tolerance
              << " (ask a larger tolerance or a narrower range)";
      throw Error(message.str());
    }
  }
  data.validate("law curves");
  result.nodes = static_cast<int>(data.separation.size());
  result.evaluations = static_cast<int>(exact.size());
  return result;
}

}  // namespace asperity::generator
