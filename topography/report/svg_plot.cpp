#include "svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace asperity::topography::detail {
namespace {

constexpr double panel_width = 430, plot_width = 330, plot_height = 250;
constexpr double left_margin = 78, top_margin = 30, axis_room = 48, legend_line = 15;
const char* font = "font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\"";

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", v);
  return text;
}

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string tick_text(double v) {
  if (std::fabs(v) < 1e-300) return "0";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

// One axis: data range to pixels, linear or logarithmic, with its ticks.
struct Axis {
  double lo = 0, hi = 1;  // in the axis variable (log10 for a log axis)
  bool log = false;
  bool usable(double v) const { return std::isfinite(v) && (!log || v > 0); }
  double variable(double v) const { return log ? std::log10(v) : v; }
  double fraction(double v) const { return (variable(v) - lo) / (hi - lo); }

  void fit(double data_lo, double data_hi) {
    if (!(data_lo <= data_hi)) data_lo = data_hi = log ? 1 : 0;
    double a = variable(data_lo), b = variable(data_hi);
    if (log) {
      a = std::floor(a + 1e-9);
      b = std::ceil(b - 1e-9);
      if (b <= a) b = a + 1;
    } else {
      const double span = b > a ? b - a : std::max(std::fabs(a), 1.0);
      a -= 0.05 * span;
      b += 0.05 * span;
    }
    lo = a;
    hi = b;
  }

  std::vector<std::pair<double, std::string>> ticks() const {
    std::vector<std::pair<double, std::string>> out;
    if (log) {
      const int first = static_cast<int>(std::ceil(lo - 1e-9)), last = static_cast<int>(std::floor(hi + 1e-9));
      const int step = std::max(1, (last - first + 7) / 7);
      for (int e = first; e <= last; e += step) out.emplace_back(std::pow(10.0, e), "1e" + std::to_string(e));
      return out;
    }
    const double raw = (hi - lo) / 5, magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double unit = raw / magnitude;
    const double step = magnitude * (unit < 1.5 ? 1 : unit < 3 ? 2 : unit < 7 ? 5 : 10);
    for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step)
      out.emplace_back(std::fabs(t) < 1e-9 * step ? 0.0 : t, tick_text(std::fabs(t) < 1e-9 * step ? 0.0 : t));
    return out;
  }
};

// Liang-Barsky: the part of segment (x0,y0)-(x1,y1) inside [0,w] x [0,h]; false if none.
bool clip(double& x0, double& y0, double& x1, double& y1, double w, double h) {
  double t0 = 0, t1 = 1;
  const double dx = x1 - x0, dy = y1 - y0;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {x0, w - x0, y0, h - y0};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0) return false;
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  const double ax = x0 + t0 * dx, ay = y0 + t0 * dy, bx = x0 + t1 * dx, by = y0 + t1 * dy;
  x0 = ax;
  y0 = ay;
  x1 = bx;
  y1 = by;
  return true;
}

// A panel's plot area: its axes fitted to the data and its frame's corner on the page.
struct PanelFrame {
  Axis ax, ay;
  double px = 0, py = 0;   // the top left corner of the plot area
  bool empty = false;      // no usable data point
  double to_x(double v) const { return ax.fraction(v) * plot_width; }
  double to_y(double v) const { return (1 - ay.fraction(v)) * plot_height; }
};

// The panel's axes, fitted to its usable series points and bars.
PanelFrame fit_panel(const PlotPanel& panel, double origin_x) {
  PanelFrame frame;
  Axis& ax = frame.ax;
  Axis& ay = frame.ay;
  ax.log = panel.log_x;
  ay.log = panel.log_y;
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo;
  const auto take = [&](double x, double y) {
    if (!ax.usable(x) || !ay.usable(y)) return;
    x_lo = std::min(x_lo, x);
    x_hi = std::max(x_hi, x);
    y_lo = std::min(y_lo, y);
    y_hi = std::max(y_hi, y);
  };
  for (const PlotSeries& s : panel.series)
    for (std::size_t k = 0; k < std::min(s.x.size(), s.y.size()); ++k) take(s.x[k], s.y[k]);
  for (std::size_t k = 0; k + 1 < panel.bars.edges.size() && k < panel.bars.heights.size(); ++k) {
    take(panel.bars.edges[k], panel.bars.heights[k]);
    take(panel.bars.edges[k + 1], panel.bars.heights[k]);
    if (!ay.log) take(panel.bars.edges[k], 0);
  }
  frame.empty = !(x_lo <= x_hi);
  ax.fit(x_lo, x_hi);
  ay.fit(y_lo, y_hi);
  // a density's axis starts at 0
  if (!ay.log && !panel.bars.edges.empty() && y_lo >= 0) ay.lo = 0;
  frame.px = origin_x + left_margin;
  frame.py = top_margin;
  return frame;
}

