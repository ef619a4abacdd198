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
// scale. The Gaussian is served from the default table. Each Weibull is served from an
// exact-shape scene table generated for the fitted shape over the pressures asked
// (asperity::generator::generate_scene_table, shapes 0.3-50), or from a given full table (the
// default table: shapes 0.5-20, between grid shapes by interpolation). A fitted shape outside
// what the table serves gets no curve; the reason is stated (ModelContact::note).
//
// Separations are reported from the mean summit height of each model (comparable across
// models); pressures are nominal (load / A0), stiffness per nominal area [N/m^3] as well.
#pragma once
#include <string>
#include <vector>

#include "asperity/contact_model.hpp"
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
};

struct ModelContact {
  std::string label;               // measured-summits(-own-radii), gaussian-moments, gaussian, weibull-tail, weibull-bounded
  bool served = false;
  std::string note;                // the table that served it, or why there is no curve
  RoughSurface surface;
  double mean_summit_height = 0;   // [m], in the map's height frame (leveled)
  std::vector<PhysicalState> curve;         // over [pressure_min, pressure_max]
  std::vector<PhysicalState> at_pressures;  // at ContactComparison::pressures
  // against measured-summits at each pressure: stiffness ratio, mean separation difference [m]
  std::vector<double> stiffness_over_measured, separation_minus_measured;
};

// The measured-summit answer at a coarser sampling (every k-th point): its stiffness at each
// pressure over the answer at the file's sampling.
struct SamplingContact {
  std::size_t factor = 1;
  std::vector<double> stiffness_over_finest;
};

struct ContactComparison {
  ContactOptions options;
  std::vector<double> pressures;   // the pressures of interest [Pa]
  double pressure_min = 0, pressure_max = 0;
  double nominal_area = 0;
  std::vector<ModelContact> models;
  // How much the measured-summit answer varies between surfaces of the same statistics (its
  // relative standard deviation over the surrogate ensemble, stiffness; separation in metres):
  // the uncertainty of every ratio to it. Empty without an ensemble.
  std::vector<double> measured_stiffness_spread, measured_separation_spread;
  std::vector<SamplingContact> sampling;
  // The fitted model nearest to the measured summits at the pressures of interest (largest
  // |ln stiffness ratio| smallest), and the headline in words.
  std::string closest;
  std::string headline;
  const ModelContact* find(const std::string& label) const;
};

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
