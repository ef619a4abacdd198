#include "asperity/topography/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "asperity/error.hpp"
#include "asperity/integrals.hpp"
#include "asperity/interrupt.hpp"
#include "asperity/number_text.hpp"
#include "asperity/topography/summit_contact.hpp"
#include "asperity/topography/surface_tests.hpp"

namespace asperity::topography {
namespace {
constexpr double min_roughness = 1e-15;  // [m]

// The noise floor of the heights (largest: the largest |h| as read, sq: the rms height):
// reached when the roughness is zero or at the heights' quantization. Throws for heights all
// below 1 fm (a wrong unit).
void find_noise_floor(NoiseFloor& floor, const HeightMap& map, double largest, double sq, bool leveled) {
  // the rounding step of the heights: the file's, and never below what doubles (and the
  // leveling's arithmetic, a few roundings) resolve at the largest height read
  floor.resolution = std::max(map.height_resolution, 4 * (std::nextafter(largest, 2 * largest + 1) - largest));
  floor.rms_limit = 10 * floor.resolution / std::sqrt(12.0);
  if (largest > 0 && largest < min_roughness) {
    throw Error(map.source + ": every height is below " + three_digits(min_roughness) +
                " m (1 fm) in size: a wrong height unit?");
  } else if (sq == 0) {
    floor.reached = true;
    floor.text = "every valid height is the same" + std::string(leveled ? " after leveling" : "") +
                 ": no roughness, so no summits, fits or contact curves";
  } else if (sq < floor.rms_limit) {
    floor.reached = true;
    floor.text = "the roughness (Sq " + three_digits(sq) + " m) is at the level of the heights' quantization (" +
                 three_digits(floor.resolution) + " m a step, rounding noise " +
                 three_digits(floor.resolution / std::sqrt(12.0)) +
                 " m rms): its summits would be rounding noise, so no summits, fits or contact curves";
  }
}

// analysis.sampling: the summits and moments at each sampling factor (the map decimated).
// Returns the summits of the coarser samplings (factor > 1), for the contact's dependence.
std::vector<std::pair<std::size_t, Summits>> add_sampling_rows(SurfaceAnalysis& analysis, const HeightMap& map,
                                                               const AnalysisOptions& options) {
  std::vector<std::pair<std::size_t, Summits>> coarse_summits;  // factor > 1: the contact's dependence
  for (std::size_t factor : options.sampling_factors) {
    poll_interrupt();  // each factor: summits of a map (Ctrl-C, asperity/interrupt.hpp)
    if (factor < 1) continue;
    const HeightMap coarse = factor == 1 ? map : decimated(map, factor);
    if (coarse.nx <= 2 * static_cast<std::size_t>(options.summits.window) + 2 ||
        coarse.ny <= 2 * static_cast<std::size_t>(options.summits.window) + 2)
      continue;
    SamplingRow row;
    row.factor = factor;
    row.dx = coarse.dx;
    row.dy = coarse.dy;
    const Summits s = factor == 1 ? analysis.summits : find_summits(coarse, options.summits);
    row.summits = s.list.size();
    row.density = s.density;
    row.radius = s.radius;
    const SpectralMoments m = factor == 1 ? analysis.moments : spectral_moments(coarse);
    row.m2 = m.m2;
    row.m4 = m.m4;
    row.alpha = m.alpha;
    row.anisotropy = m.anisotropy;
    analysis.sampling.push_back(row);
    if (factor > 1 && !s.list.empty()) coarse_summits.emplace_back(factor, s);
  }
  return coarse_summits;
}

// The summit heights to fit: all, or past options.max_fit_sample a reproducible random
// subsample of them (noted on the map).
std::vector<double> summit_heights_to_fit(const Summits& summits, HeightMap& map, const AnalysisOptions& options) {
  std::vector<double> summit_heights;
  summit_heights.reserve(summits.list.size());
  for (const Summit& s : summits.list) summit_heights.push_back(s.height);
  if (options.max_fit_sample > 0 && summit_heights.size() > options.max_fit_sample) {
    // a reproducible random subsample (a partial Fisher-Yates shuffle)
    std::mt19937_64 engine(options.assessment.seed ^ 0x5eed5a3b1e5ull);
    for (std::size_t k = 0; k < options.max_fit_sample; ++k) {
      const std::size_t pick = k + static_cast<std::size_t>(engine() % (summit_heights.size() - k));
      std::swap(summit_heights[k], summit_heights[pick]);
    }
    summit_heights.resize(options.max_fit_sample);
    map.notes.push_back("fits on a random subsample of " + std::to_string(options.max_fit_sample) + " of the " +
                        std::to_string(summits.list.size()) + " summits (max_fit_sample)");
  }
  return summit_heights;
}

// Throws for an ensemble too small for the verdict's tests (0: no tests).
void check_ensemble_size(const AnalysisOptions& options) {
  // the surface verdict tests each sample at half the significance: B must reach that
  const int ensemble = options.assessment.bootstrap;
  if (ensemble > 0 && ensemble < minimum_bootstrap(options.assessment.significance / 2))
    throw Error("an ensemble of " + std::to_string(ensemble) + " surrogate surfaces can never give p below " +
                three_digits(options.assessment.significance / 2) +
                " (the verdict tests the heights and the summit heights, each at half the significance; the smallest "
                "p-value is 1/(B + 1) = " + three_digits(1.0 / (ensemble + 1)) + "): use at least " +
                std::to_string(minimum_bootstrap(options.assessment.significance / 2)) + ", or 0 for no test");
  check_bootstrap_size(ensemble, options.assessment.significance);
}

// The surface tests' options (without on_surrogate).
SurfaceTestOptions surface_test_options(const AnalysisOptions& options, std::size_t summits) {
  SurfaceTestOptions tests_options;
  tests_options.assessment = options.assessment;
  tests_options.summits = options.summits;
  tests_options.height_sample = options.max_height_sample;
  tests_options.max_summits = options.max_fit_sample > 0 ? options.max_fit_sample : summits;
  tests_options.test_heights = options.fit_heights;
  tests_options.leveled = options.level;
  return tests_options;
}

// The sample standard deviation of v (at least two values).
double sample_spread(const std::vector<double>& v) {
  double mean = 0, squares = 0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  for (double x : v) squares += (x - mean) * (x - mean);
  return std::sqrt(squares / static_cast<double>(v.size() - 1));
}

// The spread of the measured-summit answer over the ensemble (each surrogate's stiffness and
// separation at c's pressures; a surrogate without them left out).
void add_ensemble_spread(ContactComparison& c, const std::vector<std::vector<double>>& surrogate_stiffness,
                         const std::vector<std::vector<double>>& surrogate_separation) {
  for (std::size_t k = 0; k < c.pressures.size(); ++k) {
    std::vector<double> stiffness, separation;
    for (std::size_t b = 0; b < surrogate_stiffness.size(); ++b)
      if (surrogate_stiffness[b].size() == c.pressures.size()) {
        stiffness.push_back(std::log(surrogate_stiffness[b][k]));
        separation.push_back(surrogate_separation[b][k]);
      }
    if (stiffness.size() < 2) break;
    c.measured_stiffness_spread.push_back(sample_spread(stiffness));  // of ln K: relative
    c.measured_separation_spread.push_back(sample_spread(separation));
  }
}

// The measured-summit answer at coarser samplings, over the finest's.
void add_sampling_contact(ContactComparison& c, const std::vector<std::pair<std::size_t, Summits>>& coarse_summits,
                          double contact_modulus) {
  const ModelContact* finest = c.find(ContactModelKind::measured_summits);
  for (const auto& [factor, coarse] : coarse_summits) {
    if (!finest || !finest->served) break;
    try {
      const SummitContact contact(coarse, contact_modulus, c.nominal_area);
      SamplingContact row;
      row.factor = factor;
      for (std::size_t k = 0; k < c.pressures.size(); ++k)
        row.stiffness_over_finest.push_back(contact.at_pressure(c.pressures[k]).stiffness /
                                            finest->at_pressures[k].stiffness);
      c.sampling.push_back(row);
    } catch (const Error&) {
    }
  }
}

// analysis.law: the law on the fit the verdict names for the contact, else the lowest AIC with
// curves.
void add_contact_law(SurfaceAnalysis& analysis, const HeightMap& map, const AnalysisOptions& options) {
  const SurfaceVerdict& v = analysis.verdict;
  int model = v.named ? static_cast<int>(v.model) : -1;
  std::string reason = "the verdict's model for the contact";
  if (model < 0) {
    for (HeightModel candidate : all_height_models) {
      const ModelContact* curves = analysis.contact->find(to_string(candidate));
      if (!curves || !curves->served) continue;
      if (model < 0 || analysis.summit_heights.model(candidate).aic <
                           analysis.summit_heights.models[static_cast<std::size_t>(model)].aic)
        model = static_cast<int>(candidate);
    }
    reason = "no model is named by the verdict: the fit of the lowest AIC with elastic curves";
  }
  if (model < 0) throw Error(map.source + ": contact law: no fitted model has elastic curves to set the law beside");
  analysis.law = compare_law(*analysis.contact, analysis.summits, static_cast<HeightModel>(model), reason, options.law,
                             options.law_approach_separation);
}

}  // namespace

SurfaceAnalysis analyse_height_map(HeightMap map, const AnalysisOptions& options) {
  map.validate();
  SurfaceAnalysis analysis;
  analysis.options = options;
  double largest = 0;  // |h| as read, before leveling
  for (double h : map.heights)
    if (!std::isnan(h)) largest = std::max(largest, std::fabs(h));
  if (options.level) {
    analysis.plane = fit_plane(map);
    subtract_plane(map, analysis.plane);
    analysis.leveled = true;
    map.notes.push_back("leveled: least-squares plane subtracted");
  }
  analysis.statistics = height_statistics(map);
  NoiseFloor& floor = analysis.noise_floor;
  find_noise_floor(floor, map, largest, analysis.statistics.rms, options.level);
  if (floor.reached) {
    map.notes.push_back("noise floor: " + floor.text);
    analysis.map = std::move(map);
    return analysis;
  }
  analysis.moments = spectral_moments(map);
  analysis.correlation = correlation_lengths(map, 0.1);
  analysis.summits = find_summits(map, options.summits);
  if (analysis.summits.list.size() < 5)
    throw Error(map.source + ": " + std::to_string(analysis.summits.list.size()) +
                " summits: too few to fit a distribution (a smaller summit window or threshold?)");

  const std::vector<std::pair<std::size_t, Summits>> coarse_summits = add_sampling_rows(analysis, map, options);
  const std::vector<double> summit_heights = summit_heights_to_fit(analysis.summits, map, options);
  analysis.summits_fitted = summit_heights.size();

  // the pressures and area of the contact, known before the ensemble: each surrogate's measured-
  // summit answer gives that answer's spread
  std::vector<double> pressures;
  double nominal_area = 0;
  if (options.contact) {
    pressures = contact_pressures(*options.contact);
    nominal_area = options.contact->nominal_area > 0 ? options.contact->nominal_area : map.width() * map.length();
  }
  std::vector<std::vector<double>> surrogate_stiffness, surrogate_separation;

  check_ensemble_size(options);
  SurfaceTestOptions tests_options = surface_test_options(options, analysis.summits.list.size());
  if (options.contact && options.assessment.bootstrap > 0) {
    surrogate_stiffness.assign(static_cast<std::size_t>(options.assessment.bootstrap), {});
    surrogate_separation.assign(static_cast<std::size_t>(options.assessment.bootstrap), {});
    const double modulus = options.contact->contact_modulus;
    tests_options.on_surrogate = [&, modulus, nominal_area](std::size_t b, const Summits& summits) {
      try {
        const SummitContact contact(summits, modulus, nominal_area);
        for (double p : pressures) {
          const PhysicalState state = contact.at_pressure(p);
          surrogate_stiffness[b].push_back(state.stiffness);
          surrogate_separation[b].push_back(state.mean_separation);
        }
      } catch (const Error&) {  // a surrogate without summits: left out
      }
    };
  }
  SurfaceTests tests = test_surface(map, summit_heights, analysis.correlation, tests_options, options.progress);
  analysis.summit_heights = std::move(tests.summit_heights);
  if (options.fit_heights) analysis.heights = std::move(tests.heights);
  analysis.surrogates = tests.surrogates;
  analysis.padded_nx = tests.padded_nx;
  analysis.padded_ny = tests.padded_ny;

  if (options.contact) {
    // the nominal area defaults to the measured one
    analysis.contact = compare_contact(analysis.summit_heights, analysis.summits, analysis.moments,
                                       map.width() * map.length(), *options.contact);
    ContactComparison& c = *analysis.contact;
    // Persson and the exact contact, separations from the same mean summit height as the rest
    double mean_summit = 0;
    for (const Summit& s : analysis.summits.list) mean_summit += s.height;
    mean_summit /= static_cast<double>(analysis.summits.list.size());
    add_reference_contact(c, map, mean_summit, options.exact_progress);
    // the spread of the measured-summit answer over the ensemble
    add_ensemble_spread(c, surrogate_stiffness, surrogate_separation);
    // the measured-summit answer at coarser samplings
    add_sampling_contact(c, coarse_summits, options.contact->contact_modulus);
    conclude_contact(c);
  }
  analysis.verdict = surface_verdict(analysis);
  if (options.law && analysis.contact) {
    // the law on the fit the verdict names for the contact, else the lowest AIC with curves
    add_contact_law(analysis, map, options);
  }
  analysis.map = std::move(map);
  return analysis;
}

SurfaceVerdict surface_verdict(const SurfaceAnalysis& a) {
  SurfaceEvidence evidence;
  evidence.summit_heights = &a.summit_heights;
  evidence.heights = a.heights ? &*a.heights : nullptr;
  evidence.surrogates = a.surrogates;
  if (a.noise_floor.reached) evidence.no_verdict = a.noise_floor.text;
  if (a.contact) {
    const ContactComparison& contact = *a.contact;
    evidence.has_contact_curves = [&contact](HeightModel model) {
      const ModelContact* curves = contact.find(to_string(model));
      return curves && curves->served;
    };
    evidence.contact_headline = contact.headline;
  }
  return surface_verdict(evidence);
}

SurfaceAnalysis analyse_surface_file(const std::string& path, const AnalysisOptions& options) {
  return analyse_height_map(read_height_map(path, options.read), options);
}

}  // namespace asperity::topography
