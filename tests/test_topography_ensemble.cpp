// The surface's tests that carry its correlation (issue 27): the synthetic fields they are
// measured on, the surrogate surfaces of a map's spectrum, GW on the measured summits, and the
// verdict's size and power on small ensembles (the full table: bench/surface_ensembles,
// docs/surfaces.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/topography/analysis.hpp"
#include "asperity/topography/leveling.hpp"
#include "asperity/topography/statistics.hpp"
#include "asperity/topography/summit_contact.hpp"
#include "asperity/topography/surrogates.hpp"
#include "asperity/topography/synthetic.hpp"

namespace t = asperity::topography;

namespace {
struct Spread {
  double mean_sd = 0, variance_mean = 0, variance_sd = 0;
};

Spread spread_of(const std::vector<std::vector<double>>& fields) {
  std::vector<double> means, variances;
  for (const std::vector<double>& f : fields) {
    double s = 0, q = 0;
    std::size_t n = 0;
    for (double v : f)
      if (!std::isnan(v)) {
        s += v;
        q += v * v;
        ++n;
      }
    means.push_back(s / static_cast<double>(n));
    variances.push_back(q / static_cast<double>(n) - means.back() * means.back());
  }
  const auto sd = [](const std::vector<double>& v) {
    double s = 0, q = 0;
    for (double x : v) {
      s += x;
      q += x * x;
    }
    const double m = s / static_cast<double>(v.size());
    return std::sqrt(q / static_cast<double>(v.size()) - m * m);
  };
  double vm = 0;
  for (double v : variances) vm += v;
  return {sd(means), vm / static_cast<double>(variances.size()), sd(variances)};
}
}  // namespace

// The synthetic fields: unit variance, the named correlation at one correlation length, and
// the mean's spread of the exponential field, 2 pi xi^2 / N in variance.
TEST(TopographyEnsemble, SpectralFieldsHaveTheirCorrelation) {
  for (const auto function : {t::CorrelationFunction::gaussian, t::CorrelationFunction::exponential}) {
    std::vector<std::vector<double>> fields;
    double at_xi = 0;
    const double xi = 6;
    for (int k = 0; k < 40; ++k) {
      const t::HeightMap m = t::spectral_random_field(128, 128, 1e-7, 1e-7, function, xi, 100 + k);
      double s = 0;
      int c = 0;
      for (std::size_t j = 0; j < 128; ++j)
        for (std::size_t i = 0; i + 6 < 128; ++i) {
          s += m.at(i, j) * m.at(i + 6, j);
          ++c;
        }
      at_xi += s / c / 40;
      fields.push_back(m.heights);
    }
    const Spread spread = spread_of(fields);
    EXPECT_NEAR(spread.variance_mean, 1, 0.06);
    EXPECT_NEAR(at_xi, std::exp(-1.0), 0.06);
    if (function == t::CorrelationFunction::exponential) {
      EXPECT_NEAR(spread.mean_sd / std::sqrt(2 * 3.14159265358979 * xi * xi / (128.0 * 128.0)), 1, 0.3);
    }
  }
  EXPECT_THROW(t::spectral_random_field(2, 128, 1e-7, 1e-7, t::CorrelationFunction::gaussian, 2, 1), asperity::Error);
  EXPECT_THROW(t::spectral_random_field(64, 64, 1e-7, 1e-7, t::CorrelationFunction::gaussian, 0, 1), asperity::Error);
}

// Surrogates of one map spread as maps of its process do: the mean over the map (what a Weibull
// marginal turns into a spread of its shape) and the variance, leveled or not, missing points
// kept missing.
TEST(TopographyEnsemble, SurrogatesSpreadAsTheProcessDoes) {
  const double xi = 8;
  std::vector<std::vector<double>> process;
  for (int k = 0; k < 60; ++k)
    process.push_back(t::spectral_random_field(160, 160, 1e-7, 1e-7, t::CorrelationFunction::exponential, xi, 500 + k).heights);
  const Spread truth = spread_of(process);
  // a single map pins its longest wavelengths down loosely: averaged over maps of the process
  for (const bool leveled : {false, true}) {
    double mean_ratio = 0, variance_ratio = 0, variance_mean = 0;
    const int maps = 8;
    for (int m = 0; m < maps; ++m) {
      t::HeightMap map =
          t::spectral_random_field(160, 160, 1e-7, 1e-7, t::CorrelationFunction::exponential, xi, 77 + 13 * m);
      map.heights[1234] = NAN;
      if (leveled) t::subtract_plane(map, t::fit_plane(map));  // as the analysis does: the surrogates restore it
      const t::SurrogateFields fields(map, t::correlation_lengths(map), leveled);
      std::vector<std::vector<double>> surrogates(40);
      for (std::size_t b = 0; b < surrogates.size(); ++b) fields.generate(3, b, surrogates[b]);
      EXPECT_TRUE(std::isnan(surrogates[7][1234]));
      const Spread spread = spread_of(surrogates);
      mean_ratio += spread.mean_sd / truth.mean_sd / maps;
      variance_ratio += spread.variance_sd / truth.variance_sd / maps;
      variance_mean += spread.variance_mean / maps;
      // the same surrogate for the same seed and index, whatever was drawn before
      std::vector<double> again;
      fields.generate(3, 5, again);
      ASSERT_EQ(again.size(), surrogates[5].size());
      EXPECT_EQ(std::memcmp(again.data(), surrogates[5].data(), again.size() * sizeof(double)), 0);
    }
    std::printf("surrogates against the process (leveled %d): the mean's spread %.2f, the variance's %.2f, mean "
                "variance %.3f against %.3f\n",
                leveled, mean_ratio, variance_ratio, variance_mean, truth.variance_mean);
    EXPECT_NEAR(mean_ratio, 1, 0.25) << "leveled " << leveled;
    EXPECT_NEAR(variance_mean, truth.variance_mean, 0.06) << "leveled " << leveled;
    EXPECT_NEAR(variance_ratio, 1, 0.3) << "leveled " << leveled;
  }
}

