// The contact laws of asperity/contact_law.hpp: what every law shares, and each question asked
// of a law answered through its descriptor (contact_law_registry.hpp). Each law's formulas are in
// its own file, runtime/core/laws/NAME.cpp (sources in docs/contact-laws.md).
#include "asperity/contact_law.hpp"

#include <cmath>

#include "asperity/contact_law_registry.hpp"
#include "laws/law_support.hpp"

namespace asperity {
namespace detail {

ContactLaw bad_law(ContactLawKind kind) noexcept {
  ContactLaw law;
  law.kind = kind;
  law.radius = law.modulus = law.hardness = law.yield_strength = law.poisson = nan;
  law.pressure_factor = law.work_of_adhesion = law.maugis_parameter = nan;
  law.critical_interference = law.critical_load = law.critical_area = nan;
  law.jackson_green_b = law.jackson_green_c = law.md_turning = nan;
  law.lowest_interference = law.valid_up_to = nan;
  return law;
}

ContactLaw law_with(ContactLawKind kind, double radius, double modulus) noexcept {
  ContactLaw law;
  law.kind = kind;
  law.radius = radius;
  law.modulus = modulus;
  law.lowest_interference = 0;
  law.valid_up_to = inf;
  return law;
}

void set_critical(ContactLaw& law, double critical) noexcept {
  law.critical_interference = critical;
  law.critical_load = hertz(law.radius, law.modulus, critical).load;
  law.critical_area = pi * law.radius * critical;
  law.lowest_interference = 0;
  law.valid_up_to = inf;
}

void set_adhesive_scales(ContactLaw& law) noexcept {
  const double k = (4.0 / 3.0) * law.modulus;
  const double a_s = std::cbrt(pi * law.work_of_adhesion * law.radius * law.radius / k);
  law.critical_interference = a_s * a_s / law.radius;
  law.critical_load = pi * law.work_of_adhesion * law.radius;
  law.critical_area = pi * a_s * a_s;
  law.valid_up_to = inf;
}

}  // namespace detail

const char* contact_law_name(ContactLawKind kind) noexcept {
  const ContactLawDescriptor* law = find_contact_law(kind);
  return law ? law->name : "unknown";
}

bool contact_law_kind_of(const char* name, ContactLawKind& kind) noexcept {
  if (!name) return false;
  for (std::size_t i = 0; i < contact_law_count(); ++i) {
    const char *a = name, *b = contact_law_at(i).name;
    while (*a && *a == *b) ++a, ++b;
    if (*a == 0 && *b == 0) {
      kind = contact_law_at(i).kind;
      return true;
    }
  }
  return false;
}

AsperityResponse asperity_response(const ContactLaw& law, double w) noexcept {
  using detail::nan;
  const AsperityResponse bad{nan, nan, nan}, none{0, 0, 0};
  const ContactLawDescriptor* descriptor = find_contact_law(law.kind);
  if (!descriptor || std::isnan(w) || !detail::positive(law.radius) || !detail::positive(law.modulus) ||
      std::isnan(law.lowest_interference))
    return bad;
  if (w < law.lowest_interference ||
      (w == law.lowest_interference && law.lowest_interference == 0 && !descriptor->touching_at_lowest))
    return none;
  if (w == detail::inf) return {detail::inf, detail::inf, detail::inf};
  return descriptor->response(law, w);
}

bool is_adhesive(ContactLawKind kind) noexcept {
  const ContactLawDescriptor* law = find_contact_law(kind);
  return law && law->family == LawFamily::adhesive;
}

AsperityLoadSplit asperity_load_split(const ContactLaw& law, double w) noexcept {
  using detail::nan;
  const AsperityResponse response = asperity_response(law, w);
  if (std::isnan(response.load)) return {nan, nan, nan, nan};
  const ContactLawDescriptor* descriptor = find_contact_law(law.kind);
  // out of contact (an adhesive law's lowest interference is where its contact ends): zeros
  if (!descriptor->load_split || w < law.lowest_interference) return {response.load, 0, response.stiffness, 0};
  if (w == detail::inf) return {detail::inf, detail::inf, detail::inf, detail::inf};
  return descriptor->load_split(law, w, response);
}

SwitchPoints switch_points(const ContactLaw& law) noexcept {
  SwitchPoints points;
  const ContactLawDescriptor* descriptor = find_contact_law(law.kind);
  if (!descriptor || std::isnan(law.lowest_interference) || !detail::positive(law.radius)) return points;
  for (int k = 0; k < descriptor->switch_count && k < 4; ++k)
    points.interference[points.count++] = descriptor->switch_multiples[k] * law.critical_interference;
  return points;
}

double plasticity_index(const ContactLaw& law, double summit_scale) noexcept {
  const ContactLawDescriptor* descriptor = find_contact_law(law.kind);
  if (!detail::positive(summit_scale) || !descriptor || descriptor->family != LawFamily::elastic_plastic)
    return detail::nan;
  return std::sqrt(summit_scale / law.critical_interference);
}

double greenwood_williamson_plasticity_index(double modulus, double hardness, double summit_scale,
                                             double radius) noexcept {
  using detail::positive;
  if (!positive(modulus) || !positive(hardness) || !positive(summit_scale) || !positive(radius)) return detail::nan;
  return modulus / hardness * std::sqrt(summit_scale / radius);
}

double adhesion_parameter(const ContactLaw& law, double summit_scale) noexcept {
  if (!is_adhesive(law.kind) || !detail::positive(summit_scale) || !detail::positive(law.work_of_adhesion))
    return detail::nan;
  const double dgamma = law.work_of_adhesion, e = law.modulus;
  const double delta_c = 0.75 * std::cbrt(detail::pi * detail::pi * dgamma * dgamma * law.radius / (e * e));
  return summit_scale / delta_c;
}

}  // namespace asperity
