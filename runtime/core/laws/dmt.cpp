// Derjaguin, Muller & Toporov 1975: Hertz less the pull-off 2 pi dgamma R from the first touch
// (docs/contact-laws.md section 5).
#include "law_support.hpp"

namespace asperity {

ContactLaw dmt_law(double radius, double modulus, double work_of_adhesion) noexcept {
  const auto kind = ContactLawKind::dmt;
  if (!detail::positive(radius) || !detail::positive(modulus) || !detail::positive(work_of_adhesion))
    return detail::bad_law(kind);
  ContactLaw law = detail::law_with(kind, radius, modulus);
  law.work_of_adhesion = work_of_adhesion;
  detail::set_adhesive_scales(law);
  return law;
}

namespace detail {
namespace {

ContactLaw make(double radius, double modulus, const LawValues& v) noexcept {
  return dmt_law(radius, modulus, v[LawParameter::work_of_adhesion]);
}

double pull_off(const ContactLaw& law) noexcept { return 2 * pi * law.work_of_adhesion * law.radius; }

AsperityResponse response(const ContactLaw& law, double w) noexcept {
  AsperityResponse r = hertz(law.radius, law.modulus, w);
  r.load -= pull_off(law);
  return r;
}

AsperityLoadSplit load_split(const ContactLaw& law, double, const AsperityResponse& r) noexcept {
  const double tension = pull_off(law);
  return {r.load + tension, tension, r.stiffness, 0};
}

constexpr LawParameterUse parameters[] = {{LawParameter::work_of_adhesion, true, 0}};

}  // namespace

const ContactLawDescriptor dmt_law_descriptor = {
    ContactLawKind::dmt, "dmt", "Derjaguin-Muller-Toporov 1975", "Hertz less the pull-off 2 pi dgamma R",
    LawFamily::adhesive, parameters, 1, make, response, load_split, 1, {0, 0, 0, 0}, true};

}  // namespace detail
}  // namespace asperity
