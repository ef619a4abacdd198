#include "asperity/contact_model.hpp"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "asperity/error.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace asperity {
namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
}  // namespace

const char* contact_quantity_name(ContactQuantity quantity) noexcept {
  switch (quantity) {
    case ContactQuantity::count: return "count";
    case ContactQuantity::real_area: return "real-area";
    case ContactQuantity::area_fraction: return "area-fraction";
    case ContactQuantity::load: return "load";
    case ContactQuantity::pressure: return "pressure";
    case ContactQuantity::stiffness: break;
  }
  return "stiffness";
}

bool parse_contact_quantity(const std::string& name, ContactQuantity& quantity) noexcept {
  // the command's spelling ("real-area") or the record's field ("real_area"): one quantity
  const auto same = [&name](const char* spelling) noexcept {
    std::size_t k = 0;
    for (; spelling[k] && k < name.size(); ++k)
      if (name[k] != spelling[k] && !(name[k] == '_' && spelling[k] == '-')) return false;
    return !spelling[k] && k == name.size();
  };
  for (int k = 0; k < contact_quantity_count; ++k)
    if (same(contact_quantity_name(static_cast<ContactQuantity>(k)))) {
      quantity = static_cast<ContactQuantity>(k);
      return true;
    }
  return false;
}

ContactModel::ContactModel(const Table& table, const RoughSurface& surface, SeparationDatum datum,
                           double mean_summit_height)
    : surface_(surface), datum_(datum), mean_summit_height_(mean_summit_height) {
  surface_.validate();
  datum_offset_ = separation_datum_position(surface_, datum_, mean_summit_height_) / surface_.height_scale;
  curve_ = table.curve(surface_.distribution, surface_.side, surface_.shape, contact_order_mask);
  load_inverse_ = InverseCurve(curve_, orders::load);
  area_inverse_ = InverseCurve(curve_, orders::area);
  scales_ = contact_scales({surface_.summit_count(), surface_.summit_radius, surface_.height_scale,
                            surface_.contact_modulus});
  if (surface_.distribution == Distribution::weibull)
    mean_offset_ = (surface_.side == Side::bounded ? -1 : 1) * weibull_mean(surface_.shape);
}

PhysicalState ContactModel::no_contact() const noexcept {
  PhysicalState state{};
  const bool bounded = surface_.side == Side::bounded;
  state.separation = bounded ? physical(0.0) : std::numeric_limits<double>::infinity();
  state.mean_separation = bounded ? -mean_offset_ * surface_.height_scale : state.separation;
  state.stiffness_over_load = nan;
  return state;
}

PhysicalState ContactModel::infinite_contact() const noexcept {
  const double inf = std::numeric_limits<double>::infinity();
  PhysicalState state{};
  state.separation = state.mean_separation = -inf;
  state.count = scales_.count;
  state.real_area = state.area_fraction = state.load = state.pressure = state.stiffness = inf;
  state.stiffness_over_load = 0;  // (3/2) X_1/2 / X_3/2 ~ (3/2)/|s| as s -> -inf
  return state;
}

PhysicalState ContactModel::state_at_dimensionless(double s) const noexcept {
  if (!curve_.has_order(orders::load)) return PhysicalState{nan, nan, nan, nan, nan, nan, nan, nan, nan};
  if (std::isnan(s)) return PhysicalState{nan, nan, nan, nan, nan, nan, nan, nan, nan};
  if (s == -std::numeric_limits<double>::infinity()) return infinite_contact();
  if (s == std::numeric_limits<double>::infinity() || (surface_.side == Side::bounded && s >= 0)) return no_contact();
  // contact_at's computation: one kernel call where it applies, else the logs and values
  ContactState contact;
  if (!curve_.contact_products(s, scales_.count, scales_.area, scales_.load, scales_.stiffness, &contact.count)) {
    double logs[4], values[4];
    curve_.contact_orders(s, logs, values);
    contact = contact_state_from_logs(scales_, logs, values);
  }
  const double sigma = surface_.height_scale;
  PhysicalState state;
  state.separation = physical(s);
  state.mean_separation = (s - mean_offset_) * sigma;
  state.count = contact.count;
  state.real_area = contact.area;
  state.area_fraction = contact.area / surface_.nominal_area;
  state.load = contact.load;
  state.pressure = contact.load / surface_.nominal_area;
  state.stiffness = contact.stiffness;
  state.stiffness_over_load = contact.stiffness_ratio / sigma;  // K/P [1/m] = -(dP/ds)/P / sigma
  return state;
}

