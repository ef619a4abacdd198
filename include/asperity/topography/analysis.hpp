// The whole path from a measured height map to the evidence and the contact curves:
// read, level (least-squares plane, stated), height statistics and spectral moments, summits
// (and their dependence on the sampling interval), the three height models tested on the
// heights and on the summit heights against surrogate surfaces of the map's own spectrum
// (surface_tests.hpp: the tests carry the surface's correlation), a verdict, and the contact
// curves of each fit beside GW on the measured summits (when a contact modulus is given).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "asperity/topography/contact_comparison.hpp"
#include "asperity/topography/goodness_of_fit.hpp"
#include "asperity/topography/height_map.hpp"
#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/law_contact.hpp"
#include "asperity/topography/leveling.hpp"
#include "asperity/topography/statistics.hpp"
#include "asperity/topography/summits.hpp"
#include "asperity/topography/surface_tests.hpp"
#include "asperity/topography/surface_verdict.hpp"

namespace asperity::topography {

struct AnalysisOptions {
  ReadOptions read;
  bool level = true;                      // subtract the least-squares plane
  SummitOptions summits;
  AssessmentOptions assessment;
  bool fit_heights = true;                // also test the heights (a fixed random sample of points)
  std::size_t max_height_sample = 4000;   // the heights tested
  // The summit heights fitted and tested: all of them up to this many, else a reproducible
  // random subsample of this many (seeded by the assessment's seed; stated in the report), so
  // the bootstrap's cost does not grow with the map beyond it.
  std::size_t max_fit_sample = 20000;
  std::vector<std::size_t> sampling_factors = {1, 2, 4};  // summits at k dx (sampling dependence)
  std::optional<ContactOptions> contact;  // contact curves: needs ContactOptions::contact_modulus
  // A contact law beside the elastic curves (with `contact`): its plasticity index and its
  // curves on the fit the verdict names (law_contact.hpp); empty: none
  LawSceneMaker law;
  EnsembleProgress progress;              // the ensemble's progress (surrogates done of total)
  ExactProgress exact_progress;           // the exact contact's (load steps done of total)
};

struct SamplingRow {
  std::size_t factor = 1;
  double dx = 0, dy = 0;
  std::size_t summits = 0;
  double density = 0, radius = 0;  // [1/m^2], [m]
  double m2 = 0, m4 = 0, alpha = 0, anisotropy = 1;
};

// A map whose roughness is at the level of its height quantization q (HeightMap::
// height_resolution, and never below 4 double spacings at the largest height read): Sq within
// 10 times the rms of rounding to q (q / sqrt(12)), i.e. under 2.9 q, or every height equal. Its
// summits would be rounding noise: it gets its statistics and this statement, never summits,
// fits or contact curves.
struct NoiseFloor {
  bool reached = false;
  double resolution = 0;   // q [m]
  double rms_limit = 0;    // 10 q / sqrt(12) [m]
  std::string text;
};

struct SurfaceAnalysis {
  HeightMap map;                   // as analysed (leveled when asked)
  NoiseFloor noise_floor;          // reached: what follows the statistics is empty
  bool leveled = false;
  Plane plane;                     // the plane subtracted
  HeightStatistics statistics;
  SpectralMoments moments;
  CorrelationLengths correlation;
  Summits summits;
  std::vector<SamplingRow> sampling;
  SampleAssessment summit_heights;
  std::size_t summits_fitted = 0;  // of summits.list (AnalysisOptions::max_fit_sample)
  std::optional<SampleAssessment> heights;
  std::size_t surrogates = 0;      // the ensemble's size
  std::size_t padded_nx = 0, padded_ny = 0;  // its fields' grid before cutting
  SurfaceVerdict verdict;
  std::optional<ContactComparison> contact;
  std::optional<LawContact> law;   // with AnalysisOptions::law
  AnalysisOptions options;
};

// The verdict of an analysis (surface_verdict.hpp: its tests, and its contact curves when there are any).
SurfaceVerdict surface_verdict(const SurfaceAnalysis& analysis);

// Throws asperity::Error (naming the map's source) for a map that is not one (HeightMap::
// validate), heights all below 1 fm in size (a unit slip), too few summits, or bad options. A map at its
// noise floor is not an error: the result says so (SurfaceAnalysis::noise_floor).
SurfaceAnalysis analyse_height_map(HeightMap map, const AnalysisOptions& options = {});
SurfaceAnalysis analyse_surface_file(const std::string& path, const AnalysisOptions& options = {});

}  // namespace asperity::topography
