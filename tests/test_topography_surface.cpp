// Surface statistics, summits and the whole analysis: synthetic surfaces with known spectra,
// known summits and known marginals, and the two real measured surfaces end to end.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "asperity/error.hpp"
#include "asperity/topography/analysis.hpp"
#include "asperity/topography/contact_comparison.hpp"
#include "asperity/topography/leveling.hpp"
#include "asperity/topography/statistics.hpp"
#include "asperity/topography/summits.hpp"
#include "asperity/topography/surface_report.hpp"
#include "asperity/topography/synthetic.hpp"
#include "test_subsample.hpp"

namespace t = asperity::topography;

namespace {
const std::string surfaces = ASPERITY_TEST_SURFACES;

// Paraboloid caps of radius R, one per cell of `cell` points, apex heights from `heights`:
// exactly one summit per cap, of curvature 1/R (second differences are exact on a quadratic).
t::HeightMap planted_caps(std::size_t cells, std::size_t cell, double dx, double radius, const std::vector<double>& heights) {
  t::HeightMap map;
  map.nx = map.ny = cells * cell;
  map.dx = map.dy = dx;
  map.source = "planted caps";
  map.heights.resize(map.nx * map.ny);
  for (std::size_t j = 0; j < map.ny; ++j)
    for (std::size_t i = 0; i < map.nx; ++i) {
      const std::size_t ci = i / cell, cj = j / cell;
      const double x = (static_cast<double>(i % cell) - static_cast<double>(cell / 2)) * dx;
      const double y = (static_cast<double>(j % cell) - static_cast<double>(cell / 2)) * dx;
      map.heights[j * map.nx + i] = heights[cj * cells + ci] - (x * x + y * y) / (2 * radius);
    }
  return map;
}
}  // namespace

// The points of each contact curve are bounded: 2^31 - 1 of them ran without bound (time and
// memory), checked before anything else is done.
TEST(TopographySurface, ContactCurvePointsAreBounded) {
  for (int points : {-1, 0, 1, t::max_curve_points + 1, 2147483647}) {
    t::ContactOptions options;
    options.contact_modulus = 1e11;
    options.curve_points = points;
    try {
      t::compare_contact(t::SampleAssessment{}, t::Summits{}, t::SpectralMoments{}, 1e-8, options);
      ADD_FAILURE() << "curve_points " << points << " accepted";
    } catch (const asperity::Error& error) {
      EXPECT_NE(std::string(error.what()).find("curve_points must be from 2 to 100000"), std::string::npos)
          << error.what();
    }
  }
}

// Every factor-th point, for any factor: ceil(n / factor) points (n + factor - 1 wrapped for a
// factor near the largest size, giving a map of 0 x 0 points holding one height).
TEST(TopographySurface, DecimatedByAnyFactor) {
  t::HeightMap map;
  map.nx = 7;
  map.ny = 5;
  map.dx = map.dy = 1e-6;
  for (std::size_t k = 0; k < 35; ++k) map.heights.push_back(static_cast<double>(k));
  const std::size_t largest = std::numeric_limits<std::size_t>::max();
  for (std::size_t factor : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{7}, std::size_t{8},
                             largest / 2, largest - 1, largest}) {
    const t::HeightMap out = t::decimated(map, factor);
    const auto expected = [factor](std::size_t n) { return factor >= n ? 1 : (n + factor - 1) / factor; };
    EXPECT_EQ(out.nx, expected(7)) << factor;
    EXPECT_EQ(out.ny, expected(5)) << factor;
    EXPECT_EQ(out.heights.size(), out.nx * out.ny) << factor;
    EXPECT_EQ(out.heights.front(), 0.0);
  }
}

