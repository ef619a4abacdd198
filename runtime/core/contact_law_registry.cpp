// The contact-law registry (asperity/contact_law_registry.hpp): the parameters' one definition,
// the built-in laws' list, the laws a program registers, and the checks every reader of a law's
// values (scene files, the command line, Python) goes through.
#include "asperity/contact_law_registry.hpp"

#include <array>
#include <atomic>
#include <cmath>
#include <deque>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/number_text.hpp"

#include "laws/law_support.hpp"

namespace asperity {
namespace {

// The parameters' one list (contact_law_registry.hpp), as the table law_parameter_info serves.
#define ASPERITY_LAW_PARAMETER_ENTRY(id, option, symbol, unit, type_name, meaning, lower, upper, lower_included, \
                                     upper_included, range_text, strength, ...)                                \
  {LawParameter::id, #id, option, symbol, unit, type_name, meaning, lower, upper, lower_included,             \
   upper_included, range_text, strength, {__VA_ARGS__}},
const LawParameterInfo parameter_table[] = {ASPERITY_LAW_PARAMETERS(ASPERITY_LAW_PARAMETER_ENTRY)};
#undef ASPERITY_LAW_PARAMETER_ENTRY
static_assert(sizeof parameter_table / sizeof parameter_table[0] == law_parameter_count);

// The built-ins, then registered laws: a fixed capacity, so that readers need no lock (an entry
// is written before the count that shows it).
constexpr std::size_t registry_capacity = 64;
struct Registry {
  std::array<const ContactLawDescriptor*, registry_capacity> entries{};
  std::atomic<std::size_t> count{0};
  std::mutex writing;
  std::deque<ContactLawDescriptor> registered;  // the copies registered laws point at
  Registry() {
#define ASPERITY_LIST_LAW(kind, descriptor) entries[count++] = &detail::descriptor;
    ASPERITY_BUILT_IN_CONTACT_LAWS(ASPERITY_LIST_LAW)
#undef ASPERITY_LIST_LAW
  }
};

Registry& registry() {
  static Registry instance;
  return instance;
}

bool valid_law_name(const char* name) {
  if (!name || !*name) return false;
  for (const char* c = name; *c; ++c)
    if (!((*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') || *c == '-')) return false;
  return true;
}

std::string joined(const std::vector<std::string>& items, const std::string& last) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? last : ", ") + items[i];
  return out;
}

bool within(const LawParameterInfo& p, double x) {
  if (!std::isfinite(x)) return false;
  const bool above = p.lower_included ? x >= p.lower : x > p.lower;
  const bool below = p.upper_included ? x <= p.upper : x < p.upper;
  return above && below;
}

}  // namespace

LawValues::LawValues() noexcept {
  for (double& x : value) x = detail::nan;
}

const LawParameterInfo& law_parameter_info(LawParameter parameter) noexcept {
  return parameter_table[static_cast<int>(parameter)];
}
const LawParameterInfo* law_parameters_begin() noexcept { return parameter_table; }

std::size_t contact_law_count() noexcept { return registry().count.load(std::memory_order_acquire); }

const ContactLawDescriptor& contact_law_at(std::size_t index) noexcept { return *registry().entries[index]; }

const ContactLawDescriptor* find_contact_law(ContactLawKind kind) noexcept {
  const auto index = static_cast<std::size_t>(kind);
  return index < contact_law_count() ? registry().entries[index] : nullptr;
}

const ContactLawDescriptor* find_contact_law(const std::string& name) noexcept {
  for (std::size_t i = 0; i < contact_law_count(); ++i)
    if (name == contact_law_at(i).name) return &contact_law_at(i);
  return nullptr;
}

ContactLawKind register_contact_law(const ContactLawDescriptor& descriptor) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.writing);
  if (!valid_law_name(descriptor.name))
    throw Error("register_contact_law: a law's name is lower-case letters, digits and '-', not '" +
                std::string(descriptor.name ? descriptor.name : "") + "'");
  if (find_contact_law(descriptor.name))
    throw Error(std::string("register_contact_law: a law named ") + descriptor.name + " exists");
  if (!descriptor.make || !descriptor.response)
    throw Error(std::string("register_contact_law: ") + descriptor.name + " needs its make and response functions");
  if (descriptor.parameter_count < 0 || descriptor.parameter_count > law_parameter_count ||
      (descriptor.parameter_count > 0 && !descriptor.parameters) || descriptor.switch_count < 0 ||
      descriptor.switch_count > 4)
    throw Error(std::string("register_contact_law: ") + descriptor.name + "'s parameters or switch points are not a list");
  const std::size_t index = r.count.load(std::memory_order_relaxed);
  if (index == registry_capacity) throw Error("register_contact_law: the registry is full");
  r.registered.push_back(descriptor);
  r.registered.back().kind = static_cast<ContactLawKind>(index);
  r.entries[index] = &r.registered.back();
  r.count.store(index + 1, std::memory_order_release);
  return r.registered.back().kind;
}

const LawParameterUse* law_parameter_use(const ContactLawDescriptor& law, LawParameter parameter) noexcept {
  for (int k = 0; k < law.parameter_count; ++k)
    if (law.parameters[k].parameter == parameter) return &law.parameters[k];
  return nullptr;
}

