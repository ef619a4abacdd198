// The fits carried through: contact curves of a measured surface, one per height model, side by
// side (docs/model.md section 3, through asperity::ContactModel), against the GW answer summed
// directly over the measured summits, and the ratios between their predictions at the pressures
// of interest (the paper's point, in numbers, for this surface).
//
//   measured-summits  GW summed over the measured summits with GW's one radius (summit_contact.hpp):
//                     no law fitted; what every model below is compared with
//   measured-summits-own-radii  the same with each summit's own radius 1/kappa_m
//   gaussian-moments  the Gaussian that a contact code makes from the spectral moments alone
//                     (Nayak-McCool: summit density, radius and rms summit height from m0, m2,
//                     m4; asperity::gaussian_surface_from_moments)
//   gaussian          the Gaussian fitted to the summit heights
//   weibull-tail      the tail-up Weibull fitted to the summit heights (tail side of approach)
//   weibull-bounded   the mirrored Weibull (bounded side: the flat meets the highest summits)
// The last three use the measured summit density and radius (summits.hpp) and each fit's own
// scale. Beside them, the references that neglect less than GW (add_reference_contact):
//   persson           Persson's theory from the map's power spectrum (persson_contact.hpp): no
//                     summits; every wavelength carries load
//   exact             the exact elastic contact of the map (exact_contact.hpp, when asked):
//                     boundary elements, the referee every other curve is compared with
// The measured summits, Persson and the fits are each set against the exact curve at the
// pressures of interest (ModelContact::*_over_exact) when it is there. The Gaussian is served from the default table. Each Weibull is served from an
// exact-shape scene table generated for the fitted shape over the pressures asked
// (asperity::generator::generate_scene_table, shapes 0.3-50), or from a given full table (the
// default table: shapes 0.5-20, between grid shapes by interpolation). A fitted shape outside
// what the table serves gets no curve; the reason is stated (ModelContact::note).
//
// Separations are reported from the mean summit height of each model (comparable across
// models); pressures are nominal (load / A0), stiffness per nominal area [N/m^3] as well.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "asperity/contact_model.hpp"
#include "asperity/record_fields.hpp"
#include "asperity/topography/exact_contact.hpp"
#include "asperity/topography/height_map.hpp"
#include "asperity/topography/goodness_of_fit.hpp"
#include "asperity/topography/statistics.hpp"
#include "asperity/topography/summits.hpp"