// Finite-difference moments against the field's exact expectations.
TEST(TopographySurface, SpectralMomentsOfAKnownSpectrum) {
  const std::vector<t::SpectrumComponent> spectrum = {{1.5, 1e-16}, {4.0, 2e-16}};
  const t::HeightMap field = t::gaussian_random_field(512, 512, 1e-7, 2e-7, spectrum, 42);
  const t::SpectralMoments measured = t::spectral_moments(field);
  const t::SpectralMoments expected = t::expected_spectral_moments(1e-7, 2e-7, spectrum);
  EXPECT_NEAR(measured.m0 / expected.m0, 1, 0.1);
  EXPECT_NEAR(measured.m2x / expected.m2x, 1, 0.06);
  EXPECT_NEAR(measured.m2y / expected.m2y, 1, 0.06);
  EXPECT_NEAR(measured.m4x / expected.m4x, 1, 0.06);
  EXPECT_NEAR(measured.m4y / expected.m4y, 1, 0.06);
  EXPECT_NEAR(measured.alpha / expected.alpha, 1, 0.15);
  EXPECT_NEAR(measured.anisotropy / expected.anisotropy, 1, 0.1);  // dy = 2 dx: 4 in physical units
  EXPECT_NEAR(measured.principal_angle, 0, 0.05);
  const t::HeightStatistics stats = t::height_statistics(field);
  EXPECT_NEAR(stats.skewness, 0, 0.15);
  EXPECT_NEAR(stats.kurtosis, 3, 0.3);
}

TEST(TopographySurface, LevelingRemovesAPlane) {
  t::HeightMap field = t::gaussian_random_field(200, 150, 1e-6, 1e-6, {{2.0, 1e-14}}, 3);
  for (std::size_t j = 0; j < field.ny; ++j)
    for (std::size_t i = 0; i < field.nx; ++i) field.heights[j * field.nx + i] += 5e-6 + 0.01 * i * 1e-6 - 0.02 * j * 1e-6;
  field.heights[17] = NAN;  // missing points are ignored
  const t::Plane plane = t::fit_plane(field);
  EXPECT_NEAR(plane.slope_x, 0.01, 1e-4);
  EXPECT_NEAR(plane.slope_y, -0.02, 1e-4);
  t::subtract_plane(field, plane);
  const t::Plane after = t::fit_plane(field);
  EXPECT_NEAR(after.slope_x, 0, 1e-12);
  EXPECT_NEAR(after.offset, 0, 1e-15);
  EXPECT_TRUE(std::isnan(field.heights[17]));
}

// Known summits: their count, density, heights and radius.
TEST(TopographySurface, PlantedSummits) {
  const std::size_t cells = 30, cell = 8;
  std::vector<double> heights(cells * cells);
  std::mt19937_64 engine(9);
  for (double& h : heights) h = 1e-7 * std::uniform_real_distribution<double>(0, 1)(engine);
  const double dx = 1e-7, radius = 5e-6;
  t::HeightMap map = planted_caps(cells, cell, dx, radius, heights);
  const t::Summits summits = t::find_summits(map);
  EXPECT_EQ(summits.list.size(), cells * cells);
  EXPECT_EQ(summits.candidates, (map.nx - 2) * (map.ny - 2));
  EXPECT_DOUBLE_EQ(summits.density, static_cast<double>(cells * cells) / (static_cast<double>(summits.candidates) * dx * dx));
  EXPECT_NEAR(summits.radius / radius, 1, 1e-9);
  for (const t::Summit& s : summits.list) {
    EXPECT_EQ(s.i % cell, cell / 2);
    EXPECT_NEAR(s.kappa1 * radius, 1, 1e-6);
    EXPECT_NEAR(s.kappa2 * radius, 1, 1e-6);
    EXPECT_DOUBLE_EQ(s.height, heights[(s.j / cell) * cells + s.i / cell]);
  }
  // a flat top of two equal points counts once; a missing point removes its neighbours' candidacy
  map.heights[(4 * map.nx) + 5] = map.heights[(4 * map.nx) + 4];
  map.heights[(12 * map.nx) + 12] = NAN;
  const t::Summits again = t::find_summits(map);
  EXPECT_EQ(again.list.size(), cells * cells - 1);  // the cap with the missing apex is gone
  // a height threshold keeps only summits standing that far above their neighbours' mean
  t::SummitOptions strict;
  strict.min_drop = 1.1 * (dx * dx) / (2 * radius) * 1.5;  // the caps stand 1.5 dx^2/(2R) above: all rejected
  EXPECT_EQ(t::find_summits(map, strict).list.size(), 0u);
  t::SummitOptions wide;
  wide.window = 5;  // larger than half a cell: only caps higher than their neighbours' apexes
  const std::size_t wide_count = t::find_summits(map, wide).list.size();
  EXPECT_GT(wide_count, 0u);
  EXPECT_LT(wide_count, cells * cells / 2);
  // sampling every second point: apexes on even points survive
  EXPECT_EQ(t::find_summits(t::decimated(map, 2)).list.size(), cells * cells - 1);
  EXPECT_THROW(t::find_summits(map, t::SummitOptions{0, 0}), asperity::Error);
}