std::string contact_law_names(const std::string& last, bool quoted) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < contact_law_count(); ++i)
    names.push_back(quoted ? "\"" + std::string(contact_law_at(i).name) + "\"" : contact_law_at(i).name);
  return joined(names, last);
}

std::string laws_taking(LawParameter parameter, const std::string& last) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < contact_law_count(); ++i)
    if (law_parameter_use(contact_law_at(i), parameter)) names.push_back(contact_law_at(i).name);
  return joined(names, last);
}

bool law_choice_index(LawParameter parameter, const std::string& text, double& index) noexcept {
  const LawParameterInfo& p = law_parameter_info(parameter);
  for (int k = 0; k < 3 && p.choices[k]; ++k)
    if (text == p.choices[k]) {
      index = k;
      return true;
    }
  return false;
}

std::string law_choices_text(LawParameter parameter, const std::string& last, bool quoted) {
  std::vector<std::string> choices;
  const LawParameterInfo& p = law_parameter_info(parameter);
  for (int k = 0; k < 3 && p.choices[k]; ++k) choices.push_back(quoted ? "\"" + std::string(p.choices[k]) + "\"" : p.choices[k]);
  return joined(choices, last);
}

double law_parameter_value(const ContactLaw& law, LawParameter parameter) noexcept {
  const ContactLawDescriptor* descriptor = find_contact_law(law.kind);
  if (!descriptor || !law_parameter_use(*descriptor, parameter)) return detail::nan;
  switch (parameter) {
    case LawParameter::hardness: return law.hardness;
    case LawParameter::yield_strength: return law.yield_strength;
    case LawParameter::poisson: return law.poisson;
    case LawParameter::pressure_factor: return law.pressure_factor;
    case LawParameter::geometric_hardness:
      return law.jackson_green_hardness == JacksonGreenHardness::exponential ? 1 : 0;
    case LawParameter::work_of_adhesion: return law.work_of_adhesion;
    case LawParameter::maugis_parameter: return law.maugis_parameter;
  }
  return detail::nan;
}

std::string law_parameters_text(const ContactLaw& law) {
  const ContactLawDescriptor* descriptor = find_contact_law(law.kind);
  if (!descriptor) return "";
  std::ostringstream text;
  for (int k = 0; k < descriptor->parameter_count; ++k) {
    const LawParameterInfo& p = law_parameter_info(descriptor->parameters[k].parameter);
    const double value = law_parameter_value(law, p.id);
    text << (k ? ", " : "") << p.symbol << " = ";
    if (p.choices[0] && value >= 0 && value < 3 && p.choices[static_cast<int>(value)])
      text << p.choices[static_cast<int>(value)];
    else
      text << format_double(value);  // shortest round-trip: 0.3, not 0.29999999999999999
    if (*p.unit) text << " " << p.unit;
  }
  return text.str();
}

std::string law_parameter_name(LawParameter parameter, LawNaming naming) {
  const LawParameterInfo& p = law_parameter_info(parameter);
  switch (naming) {
    case LawNaming::scene_key: return std::string("'") + p.key + "'";
    case LawNaming::option: return p.option;
    case LawNaming::keyword: return std::string(p.key) + "=";
  }
  return p.key;
}

LawValues checked_law_values(const ContactLawDescriptor& law, const LawValues& values, LawNaming naming) {
  const std::string law_text = naming == LawNaming::option ? std::string("--law ") + law.name : law.name;
  for (const LawParameterInfo* p = law_parameters_begin(); p != law_parameters_end(); ++p)
    if (values.given(p->id) && !law_parameter_use(law, p->id))
      throw LawValuesError(p->id, law_parameter_name(p->id, naming) + " does not apply to " + law_text,
                           "remove this key");
  LawValues out;
  for (int k = 0; k < law.parameter_count; ++k) {
    const LawParameterUse& use = law.parameters[k];
    if (!values.given(use.parameter) && use.required)
      throw LawValuesError(use.parameter,
                           (naming == LawNaming::scene_key ? "the law has no " : law_text + " needs ") +
                               law_parameter_name(use.parameter, naming),
                           "this law");
    out.set(use.parameter, values.given(use.parameter) ? values[use.parameter] : use.default_value);
  }
  for (int k = 0; k < law.parameter_count; ++k) {
    const LawParameterInfo& p = law_parameter_info(law.parameters[k].parameter);
    const double x = out[p.id];
    const bool ok = p.choices[0] ? (x == 0 || x == 1 || (x == 2 && p.choices[2])) : within(p, x);
    if (!ok)
      throw LawValuesError(p.id, law_parameter_name(p.id, naming) + (p.choices[0] ? " is " : " must be ") + p.range_text,
                           "here");
  }
  return out;
}

ContactLaw make_contact_law(ContactLawKind kind, double radius, double modulus, const LawValues& values,
                            LawNaming naming) {
  const ContactLawDescriptor* law = find_contact_law(kind);
  if (!law) throw Error("make_contact_law: no law of kind " + std::to_string(static_cast<int>(kind)));
  ContactLaw made = law->make(radius, modulus, checked_law_values(*law, values, naming));
  made.kind = kind;
  if (!std::isfinite(made.lowest_interference))
    throw Error("the law's parameters give no finite critical interference (not physical?)");
  return made;
}

}  // namespace asperity
