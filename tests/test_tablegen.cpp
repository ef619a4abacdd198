// The generator reproduces the shipped default table: a few curves regenerated here must
// match the file knot for knot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "asperity/table.hpp"
#include "chain_ode.hpp"
#include "generate.hpp"

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
      const tablegen::CurveId id{set.distribution, set.side, set.shapes[index]};
      const std::vector<double> knots = tablegen::integrate_curve(id, set.layout, tablegen::ChainOptions{});
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
  tablegen::GenerateOptions options;
  const std::vector<double> shapes = tablegen::shape_grid(options);
  for (double anchor : {0.5, 1.0, 2.0, 3.0, 5.0, 20.0})
    EXPECT_NE(std::find(shapes.begin(), shapes.end(), anchor), shapes.end()) << anchor;
  EXPECT_TRUE(std::is_sorted(shapes.begin(), shapes.end()));
  EXPECT_EQ(std::count_if(shapes.begin(), shapes.end(), [](double a) { return a < 0.5; }), shape_stencil / 2);
  EXPECT_EQ(std::count_if(shapes.begin(), shapes.end(), [](double a) { return a > 20; }), shape_stencil / 2);
  for (std::size_t i = 1; i < shapes.size(); ++i)
    EXPECT_LE(shape_grid_variable(shapes[i]) - shape_grid_variable(shapes[i - 1]), options.shape_log_step + 1e-12);
}

}  // namespace