// Summit heights with a known Weibull law, on both sides: the whole analysis names the model and
// recovers the shape; planted caps make the summit heights independent, where the i.i.d.
// bootstrap (assess_sample) is valid and its interval holds the shape.
TEST(TopographySurface, PlantedWeibullSummitsRecovered) {
  for (bool bounded : {false, true})
    for (double shape : {0.8, 2.0}) {
      t::HeightDistribution truth;
      truth.model = bounded ? t::HeightModel::weibull_bounded : t::HeightModel::weibull_tail;
      truth.location = 0;
      truth.scale = 5e-8;
      truth.shape = shape;
      const std::vector<double> heights = t::draw_sample(truth, 24 * 24, 77 + static_cast<int>(10 * shape) + bounded);
      const t::HeightMap map = planted_caps(24, 8, 1e-7, 1e-5, heights);
      t::AnalysisOptions options;
      options.level = false;
      options.fit_heights = false;
      options.sampling_factors = {1};
      options.assessment.bootstrap = 59;
      const t::SurfaceAnalysis analysis = t::analyse_height_map(map, options);
      const t::ModelAssessment& m = analysis.summit_heights.model(truth.model);
      EXPECT_EQ(analysis.summits.list.size(), 24u * 24u);
      EXPECT_NEAR(m.fit.distribution.shape / shape, 1, 0.25) << (bounded ? "bounded" : "tail") << " a = " << shape;
      EXPECT_EQ(analysis.summit_heights.verdict.best, truth.model) << analysis.summit_heights.verdict.text;
      t::AssessmentOptions independent;
      independent.bootstrap = 99;
      const t::SampleAssessment assessed = t::assess_sample("summit heights", heights, independent);
      const t::ModelAssessment& iid = assessed.model(truth.model);  // a reference into `assessed`, kept alive
      EXPECT_LE(iid.shape.lo, shape) << (bounded ? "bounded" : "tail") << " a = " << shape << " fit " << iid.fit.distribution.shape;
      EXPECT_GE(iid.shape.hi, shape) << (bounded ? "bounded" : "tail") << " a = " << shape << " fit " << iid.fit.distribution.shape;
    }
}

