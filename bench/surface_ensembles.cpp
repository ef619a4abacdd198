// Size, power and interval coverage of `asperity surface`'s verdict, measured on ensembles of
// synthetic maps that look like measured ones (correlated fields, thousands of summits): the
// table of docs/surfaces.md, section 4 (scripts/surface-ensembles.sh writes it).
//
//   surface_ensembles [--maps M] [--surrogates B] [--size N] [--ny NY] [--correlation XI]
//                     [--family NAME] [--threads T] [--seed-offset K] [--csv FILE] [--oversize F]
//
// --ny: strips (N x NY points); --correlation: every family's correlation length in points
// instead of its own (few summits on a small map: the summit test's power against the count);
// --seed-offset: the maps' seeds moved by K (a second set of seeds, never tuned on); --csv: one
// line a map (its summits, both tests' p, the heights' and the summit heights' Weibull fits of
// each side, what the verdict says), from which the rules of issue 40 items 2 and 3 were measured.
//
// Families: Gaussian fields narrow- to broad-band (Nayak alpha ~3 to ~30, 256^2, 2,400 to
// 3,000 summits), and fields of exponential correlation given Weibull marginals (a = 1.5, 2, 3),
// tail up and bounded above; self-affine Gaussian fields without roll-off, H 0.3-0.9 (--family
// self-affine; cut from a draw --oversize times the map, 4 by default: synthetic.hpp). For each map, the whole analysis (analyse_height_map) with B
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
  double hurst = 0;    // > 0: a self-affine field without roll-off of this H (correlation unused)
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
    // smooth fields (Gaussian correlation): few summits on a small map, for the summit test's
    // power against the summit count (--correlation sets it)
    {"smooth-gaussian", t::CorrelationFunction::gaussian, 4, 0, false},
    {"smooth-weibull-tail-1.5", t::CorrelationFunction::gaussian, 4, 1.5, false},
    {"smooth-weibull-bounded-1.5", t::CorrelationFunction::gaussian, 4, 1.5, true},
    {"smooth-weibull-tail-2", t::CorrelationFunction::gaussian, 4, 2, false},
    {"smooth-weibull-bounded-2", t::CorrelationFunction::gaussian, 4, 2, true},
    // self-affine Gaussian fields without roll-off (issue 40, item 1): steep spectra whose longest
    // wavelengths are longer than the map, cut from a draw --oversize (4) times the map's longer side
    {"self-affine-H0.3", t::CorrelationFunction::exponential, 0, 0, false, 0.3},
    {"self-affine-H0.5", t::CorrelationFunction::exponential, 0, 0, false, 0.5},
    {"self-affine-H0.7", t::CorrelationFunction::exponential, 0, 0, false, 0.7},
    {"self-affine-H0.8", t::CorrelationFunction::exponential, 0, 0, false, 0.8},
    {"self-affine-H0.9", t::CorrelationFunction::exponential, 0, 0, false, 0.9},
};

// --family: one name, several separated by commas, or none: the nine of the table (not the smooth
// or self-affine ones); "self-affine": the five self-affine families
bool selected(const std::string& only, const std::string& name) {
  if (only.empty()) return name.rfind("smooth-", 0) != 0 && name.rfind("self-affine-", 0) != 0;
  if (only == "self-affine") return name.rfind("self-affine-", 0) == 0;
  return ("," + only + ",").find("," + name + ",") != std::string::npos;
}

