// What the lookup grid of each curve costs: intervals per order, memory, the grid's measured
// error against the table's own curve, and the time Table::curve takes to make it; with the
// largest max_rel_error the table stores for its served shapes, the table's shapes, its knot
// data in memory and the time Table::open takes (median of 7) (docs/accuracy.md, Cost).
//   grid_report [TABLE]     (default: the table this build ships)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "asperity/table.hpp"

int main(int argc, char** argv) try {
  using namespace asperity;
  const std::string path = argc > 1 ? argv[1] : Table::default_path();
  std::vector<double> open_ms;
  for (int i = 0; i < 7; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const Table opened = Table::open(path);
    open_ms.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(open_ms.begin(), open_ms.end());
  const Table table = Table::open(path);
  std::size_t knot_bytes = 0;
  for (const CurveSet& set : table.data().sets) {
    knot_bytes += set.knots.size() * sizeof(double);
    std::printf("%s %s: %zu shapes, %d knots a curve and order\n", to_string(set.distribution), to_string(set.side),
                set.shapes.size(), set.total_knots());
  }
  std::printf("knot data in memory: %.1f MiB; Table::open: %.0f ms (median of 7)\n", knot_bytes / 1048576.0, open_ms[3]);
  double stored = 0;
  for (const CurveSet& set : table.data().sets)
    for (std::size_t i = 0; i < set.max_rel_error.size(); ++i) {
      const double shape = set.shapes[i / order_count];
      if (shape >= set.shape_min && shape <= set.shape_max) stored = std::max(stored, set.max_rel_error[i]);
    }
  std::printf("largest max_rel_error stored for the served shapes: %.2g\n\n", stored);
  std::printf("| curve | intervals per order | memory (KiB, six orders) | grid error | made in (ms) |\n|---|---|---|---|---|\n");
  auto row = [](const char* name, double shape, const auto& make) {
    const auto start = std::chrono::steady_clock::now();
    const Curve curve = make();
    const double ms = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("| %s %g | %zu | %.0f | %.1e | %.1f |\n", name, shape, curve.grid_intervals(), curve.memory_bytes() / 1024.0,
                curve.grid_error(), ms);
  };
  for (Side side : {Side::tail, Side::bounded})
    for (double shape : {0.5, 0.7, 1.0, 1.73, 2.0, 3.0, 5.0, 12.0, 20.0}) {
      const CurveSet* set = table.find(Distribution::weibull, side);
      if (!set || shape < set->shape_min || shape > set->shape_max) continue;
      row(side == Side::tail ? "Weibull tail" : "Weibull bounded", shape,
          [&] { return table.curve(Distribution::weibull, side, shape); });
    }
  if (table.find(Distribution::gaussian, Side::tail))
    row("Gaussian", 2.0, [&] { return table.curve(Distribution::gaussian, Side::tail, 2.0); });
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "grid_report: %s\n", error.what());
  return 1;
}
