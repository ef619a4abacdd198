#include "asperity/topography/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "asperity/error.hpp"

namespace asperity::topography {
namespace {
constexpr double min_roughness = 1e-15;  // [m]

std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
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
  const double sq = analysis.statistics.rms;
  NoiseFloor& floor = analysis.noise_floor;
  // the rounding step of the heights: the file's, and never below what doubles (and the
  // leveling's arithmetic, a few roundings) resolve at the largest height read
  floor.resolution = std::max(map.height_resolution, 4 * (std::nextafter(largest, 2 * largest + 1) - largest));
  floor.rms_limit = 10 * floor.resolution / std::sqrt(12.0);
  if (largest > 0 && largest < min_roughness) {
    throw Error(map.source + ": every height is below " + short_number(min_roughness) +
                " m (1 fm) in size: a wrong height unit?");
  } else if (sq == 0) {
    floor.reached = true;
    floor.text = "every valid height is the same" + std::string(options.level ? " after leveling" : "") +
                 ": no roughness, so no summits, fits or contact curves";
  } else if (sq < floor.rms_limit) {
    floor.reached = true;
    floor.text = "the roughness (Sq " + short_number(sq) + " m) is at the level of the heights' quantization (" +
                 short_number(floor.resolution) + " m a step, rounding noise " +
                 short_number(floor.resolution / std::sqrt(12.0)) +
                 " m rms): its summits would be rounding noise, so no summits, fits or contact curves";
  }
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

  for (std::size_t factor : options.sampling_factors) {
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
    analysis.sampling.push_back(row);
  }

  std::vector<double> summit_heights;
  summit_heights.reserve(analysis.summits.list.size());
  for (const Summit& s : analysis.summits.list) summit_heights.push_back(s.height);
  if (options.max_fit_sample > 0 && summit_heights.size() > options.max_fit_sample) {
    // a reproducible random subsample (a partial Fisher-Yates shuffle)
    std::mt19937_64 engine(options.assessment.seed ^ 0x5eed5a3b1e5ull);
    for (std::size_t k = 0; k < options.max_fit_sample; ++k) {
      const std::size_t pick = k + static_cast<std::size_t>(engine() % (summit_heights.size() - k));
      std::swap(summit_heights[k], summit_heights[pick]);
    }
    summit_heights.resize(options.max_fit_sample);
    map.notes.push_back("fits on a random subsample of " + std::to_string(options.max_fit_sample) + " of the " +
                        std::to_string(analysis.summits.list.size()) + " summits (max_fit_sample)");
  }
  analysis.summits_fitted = summit_heights.size();
  analysis.summit_heights = assess_sample("summit heights", summit_heights, options.assessment);

  if (options.fit_heights) {
    analysis.height_stride_x = std::max<std::size_t>(1, analysis.correlation.x);
    analysis.height_stride_y = std::max<std::size_t>(1, analysis.correlation.y);
    const std::vector<double> thinned = thinned_heights(map, analysis.correlation, options.max_height_sample);
    if (thinned.size() >= 20) analysis.heights = assess_sample("heights (thinned)", thinned, options.assessment);
  }

  if (options.contact) {
    // the nominal area defaults to the measured one
    analysis.contact = compare_contact(analysis.summit_heights, analysis.summits, analysis.moments,
                                       map.width() * map.length(), *options.contact);
  }
  analysis.map = std::move(map);
  return analysis;
}

SurfaceAnalysis analyse_surface_file(const std::string& path, const AnalysisOptions& options) {
  return analyse_height_map(read_height_map(path, options.read), options);
}

}  // namespace asperity::topography
