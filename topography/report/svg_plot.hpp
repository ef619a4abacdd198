// Plots as SVG, drawn here rather than by a plotting program (internal to the report): the
// report needs no Python, runs nothing, and its figures render the same in every SVG renderer
// (librsvg, ImageMagick's own, browsers). Only the elements every renderer knows: rect, line,
// polyline, circle and text with presentation attributes; no CSS, <defs>, <use> or clip paths
// (lines are clipped to the axes here), and <g> to group them. Legends sit below their panel,
// never on the data: panel k's curves and markers are in <g id="data-k">, its legend in
// <g id="legend-k"> (tests/test_topography_report.cpp checks that the two never meet).
#pragma once
#include <string>
#include <vector>

namespace asperity::topography::detail {

struct PlotSeries {
  std::string label;                // empty: not in the legend
  std::string colour = "#000000";
  std::vector<double> x, y;
  bool points = false;              // markers instead of a line
  bool dashed = false;
};

struct PlotBars {                   // a histogram: edges.size() == heights.size() + 1
  std::string label;
  std::vector<double> edges, heights;
};

struct PlotPanel {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  PlotBars bars;                    // none when empty
  std::vector<PlotSeries> series;
  std::vector<double> x_marks, y_marks;  // dotted reference lines
};

// The panels side by side in one SVG document. Non-finite points (and, on a log axis,
// points <= 0) are left out; a panel with no point left says so in its frame.
std::string svg_figure(const std::vector<PlotPanel>& panels);

}  // namespace asperity::topography::detail
