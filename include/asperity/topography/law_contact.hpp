// A measured surface under a contact law (issue 30 item 6; docs/surfaces.md, "The surface under
// a contact law"): its plasticity index from the measured summits, and the law's rough-surface
// curves for one fitted summit-height model next to that model's elastic (Hertz) curves at the
// pressures of interest.
//
//   psi (the law's)  (sigma_s / omega_c)^1/2: Kogut-Etsion 2003's with the CEB/KE omega_c, JG's
//                    with JG's (asperity::plasticity_index)
//   psi (GW's)       (E*/H)(sigma_s/R)^1/2 (asperity::greenwood_williamson_plasticity_index), for
//                    a law with a hardness (CEB, ZMC: H; KE: 2.8 Y); GW 1966: < 0.6 elastic, > 1
//                    plastic at practically every load
// with sigma_s the standard deviation of the measured summit heights and R the measured summit
// radius 1/<kappa_m> (the radius of GW on the measured summits).
//
// The law's curves are tabulated by the generator (asperity::generator::generate_law_curves,
// a law scene made by the caller's LawSceneMaker, so that its material is checked as a scene's)
// on the fitted model's surface (its distribution, shape and scale; the measured summit density
// and radius; the comparison's nominal area and E*), over the separations where the law's
// pressure covers the comparison's pressure range, and served as contact curves (ContactCurves).
// Where they cannot be tabulated there (an area fraction beyond 1, interferences past the law's
// source), the plasticity index is still given and the reason stated. An adhesive law's curves
// (their approach branch) are compared at the same positive pressures on their stable branch,
// and tabulated on past the pull-off, which is reported with Fuller-Tabor's adhesion parameter
// instead of a plasticity index.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "asperity/contact_law_registry.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/record_fields.hpp"
#include "asperity/scene.hpp"
#include "asperity/surface.hpp"
#include "asperity/topography/contact_comparison.hpp"
#include "asperity/topography/goodness_of_fit.hpp"
#include "asperity/topography/summits.hpp"