// The title, the plot area's background, the grid with its ticks, the axis labels and, without
// data, "no data".
void draw_axes(std::string& svg, const PlotPanel& panel, const PanelFrame& frame, double origin_x) {
  const double px = frame.px, py = frame.py;
  svg += "<text x=\"" + number(px + plot_width / 2) + "\" y=\"18\" font-size=\"12\" text-anchor=\"middle\" " + font +
         " fill=\"#000000\">" + escaped(panel.title) + "</text>\n";
  svg += "<rect x=\"" + number(px) + "\" y=\"" + number(py) + "\" width=\"" + number(plot_width) + "\" height=\"" +
         number(plot_height) + "\" fill=\"#ffffff\"/>\n";
  // grid and ticks
  for (const auto& [value, text] : frame.ax.ticks()) {
    const double x = px + frame.to_x(value);
    if (x < px - 0.5 || x > px + plot_width + 0.5) continue;
    svg += "<line x1=\"" + number(x) + "\" y1=\"" + number(py) + "\" x2=\"" + number(x) + "\" y2=\"" +
           number(py + plot_height) + "\" stroke=\"#e0e0e0\" stroke-width=\"1\"/>\n";
    svg += "<line x1=\"" + number(x) + "\" y1=\"" + number(py + plot_height) + "\" x2=\"" + number(x) + "\" y2=\"" +
           number(py + plot_height + 4) + "\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
    svg += "<text x=\"" + number(x) + "\" y=\"" + number(py + plot_height + 16) +
           "\" font-size=\"10\" text-anchor=\"middle\" " + font + " fill=\"#000000\">" + escaped(text) + "</text>\n";
  }
  for (const auto& [value, text] : frame.ay.ticks()) {
    const double y = py + frame.to_y(value);
    if (y < py - 0.5 || y > py + plot_height + 0.5) continue;
    svg += "<line x1=\"" + number(px) + "\" y1=\"" + number(y) + "\" x2=\"" + number(px + plot_width) + "\" y2=\"" +
           number(y) + "\" stroke=\"#e0e0e0\" stroke-width=\"1\"/>\n";
    svg += "<line x1=\"" + number(px - 4) + "\" y1=\"" + number(y) + "\" x2=\"" + number(px) + "\" y2=\"" + number(y) +
           "\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
    svg += "<text x=\"" + number(px - 6) + "\" y=\"" + number(y + 3.5) + "\" font-size=\"10\" text-anchor=\"end\" " +
           font + " fill=\"#000000\">" + escaped(text) + "</text>\n";
  }
  svg += "<text x=\"" + number(px + plot_width / 2) + "\" y=\"" + number(py + plot_height + 34) +
         "\" font-size=\"11\" text-anchor=\"middle\" " + font + " fill=\"#000000\">" + escaped(panel.x_label) +
         "</text>\n";
  const double label_x = origin_x + 14, label_y = py + plot_height / 2;
  // rotated about its own anchor by translate and a one-argument rotate: ImageMagick's renderer ignores
  // rotate's centre (rotate(-90 x y)) and drew no y label
  svg += std::string("<text x=\"0\" y=\"0\" font-size=\"11\" text-anchor=\"middle\" ") + font + " fill=\"#000000\" transform=\"translate(" +
         number(label_x) + " " + number(label_y) + ") rotate(-90)\">" + escaped(panel.y_label) + "</text>\n";
  if (frame.empty) {
    svg += "<text x=\"" + number(px + plot_width / 2) + "\" y=\"" + number(py + plot_height / 2) +
           "\" font-size=\"11\" text-anchor=\"middle\" " + font + " fill=\"#808080\">no data</text>\n";
  }
}