PhysicalState ContactModel::at_separation(double separation) const noexcept {
  return state_at_dimensionless(dimensionless(separation));
}

void ContactModel::at_separations(ContactQuantity quantity, const double* separations, double* out,
                                  std::size_t count) const noexcept {
  // quantity = factor * X_n (/ A0 for the fractions), as state_at_dimensionless forms it
  int twice_order = orders::load;
  double factor = scales_.load;
  bool per_area = false;
  switch (quantity) {
    case ContactQuantity::count: twice_order = orders::count, factor = scales_.count; break;
    case ContactQuantity::area_fraction: per_area = true; [[fallthrough]];
    case ContactQuantity::real_area: twice_order = orders::area, factor = scales_.area; break;
    case ContactQuantity::pressure: per_area = true; break;
    case ContactQuantity::load: break;
    case ContactQuantity::stiffness: twice_order = orders::stiffness, factor = scales_.stiffness; break;
  }
  if (!curve_.has_order(orders::load) || static_cast<unsigned>(quantity) >= contact_quantity_count) {
    for (std::size_t i = 0; i < count; ++i) out[i] = nan;
    return;
  }
  const double area = surface_.nominal_area, sigma = surface_.height_scale, offset = datum_offset_;
  // state_at_dimensionless's rare answers need not build the whole state: contact_products'
  // lane of the quantity (count, area, load, stiffness), the same bits
  const int lane = twice_order == orders::count ? 0 : twice_order == orders::area ? 1 : twice_order == orders::load ? 2 : 3;
  const bool bounded = surface_.side == Side::bounded;
  constexpr std::size_t block = 256;
  double s[block];  // the block's dimensionless separations (a copy: out may be separations)
  double x[block];  // X_n at them
  // Branch-free passes (dimensionless's and state_at_dimensionless's arithmetic, the same
  // operations in the same order): s, the batch lookup, then the factor (and the nominal area)
  // with the rare elements' bit mask in one pass; the rare ones one by one, found by their bits,
  // only in a block that has any.
  for (std::size_t start = 0; start < count; start += block) {
    const std::size_t size = count - start < block ? count - start : block;
    const double* in = separations + start;
    double* to = out + start;
    if (offset == 0)
      for (std::size_t j = 0; j < size; ++j) s[j] = in[j] / sigma;
    else
      for (std::size_t j = 0; j < size; ++j) s[j] = in[j] / sigma + offset;
    curve_.value_batch(twice_order, s, x, size);
    // the rare elements (X_n NaN, 0, subnormal or inf, or the product inf): bit j of rare[j / 64]
    std::uint64_t rare[block / 64] = {0, 0, 0, 0};
#if defined(__SSE2__)
    const __m128d factors = _mm_set1_pd(factor), areas = _mm_set1_pd(area);
    const __m128d smallest = _mm_set1_pd(DBL_MIN), largest = _mm_set1_pd(DBL_MAX);
#endif
    for (std::size_t word = 0; 64 * word < size; ++word) {
      const std::size_t first = 64 * word, end = size - first < 64 ? size : first + 64;
      std::uint64_t bits = 0;  // in a register: the mask of 64 elements
      std::size_t j = first;
#if defined(__SSE2__)
      // two a step, the rare ones by movemask: no scan of the block for them
      for (; j + 2 <= end; j += 2) {
        const __m128d value = _mm_loadu_pd(x + j), product = _mm_mul_pd(value, factors);
        const int two = _mm_movemask_pd(_mm_or_pd(_mm_cmpnge_pd(value, smallest), _mm_cmpnle_pd(product, largest)));
        bits |= static_cast<std::uint64_t>(two) << (j - first);
        _mm_storeu_pd(to + j, per_area ? _mm_div_pd(product, areas) : product);
      }
#endif
      for (; j < end; ++j) {
        const double product = x[j] * factor;
        bits |= static_cast<std::uint64_t>(!(x[j] >= DBL_MIN) | !(product <= DBL_MAX)) << (j - first);
        to[j] = per_area ? product / area : product;
      }
      rare[word] = bits;
    }
    if (__builtin_expect((rare[0] | rare[1] | rare[2] | rare[3]) == 0, 1)) continue;
    for (std::size_t word = 0; word < block / 64; ++word)
      for (std::uint64_t bits = rare[word]; bits != 0; bits &= bits - 1) {
        const std::size_t j = 64 * word + static_cast<std::size_t>(__builtin_ctzll(bits));
        // X_n beyond the doubles where contact is partial: contact_products' one kernel call, as
        // state_at_dimensionless makes it
        double state[5];
        if (std::isfinite(s[j]) && !(bounded && s[j] >= 0) &&
            curve_.contact_products(s[j], scales_.count, scales_.area, scales_.load, scales_.stiffness, state)) {
          to[j] = per_area ? state[lane] / area : state[lane];
          continue;
        }
        // NaN, no contact, all in contact, off the grid: the scalar path's answer
        const PhysicalState answer = state_at_dimensionless(s[j]);
        switch (quantity) {
          case ContactQuantity::count: to[j] = answer.count; break;
          case ContactQuantity::real_area: to[j] = answer.real_area; break;
          case ContactQuantity::area_fraction: to[j] = answer.area_fraction; break;
          case ContactQuantity::load: to[j] = answer.load; break;
          case ContactQuantity::pressure: to[j] = answer.pressure; break;
          case ContactQuantity::stiffness: to[j] = answer.stiffness; break;
        }
      }
  }
}

