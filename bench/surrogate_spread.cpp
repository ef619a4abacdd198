// The heights' test's null distribution, by the surrogates and by the process (issue 40, item 1:
// the diagnosis of docs/surfaces.md, "Steep spectra"): the Anderson-Darling A^2 of a Gaussian
// fitted to 4,000 heights of each leveled map of a family, against the same A^2 on 99 surrogates
// of each map (SurrogateFields, leveled as the map). Where the surrogates' A^2 spreads less than
// the maps' own, the test rejects too often.
//
//   surrogate_spread [--hurst H | --exponential XI] [--size N] [--ny NY] [--maps M] [--surrogates B]
//                    [--seed-offset K] [--oversize F]
//
// --hurst: a self-affine field without roll-off (synthetic.hpp, cut from a draw --oversize, 4, times
// the map); --exponential: of exponential correlation XI points. The maps' seeds are
// surface_ensembles' (the same maps). Prints the maps' A^2 median and 90% and 95% quantiles, the
// surrogates' (pooled over the maps), and how many maps' p = (1 + #{A^2_b >= A^2}) / (B + 1) is at
// most 0.05 and 0.025 (the verdict tests the heights at 0.025); last, the surrogates' mean Nayak
// alpha (spectral_moments of the leveled fields) over the map's, averaged over the maps: what the summit
// heights' distribution follows.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include "asperity/topography/distribution_fit.hpp"
#include "asperity/topography/goodness_of_fit.hpp"
#include "asperity/topography/leveling.hpp"
#include "asperity/topography/statistics.hpp"
#include "asperity/topography/surrogates.hpp"
#include "asperity/topography/synthetic.hpp"

namespace t = asperity::topography;

namespace {
// A^2 of the Gaussian fitted to the map's heights at `positions`, after leveling
double gaussian_a2(t::HeightMap map, const std::vector<std::size_t>& positions) {
  t::subtract_plane(map, t::fit_plane(map));
  std::vector<double> x;
  for (std::size_t k : positions) x.push_back(map.heights[k]);
  std::sort(x.begin(), x.end());
  return t::anderson_darling(t::fit_height_distribution(t::HeightModel::gaussian, x).distribution, x);
}

double quantile(std::vector<double> v, double f) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(f * static_cast<double>(v.size() - 1))];
}
}  // namespace

int main(int argc, char** argv) {
  double hurst = 0.8, exponential = 0;
  std::size_t nx = 128, ny = 0, oversize = t::self_affine_default_oversize;
  int maps = 30, surrogates = 99;
  long offset = 0;
  const char* usage =
      "usage: surrogate_spread [--hurst H | --exponential XI] [--size N] [--ny NY] [--maps M] [--surrogates B] "
      "[--seed-offset K] [--oversize F]\n";
  for (int k = 1; k < argc; k += 2) {
    if (k + 1 >= argc) {
      std::fputs(usage, stderr);
      return 2;
    }
    if (!std::strcmp(argv[k], "--hurst")) hurst = std::atof(argv[k + 1]);
    else if (!std::strcmp(argv[k], "--exponential")) exponential = std::atof(argv[k + 1]);
    else if (!std::strcmp(argv[k], "--size")) nx = static_cast<std::size_t>(std::atol(argv[k + 1]));
    else if (!std::strcmp(argv[k], "--ny")) ny = static_cast<std::size_t>(std::atol(argv[k + 1]));
    else if (!std::strcmp(argv[k], "--maps")) maps = std::atoi(argv[k + 1]);
    else if (!std::strcmp(argv[k], "--surrogates")) surrogates = std::atoi(argv[k + 1]);
    else if (!std::strcmp(argv[k], "--seed-offset")) offset = std::atol(argv[k + 1]);
    else if (!std::strcmp(argv[k], "--oversize")) oversize = static_cast<std::size_t>(std::atol(argv[k + 1]));
    else {
      std::fputs(usage, stderr);
      return 2;
    }
  }
  if (ny == 0) ny = nx;
  if (maps < 1 || surrogates < 1 || nx < 16 || ny < 16) {
    std::fputs(usage, stderr);
    return 2;
  }
  std::vector<std::size_t> positions(nx * ny);
  for (std::size_t k = 0; k < positions.size(); ++k) positions[k] = k;
  std::mt19937_64 engine(5);
  std::shuffle(positions.begin(), positions.end(), engine);
  positions.resize(std::min<std::size_t>(4000, positions.size()));
  std::vector<double> of_maps, of_surrogates;
  int at_5 = 0, at_2_5 = 0;
  double alpha_ratio = 0;  // the surrogates' mean Nayak alpha over the map's, averaged over the maps
  for (int m = 0; m < maps; ++m) {
    const std::uint64_t seed = 1000003u * static_cast<std::uint64_t>(m + offset) + 17;
    t::HeightMap map = exponential > 0
                           ? t::spectral_random_field(nx, ny, 1e-7, 1e-7, t::CorrelationFunction::exponential, exponential, seed)
                           : t::self_affine_random_field(nx, ny, 1e-7, 1e-7, hurst, seed, oversize);
    const double a2 = gaussian_a2(map, positions);
    of_maps.push_back(a2);
    t::subtract_plane(map, t::fit_plane(map));  // as the analysis levels it
    const t::SurrogateFields fields(map, t::correlation_lengths(map, 0.1), true);
    const double alpha = t::spectral_moments(map).alpha;
    double alpha_surrogates = 0;
    int above = 0;
    t::HeightMap surrogate = map;
    for (int b = 0; b < surrogates; ++b) {
      fields.generate(static_cast<std::uint64_t>(m + offset) + 1, static_cast<std::size_t>(b), surrogate.heights);
      t::subtract_plane(surrogate, t::fit_plane(surrogate));  // leveled as the map
      const double a2_b = gaussian_a2(surrogate, positions);
      of_surrogates.push_back(a2_b);
      alpha_surrogates += t::spectral_moments(surrogate).alpha / surrogates;
      above += a2_b >= a2 ? 1 : 0;
    }
    alpha_ratio += alpha_surrogates / alpha / maps;
    const double p = (1.0 + above) / (surrogates + 1.0);
    at_5 += p <= 0.05 ? 1 : 0;
    at_2_5 += p <= 0.025 ? 1 : 0;
  }
  char field[64];
  if (exponential > 0) std::snprintf(field, sizeof field, "exponential, %g points", exponential);
  else std::snprintf(field, sizeof field, "self-affine H %g", hurst);
  std::printf("| %s | %zu x %zu | %d | %.2f, %.2f, %.2f | %.2f, %.2f, %.2f | %d | %d | %.3f |\n", field, nx, ny,
              maps, quantile(of_maps, 0.5), quantile(of_maps, 0.9), quantile(of_maps, 0.95), quantile(of_surrogates, 0.5),
              quantile(of_surrogates, 0.9), quantile(of_surrogates, 0.95), at_5, at_2_5, alpha_ratio);
}
