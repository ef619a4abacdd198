// The generator reproduces the shipped default table: a few curves regenerated here must
// match the file knot for knot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "asperity/table.hpp"
#include "asperity/generator/chain_ode.hpp"
#include "asperity/generator/generate.hpp"

namespace {
using namespace asperity;

TEST(Tablegen, RegeneratedCurvesMatchTheShippedTable) {
  const TableData shipped = read_table_file(ASPERITY_TEST_TABLE);
  int compared = 0;
  for (const CurveSet& set : shipped.sets) {
    // three shapes of each set: the ends of the served range and one in the middle
    std::vector<std::size_t> picks;
    for (std::size_t i = 0; i < set.shapes.size(); ++i)
      if (set.shapes[i] == set.shape_min || set.shapes[i] == set.shape_max) picks.push_back(i);
    picks.push_back(set.shapes.size() / 2);
    for (std::size_t index : picks) {
      const generator::CurveId id{set.distribution, set.side, set.shapes[index]};
      const std::vector<double> knots = generator::integrate_curve(id, set.layout, generator::ChainOptions{});
      const double* stored = &set.knots[index * set.curve_stride()];
      double worst = 0;
      for (std::size_t k = 0; k < knots.size(); ++k)
        worst = std::max(worst, std::fabs(knots[k] - stored[k]) / (1 + std::fabs(stored[k])));
      EXPECT_LE(worst, 1e-13) << to_string(set.distribution) << " " << to_string(set.side) << " shape "
                              << set.shapes[index];
      ++compared;
    }
  }
  EXPECT_GE(compared, 7);
}

TEST(Tablegen, ShapeGridHasTheAnchorsAndACentredMargin) {
  generator::GenerateOptions options;
  const std::vector<double> shapes = generator::shape_grid(options);
  for (double anchor : {0.5, 1.0, 2.0, 3.0, 5.0, 20.0})
    EXPECT_NE(std::find(shapes.begin(), shapes.end(), anchor), shapes.end()) << anchor;
  EXPECT_TRUE(std::is_sorted(shapes.begin(), shapes.end()));
  EXPECT_EQ(std::count_if(shapes.begin(), shapes.end(), [](double a) { return a < 0.5; }), shape_stencil / 2);
  EXPECT_EQ(std::count_if(shapes.begin(), shapes.end(), [](double a) { return a > 20; }), shape_stencil / 2);
  for (std::size_t i = 1; i < shapes.size(); ++i)
    EXPECT_LE(shape_grid_variable(shapes[i]) - shape_grid_variable(shapes[i - 1]), options.shape_log_step + 1e-12);
  // the bounded side's grid: the same anchors and margin, 2/3 of the spacing (issue #28)
  const std::vector<double> bounded = generator::shape_grid(options, Side::bounded);
  for (double anchor : {0.5, 1.0, 2.0, 3.0, 5.0, 20.0})
    EXPECT_NE(std::find(bounded.begin(), bounded.end(), anchor), bounded.end()) << anchor;
  EXPECT_EQ(std::count_if(bounded.begin(), bounded.end(), [](double a) { return a > 20; }), shape_stencil / 2);
  for (std::size_t i = 1; i < bounded.size(); ++i)
    EXPECT_LE(shape_grid_variable(bounded[i]) - shape_grid_variable(bounded[i - 1]),
              options.shape_log_step * generator::GenerateOptions::bounded_step_factor + 1e-12);
  EXPECT_GT(bounded.size(), shapes.size() * 5 / 4);
}

}  // namespace

namespace {
// A cheaper table (tablegen --density): fewer knots in every segment, still read back and
// checked by the generator; its error, measured here against 50-digit references elsewhere
// (docs/speed-vs-error.md), grows as the density falls.
TEST(Tablegen, KnotDensityScalesTheLayout) {
  generator::GenerateOptions options;
  options.shape_min = 1.9;
  options.shape_max = 2.1;
  options.bounded = false;
  options.gaussian = false;
  options.knot_density = 0.25;
  options.check_stride = 8;
  const TableData table = generator::generate_table(options);
  ASSERT_EQ(table.sets.size(), 1u);
  const std::vector<SegmentSpec> base = default_layout(Distribution::weibull, Side::tail);
  const std::vector<SegmentSpec>& layout = table.sets[0].layout;
  ASSERT_EQ(layout.size(), base.size());
  for (std::size_t i = 0; i < base.size(); ++i)
    EXPECT_EQ(layout[i].knots - 1, static_cast<int>(std::round(0.25 * (base[i].knots - 1))));
  EXPECT_NE(table.generator_options.find("knot_density=0.25"), std::string::npos);
  const double worst = *std::max_element(table.sets[0].max_rel_error.begin(), table.sets[0].max_rel_error.end());
  EXPECT_GT(worst, 1e-13);  // coarser than the default table ...
  EXPECT_LT(worst, 1e-8);   // ... but still good (measured 1.6e-10 for the load at a = 2)
}
}  // namespace
