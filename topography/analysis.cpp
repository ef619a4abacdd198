#include "asperity/topography/analysis.hpp"

#include <algorithm>
#include <cmath>

#include "asperity/error.hpp"

namespace asperity::topography {

SurfaceAnalysis analyse_height_map(HeightMap map, const AnalysisOptions& options) {
  map.validate();
  SurfaceAnalysis analysis;
  analysis.options = options;
  if (options.level) {
    analysis.plane = fit_plane(map);
    subtract_plane(map, analysis.plane);
    analysis.leveled = true;
    map.notes.push_back("leveled: least-squares plane subtracted");
  }
  analysis.statistics = height_statistics(map);
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
