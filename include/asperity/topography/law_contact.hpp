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
#include "asperity/scene.hpp"
#include "asperity/surface.hpp"
#include "asperity/topography/contact_comparison.hpp"
#include "asperity/topography/goodness_of_fit.hpp"
#include "asperity/topography/summits.hpp"

namespace asperity::topography {

// The user's law and material on `surface` over the dimensionless separations [s_min, s_max]
// (origin convention) as a law scene; throws asperity::Error for a material the law lacks or
// does not take (`asperity surface --law`: the command's options through the scene's checks).
using LawSceneMaker = std::function<SceneLaw(const RoughSurface& surface, double s_min, double s_max)>;

// One material parameter of the law (the registry's, contact_law_registry.hpp) and the value the
// law was made with (its default where not given; a choice parameter: its index).
struct LawParameterValue {
  LawParameter parameter;
  double value;
};

struct LawContact {
  std::string law;                 // its name (asperity::contact_law_name)
  // every parameter the law takes, in the registry's order for the law (Hertz: none), and the
  // same in words ("Y = 1e+09 Pa, nu = 0.3": asperity::law_parameters_text)
  std::vector<LawParameterValue> parameters;
  std::string parameters_text;
  HeightModel fit = HeightModel::gaussian;  // the fit the curves are of (to_string: its name in the outputs)
  std::string model_reason;        // why that fit
  RoughSurface surface;            // its surface (the elastic curves' too)
  // the plasticity index from the measured summits
  double summit_height_sd = 0;     // sigma_s: standard deviation of the measured summit heights [m]
  double summit_radius = 0;        // R [m]
  double contact_modulus = 0;      // E* [Pa]
  double hardness = 0.0 / 0.0;     // H of GW's psi [Pa]; NaN: the law has none (JG, Hertz)
  double critical_interference = 0.0 / 0.0;  // the law's omega_c of first yield at R [m]; NaN: none (Hertz)
  double plasticity_index = 0.0 / 0.0;       // (sigma_s / omega_c)^1/2
  double gw_plasticity_index = 0.0 / 0.0;    // (E*/H)(sigma_s/R)^1/2
  double valid_up_to = 0;          // the largest interference the law's source supports [m] (inf: every one)
  std::string regime;              // what psi says, in words, naming the definition
  // an adhesive law (DMT, JKR, Maugis-Dugdale; the approach branch): Fuller-Tabor's adhesion
  // parameter sigma_s / delta_c (asperity::adhesion_parameter), the law's length scale (Maugis'
  // d_s), and the pull-off of its curves: the greatest tension [Pa] and where (mean separation
  // from the fit's mean summit height [m]); NaN where not adhesive or not served
  bool adhesive = false;
  double adhesion_parameter = 0.0 / 0.0, adhesion_length = 0.0 / 0.0;
  double pull_off_pressure = 0.0 / 0.0, pull_off_mean_separation = 0.0 / 0.0;
  // the curves
  bool served = false;
  std::string note;                // the table made (nodes, stored error bound) or why there are none
  double separation_min = 0, separation_max = 0;  // dimensionless separations tabulated
  int nodes = 0;
  double max_rel_error[3] = {0, 0, 0};  // stored bound: pressure, stiffness, area fraction
  // the law's states over the comparison's curve pressures and at its pressures of interest
  // (count NaN: the law's table does not hold it); separations as every model's (mean_separation
  // from the fit's mean summit height, separation in the origin convention)
  std::vector<PhysicalState> curve, at_pressures;
  std::vector<PhysicalState> elastic_at_pressures;  // the same fit's elastic (Hertz) states
  // at each pressure of interest, the law against the elastic curve
  std::vector<double> area_over_elastic, stiffness_over_elastic, separation_minus_elastic;
  std::vector<std::string> warnings;  // e.g. an area fraction past GW's sparse-contact limit
};

// The law on `model`'s fit of the comparison (served: its elastic curves are the comparison's).
// Throws asperity::Error from `make` (the material), or for a model without elastic curves; a
// law whose curves cannot be tabulated gets its plasticity index and the reason (served false).
LawContact compare_law(const ContactComparison& comparison, const Summits& summits, HeightModel model,
                       const std::string& model_reason, const LawSceneMaker& make);

}  // namespace asperity::topography