// GW summed over the measured summits: each summit a Hertz asperity, by hand.
TEST(TopographyEnsemble, SummitContactIsTheDirectSum) {
  t::Summits summits;
  for (double h : {3e-8, 1e-8, -2e-8}) {
    t::Summit s;
    s.height = h;
    s.mean_curvature = 1 / 5e-6;
    summits.list.push_back(s);
  }
  summits.area_searched = 1e-10;
  summits.radius = 5e-6;
  const double modulus = 1e11, area = 2e-10, pi = 3.14159265358979323846;
  const t::SummitContact contact(summits, modulus, area);
  EXPECT_NEAR(contact.mean_summit_height(), 2e-8 / 3, 1e-23);
  const double d = 2e-9;  // from the mean summit height 6.67e-9: the top two in contact
  const asperity::PhysicalState s = contact.at_separation(d);
  const double mean = contact.mean_summit_height();
  double load = 0, stiffness = 0, real = 0;
  for (double h : {3e-8, 1e-8}) {
    const double w = h - mean - d;
    load += (4.0 / 3.0) * modulus * std::sqrt(5e-6) * std::pow(w, 1.5);
    stiffness += 2 * modulus * std::sqrt(5e-6 * w);
    real += pi * 5e-6 * w;
  }
  EXPECT_DOUBLE_EQ(s.count, 2 * 2.0);  // scaled from the area searched to A0 = 2 of it
  EXPECT_NEAR(s.load / (2 * load), 1, 1e-14);
  EXPECT_NEAR(s.stiffness / (2 * stiffness), 1, 1e-14);
  EXPECT_NEAR(s.real_area / (2 * real), 1, 1e-14);
  EXPECT_NEAR(contact.at_pressure(s.pressure).mean_separation / d, 1, 1e-9);
  EXPECT_EQ(contact.at_separation(1).load, 0);
  EXPECT_THROW(t::SummitContact(t::Summits{}, modulus, area), asperity::Error);
}

// The verdict's size on Gaussian surfaces (broad-band: where the old i.i.d. test rejected 13 of
// 20) and its power against Weibull heights, on small ensembles: a gross error shows here; the
// measured rates with their intervals are bench/surface_ensembles' (docs/surfaces.md).
TEST(TopographyEnsemble, VerdictSizeAndPower) {
  int gaussian_rejected = 0, weibull_rejected = 0;
  const int maps = 24;  // (the sanitizer pass too: the rates need the maps)
  for (int m = 0; m < maps; ++m) {
    t::HeightMap gaussian =
        t::spectral_random_field(128, 128, 1e-7, 1e-7, t::CorrelationFunction::exponential, 12, 4000 + m);
    for (double& h : gaussian.heights) h *= 1e-8;
    t::AnalysisOptions options;
    options.assessment.bootstrap = 40;
    options.assessment.seed = static_cast<std::uint64_t>(m) + 1;
    options.sampling_factors = {1};
    gaussian_rejected += t::analyse_height_map(gaussian, options).verdict.gaussian_rejected ? 1 : 0;
    if (m < 8) {
      t::HeightMap weibull =
          t::spectral_random_field(128, 128, 1e-7, 1e-7, t::CorrelationFunction::exponential, 4, 6000 + m);
      t::to_weibull_marginal(weibull, 1.5, m % 2 == 1);
      for (double& h : weibull.heights) h *= 1e-8;
      weibull_rejected += t::analyse_height_map(weibull, options).verdict.gaussian_rejected ? 1 : 0;
    }
  }
  // at 5%, 5 or more of 24 happens with probability 0.007
  EXPECT_LE(gaussian_rejected, 4) << gaussian_rejected << " of " << maps;
  EXPECT_GE(weibull_rejected, 7) << weibull_rejected << " of 8";
}