namespace asperity::topography {

// The user's law and material on `surface` over the dimensionless separations [s_min, s_max]
// (origin convention) as a law scene, an adhesive law's withdrawal branch after an approach to
// approach_separation (s0 <= s_min; NaN: the approach branch); throws asperity::Error for a
// material the law lacks or does not take, or an s0 it refuses (`asperity surface --law`: the
// command's options through the scene's checks).
using LawSceneMaker =
    std::function<SceneLaw(const RoughSurface& surface, double s_min, double s_max, double approach_separation)>;

// One material parameter of the law (the registry's, contact_law_registry.hpp) and the value the
// law was made with (its default where not given; a choice parameter: its index).
struct LawParameterValue {
  LawParameter parameter;
  double value;
};

// The law on a fit; its fields defined once (a record's list, record_fields.hpp): report.json's
// contact.law object holds the written fields, and the writer composes the others into its nested
// objects (parameters, plasticity, adhesion, separation_range, max_rel_error, at_pressures)
#define ASPERITY_LAW_CONTACT_FIELDS(X)                                                                      \
  X(std::string, law, "law", "its name (asperity::contact_law_name)")                                      \
  X(HeightModel, fit, "model", "the fit the curves are of", HeightModel::gaussian)                        \
  X(std::string, model_reason, "model_reason", "why that fit")                                             \
  X(std::vector<LawParameterValue>, parameters, nullptr,                                                   \
    "every parameter the law takes, in the registry's order for the law (Hertz: none)")                   \
  X(std::string, parameters_text, nullptr, "the same in words (asperity::law_parameters_text)")          \
  X(RoughSurface, surface, nullptr, "the fit's surface (the elastic curves' too)")                        \
  X(double, summit_height_sd, nullptr, "sigma_s: standard deviation of the measured summit heights [m]", 0) \
  X(double, summit_radius, nullptr, "R, the measured summit radius [m]", 0)                              \
  X(double, contact_modulus, nullptr, "E* [Pa]", 0)                                                        \
  X(double, hardness, nullptr, "H of GW's psi [Pa]; NaN: the law has none (JG, Hertz)", 0.0 / 0.0)        \
  X(double, critical_interference, nullptr, "the law's omega_c of first yield at R [m]; NaN: none (Hertz)", \
    0.0 / 0.0)                                                                                             \
  X(double, plasticity_index, nullptr, "(sigma_s / omega_c)^1/2", 0.0 / 0.0)                               \
  X(double, gw_plasticity_index, nullptr, "(E*/H)(sigma_s/R)^1/2", 0.0 / 0.0)                              \
  X(double, valid_up_to, nullptr, "the largest interference the law's source supports [m] (inf: every one)", 0) \
  X(std::string, regime, nullptr, "what psi says, in words, naming the definition")                       \
  X(bool, adhesive, nullptr, "an adhesive law (DMT, JKR, Maugis-Dugdale)", false)                         \
  X(double, approach_separation, nullptr,                                                                  \
    "an adhesive law's withdrawal branch after an approach to this dimensionless separation (the fit's "   \
    "scale, origin convention); NaN: the approach branch", 0.0 / 0.0)                                      \
  X(double, adhesion_parameter, nullptr, "Fuller-Tabor's sigma_s / delta_c; NaN where not adhesive", 0.0 / 0.0) \
  X(double, adhesion_length, nullptr, "the law's length scale (Maugis' d_s) [m]; NaN where not adhesive",  \
    0.0 / 0.0)                                                                                             \
  X(double, pull_off_pressure, nullptr, "the curves' greatest tension [Pa]; NaN where not adhesive or not served", \
    0.0 / 0.0)                                                                                             \
  X(double, pull_off_mean_separation, nullptr,                                                             \
    "where: mean separation from the fit's mean summit height [m]; NaN where not adhesive or not served", 0.0 / 0.0) \
  X(bool, served, "served", "whether the law's curves were tabulated", false)                             \
  X(std::string, note, "note", "the table made (nodes, stored error bound) or why there are none")       \
  X(double, separation_min, nullptr, "the lowest dimensionless separation tabulated", 0)                  \
  X(double, separation_max, nullptr, "the highest dimensionless separation tabulated", 0)                 \
  X(int, nodes, "nodes", "the table's nodes", 0)                                                           \
  X(double[3], max_rel_error, nullptr, "stored bound: pressure, stiffness, area fraction")                \
  X(std::vector<PhysicalState>, curve, "curve", "the law's states over the comparison's curve pressures")  \
  X(std::vector<PhysicalState>, at_pressures, nullptr,                                                     \
    "the law's states at the pressures of interest (count NaN: the law's table does not hold it)")        \
  X(std::vector<PhysicalState>, elastic_at_pressures, nullptr, "the same fit's elastic (Hertz) states there") \
  X(std::vector<double>, area_over_elastic, nullptr, "at each pressure of interest, the law's area over the elastic") \
  X(std::vector<double>, stiffness_over_elastic, nullptr, "the law's stiffness over the elastic")         \
  X(std::vector<double>, separation_minus_elastic, nullptr, "the law's mean separation less the elastic [m]") \
  X(std::vector<std::string>, warnings, "warnings", "e.g. an area fraction past GW's sparse-contact limit")

// Separations are every model's (mean_separation from the fit's mean summit height, separation in
// the origin convention).
struct LawContact {
  ASPERITY_LAW_CONTACT_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

// The law on `model`'s fit of the comparison (served: its elastic curves are the comparison's).
// Throws asperity::Error from `make` (the material, an approach separation it refuses), or for a
// model without elastic curves; a law whose curves cannot be tabulated gets its plasticity index
// and the reason (served false). With approach_separation s0 (an adhesive law's; dimensionless in
// the fit's scale, origin convention) the curves are the withdrawal branch after an approach to
// s0, from where its pressure covers the comparison's largest (at or above s0) on; an approach
// that does not reach that pressure is the reason (served false).
LawContact compare_law(const ContactComparison& comparison, const Summits& summits, HeightModel model,
                       const std::string& model_reason, const LawSceneMaker& make,
                       double approach_separation = 0.0 / 0.0);

}  // namespace asperity::topography

namespace asperity {
ASPERITY_DEFINE_RECORD(topography::LawContact, ASPERITY_LAW_CONTACT_FIELDS)
}  // namespace asperity