// The bars (clamped to the plot area) and the dashed reference lines.
void draw_bars_and_marks(std::string& svg, const PlotPanel& panel, const PanelFrame& frame) {
  const Axis& ax = frame.ax;
  const Axis& ay = frame.ay;
  const double px = frame.px, py = frame.py;
  const auto to_x = [&](double v) { return frame.to_x(v); };
  const auto to_y = [&](double v) { return frame.to_y(v); };
  // bars
  const auto& bars = panel.bars;
  for (std::size_t k = 0; k + 1 < bars.edges.size() && k < bars.heights.size(); ++k) {
    if (!ax.usable(bars.edges[k]) || !ax.usable(bars.edges[k + 1]) || !ay.usable(bars.heights[k])) continue;
    double x0 = std::clamp(to_x(bars.edges[k]), 0.0, plot_width), x1 = std::clamp(to_x(bars.edges[k + 1]), 0.0, plot_width);
    const double top = std::clamp(to_y(bars.heights[k]), 0.0, plot_height);
    const double bottom = ay.log ? plot_height : std::clamp(to_y(0), 0.0, plot_height);
    if (x1 <= x0 || bottom <= top) continue;
    svg += "<rect x=\"" + number(px + x0) + "\" y=\"" + number(py + top) + "\" width=\"" + number(x1 - x0) +
           "\" height=\"" + number(bottom - top) + "\" fill=\"#d9d9d9\" stroke=\"#999999\" stroke-width=\"0.5\"/>\n";
  }
  // reference lines
  for (double v : panel.x_marks)
    if (ax.usable(v) && to_x(v) >= 0 && to_x(v) <= plot_width)
      svg += "<line x1=\"" + number(px + to_x(v)) + "\" y1=\"" + number(py) + "\" x2=\"" + number(px + to_x(v)) +
             "\" y2=\"" + number(py + plot_height) + "\" stroke=\"#a0a0a0\" stroke-width=\"1\" stroke-dasharray=\"2,3\"/>\n";
  for (double v : panel.y_marks)
    if (ay.usable(v) && to_y(v) >= 0 && to_y(v) <= plot_height)
      svg += "<line x1=\"" + number(px) + "\" y1=\"" + number(py + to_y(v)) + "\" x2=\"" + number(px + plot_width) +
             "\" y2=\"" + number(py + to_y(v)) + "\" stroke=\"#a0a0a0\" stroke-width=\"1\" stroke-dasharray=\"2,3\"/>\n";
}

// One series, clipped to the frame: its points as dots, or its line as polylines.
void draw_series(std::string& svg, const PlotSeries& s, const PanelFrame& frame) {
  const Axis& ax = frame.ax;
  const Axis& ay = frame.ay;
  const double px = frame.px, py = frame.py;
  const auto to_x = [&](double v) { return frame.to_x(v); };
  const auto to_y = [&](double v) { return frame.to_y(v); };
  const std::size_t n = std::min(s.x.size(), s.y.size());
  if (s.points) {
    for (std::size_t k = 0; k < n; ++k) {
      if (!ax.usable(s.x[k]) || !ay.usable(s.y[k])) continue;
      const double x = to_x(s.x[k]), y = to_y(s.y[k]);
      if (x < 0 || x > plot_width || y < 0 || y > plot_height) continue;
      svg += "<circle cx=\"" + number(px + x) + "\" cy=\"" + number(py + y) + "\" r=\"1.3\" fill=\"" + s.colour +
             "\"/>\n";
    }
    return;
  }
  std::string points;
  const std::string style = "\" fill=\"none\" stroke=\"" + s.colour + "\" stroke-width=\"1.4\"" +
                            (s.dashed ? " stroke-dasharray=\"5,3\"" : "") + "/>\n";
  const auto flush = [&] {
    if (points.find(' ') != std::string::npos) svg += "<polyline points=\"" + points + style;
    points.clear();
  };
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (!ax.usable(s.x[k]) || !ay.usable(s.y[k]) || !ax.usable(s.x[k + 1]) || !ay.usable(s.y[k + 1])) {
      flush();
      continue;
    }
    double x0 = to_x(s.x[k]), y0 = to_y(s.y[k]), x1 = to_x(s.x[k + 1]), y1 = to_y(s.y[k + 1]);
    const bool start_inside = x0 >= 0 && x0 <= plot_width && y0 >= 0 && y0 <= plot_height;
    const bool end_inside = x1 >= 0 && x1 <= plot_width && y1 >= 0 && y1 <= plot_height;
    if (!clip(x0, y0, x1, y1, plot_width, plot_height)) {
      flush();
      continue;
    }
    if (!start_inside) flush();
    if (points.empty()) points = number(px + x0) + "," + number(py + y0);
    points += " " + number(px + x1) + "," + number(py + y1);
    if (!end_inside) flush();
  }
  flush();
}

