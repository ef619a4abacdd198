// Hertz: the elastic sphere (docs/model.md "Contact laws").
#include "law_support.hpp"

namespace asperity {

ContactLaw hertz_law(double radius, double modulus) noexcept {
  if (!detail::positive(radius) || !detail::positive(modulus)) return detail::bad_law(ContactLawKind::hertz);
  ContactLaw law = detail::law_with(ContactLawKind::hertz, radius, modulus);
  law.critical_interference = law.critical_load = law.critical_area = detail::nan;  // no yield in an elastic law
  return law;
}

namespace detail {
namespace {

ContactLaw make(double radius, double modulus, const LawValues&) noexcept { return hertz_law(radius, modulus); }
AsperityResponse response(const ContactLaw& law, double w) noexcept { return hertz(law.radius, law.modulus, w); }

}  // namespace

const ContactLawDescriptor hertz_law_descriptor = {
    ContactLawKind::hertz, "hertz", "Hertz 1882", "elastic spheres", LawFamily::elastic, nullptr, 0, make, response,
    nullptr, 0, {0, 0, 0, 0}, false};

}  // namespace detail
}  // namespace asperity