// A Gaussian field mapped to Weibull heights (both orientations): the fit on the thinned
// heights recovers the shape within its interval, and the Gaussian is rejected.
TEST(TopographySurface, WeibullMarginalFieldRecovered) {
  for (bool bounded : {false, true}) {
    t::HeightMap field = t::gaussian_random_field(320, 320, 1e-7, 1e-7, {{1.5, 1.0}}, bounded ? 5 : 6);
    t::to_weibull_marginal(field, 1.5, bounded);
    for (double& h : field.heights) h *= 1e-8;
    // what the analysis does with all heights: thinned to the correlation length, then fitted
    const t::CorrelationLengths lengths = t::correlation_lengths(field, 0.1);
    EXPECT_GE(lengths.x, 3u);
    EXPECT_LE(lengths.x, 8u);
    t::AssessmentOptions options;
    options.bootstrap = 79;
    const t::SampleAssessment heights = t::assess_sample("heights", t::thinned_heights(field, lengths, 800), options);
    const t::HeightModel model = bounded ? t::HeightModel::weibull_bounded : t::HeightModel::weibull_tail;
    const t::ModelAssessment& m = heights.model(model);
    EXPECT_LE(m.shape.lo, 1.5) << m.fit.distribution.shape;
    EXPECT_GE(m.shape.hi, 1.5) << m.fit.distribution.shape;
    EXPECT_TRUE(heights.verdict.gaussian_rejected) << heights.verdict.text;
    // the true model beats the Gaussian by AIC (whether a 5% test rejects it is, by design, chance
    // in 1 of 20 samples, and the thinned heights keep a weak correlation: see docs/surfaces.md)
    EXPECT_LT(m.aic, heights.model(t::HeightModel::gaussian).aic - 50) << heights.verdict.text;
    // the whole analysis, its tests carrying the field's correlation: the heights' interval holds
    // the shape, the orientation is the true one, and the surface is not Gaussian
    t::AnalysisOptions analysis_options;
    analysis_options.sampling_factors = {1};
    const t::SurfaceAnalysis analysis = t::analyse_height_map(field, analysis_options);
    const t::ModelAssessment& marginal = analysis.heights->model(model);
    EXPECT_LE(marginal.shape.lo, 1.5) << marginal.fit.distribution.shape;
    EXPECT_GE(marginal.shape.hi, 1.5) << marginal.fit.distribution.shape;
    EXPECT_EQ(analysis.verdict.orientation, model) << analysis.verdict.text;
    EXPECT_TRUE(analysis.verdict.gaussian_rejected) << analysis.verdict.text;
    // the heights' Weibull intervals carry the bias's slope in ln a, measured on the surrogates
    // (a = 1.5: the bias falls as the shape grows); nothing else has one
    for (t::HeightModel weibull : {t::HeightModel::weibull_tail, t::HeightModel::weibull_bounded}) {
      const double slope = analysis.heights->model(weibull).bias_slope;
      EXPECT_TRUE(std::isfinite(slope) && slope > -0.75 && slope < 1) << slope;
      EXPECT_TRUE(std::isnan(analysis.summit_heights.model(weibull).bias_slope));
    }
    EXPECT_LT(marginal.bias_slope, 0) << "the bias of ln a_hat falls with the shape at a = 1.5";
    EXPECT_TRUE(std::isnan(analysis.heights->model(t::HeightModel::gaussian).bias_slope));
    EXPECT_TRUE(std::isnan(m.bias_slope)) << "the i.i.d. bootstrap measures no slope";
  }
}

// The two real surfaces, end to end: read, level, statistics, summits, fits, contact curves of
// every fit (scene tables at the fitted shapes), the report.
TEST(TopographySurface, RealSurfacesEndToEnd) {
  struct Case {
    std::string file;
    std::size_t summits;
    std::vector<std::size_t> in_contact;  // measured summits in contact at 1e6 and 1e7 Pa
  };
  for (const Case& c : {Case{"digitalsurf-650x650.x3p", 2482, {27, 129}}, Case{"afm-zsensor-10um.txt", 1670, {1, 1}}}) {
    t::AnalysisOptions options;
    options.assessment.bootstrap = 40;
    options.sampling_factors = {1, 2};
    t::ContactOptions contact;
    contact.contact_modulus = 1e11;
    contact.pressures = {1e6, 1e7};
    contact.curve_points = 9;
    contact.exact_auto = false;  // the asperity models' curves here (the exact contact: test_exact_contact)
    options.contact = contact;
    const t::SurfaceAnalysis a = t::analyse_surface_file(surfaces + "/" + c.file, options);
    EXPECT_EQ(a.summits.list.size(), c.summits) << c.file;
    EXPECT_GT(a.moments.alpha, 10) << c.file;
    EXPECT_LT(std::abs(a.statistics.mean), 1e-6 * a.statistics.rms) << c.file;  // leveled
    ASSERT_EQ(a.sampling.size(), 2u);
    EXPECT_LT(a.sampling[1].density, a.sampling[0].density) << c.file;  // coarser sampling, fewer summits
    EXPECT_GT(a.sampling[1].radius, a.sampling[0].radius) << c.file;
    EXPECT_FALSE(a.summit_heights.verdict.text.empty());
    ASSERT_TRUE(a.contact);
    int served = 0;
    for (const t::ModelContact& m : a.contact->models) {
      if (!m.served) {
        EXPECT_FALSE(m.note.empty());
        continue;
      }
      ++served;
      ASSERT_EQ(m.curve.size(), 9u);
      for (std::size_t k = 1; k < m.curve.size(); ++k) {
        EXPECT_GT(m.curve[k].pressure, m.curve[k - 1].pressure) << m.label();
        EXPECT_GT(m.curve[k].stiffness, m.curve[k - 1].stiffness) << m.label();
        EXPECT_GT(m.curve[k].area_fraction, m.curve[k - 1].area_fraction) << m.label();
        EXPECT_LT(m.curve[k].mean_separation, m.curve[k - 1].mean_separation) << m.label();
      }
      ASSERT_EQ(m.at_pressures.size(), 2u);
      EXPECT_NEAR(m.at_pressures[0].pressure / 1e6, 1, 1e-9) << m.label();
    }
    EXPECT_GE(served, 3) << c.file;
    // issue 40, item 4: the AFM map has about one measured summit in contact at both pressures, so
    // no model is named closest there; the X3P map has enough at both
    EXPECT_EQ(a.contact->measured_summits_in_contact, c.in_contact) << c.file;
    const bool enough = c.in_contact.front() >= t::min_summits_to_compare;
    EXPECT_EQ(a.contact->closest.has_value(), enough) << c.file << ": " << a.contact->headline;
    EXPECT_EQ(a.contact->headline.find("only 1 measured summit in contact: too few to compare models") != std::string::npos,
              !enough)
        << a.contact->headline;
  }
}

