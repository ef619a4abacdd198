// Contact laws as a registry: one descriptor per law (runtime/core/laws/NAME.cpp) says what the
// law is called, which material parameters it takes (with units, ranges and which are required),
// how it is made from values, its response, its switch points and the figure that says its
// regime. The scene reader, the command's options and help, the Python keywords, the generator's
// summaries and the surface report all loop over it; no one else spells which law takes what.
//
// Adding a law (docs/architecture.md "Recipes"): its file runtime/core/laws/NAME.cpp with the
// formulas and the descriptor, a line in ASPERITY_BUILT_IN_CONTACT_LAWS (contact_law.hpp) and a
// line in runtime/CMakeLists.txt; then its tests and docs. A program may also register a law of
// its own at run time (register_contact_law): tests/test_law_registry.cpp does.
#pragma once
#include <cmath>  // HUGE_VAL, the parameters' list
#include <cstddef>
#include <string>

#include "asperity/contact_law.hpp"
#include "asperity/error.hpp"

namespace asperity {

// The material parameters a law may take, beyond the summit radius R and the contact modulus E*
// that every law takes from the surface, each defined once here:
//   X(id, option, symbol, unit, type_name, meaning, lower, upper, lower_included, upper_included,
//     range_text, strength, choices...)
// id is the enum's name, the scene key and the Python keyword; the rest are LawParameterInfo's
// fields below; choices... a choice parameter's values, null-terminated (nullptr alone: a number).
#define ASPERITY_LAW_PARAMETERS(X)                                                                                   \
  X(hardness, "--hardness", "H", "Pa", "PA", "hardness H [Pa]", 0, HUGE_VAL, false, false, "positive and finite",     \
    true, nullptr)                                                                                                   \
  X(yield_strength, "--yield-strength", "Y", "Pa", "PA", "yield strength Y [Pa]", 0, HUGE_VAL, false, false,          \
    "positive and finite", true, nullptr)                                                                            \
  X(poisson, "--law-poisson", "nu", "", "X", "Poisson's ratio of the asperity", 0, 0.5, true, true,                   \
    "between 0 and 0.5", false, nullptr)                                                                             \
  X(pressure_factor, "--pressure-factor", "K", "", "X",                                                              \
    "the mean contact pressure at first yield over H (0.6 in the paper)", 0, 1, false, false, "in (0, 1)", false,    \
    nullptr)                                                                                                         \
  X(geometric_hardness, "--geometric-hardness", "H_G", "", "FORM",                                                   \
    "its geometric hardness H_G(a/R) by formula: cosine, 2.84 - 0.92 (1 - cos(pi a/R)) (Jackson & Green 2006; "     \
    "the default), or exponential, 2.84 (1 - exp(-0.82 (a/R)^-0.7)) (Jackson & Green 2005)",                         \
    0, 1, true, true,                                                                                                \
    "cosine or exponential (named by formula; 2005 and 2006 are not taken: asperity 0.2 had those years the "       \
    "wrong way round)",                                                                                             \
    false, "cosine", "exponential", nullptr)                             \
  X(work_of_adhesion, "--work-of-adhesion", "work of adhesion", "J/m^2", "J/M2",                                     \
    "work of adhesion [J/m^2] (the approach branch is tabulated)", 0, HUGE_VAL, false, false, "positive and finite", \
    false, nullptr)                                                                                                  \
  X(maugis_parameter, "--maugis-parameter", "Maugis parameter lambda", "", "X",                                      \
    "Maugis' parameter lambda > 0 (0: DMT, infinity: JKR)", 0, HUGE_VAL, false, false, "positive and finite", false, \
    nullptr)

#define ASPERITY_LAW_PARAMETER_ENUMERATOR(id, ...) id,
enum class LawParameter : int { ASPERITY_LAW_PARAMETERS(ASPERITY_LAW_PARAMETER_ENUMERATOR) };
#undef ASPERITY_LAW_PARAMETER_ENUMERATOR
#define ASPERITY_LAW_PARAMETER_ONE(id, ...) +1
inline constexpr int law_parameter_count = 0 ASPERITY_LAW_PARAMETERS(ASPERITY_LAW_PARAMETER_ONE);
#undef ASPERITY_LAW_PARAMETER_ONE

struct LawParameterInfo {
  LawParameter id;
  const char* key;          // the scene key and the Python keyword ("yield_strength")
  const char* option;       // the command-line option ("--yield-strength")
  const char* symbol;       // in summaries ("Y", "nu", "work of adhesion")
  const char* unit;         // SI ("Pa"; "" when dimensionless)
  const char* type_name;    // the option's value in help texts ("PA")
  const char* meaning;      // what it is, for help texts ("yield strength Y [Pa]")
  // The accepted range of a number, lower < x < upper, each end included when its flag says so;
  // `range_text` is how messages say it ("positive and finite", "between 0 and 0.5").
  double lower, upper;
  bool lower_included, upper_included;
  const char* range_text;
  // What the generator's checks compare: a strength set against E* (the H/E* and Y/E* range)
  bool strength;
  // A choice parameter's values (its value is the index of one; null-terminated), else none.
  const char* choices[3];
};
const LawParameterInfo& law_parameter_info(LawParameter parameter) noexcept;
// Every parameter, in the order above.
const LawParameterInfo* law_parameters_begin() noexcept;
inline const LawParameterInfo* law_parameters_end() noexcept { return law_parameters_begin() + law_parameter_count; }

// Values given for a law's parameters; NaN: not given. A choice parameter holds its index.
struct LawValues {
  double value[law_parameter_count];
  LawValues() noexcept;
  bool given(LawParameter p) const noexcept { return value[static_cast<int>(p)] == value[static_cast<int>(p)]; }
  double operator[](LawParameter p) const noexcept { return value[static_cast<int>(p)]; }
  LawValues& set(LawParameter p, double x) noexcept {
    value[static_cast<int>(p)] = x;
    return *this;
  }
};

// How one law takes one parameter: required, or optional with a default.
struct LawParameterUse {
  LawParameter parameter;
  bool required;
  double default_value;  // when optional and not given (a choice: its index)
};

// What a law's regime is told by (the report, the command's notes): the plasticity index
// psi = (sigma_s / omega_c)^1/2 of an elastic-plastic law, Fuller & Tabor's adhesion parameter of
// an adhesive one, nothing for an elastic law.
enum class LawFamily { elastic, elastic_plastic, adhesive };

struct ContactLawDescriptor {
  ContactLawKind kind;          // built-ins: theirs; a registered law: given by register_contact_law
  const char* name;             // in files, options and messages ("kogut-etsion")
  const char* title;            // its source ("Kogut-Etsion 2002")
  const char* summary;          // one line: what it does
  LawFamily family;
  const LawParameterUse* parameters;  // in the order summaries list them
  int parameter_count;
  // The law from R, E* and its parameters' values (every parameter it takes given, defaults
  // filled, each within its range): a ContactLaw whose derived fields are set, NaN-filled for
  // values it cannot use (noexcept, like the factories of contact_law.hpp).
  ContactLaw (*make)(double radius, double modulus, const LawValues& values) noexcept;
  // P, A, dP/domega at omega in contact (lowest_interference <= omega < inf; the registry's
  // asperity_response handles NaN, out of contact and infinity).
  AsperityResponse (*response)(const ContactLaw& law, double interference) noexcept;
  // An adhesive law's load split into compressive and tensile parts (contact_law.hpp), given the
  // response at the same omega; null for a law without adhesion (the split is then (P, 0)).
  AsperityLoadSplit (*load_split)(const ContactLaw& law, double interference, const AsperityResponse& response) noexcept;
  // Where the formula changes, as multiples of omega_c (DMT: 0, where its load jumps at contact).
  int switch_count;
  double switch_multiples[4];
  // Whether an asperity at exactly omega = lowest_interference = 0 is in contact (DMT: its
  // pull-off load acts from the first touch); otherwise the response there is 0.
  bool touching_at_lowest;
};

// The registry: the built-in laws in ASPERITY_BUILT_IN_CONTACT_LAWS' order, then those registered.
std::size_t contact_law_count() noexcept;
const ContactLawDescriptor& contact_law_at(std::size_t index) noexcept;
// The law of a kind or a name; null for none.
const ContactLawDescriptor* find_contact_law(ContactLawKind kind) noexcept;
const ContactLawDescriptor* find_contact_law(const std::string& name) noexcept;
// Registers one more law (the descriptor is copied; `name` must be new, of lower-case letters,
// digits and '-'; `make` and `response` set; its parameters' strings must outlive the program,
// as literals do). Returns its kind. Throws asperity::Error for a descriptor it cannot take.
ContactLawKind register_contact_law(const ContactLawDescriptor& descriptor);

// Whether `law` takes `parameter`, and how (null: it does not).
const LawParameterUse* law_parameter_use(const ContactLawDescriptor& law, LawParameter parameter) noexcept;
// Every law's name joined: "hertz, chang-etsion-bogy, ... or maugis-dugdale" (`last` before the
// last one; quoted: each in double quotes).
std::string contact_law_names(const std::string& last = " or ", bool quoted = false);
// The laws taking `parameter`, joined the same way ("chang-etsion-bogy or zhao-maietta-chang").
std::string laws_taking(LawParameter parameter, const std::string& last = " or ");
// A choice parameter's index for `text`; false when it is not one of its choices.
bool law_choice_index(LawParameter parameter, const std::string& text, double& index) noexcept;
// "cosine or exponential": a choice parameter's choices, joined.
std::string law_choices_text(LawParameter parameter, const std::string& last = " or ", bool quoted = false);
// A law's parameters as its summaries state them: "H = 2e+09 Pa, nu = 0.3" (17 digits, like the
// tables' descriptions), in the law's order.
std::string law_parameters_text(const ContactLaw& law);
// The value of `parameter` a made law holds (a choice: its index); NaN when it does not take it.
double law_parameter_value(const ContactLaw& law, LawParameter parameter) noexcept;

// Which vocabulary a message speaks: the scene file's keys ('hardness'), the command line's
// options (--hardness) or Python's keywords (hardness=).
enum class LawNaming { scene_key, option, keyword };
std::string law_parameter_name(LawParameter parameter, LawNaming naming);

// A law's values checked: each parameter the law does not take, each it needs and lacks, each
// outside its range is refused, in that order. `parameter` is the first at fault.
class LawValuesError : public Error {
 public:
  LawValuesError(LawParameter parameter, const std::string& message, const char* label)
      : Error(message), parameter(parameter), label(label) {}
  LawParameter parameter;
  const char* label;  // a short note for where it points ("remove this key", "here")
};
// Throws LawValuesError; returns the values with the law's defaults filled in.
LawValues checked_law_values(const ContactLawDescriptor& law, const LawValues& values, LawNaming naming);
// The law of `kind` made from checked values; throws asperity::Error (LawValuesError for a value
// at fault; Error when the values give no finite critical interference).
ContactLaw make_contact_law(ContactLawKind kind, double radius, double modulus, const LawValues& values,
                            LawNaming naming = LawNaming::scene_key);

}  // namespace asperity
