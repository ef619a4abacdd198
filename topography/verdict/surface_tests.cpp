#include "asperity/topography/surface_tests.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <random>

#include "asperity/detail/parallel_for.hpp"
#include "asperity/error.hpp"
#include "asperity/topography/leveling.hpp"
#include "asperity/topography/surrogates.hpp"
#include "sample_verdict.hpp"
#include "statistics/plane_fit.hpp"

namespace asperity::topography {
namespace {

using verdict::nan;
using verdict::bias_step;
using verdict::splitmix64;
using verdict::Refit;

// ln Phi(z), accurate far into both tails
double log_normal_cdf(double z) {
  if (z > -30) return std::log(normal_cdf(z));
  const double z2 = z * z;
  return -0.5 * z2 - 0.91893853320467274178 - std::log(-z) + std::log1p(-1 / z2 + 3 / (z2 * z2));
}

// k of n indices, a reproducible random choice (partial Fisher-Yates), in ascending order
std::vector<std::size_t> choose(std::size_t n, std::size_t k, std::uint64_t seed) {
  std::vector<std::size_t> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = i;
  if (k >= n) return all;
  std::mt19937_64 engine(seed);
  for (std::size_t i = 0; i < k; ++i) std::swap(all[i], all[i + static_cast<std::size_t>(engine() % (n - i))]);
  all.resize(k);
  std::sort(all.begin(), all.end());
  return all;
}

// F^-1(Phi(g)) tabulated on a fine grid of g and interpolated linearly (within ~1e-7 of the
// scale; direct beyond the table): the Weibull surrogate of a whole surface.
class MarginalTable {
 public:
  explicit MarginalTable(const HeightDistribution& marginal) : marginal_(marginal) {
    values_.resize(points);
    for (std::size_t k = 0; k < points; ++k) values_[k] = surrogate_height(marginal, lo + step * static_cast<double>(k));
  }
  double at(double g) const noexcept {
    const double position = (g - lo) / step;
    if (!(position >= 0 && position < static_cast<double>(points - 1)))
      return std::isnan(g) ? g : surrogate_height(marginal_, g);
    const std::size_t i = static_cast<std::size_t>(position);
    const double f = position - static_cast<double>(i);
    return values_[i] + f * (values_[i + 1] - values_[i]);
  }