namespace asperity::topography {

// Points of each contact curve (each one inverse and one PhysicalState): bounded, so that an
// option cannot make the curves' time and memory unbounded.
inline constexpr int min_curve_points = 2, max_curve_points = 100000;

struct ContactOptions {
  double contact_modulus = 0;     // E* [Pa] (plane strain); required
  double nominal_area = 0;        // A0 [m^2]; 0: the measured area
  std::vector<double> pressures;  // nominal pressures of interest [Pa]; empty: E* x {1e-5, 1e-4, 1e-3}
  int curve_points = 61;          // points of each curve, log-uniform in pressure (2 to 100000)
  double scene_tolerance = 1e-8;  // of the scene tables
  std::string table_path;         // a full table instead of scene tables (empty: scene tables)
  int threads = 0;
  // the references (add_reference_contact)
  bool persson = true;             // Persson's theory of the map's spectrum (cheap)
  // The exact elastic contact of the map, the referee every curve is set against: solved when
  // asked (exact), or by default (exact_auto) where the map has at most exact_auto_max_points
  // points: 256 x 256 adds about 2 s, 650 x 650 about 20 s on one core (docs/surfaces.md).
  bool exact = false;
  bool exact_auto = true;
  // A measured map is not periodic: by default it is solved as a patch of an unloaded half-space
  // (padded), with Love's pixel-constant coefficients (then exactly non-periodic: no images).
  ContactBoundary exact_boundary = ContactBoundary::padded;
  ContactKernel exact_kernel = ContactKernel::love;
  int exact_points = 13;           // solves along the curves' pressure range, besides the pressures of interest
  double exact_tolerance = 1e-8;   // ExactContactOptions::tolerance
};

inline constexpr int min_exact_points = 2, max_exact_points = 1000;
inline constexpr std::size_t exact_auto_max_points = 512 * 512;

// Whether the exact contact of a map of `points` points is solved with these options.
inline bool exact_contact_wanted(const ContactOptions& options, std::size_t points) {
  return options.exact || (options.exact_auto && points <= exact_auto_max_points);
}

// The fewest measured summits in contact at a pressure for a model to be named closest to GW on
// the measured summits there. Below it the answer there is that handful's: its stiffness is a sum
// over n summits, whose relative sampling spread is about 1/sqrt(n) (a count's Poisson spread;
// each summit's own Hertz term spreads too), so with fewer than 25 summits a difference of 20%
// between two models cannot be told from the luck of which summits were measured (at 25 the
// surrogate ensemble's spread of the answer is itself ~25%: the X3P map at 1 MPa, 27 summits). At
// such a pressure the ratios are still reported, but no model is named from them
// (docs/surfaces.md, section 5).
inline constexpr std::size_t min_summits_to_compare = 25;

// Which curve a comparison holds, each named once (to_string: the name in JSON, the report, the
// batch's table and Python): GW on the measured summits (one radius, or each its own), the
// Gaussian from the spectral moments, the fitted height models (HeightModel's names), and the
// references (Persson's theory, the exact contact).
enum class ContactModelKind {
  measured_summits, measured_summits_own_radii, gaussian_moments, gaussian, weibull_tail, weibull_bounded, persson, exact
};
inline constexpr ContactModelKind all_contact_model_kinds[] = {
    ContactModelKind::measured_summits, ContactModelKind::measured_summits_own_radii, ContactModelKind::gaussian_moments,
    ContactModelKind::gaussian,         ContactModelKind::weibull_tail,               ContactModelKind::weibull_bounded,
    ContactModelKind::persson,          ContactModelKind::exact};
// "measured-summits", "measured-summits-own-radii", "gaussian-moments", "gaussian", "weibull-tail",
// "weibull-bounded", "persson", "exact"
const char* to_string(ContactModelKind kind);
bool parse_contact_model_kind(const std::string& name, ContactModelKind& kind) noexcept;  // to_string's inverse
// A curve named, or none (a comparison's closest, NextSteps::model): to_string's name, "" for none
// (JSON, the summary, Python).
std::string contact_model_name(const std::optional<ContactModelKind>& kind);
ContactModelKind contact_model_kind(HeightModel model) noexcept;  // a fitted height model's curve
bool is_fitted(ContactModelKind kind) noexcept;  // a law fitted to the map: gaussian-moments and the height models

// One curve of a comparison; its fields defined once (a record's list, record_fields.hpp): the
// JSON object of a model (contact.models[]) is made from it, its states at the pressures of
// interest given their ratios to the references by the writer (report.json), which the ratios
// here (not written as fields) hold
#define ASPERITY_MODEL_CONTACT_FIELDS(X)                                                                   \
  X(ContactModelKind, kind, "model", "which curve: its one name (to_string, the label)",                  \
    ContactModelKind::measured_summits)                                                                    \
  X(double, mean_summit_height, "mean_summit_height_m", "[m], in the map's height frame (leveled)", 0)   \
  X(bool, served, "served", "whether it has a curve", false)                                              \
  X(std::string, note, "note", "the table that served it, or why there is no curve")                    \
  X(RoughSurface, surface, "surface", "its surface (distribution, side, shape, scales)")                   \
  X(std::vector<PhysicalState>, at_pressures, "at_pressures", "its states at the pressures of interest")  \
  X(std::vector<PhysicalState>, curve, "curve", "its states over [pressure_min, pressure_max]")           \
  X(std::vector<double>, stiffness_over_measured, nullptr, "its stiffness over measured-summits' at each pressure") \
  X(std::vector<double>, separation_minus_measured, nullptr,                                             \
    "its mean separation less measured-summits' at each pressure [m]")                                   \
  X(std::vector<double>, stiffness_over_exact, nullptr,                                                  \
    "its stiffness over the exact contact's at each pressure (empty without it)")                         \
  X(std::vector<double>, area_over_exact, nullptr,                                                       \
    "its real area over the exact contact's at each pressure (empty without it)")                        \
  X(std::vector<double>, separation_minus_exact, nullptr,                                                \
    "its mean separation less the exact contact's at each pressure [m] (empty without it)")

struct ModelContact {
  ASPERITY_MODEL_CONTACT_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
  // its name in the outputs, kind's one spelling (to_string(ContactModelKind))
  const char* label() const noexcept { return to_string(kind); }
};

// The measured-summit answer at a coarser sampling (every k-th point): its stiffness at each
// pressure over the answer at the file's sampling (report.json's
// contact.measured_summits_sampling_dependence)
#define ASPERITY_SAMPLING_CONTACT_FIELDS(X)                                           \
  X(std::size_t, factor, "factor", "every factor-th point in x and y", 1)             \
  X(std::vector<double>, stiffness_over_finest, "stiffness_over_finest",              \
    "the measured-summit stiffness at each pressure over the answer at the file's sampling")

struct SamplingContact {
  ASPERITY_SAMPLING_CONTACT_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

// The curves side by side; its fields defined once (a record's list): the JSON object of the
// comparison (report.json's contact) holds its written fields and the keys the writer composes
// from the others (the pressure range, the spread, the references)
#define ASPERITY_CONTACT_COMPARISON_FIELDS(X)                                                              \
  X(ContactOptions, options, nullptr, "the options it was made with")                                     \
  X(std::vector<double>, pressures, "pressures_Pa", "the pressures of interest [Pa]")                      \
  X(double, pressure_min, nullptr, "the curves' lowest pressure [Pa]", 0)                                 \
  X(double, pressure_max, nullptr, "the curves' highest pressure [Pa]", 0)                                \
  X(double, nominal_area, "nominal_area_m2", "A0 [m^2]", 0)                                                \
  X(std::vector<std::size_t>, measured_summits_in_contact, "measured_summits_in_contact",                  \
    "the measured summits in contact at each pressure (not scaled to the nominal area)")                   \
  X(std::vector<ModelContact>, models, "models", "every curve")                                            \
  X(std::vector<double>, measured_stiffness_spread, nullptr,                                               \
    "the relative standard deviation of the measured-summit stiffness over the surrogate ensemble, at each " \
    "pressure: the uncertainty of every ratio to it (empty without an ensemble)")                           \
  X(std::vector<double>, measured_separation_spread, nullptr,                                              \
    "the standard deviation of the measured-summit mean separation over the ensemble, at each pressure [m]") \
  X(std::optional<ContactModelKind>, closest, "closest_fitted_model",                                      \
    "the fitted model nearest the measured summits at the pressures compared ('' where none is)")           \
  X(std::string, headline, "headline", "the comparison in words")                                          \
  X(std::string, exact_method, nullptr, "how the exact contact was solved")                                \
  X(std::optional<ContactModelKind>, closest_to_exact, nullptr,                                            \
    "the curve nearest the exact contact, of all ('' where none is)")                                       \
  X(std::string, exact_headline, nullptr,                                                                  \
    "the comparison with the exact contact in words, or, where the map's size alone left it out, that and how to ask") \
  X(std::vector<SamplingContact>, sampling, "measured_summits_sampling_dependence",                         \
    "the measured-summit answer at coarser samplings")                                                      \
  X(std::size_t, map_nx, nullptr, "the map add_reference_contact was given: points along x (0: none)", 0)  \
  X(std::size_t, map_ny, nullptr, "the map add_reference_contact was given: points along y (0: none)", 0)

struct ContactComparison {
  ASPERITY_CONTACT_COMPARISON_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
  // At least min_summits_to_compare measured summits are in contact at pressure k: the models are
  // compared there (closest: the fitted model nearest to the measured summits at the pressures
  // compared, largest |ln stiffness ratio| smallest; the headline says how many summits are in
  // contact at each pressure and why no model is named where too few are).
  bool compared_at(std::size_t k) const noexcept {
    return k < measured_summits_in_contact.size() && measured_summits_in_contact[k] >= min_summits_to_compare;
  }
  const ModelContact* find(ContactModelKind kind) const;
  const ModelContact* find(const std::string& label) const;  // by to_string(kind); nullptr for another name
};

// Progress of the exact solves: `done` of `total` load steps.
using ExactProgress = std::function<void(std::size_t done, std::size_t total)>;

// Persson's theory (when ContactOptions::persson) and the exact contact (when ::exact) of the
// map the comparison was made for, appended to its models as "persson" and "exact" over the same
// pressures; separations from `mean_summit_height` (the measured summits' mean above the mean
// plane, as every other curve's). A failed reference gets no curve and says why. Throws
// asperity::Error for exact_points outside [min_exact_points, max_exact_points].
void add_reference_contact(ContactComparison& comparison, const HeightMap& map, double mean_summit_height,
                           const ExactProgress& progress = {});

// The pressures of every curve: log-uniform over [pressure_min, pressure_max], curve_points of them.
std::vector<double> curve_pressures(const ContactComparison& comparison);

// The pressures of interest (sorted) that compare_contact will use.
std::vector<double> contact_pressures(const ContactOptions& options);

// The measured-summit comparison's uncertainty and sampling dependence, and the headline:
// called by the analysis once the ensemble and the coarser samplings are known.
void conclude_contact(ContactComparison& comparison);

// Throws asperity::Error for a missing or bad modulus, bad pressures, curve_points outside
// [min_curve_points, max_curve_points], or no summits.
ContactComparison compare_contact(const SampleAssessment& summit_fit, const Summits& summits,
                                  const SpectralMoments& moments, double measured_area, const ContactOptions& options);

}  // namespace asperity::topography

namespace asperity {
ASPERITY_DEFINE_RECORD(topography::ModelContact, ASPERITY_MODEL_CONTACT_FIELDS)
ASPERITY_DEFINE_RECORD(topography::SamplingContact, ASPERITY_SAMPLING_CONTACT_FIELDS)
ASPERITY_DEFINE_RECORD(topography::ContactComparison, ASPERITY_CONTACT_COMPARISON_FIELDS)
}  // namespace asperity
