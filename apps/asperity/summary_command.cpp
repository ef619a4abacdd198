#include "summary_command.hpp"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "asperity/contact.hpp"
#include "command_line.hpp"

namespace asperity::cli {
namespace {

int summary(const Table& table) {
  const SurfaceScales unit;  // N = R = sigma_s = E* = 1: the values are the dimensionless X_n scaled
  std::printf("Unit surface (N = R = sigma_s = E* = 1). sep: origin convention; xi: (s - mean)/rms.\n");
  std::printf("%-9s %-8s %6s %9s %9s %12s %12s %12s %12s %10s\n", "dist", "side", "shape", "sep", "xi", "count",
              "area", "load", "stiffness", "K/P");
  struct Row {
    Distribution distribution;
    Side side;
    double shape;
  };
  const std::vector<Row> rows = {{Distribution::gaussian, Side::tail, 2},   {Distribution::weibull, Side::tail, 1},
                                 {Distribution::weibull, Side::tail, 2},    {Distribution::weibull, Side::tail, 5},
                                 {Distribution::weibull, Side::bounded, 1}, {Distribution::weibull, Side::bounded, 2},
                                 {Distribution::weibull, Side::bounded, 5}};
  for (const Row& row : rows) {
    const Curve curve = table.curve(row.distribution, row.side, row.shape);
    const std::vector<double> positions = row.side == Side::tail ? std::vector<double>{0, 1, 2, 3}
                                                                 : std::vector<double>{-0.05, -0.2, -0.5, -1};
    for (double position : positions) {
      const double separation = row.side == Side::tail ? origin_from_standardized(curve, position) : position;
      ContactState state;
      contact_at(curve, unit, separation, state);
      // the Gaussian has neither a side nor a shape: dashes, not the Weibull's defaults
      const bool weibull = row.distribution == Distribution::weibull;
      char shape[16];
      std::snprintf(shape, sizeof shape, "%6.2g", row.shape);
      std::printf("%-9s %-8s %6s %9.4f %9.4f %12.5g %12.5g %12.5g %12.5g %10.4g\n", to_string(row.distribution),
                  weibull ? to_string(row.side) : "-", weibull ? shape : "-", separation,
                  standardized_from_origin(curve, separation), state.count, state.area, state.load, state.stiffness,
                  state.stiffness_ratio);
    }
  }
  return exit_success;
}

}  // namespace

void add_summary_command(CLI::App& app) {
  auto table_path = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "summary", "count, area, load and stiffness of a unit surface for a few shapes on both sides (a quick check)");
  add_table_option(*command, *table_path);
  command->footer(exit_status_help);
  set_action(*command, [table_path] { return summary(open_table(*table_path)); });
}

}  // namespace asperity::cli