// The legend, below the axes and their labels: never on the data.
void draw_legend(std::string& svg, const PlotPanel& panel, const PanelFrame& frame, std::size_t index) {
  const double px = frame.px, py = frame.py;
  svg += "<g id=\"legend-" + std::to_string(index) + "\">\n";
  double row = py + plot_height + axis_room;
  const auto legend = [&](const std::string& label, const std::string& colour, bool points, bool dashed, bool bar) {
    row += legend_line;
    const double x = px;
    if (bar)
      svg += "<rect x=\"" + number(x) + "\" y=\"" + number(row - 8) + "\" width=\"18\" height=\"9\" fill=\"#d9d9d9\" "
             "stroke=\"#999999\" stroke-width=\"0.5\"/>\n";
    else if (points)
      svg += "<circle cx=\"" + number(x + 9) + "\" cy=\"" + number(row - 3.5) + "\" r=\"2.5\" fill=\"" + colour + "\"/>\n";
    else
      svg += "<line x1=\"" + number(x) + "\" y1=\"" + number(row - 3.5) + "\" x2=\"" + number(x + 18) + "\" y2=\"" +
             number(row - 3.5) + "\" stroke=\"" + colour + "\" stroke-width=\"1.6\"" +
             (dashed ? " stroke-dasharray=\"5,3\"" : "") + "/>\n";
    svg += "<text x=\"" + number(x + 24) + "\" y=\"" + number(row) + "\" font-size=\"10\" " + font +
           " fill=\"#000000\">" + escaped(label) + "</text>\n";
  };
  if (!panel.bars.label.empty()) legend(panel.bars.label, "", false, false, true);
  for (const PlotSeries& s : panel.series)
    if (!s.label.empty()) legend(s.label, s.colour, s.points, s.dashed, false);
  svg += "</g>\n";
}

void draw_panel(std::string& svg, const PlotPanel& panel, double origin_x, std::size_t index) {
  const PanelFrame frame = fit_panel(panel, origin_x);
  draw_axes(svg, panel, frame, origin_x);

  // the data: bars, reference lines and series, grouped (a plain <g>, which every renderer knows) so
  // that a test can tell them from the legend
  svg += "<g id=\"data-" + std::to_string(index) + "\">\n";
  draw_bars_and_marks(svg, panel, frame);
  // series, clipped to the frame
  for (const PlotSeries& s : panel.series) draw_series(svg, s, frame);
  svg += "</g>\n";
  // the frame (the axes) over the data, so that no bar or curve hides it
  svg += "<rect x=\"" + number(frame.px) + "\" y=\"" + number(frame.py) + "\" width=\"" + number(plot_width) +
         "\" height=\"" + number(plot_height) + "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
  draw_legend(svg, panel, frame, index);
}

}  // namespace

std::string svg_figure(const std::vector<PlotPanel>& panels) {
  std::size_t rows = 0;
  for (const PlotPanel& panel : panels) {
    std::size_t n = panel.bars.label.empty() ? 0 : 1;
    for (const PlotSeries& s : panel.series) n += s.label.empty() ? 0 : 1;
    rows = std::max(rows, n);
  }
  const double width = panel_width * static_cast<double>(std::max<std::size_t>(panels.size(), 1));
  const double height = top_margin + plot_height + axis_room + legend_line * static_cast<double>(rows) + 12;
  std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
                    number(width) + "\" height=\"" + number(height) + "\" viewBox=\"0 0 " + number(width) + " " +
                    number(height) + "\">\n";
  // the background a unit past each edge: ImageMagick left the last column and row unpainted (black)
  svg += "<rect x=\"-1\" y=\"-1\" width=\"" + number(width + 2) + "\" height=\"" + number(height + 2) + "\" fill=\"#ffffff\"/>\n";
  for (std::size_t k = 0; k < panels.size(); ++k)
    draw_panel(svg, panels[k], panel_width * static_cast<double>(k), k);
  svg += "</svg>\n";
  return svg;
}

}  // namespace asperity::topography::detail
