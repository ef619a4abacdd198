// Surface statistics, summits and the whole analysis: synthetic surfaces with known spectra,
// known summits and known marginals, and the two real measured surfaces end to end.
#include <gtest/gtest.h>

#include <algorithm>
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

// Summit heights with a known Weibull law, on both sides: the whole analysis recovers the
// shape within its stated interval.
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
      EXPECT_LE(m.shape.lo, shape) << (bounded ? "bounded" : "tail") << " a = " << shape << " fit " << m.fit.distribution.shape;
      EXPECT_GE(m.shape.hi, shape) << (bounded ? "bounded" : "tail") << " a = " << shape << " fit " << m.fit.distribution.shape;
      EXPECT_EQ(analysis.summit_heights.verdict.best, truth.model) << analysis.summit_heights.verdict.text;
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
  }
}

// The two real surfaces, end to end: read, level, statistics, summits, fits, contact curves of
// every fit (scene tables at the fitted shapes), the report.
TEST(TopographySurface, RealSurfacesEndToEnd) {
  struct Case {
    std::string file;
    std::size_t summits;
  };
  for (const Case& c : {Case{"digitalsurf-650x650.x3p", 2482}, Case{"afm-zsensor-10um.txt", 1670}}) {
    t::AnalysisOptions options;
    options.assessment.bootstrap = 19;
    options.sampling_factors = {1, 2};
    t::ContactOptions contact;
    contact.contact_modulus = 1e11;
    contact.pressures = {1e6, 1e7};
    contact.curve_points = 9;
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
        EXPECT_GT(m.curve[k].pressure, m.curve[k - 1].pressure) << m.label;
        EXPECT_GT(m.curve[k].stiffness, m.curve[k - 1].stiffness) << m.label;
        EXPECT_GT(m.curve[k].area_fraction, m.curve[k - 1].area_fraction) << m.label;
        EXPECT_LT(m.curve[k].mean_separation, m.curve[k - 1].mean_separation) << m.label;
      }
      ASSERT_EQ(m.at_pressures.size(), 2u);
      EXPECT_NEAR(m.at_pressures[0].pressure / 1e6, 1, 1e-9) << m.label;
    }
    EXPECT_GE(served, 3) << c.file;
  }
}

TEST(TopographySurface, ReportWithoutPlots) {
  const std::vector<double> heights(100, 0.0);
  std::vector<double> h(100);
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = 1e-8 * std::sin(0.7 * static_cast<double>(k)) + 1e-8;
  const t::HeightMap map = planted_caps(10, 8, 1e-7, 1e-5, h);
  t::AnalysisOptions options;
  options.level = false;
  options.assessment.bootstrap = 9;
  t::ContactOptions contact;
  contact.contact_modulus = 1e11;
  contact.curve_points = 5;
  options.contact = contact;
  const t::SurfaceAnalysis a = t::analyse_height_map(map, options);
  const std::string dir = std::string(ASPERITY_TEST_BINARY_DIR) + "/topography_report";
  const t::ReportOutcome outcome = t::write_report(a, dir, "/nonexistent/plots.py");
  EXPECT_FALSE(outcome.plots);
  EXPECT_NE(outcome.plot_note.find("not found"), std::string::npos);
  std::ifstream md(dir + "/report.md");
  const std::string text((std::istreambuf_iterator<char>(md)), {});
  EXPECT_NE(text.find("no plots"), std::string::npos);
  EXPECT_NE(text.find("Verdict"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir + "/curves.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/summits.csv"));
  const std::string json = t::analysis_json(a);
  EXPECT_NE(json.find("\"schema\": \"asperity-surface/1\""), std::string::npos);
  EXPECT_THROW(t::write_report(a, "/proc/no/such/dir"), asperity::Error);
}
