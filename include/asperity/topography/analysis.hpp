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
  // with `law`, an adhesive law's withdrawal branch after an approach to this dimensionless
  // separation (the fit's scale, origin convention: law_contact.hpp's compare_law); NaN: approach
  double law_approach_separation = 0.0 / 0.0;
  EnsembleProgress progress;              // the ensemble's progress (surrogates done of total)
  ExactProgress exact_progress;           // the exact contact's (load steps done of total)
};

// Summits and moments at factor times the sampling interval (report.json's sampling_dependence);
// its fields defined once (record_fields.hpp)
#define ASPERITY_SAMPLING_ROW_FIELDS(X)                                           \
  X(std::size_t, factor, "factor", "every factor-th point in x and y", 1)        \
  X(double, dx, "dx_m", "the sampling interval along x [m]")                      \
  X(double, dy, "dy_m", "the sampling interval along y [m]")                      \
  X(std::size_t, summits, "summits", "the summits found")                        \
  X(double, density, "density_per_m2", "summits per unit area [1/m^2]")           \
  X(double, radius, "radius_m", "the summit radius R = 1 / <kappa_m> [m]")        \
  X(double, m2, "m2", "the equivalent isotropic slope variance")                  \
  X(double, m4, "m4_per_m2", "the equivalent isotropic curvature variance [1/m^2]") \
  X(double, alpha, "alpha", "Nayak's bandwidth m0 m4 / m2^2")                     \
  X(double, anisotropy, "anisotropy", "the ratio of the principal slope variances", 1)

struct SamplingRow {
  ASPERITY_SAMPLING_ROW_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

// A map whose roughness is at the level of its height quantization q (HeightMap::
// height_resolution, and never below 4 double spacings at the largest height read): Sq within
// 10 times the rms of rounding to q (q / sqrt(12)), i.e. under 2.9 q, or every height equal. Its
// summits would be rounding noise: it gets its statistics and this statement, never summits,
// fits or contact curves.
#define ASPERITY_NOISE_FLOOR_FIELDS(X)                                                      \
  X(bool, reached, "reached", "the roughness is at the heights' quantization: no summits, fits or curves") \
  X(double, resolution, "height_resolution_m", "q, the heights' quantization step [m]")   \
  X(double, rms_limit, "rms_limit_m", "10 q / sqrt(12) [m]")                               \
  X(std::string, text, "text", "the statement, in words")

struct NoiseFloor {
  ASPERITY_NOISE_FLOOR_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

// A surface analysed; its fields defined once (a record's list, record_fields.hpp): report.json
// holds its written records as their objects (noise_floor, statistics, correlation,
// sampling_dependence), and the writer composes the others' (the surface, the leveling, the
// spectral moments, the summits, the fits, the ensemble, the verdict, the contact curves)
#define ASPERITY_SURFACE_ANALYSIS_FIELDS(X)                                                              \
  X(HeightMap, map, nullptr, "the map as analysed (leveled when asked)")                                \
  X(NoiseFloor, noise_floor, "noise_floor",                                                              \
    "whether the roughness is at the level of the heights' quantization (then no summits, fits or contact " \
    "curves follow the statistics)")                                                                     \
  X(bool, leveled, nullptr, "whether the least-squares plane was subtracted", false)                    \
  X(Plane, plane, nullptr, "the plane subtracted")                                                       \
  X(HeightStatistics, statistics, "statistics", "the heights' statistics")                              \
  X(SpectralMoments, moments, nullptr, "the spectral moments")                                           \
  X(CorrelationLengths, correlation, "correlation", "the correlation lengths")                          \
  X(Summits, summits, nullptr, "the summits")                                                            \
  X(std::vector<SamplingRow>, sampling, "sampling_dependence", "summits and moments at 1, 2, 4 times dx") \
  X(SampleAssessment, summit_heights, nullptr, "the fits of the summit heights")                        \
  X(std::size_t, summits_fitted, nullptr,                                                                \
    "the summit heights fitted (all, or a random subsample of AnalysisOptions.max_fit_sample)", 0)       \
  X(std::optional<SampleAssessment>, heights, nullptr,                                                   \
    "the fits of the heights (a fixed random sample of points), or none")                                \
  X(std::size_t, surrogates, nullptr, "the ensemble's size", 0)                                          \
  X(std::size_t, padded_nx, nullptr, "the ensemble's fields' grid before cutting: points along x", 0)   \
  X(std::size_t, padded_ny, nullptr, "the ensemble's fields' grid before cutting: points along y", 0)   \
  X(SurfaceVerdict, verdict, nullptr, "the verdict")                                                     \
  X(std::optional<ContactComparison>, contact, nullptr, "the contact curves, or none (no contact modulus)") \
  X(AnalysisOptions, options, nullptr, "the options it was made with")

struct SurfaceAnalysis {
  ASPERITY_SURFACE_ANALYSIS_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
  // with AnalysisOptions::law (kept off the list: report.json's contact.law, law_contact.hpp)
  std::optional<LawContact> law;
};

// The verdict of an analysis (surface_verdict.hpp: its tests, and its contact curves when there are any).
SurfaceVerdict surface_verdict(const SurfaceAnalysis& analysis);

// Throws asperity::Error (naming the map's source) for a map that is not one (HeightMap::
// validate), heights all below 1 fm in size (a unit slip), too few summits, or bad options. A map at its
// noise floor is not an error: the result says so (SurfaceAnalysis::noise_floor).
SurfaceAnalysis analyse_height_map(HeightMap map, const AnalysisOptions& options = {});
SurfaceAnalysis analyse_surface_file(const std::string& path, const AnalysisOptions& options = {});

}  // namespace asperity::topography

namespace asperity {
ASPERITY_DEFINE_RECORD(topography::SamplingRow, ASPERITY_SAMPLING_ROW_FIELDS)
ASPERITY_DEFINE_RECORD(topography::NoiseFloor, ASPERITY_NOISE_FLOOR_FIELDS)
ASPERITY_DEFINE_RECORD(topography::SurfaceAnalysis, ASPERITY_SURFACE_ANALYSIS_FIELDS)
}  // namespace asperity