// k of n, for the rules' table (its Clopper-Pearson intervals: docs/surfaces.md, made from the --csv lines)
std::string count(int hits, int total) { return std::to_string(hits) + "/" + std::to_string(total); }

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
  std::size_t size = 256, ny = 0, oversize = t::self_affine_default_oversize;
  double correlation = 0;
  long seed_offset = 0;
  std::string only, csv_path;
  const char* usage =
      "usage: surface_ensembles [--maps M] [--surrogates B] [--size N] [--ny NY] [--correlation XI] [--family NAME] "
      "[--threads T] [--seed-offset K] [--csv FILE] [--oversize F]\n";
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
    else if (!std::strcmp(argv[k], "--ny")) ny = static_cast<std::size_t>(std::atol(argv[k + 1]));
    else if (!std::strcmp(argv[k], "--correlation")) correlation = std::atof(argv[k + 1]);
    else if (!std::strcmp(argv[k], "--seed-offset")) seed_offset = std::atol(argv[k + 1]);
    else if (!std::strcmp(argv[k], "--csv")) csv_path = argv[k + 1];
    else if (!std::strcmp(argv[k], "--oversize")) oversize = static_cast<std::size_t>(std::atol(argv[k + 1]));
    else {
      std::fprintf(stderr, "surface_ensembles: unknown option %s\n%s", argv[k], usage);
      return 2;
    }
  }
  if (ny == 0) ny = size;
  if (maps < 1 || surrogates < 0 || size < 16 || ny < 16 || threads < 0 || correlation < 0) {
    std::fputs(usage, stderr);
    return 2;
  }
  FILE* csv = nullptr;
  if (!csv_path.empty()) {
    csv = std::fopen(csv_path.c_str(), "w");
    if (!csv) {
      std::fprintf(stderr, "surface_ensembles: cannot write %s\n", csv_path.c_str());
      return 2;
    }
    std::fprintf(csv, "family,nx,ny,correlation,seed,truth_shape,truth_bounded,alpha,summits,summit_test_applicable,"
                      "gaussian_rejected,p_heights,p_summits");
    for (const char* sample : {"h", "s"})
      for (const char* side : {"tail", "bounded"})
        std::fprintf(csv, ",%s_%s_a,%s_%s_lo,%s_%s_hi,%s_%s_p,%s_%s_identified,%s_%s_daic", sample, side, sample, side,
                     sample, side, sample, side, sample, side, sample, side);
    std::fprintf(csv, ",orientation,side_told,model_for_contact\n");
  }
  std::printf("| family | alpha | summits | Gaussian verdict rejects | heights' test rejects (5%%) | summit heights' test "
              "rejects (5%%) | heights' orientation right | heights' shape interval holds a | identified |\n"
              "|---|---:|---:|---|---|---|---|---|---:|\n");
  std::vector<std::string> rules;
  for (const Family& family : families) {
    if (!selected(only, family.name)) continue;
    int verdict = 0, heights = 0, summit_heights = 0, oriented = 0, covered = 0, identified = 0;
    // issue 40: the summit test applicable; the side told right or wrong (on a Gaussian map every
    // side told is wrong); a Weibull of the wrong side named for the contact
    int applicable = 0, side_right = 0, side_wrong = 0, contact_wrong = 0;
    double alpha = 0, summits = 0;
    std::size_t summits_total = 0;
    for (int m = 0; m < maps; ++m) {
      const double xi = correlation > 0 ? correlation : family.correlation;
      const std::uint64_t seed = 1000003u * static_cast<std::uint64_t>(m + seed_offset) + 17;
      t::HeightMap map = family.hurst > 0
                             ? t::self_affine_random_field(size, ny, 1e-7, 1e-7, family.hurst, seed, oversize)
                             : t::spectral_random_field(size, ny, 1e-7, 1e-7, family.function, xi, seed);
      if (family.shape > 0) t::to_weibull_marginal(map, family.shape, family.bounded);
      for (double& h : map.heights) h *= 1e-8;  // a 10 nm Sq scale, in metres
      t::AnalysisOptions options;
      options.assessment.bootstrap = surrogates;
      options.assessment.seed = static_cast<std::uint64_t>(m + seed_offset) + 1;
      options.assessment.threads = threads;
      options.sampling_factors = {1};
      const t::SurfaceAnalysis a = t::analyse_height_map(map, options);
      alpha += a.moments.alpha;
      summits += static_cast<double>(a.summits.list.size());
      summits_total += a.summits.list.size();
      verdict += a.verdict.gaussian_rejected ? 1 : 0;
      heights += a.heights->model(t::HeightModel::gaussian).anderson_darling_p < 0.05 ? 1 : 0;
      summit_heights += a.summit_heights.model(t::HeightModel::gaussian).anderson_darling_p < 0.05 ? 1 : 0;
      {
        const t::HeightModel truth = family.shape == 0 ? t::HeightModel::gaussian
                                     : family.bounded  ? t::HeightModel::weibull_bounded
                                                       : t::HeightModel::weibull_tail;
        applicable += a.verdict.summit_test_applicable ? 1 : 0;
        if (a.verdict.side_told) (a.verdict.orientation == truth ? side_right : side_wrong) += 1;
        contact_wrong += a.verdict.named && a.verdict.model != t::HeightModel::gaussian && a.verdict.model != truth ? 1 : 0;
      }
      if (family.shape > 0) {
        const t::HeightModel truth = family.bounded ? t::HeightModel::weibull_bounded : t::HeightModel::weibull_tail;
        oriented += a.verdict.orientation == truth ? 1 : 0;
        const t::ModelAssessment& fit = a.heights->model(truth);
        identified += fit.shape_identified ? 1 : 0;
        covered += fit.shape.lo <= family.shape && family.shape <= fit.shape.hi ? 1 : 0;
      }
      if (csv) {
        std::fprintf(csv, "%s,%zu,%zu,%g,%llu,%g,%d,%.4g,%zu,%d,%d,%.6g,%.6g", family.name.c_str(), size, ny, xi,
                     static_cast<unsigned long long>(seed), family.shape, family.bounded ? 1 : 0, a.moments.alpha,
                     a.summits.list.size(), a.verdict.summit_test_applicable ? 1 : 0, a.verdict.gaussian_rejected ? 1 : 0,
                     a.verdict.p_heights, a.verdict.p_summits);
        for (const t::SampleAssessment* sample : {&*a.heights, &a.summit_heights})
          for (const t::HeightModel side : {t::HeightModel::weibull_tail, t::HeightModel::weibull_bounded}) {
            const t::ModelAssessment& w = sample->model(side);
            std::fprintf(csv, ",%.6g,%.6g,%.6g,%.6g,%d,%.6g", w.fit.distribution.shape, w.shape.lo, w.shape.hi,
                         w.anderson_darling_p, w.shape_identified ? 1 : 0,
                         w.aic - sample->model(t::HeightModel::gaussian).aic);
          }
        std::fprintf(csv, ",%s,%d,%s\n", t::to_string(a.verdict.orientation), a.verdict.side_told ? 1 : 0,
                     a.verdict.named ? t::to_string(a.verdict.model) : "none");
        std::fflush(csv);
      }
    }
    const bool weibull = family.shape > 0;
    std::printf("| %s | %.1f | %.0f | %s | %s | %s | %s | %s | %s |\n", family.name.c_str(), alpha / maps, summits / maps,
                rate(verdict, maps).c_str(), rate(heights, maps).c_str(), rate(summit_heights, maps).c_str(),
                weibull ? rate(oriented, maps).c_str() : "–", weibull ? rate(covered, maps).c_str() : "–",
                weibull ? (std::to_string(identified) + "/" + std::to_string(maps)).c_str() : "–");
    rules.push_back(family.name + " | " + std::to_string(summits_total / maps) + " | " +
                    count(applicable, maps) + " | " + count(side_right, maps) + " | " + count(side_wrong, maps) + " | " +
                    count(contact_wrong, maps));
    std::fflush(stdout);
  }
  // issue 40, items 2 and 3: the rules' own rates (on a Gaussian family every side told is wrong)
  std::printf("\n| family | summits | summit test applicable | side told right | side told wrong | contact Weibull of "
              "the wrong side |\n|---|---:|---:|---|---|---|\n");
  for (const std::string& row : rules) std::printf("| %s |\n", row.c_str());
  std::printf("\n%d maps of %zu x %zu points a family, %d surrogates each; rates with their 95%% Wilson intervals.\n", maps,
              size, ny, surrogates);
  if (csv) std::fclose(csv);
}