 private:
  static constexpr std::size_t points = 16385;
  static constexpr double lo = -8, step = 16.0 / (points - 1);
  HeightDistribution marginal_;
  std::vector<double> values_;
};


}  // namespace

double surrogate_height(const HeightDistribution& marginal, double g) noexcept {
  switch (marginal.model) {
    case HeightModel::gaussian: return marginal.location + marginal.scale * g;
    case HeightModel::weibull_tail:  // W = (-ln(1 - Phi(g)))^(1/a) = (-ln Phi(-g))^(1/a)
      return marginal.location + marginal.scale * std::pow(-log_normal_cdf(-g), 1 / marginal.shape);
    case HeightModel::weibull_bounded:  // bounded above: x = location - scale (-ln Phi(g))^(1/a)
      return marginal.location - marginal.scale * std::pow(-log_normal_cdf(g), 1 / marginal.shape);
  }
  return nan;
}

SurfaceTests test_surface(const HeightMap& map, const std::vector<double>& summit_heights,
                          const CorrelationLengths& lengths, const SurfaceTestOptions& options,
                          const EnsembleProgress& progress) {
  const AssessmentOptions& a = options.assessment;
  if (!(a.confidence > 0 && a.confidence < 1)) throw Error("assessment: confidence must be in (0, 1)");
  if (!(a.significance > 0 && a.significance < 1)) throw Error("assessment: significance must be in (0, 1)");
  check_bootstrap_size(a.bootstrap, a.significance);
  SurfaceTests tests;
  tests.surrogates = static_cast<std::size_t>(a.bootstrap);

  // the samples: a fixed random set of valid positions, and the summit heights
  std::vector<std::size_t> valid;
  for (std::size_t k = 0; k < map.heights.size(); ++k)
    if (!std::isnan(map.heights[k])) valid.push_back(k);
  for (std::size_t k : choose(valid.size(), options.height_sample, splitmix64(a.seed ^ 0x4e16475ull)))
    tests.height_positions.push_back(valid[k]);
  std::vector<double> heights;
  for (std::size_t k : tests.height_positions) heights.push_back(map.heights[k]);
  std::sort(heights.begin(), heights.end());
  std::vector<double> summits = summit_heights;
  std::sort(summits.begin(), summits.end());
  if (heights.size() < 5 || summits.size() < 5) throw Error(map.source + ": too few heights or summits to test");

  SampleAssessment& H = tests.heights;
  SampleAssessment& S = tests.summit_heights;
  H.name = "heights (a random sample of " + std::to_string(heights.size()) + " points)";
  S.name = "summit heights";
  H.n = heights.size();
  S.n = summits.size();
  H.options = S.options = a;
  for (HeightModel model : all_height_models) {
    H.models.push_back(verdict::observed(model, heights, a.fit));
    S.models.push_back(verdict::observed(model, summits, a.fit));
  }

  if (a.bootstrap > 0) {
    const SurrogateFields fields(map, lengths, options.leveled, a.threads);
    tests.padded_nx = fields.padded_nx();
    tests.padded_ny = fields.padded_ny();
    const std::size_t B = static_cast<std::size_t>(a.bootstrap);
    // each Weibull marginal as a table in g: a surface's worth of transforms at a few ns each
    std::vector<MarginalTable> tables;
    for (int m = 0; m < 3; ++m) tables.emplace_back(H.models[static_cast<std::size_t>(m)].fit.distribution);
    // The heights' Weibull intervals correct the estimator's bias for its change with the shape:
    // the same surrogate fields (common random numbers) also mapped to the marginal of shape
    // a_hat e^-bias_step and refitted, so the bias is known at two shapes (see conclude).
    std::vector<HeightDistribution> stepped(3);
    for (int m = 1; m < 3; ++m) {
      stepped[static_cast<std::size_t>(m)] = H.models[static_cast<std::size_t>(m)].fit.distribution;
      stepped[static_cast<std::size_t>(m)].shape *= std::exp(-bias_step);
      tables.emplace_back(stepped[static_cast<std::size_t>(m)]);  // tables[2 + m]
    }
    // refits[b][sample * 3 + model]; [6 + model]: the heights at the stepped shape
    std::vector<std::array<Refit, 9>> refits(B);
    std::mutex progress_mutex;
    std::size_t done = 0;
    asperity::detail::parallel_for(B, a.threads, [&](std::size_t b) {
      std::vector<double> g;
      fields.generate(a.seed, b, g);
      HeightMap surface;
      surface.nx = map.nx;
      surface.ny = map.ny;
      surface.dx = map.dx;
      surface.dy = map.dy;
      surface.source = "surrogate";
      // the Gaussian surface (its scale, so that a height threshold in metres means the same),
      // leveled as the map was: its summits are every model's (a monotone map keeps them; the
      // leveling of the others moves them by far less than a point)
      const HeightDistribution& gaussian_marginal = H.models[0].fit.distribution;
      surface.heights.resize(g.size());
      for (std::size_t k = 0; k < g.size(); ++k) surface.heights[k] = surrogate_height(gaussian_marginal, g[k]);
      if (options.leveled) subtract_plane(surface, fit_plane(surface));
      const Summits found = find_summits(surface, options.summits);
      if (options.on_surrogate) options.on_surrogate(b, found);
      std::vector<std::size_t> summit_points;
      for (std::size_t k : choose(found.list.size(), options.max_summits, splitmix64(a.seed ^ (0x5u + b * 7919u))))
        summit_points.push_back(found.list[k].j * map.nx + found.list[k].i);
      std::vector<double> x_heights(tests.height_positions.size()), x_summits(summit_points.size());
      // A Weibull model's surface, F^-1(Phi(g)), leveled as the map was (leveling a skewed surface
      // changes its marginal: left out, the heights' shape intervals missed the truth in half the
      // maps): its plane fitted over every point, the surface itself evaluated only at the samples.
      const auto sample = [&](const auto& height, const Plane& plane, const std::vector<std::size_t>& points,
                              std::vector<double>& out) {
        for (std::size_t k = 0; k < out.size(); ++k)
          out[k] = height(points[k]) - plane_height(plane, map, points[k] % map.nx, points[k] / map.nx);
        std::sort(out.begin(), out.end());
      };
      const auto leveled_plane = [&](const auto& height) {
        return options.leveled ? detail::fit_plane_of(map, "surrogate", height) : Plane{};
      };
      const auto gaussian_height = [&](std::size_t k) { return surface.heights[k]; };  // leveled already
      for (int m = 0; m < 3; ++m) {
        const HeightModel model = all_height_models[m];
        const HeightDistribution& marginal = H.models[static_cast<std::size_t>(m)].fit.distribution;
        const MarginalTable& table = tables[static_cast<std::size_t>(m)];
        const auto weibull_height = [&](std::size_t k) { return table.at(g[k]); };
        if (model == HeightModel::gaussian) {
          sample(gaussian_height, Plane{}, tests.height_positions, x_heights);
          sample(gaussian_height, Plane{}, summit_points, x_summits);
        } else {
          const Plane plane = leveled_plane(weibull_height);
          sample(weibull_height, plane, tests.height_positions, x_heights);
          sample(weibull_height, plane, summit_points, x_summits);
        }
        if (options.test_heights) refits[b][static_cast<std::size_t>(m)] = verdict::refit(model, x_heights, marginal, a.fit);
        if (x_summits.size() >= 5)
          refits[b][static_cast<std::size_t>(3 + m)] =
              verdict::refit(model, x_summits, S.models[static_cast<std::size_t>(m)].fit.distribution, a.fit);
        if (options.test_heights && model != HeightModel::gaussian) {  // the same field at the stepped shape
          const MarginalTable& stepped_table = tables[static_cast<std::size_t>(2 + m)];
          const auto stepped_height = [&](std::size_t k) { return stepped_table.at(g[k]); };
          sample(stepped_height, leveled_plane(stepped_height), tests.height_positions, x_heights);
          refits[b][static_cast<std::size_t>(6 + m)] = verdict::refit(model, x_heights, stepped[static_cast<std::size_t>(m)], a.fit);
        }
      }
      if (progress) {
        std::lock_guard<std::mutex> lock(progress_mutex);
        progress(++done, B);
      }
    });
    for (int m = 0; m < 3; ++m) {
      std::vector<Refit> of_heights, of_summits, of_stepped;
      for (const auto& r : refits) {
        of_heights.push_back(r[static_cast<std::size_t>(m)]);
        of_summits.push_back(r[static_cast<std::size_t>(3 + m)]);
        if (m > 0) of_stepped.push_back(r[static_cast<std::size_t>(6 + m)]);
      }
      if (options.test_heights)
        verdict::conclude(H.models[static_cast<std::size_t>(m)], of_heights, a, verdict::ShapeInterval::bias_corrected,
                          &of_stepped);
      verdict::conclude(S.models[static_cast<std::size_t>(m)], of_summits, a, verdict::ShapeInterval::centred_on_estimate);
    }
  }
  for (SampleAssessment* sample : {&H, &S}) {
    verdict::judge(*sample, verdict::NullSamples::surrogate_surfaces);
  }
  return tests;
}

}  // namespace asperity::topography