TEST(TopographySurface, ReportFolder) {
  const std::vector<double> heights(100, 0.0);
  std::vector<double> h(100);
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = 1e-8 * std::sin(0.7 * static_cast<double>(k)) + 1e-8;
  const t::HeightMap map = planted_caps(10, 8, 1e-7, 1e-5, h);
  t::AnalysisOptions options;
  options.level = false;
  options.assessment.bootstrap = 40;
  t::ContactOptions contact;
  contact.contact_modulus = 1e11;
  contact.curve_points = 5;
  options.contact = contact;
  const t::SurfaceAnalysis a = t::analyse_height_map(map, options);
  const std::string dir = std::string(ASPERITY_TEST_BINARY_DIR) + "/topography_report";
  const t::ReportOutcome outcome = t::write_report(a, dir);
  EXPECT_TRUE(outcome.plots);
  EXPECT_EQ(outcome.plot_note, "");
  std::ifstream md(dir + "/report.md");
  const std::string text((std::istreambuf_iterator<char>(md)), {});
  EXPECT_NE(text.find("![contact](contact.svg)"), std::string::npos);
  EXPECT_NE(text.find("Verdict"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir + "/curves.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/summits.csv"));
  const std::string json = t::analysis_json(a);
  EXPECT_NE(json.find("\"schema\": \"asperity-surface/3\""), std::string::npos);
  EXPECT_THROW(t::write_report(a, "/proc/no/such/dir"), asperity::Error);
}

// ---- hostile maps (issue 26) ----

// A perfect tilted plane stored as float32: after leveling what is left is rounding noise
// (before: 192 "summits" and their contact curves). It gets its statistics and the statement.
TEST(TopographyHostile, Float32PlaneIsAtItsNoiseFloor) {
  t::HeightMap plane;
  plane.nx = plane.ny = 64;
  plane.dx = plane.dy = 1e-6;
  plane.source = "tilted plane";
  for (std::size_t j = 0; j < plane.ny; ++j)
    for (std::size_t i = 0; i < plane.nx; ++i)
      plane.heights.push_back(static_cast<float>(1e-5 + 2e-8 * static_cast<double>(i) - 3e-8 * static_cast<double>(j)));
  const std::string gsf = std::string(ASPERITY_TEST_BINARY_DIR) + "/float32-plane.gsf";
  t::write_gsf(plane, gsf);
  t::AnalysisOptions options;
  options.assessment.bootstrap = 0;
  t::ContactOptions contact;
  contact.contact_modulus = 1e11;
  options.contact = contact;
  const t::SurfaceAnalysis a = t::analyse_surface_file(gsf, options);
  ASSERT_TRUE(a.noise_floor.reached) << a.statistics.rms;
  EXPECT_NE(a.noise_floor.text.find("quantization"), std::string::npos) << a.noise_floor.text;
  EXPECT_TRUE(a.summits.list.empty());
  EXPECT_FALSE(a.contact.has_value());
  EXPECT_NE(t::analysis_summary(a).find("noise floor"), std::string::npos);
  // the same plane with roughness well above the float's step is analysed
  std::mt19937_64 random(3);
  std::normal_distribution<double> normal(0, 1e-9);
  for (double& h : plane.heights) h += normal(random);
  t::write_gsf(plane, gsf);
  EXPECT_FALSE(t::analyse_surface_file(gsf, options).noise_floor.reached);
  // heights below a femtometre are a unit slip, not a surface
  t::HeightMap tiny = plane;
  for (double& h : tiny.heights) h *= 1e-12;
  EXPECT_THROW(t::analyse_height_map(tiny, options), asperity::Error);
  // a plane of exact doubles levels to a residual of a few roundings: flat, not a surface
  t::HeightMap exact = plane;
  for (std::size_t k = 0; k < exact.heights.size(); ++k)
    exact.heights[k] = 1e-9 * static_cast<double>(k % exact.nx + 2 * (k / exact.nx));
  exact.height_resolution = 0;
  EXPECT_TRUE(t::analyse_height_map(exact, options).noise_floor.reached);
}