// The inverses give the quantity asked back as asked (the curve at the separation found gives it
// to a few ulp: 999999.9999999995 for 1e6), in every interface alike.
PhysicalState ContactModel::at_load(double load) const noexcept {
  if (std::isnan(load)) return state_at_dimensionless(nan);
  if (load <= 0) return no_contact();
  if (load == std::numeric_limits<double>::infinity()) return infinite_contact();
  PhysicalState state = state_at_dimensionless(load_inverse_.separation_at_log(std::log(load) - std::log(scales_.load)));
  if (std::isfinite(state.separation)) state.load = load, state.pressure = load / surface_.nominal_area;
  return state;
}

PhysicalState ContactModel::at_pressure(double pressure) const noexcept {
  PhysicalState state = at_load(pressure * surface_.nominal_area);
  if (std::isfinite(state.separation)) state.pressure = pressure;
  return state;
}

PhysicalState ContactModel::at_real_area(double real_area) const noexcept {
  if (std::isnan(real_area)) return state_at_dimensionless(nan);
  if (real_area <= 0) return no_contact();
  if (real_area == std::numeric_limits<double>::infinity()) return infinite_contact();
  PhysicalState state =
      state_at_dimensionless(area_inverse_.separation_at_log(std::log(real_area) - std::log(scales_.area)));
  if (std::isfinite(state.separation)) state.real_area = real_area, state.area_fraction = real_area / surface_.nominal_area;
  return state;
}

// The range: the curve's served separations (a scene table's), as the model's physical ones
double ContactModel::min_separation() const noexcept { return physical(curve_.served_min_separation()); }
double ContactModel::max_separation() const noexcept { return physical(curve_.served_max_separation()); }
// (the states at the ends in s itself: a round trip through the physical separation could
// round past the range)
double ContactModel::min_load() const noexcept {
  return state_at_dimensionless(curve_.served_max_separation()).load;
}
double ContactModel::max_load() const noexcept {
  return state_at_dimensionless(curve_.served_min_separation()).load;
}
double ContactModel::min_real_area() const noexcept {
  return state_at_dimensionless(curve_.served_max_separation()).real_area;
}
double ContactModel::max_real_area() const noexcept {
  return state_at_dimensionless(curve_.served_min_separation()).real_area;
}
bool ContactModel::answers_separation(double separation) const noexcept {
  const double s = dimensionless(separation);
  return curve_.has_order(orders::load) && !std::isnan(s) && (std::isinf(s) || curve_.serves(s));
}

std::string gw_area_fraction_warning(double area_fraction) {
  if (!(area_fraction > gw_area_fraction_limit)) return {};
  char text[320];
  std::snprintf(text, sizeof text,
                "the real contact area reaches %.4g of the nominal area (above %.4g): Greenwood-Williamson treats "
                "the asperity contacts as sparse and independent, which no longer holds there%s",
                area_fraction, gw_area_fraction_limit, area_fraction > 1 ? "; above 1 the answer is impossible" : "");
  return text;
}

}  // namespace asperity
