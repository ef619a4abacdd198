// Size, power and interval coverage of `asperity surface`'s verdict, measured on ensembles of
// synthetic maps that look like measured ones (correlated fields, thousands of summits): the
// table of docs/surfaces.md, section 4 (scripts/surface-ensembles.sh writes it).
//
//   surface_ensembles [--maps M] [--surrogates B] [--size N] [--family NAME] [--threads T]
//
// Families: Gaussian fields narrow- to broad-band (Nayak alpha ~3 to ~30, 256^2, 2,400 to
// 3,000 summits), and fields of exponential correlation given Weibull marginals (a = 1.5, 2, 3),
// tail up and bounded above. For each map, the whole analysis (analyse_height_map) with B
// surrogates; per family the rate at which the verdict rejects a Gaussian surface (size on the
// Gaussian families, power on the others; and each sample's own test at 5%), how often the
// heights' orientation is the true one, and how often the 95% interval of the heights' Weibull
// shape of the true orientation holds the true shape (and is identified).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "asperity/topography/analysis.hpp"
#include "asperity/topography/synthetic.hpp"

namespace t = asperity::topography;

namespace {
struct Family {
  std::string name;
  t::CorrelationFunction function;
  double correlation;  // points
  double shape;        // 0: Gaussian marginal
  bool bounded;
};

const std::vector<Family> families = {
    {"gaussian-narrow", t::CorrelationFunction::gaussian, 2, 0, false},
    {"gaussian-medium", t::CorrelationFunction::exponential, 4, 0, false},
    {"gaussian-broad", t::CorrelationFunction::exponential, 24, 0, false},
    {"weibull-tail-1.5", t::CorrelationFunction::exponential, 8, 1.5, false},
    {"weibull-tail-2", t::CorrelationFunction::exponential, 8, 2, false},
    {"weibull-tail-3", t::CorrelationFunction::exponential, 8, 3, false},
    {"weibull-bounded-1.5", t::CorrelationFunction::exponential, 8, 1.5, true},
    {"weibull-bounded-2", t::CorrelationFunction::exponential, 8, 2, true},
    {"weibull-bounded-3", t::CorrelationFunction::exponential, 8, 3, true},
};

// a binomial proportion with its 95% Wilson interval, as text
std::string rate(int hits, int total) {
  if (total == 0) return "–";
  const double n = total, p = hits / n, z = 1.96, centre = (p + z * z / (2 * n)) / (1 + z * z / n);
  const double half = z * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n);
  char text[64];
  std::snprintf(text, sizeof text, "%.3f [%.3f, %.3f]", p, std::max(0.0, centre - half), std::min(1.0, centre + half));
  return text;
}
}  // namespace

int main(int argc, char** argv) {
  int maps = 100, surrogates = 99, threads = 0;
  std::size_t size = 256;
  std::string only;
  const char* usage = "usage: surface_ensembles [--maps M] [--surrogates B] [--size N] [--family NAME] [--threads T]\n";
  for (int k = 1; k < argc; k += 2) {
    if (k + 1 >= argc) {  // a lone word (--help included): the usage, not a half-hour run
      std::fputs(usage, stderr);
      return 2;
    }
    if (!std::strcmp(argv[k], "--maps")) maps = std::atoi(argv[k + 1]);
    else if (!std::strcmp(argv[k], "--surrogates")) surrogates = std::atoi(argv[k + 1]);
    else if (!std::strcmp(argv[k], "--size")) size = static_cast<std::size_t>(std::atol(argv[k + 1]));
    else if (!std::strcmp(argv[k], "--family")) only = argv[k + 1];
    else if (!std::strcmp(argv[k], "--threads")) threads = std::atoi(argv[k + 1]);
    else {
      std::fprintf(stderr, "surface_ensembles: unknown option %s\n%s", argv[k], usage);
      return 2;
    }
  }
  if (maps < 1 || surrogates < 0 || size < 16 || threads < 0) {
    std::fputs(usage, stderr);
    return 2;
  }
  std::printf("| family | alpha | summits | Gaussian verdict rejects | heights' test rejects (5%%) | summit heights' test "
              "rejects (5%%) | heights' orientation right | heights' shape interval holds a | identified |\n"
              "|---|---:|---:|---|---|---|---|---|---:|\n");
  for (const Family& family : families) {
    if (!only.empty() && family.name != only) continue;
    int verdict = 0, heights = 0, summit_heights = 0, oriented = 0, covered = 0, identified = 0;
    double alpha = 0, summits = 0;
    for (int m = 0; m < maps; ++m) {
      t::HeightMap map =
          t::spectral_random_field(size, size, 1e-7, 1e-7, family.function, family.correlation, 1000003u * m + 17);
      if (family.shape > 0) t::to_weibull_marginal(map, family.shape, family.bounded);
      for (double& h : map.heights) h *= 1e-8;  // a 10 nm Sq scale, in metres
      t::AnalysisOptions options;
      options.assessment.bootstrap = surrogates;
      options.assessment.seed = static_cast<std::uint64_t>(m) + 1;
      options.assessment.threads = threads;
      options.sampling_factors = {1};
      const t::SurfaceAnalysis a = t::analyse_height_map(map, options);
      alpha += a.moments.alpha;
      summits += static_cast<double>(a.summits.list.size());
      verdict += a.verdict.gaussian_rejected ? 1 : 0;
      heights += a.heights->model(t::HeightModel::gaussian).anderson_darling_p < 0.05 ? 1 : 0;
      summit_heights += a.summit_heights.model(t::HeightModel::gaussian).anderson_darling_p < 0.05 ? 1 : 0;
      if (family.shape > 0) {
        const t::HeightModel truth = family.bounded ? t::HeightModel::weibull_bounded : t::HeightModel::weibull_tail;
        oriented += a.verdict.orientation == truth ? 1 : 0;
        const t::ModelAssessment& fit = a.heights->model(truth);
        identified += fit.shape_identified ? 1 : 0;
        covered += fit.shape.lo <= family.shape && family.shape <= fit.shape.hi ? 1 : 0;
      }
    }
    const bool weibull = family.shape > 0;
    std::printf("| %s | %.1f | %.0f | %s | %s | %s | %s | %s | %s |\n", family.name.c_str(), alpha / maps, summits / maps,
                rate(verdict, maps).c_str(), rate(heights, maps).c_str(), rate(summit_heights, maps).c_str(),
                weibull ? rate(oriented, maps).c_str() : "–", weibull ? rate(covered, maps).c_str() : "–",
                weibull ? (std::to_string(identified) + "/" + std::to_string(maps)).c_str() : "–");
    std::fflush(stdout);
  }
  std::printf("\n%d maps of %zu x %zu points a family, %d surrogates each; rates with their 95%% Wilson intervals.\n", maps,
              size, size, surrogates);
}