// p = (1 + #)/(B + 1) >= 1/(B + 1): a bootstrap under 20 samples can never reject at 5%, so
// exponential data were called "consistent with a Gaussian". Refused; 0 says "not tested".
TEST(TopographyHostile, BootstrapTooSmallToRejectIsRefused) {
  std::mt19937_64 random(1);
  std::exponential_distribution<double> exponential(1e8);
  std::vector<double> values(200);
  for (double& v : values) v = exponential(random);
  t::AssessmentOptions options;
  options.bootstrap = 19;
  EXPECT_THROW(t::assess_sample("exponential", values, options), asperity::Error);
  // the surface verdict tests each of its two samples at half the significance: 40 at least
  t::AnalysisOptions analysis;
  analysis.assessment.bootstrap = 39;
  EXPECT_THROW(t::analyse_height_map(t::spectral_random_field(64, 64, 1e-7, 1e-7, t::CorrelationFunction::exponential,
                                                             2, 1), analysis),
               asperity::Error);
  EXPECT_EQ(t::minimum_bootstrap(0.05), 20);
  EXPECT_EQ(t::minimum_bootstrap(0.01), 100);
  options.bootstrap = 20;
  const t::SampleAssessment tested = t::assess_sample("exponential", values, options);
  EXPECT_TRUE(tested.verdict.gaussian_rejected) << tested.verdict.text;
  options.bootstrap = 0;
  const t::SampleAssessment untested = t::assess_sample("exponential", values, options);
  EXPECT_FALSE(untested.verdict.gaussian_rejected);
  EXPECT_NE(untested.verdict.text.find("not tested"), std::string::npos) << untested.verdict.text;
  EXPECT_EQ(untested.verdict.text.find("consistent"), std::string::npos) << untested.verdict.text;
}

// Summits of a window wider than 3 x 3 by the O(N) sliding maximum are the summits of the
// direct test (every point of the window compared), ties and missing points included.
TEST(TopographyHostile, WindowSummitsInLinearTime) {
  std::mt19937_64 random(7);
  for (int trial = 0; trial < 6; ++trial) {
    t::HeightMap map;
    map.nx = 37 + 5 * static_cast<std::size_t>(trial);
    map.ny = 29 + 3 * static_cast<std::size_t>(trial);
    map.dx = map.dy = 1e-7;
    map.source = "random";
    std::uniform_int_distribution<int> level(0, trial % 2 ? 6 : 1000);  // many ties, or few
    for (std::size_t k = 0; k < map.nx * map.ny; ++k) map.heights.push_back(1e-9 * level(random));
    for (int hole = 0; hole < trial * 3; ++hole) map.heights[random() % map.heights.size()] = NAN;
    for (int w : {2, 3, 5}) {
      t::SummitOptions options;
      options.window = w;
      const t::Summits fast = t::find_summits(map, options);
      std::vector<std::pair<std::size_t, std::size_t>> expected;
      std::size_t candidates = 0;
      const std::size_t W = static_cast<std::size_t>(w);
      for (std::size_t j = W; j + W < map.ny; ++j)
        for (std::size_t i = W; i + W < map.nx; ++i) {
          const double h = map.at(i, j);
          bool complete = !std::isnan(h), summit = true;
          for (std::size_t q = j - W; q <= j + W && complete; ++q)
            for (std::size_t p = i - W; p <= i + W && complete; ++p) {
              if (p == i && q == j) continue;
              const double other = map.at(p, q);
              if (std::isnan(other)) complete = false;
              else if ((q < j || (q == j && p < i)) ? !(h > other) : !(h >= other)) summit = false;
            }
          if (!complete) continue;
          ++candidates;
          if (summit) expected.emplace_back(i, j);
        }
      ASSERT_EQ(fast.candidates, candidates) << "trial " << trial << " window " << w;
      ASSERT_EQ(fast.list.size(), expected.size()) << "trial " << trial << " window " << w;
      for (std::size_t k = 0; k < expected.size(); ++k) {
        EXPECT_EQ(fast.list[k].i, expected[k].first);
        EXPECT_EQ(fast.list[k].j, expected[k].second);
      }
    }
  }
}

// Correlation lengths by FFT are those of the direct sums (points x lag, which kept a 3 x 2 M
// strip busy for hours), missing points included; the strip itself is analysed.
TEST(TopographyHostile, CorrelationLengthsByFft) {
  std::mt19937_64 random(5);
  for (int trial = 0; trial < 4; ++trial) {
    t::HeightMap map = t::gaussian_random_field(40 + 7 * trial, 33 + 5 * trial, 1e-7, 1e-7,
                                                {{1.0 + trial, 1e-16}}, 11 + trial);
    for (int hole = 0; hole < 20 * trial; ++hole) map.heights[random() % map.heights.size()] = NAN;
    const t::HeightStatistics stats = t::height_statistics(map);
    const t::CorrelationLengths fast = t::correlation_lengths(map, 0.1);
    for (int direction = 0; direction < 2; ++direction) {
      const std::size_t along = direction == 0 ? map.nx : map.ny, across = direction == 0 ? map.ny : map.nx;
      std::size_t lag = 1;
      for (; lag < along / 2; ++lag) {
        long double sum = 0;
        std::size_t count = 0;
        for (std::size_t a = 0; a < across; ++a)
          for (std::size_t k = 0; k + lag < along; ++k) {
            const double p = direction == 0 ? map.at(k, a) : map.at(a, k);
            const double q = direction == 0 ? map.at(k + lag, a) : map.at(a, k + lag);
            if (std::isnan(p) || std::isnan(q)) continue;
            sum += (p - stats.mean) * (q - stats.mean);
            ++count;
          }
        if (count == 0 || static_cast<double>(sum / count) / (stats.rms * stats.rms) < 0.1) break;
      }
      EXPECT_EQ(direction == 0 ? fast.x : fast.y, lag) << "trial " << trial << " direction " << direction;
    }
  }
  // the 3 x 2,000,000 strip, whole (under the sanitizers, ASPERITY_TEST_SUBSAMPLE = k, 1/k of it:
  // the same code, without the minutes an instrumented 6-million-point analysis takes)
  const std::size_t strip_length = 2000000 / asperity::test::subsample_stride();
  t::HeightMap strip = t::gaussian_random_field(strip_length, 3, 1e-8, 1e-8, {{3.0, 1e-16}}, 3);
  t::AnalysisOptions options;
  options.assessment.bootstrap = 0;
  options.fit_heights = false;
  options.max_fit_sample = 5000 / asperity::test::subsample_stride();  // the strip's summits still exceed it
  const auto start = std::chrono::steady_clock::now();
  const t::SurfaceAnalysis a = t::analyse_height_map(std::move(strip), options);
  std::printf("the 3 x %zu strip analysed in %.2f s\n", strip_length,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  EXPECT_GT(a.correlation.x, 2u);
  EXPECT_LE(a.summits_fitted, options.max_fit_sample);
  EXPECT_GT(a.summits.list.size(), options.max_fit_sample);  // a subsample was fitted, and said so
  EXPECT_NE(std::find_if(a.map.notes.begin(), a.map.notes.end(),
                         [](const std::string& note) { return note.find("random subsample") != std::string::npos; }),
            a.map.notes.end());
}
