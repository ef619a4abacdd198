// Report folders written as tables are (issue 26): no link followed, no special file opened or
// waited on, each file replaced whole, one run's files never beside another's, write errors
// reported; and plots that every SVG renderer draws with their axes and curves (issue 32).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "asperity/error.hpp"
#include "asperity/topography/analysis.hpp"
#include "asperity/topography/goodness_of_fit.hpp"
#include "asperity/topography/surface_report.hpp"
#include "asperity/topography/surrogates.hpp"
#include "asperity/topography/synthetic.hpp"
#ifdef ASPERITY_TEST_LAW  // with the commands: a law made as `asperity surface --law` makes it
#include "law_options.hpp"
#endif

namespace t = asperity::topography;
namespace fs = std::filesystem;

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A small synthetic surface analysed with its contact curves (the default table), and a contact
// law beside them when one is given.
t::SurfaceAnalysis small_analysis(std::uint64_t seed, int bootstrap = 40, t::LawSceneMaker law = {}) {
  t::HeightMap map = t::gaussian_random_field(96, 96, 1e-7, 1e-7, {{1.5, 4e-16}}, seed);
  map.source = "synthetic-" + std::to_string(seed);
  t::AnalysisOptions options;
  options.assessment.bootstrap = bootstrap;
  options.assessment.threads = 2;
  options.fit_heights = false;
  t::ContactOptions contact;
  contact.contact_modulus = 1e11;
  contact.curve_points = 9;
  contact.table_path = ASPERITY_TEST_TABLE;
  options.contact = contact;
  options.law = std::move(law);
  return t::analyse_height_map(map, options);
}

const t::SurfaceAnalysis& analysis() {
  static const t::SurfaceAnalysis a = small_analysis(1);
  return a;
}

#ifdef ASPERITY_TEST_LAW
// The same surface with a contact law beside the elastic curves (Kogut-Etsion, a steel's yield
// strength), made as `asperity surface --law` makes it: its report adds law.svg.
const t::SurfaceAnalysis& law_analysis() {
  static const t::SurfaceAnalysis a = [] {
    asperity::cli::LawOptions law;
    law.law = "kogut-etsion";
    law.material.set(asperity::LawParameter::yield_strength, 1e9);
    law.material.set(asperity::LawParameter::poisson, 0.3);
    return small_analysis(1, 0, [law](const asperity::RoughSurface& surface, double s_min, double s_max, double approach) {
      return asperity::cli::law_scene(law, surface, s_min, s_max, "test", approach);
    });
  }();
  return a;
}
#endif

// Each plot of the reports, and the analysis whose report has it.
struct Plot {
  std::string name;
  const t::SurfaceAnalysis& (*analysis)();
};
const Plot plots[] = {{"fits", analysis},
                      {"contact", analysis},
#ifdef ASPERITY_TEST_LAW
                      {"law", law_analysis}
#endif
};

// A box in the SVG's user units (the renderers draw one unit a pixel).
struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  bool empty() const { return x0 > x1; }
  void add(double x, double y) {
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  bool meets(const Box& o) const { return !empty() && !o.empty() && x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

// The value of attribute `name` in the element starting at `from`.
double attribute(const std::string& svg, std::size_t from, const std::string& name) {
  const std::size_t end = svg.find('>', from);
  const std::size_t at = svg.find(" " + name + "=\"", from);
  if (at == std::string::npos || at > end) return NAN;
  return std::strtod(svg.c_str() + at + name.size() + 3, nullptr);
}

// The text of attribute `name` in the element starting at `from` (empty: none).
std::string attribute_text(const std::string& svg, std::size_t from, const std::string& name) {
  const std::size_t end = svg.find('>', from);
  const std::size_t at = svg.find(" " + name + "=\"", from);
  if (at == std::string::npos || at > end) return "";
  const std::size_t open = at + name.size() + 3;
  return svg.substr(open, svg.find('"', open) - open);
}

// What <g id="ID"> ... </g> draws: every polyline point, circle, rect, line and text (a text's box
// from its anchor, font size and length, generously: 0.62 em a character).
Box group_box(const std::string& svg, const std::string& id) {
  Box box;
  const std::size_t start = svg.find("<g id=\"" + id + "\">");
  if (start == std::string::npos) return box;
  const std::size_t stop = svg.find("</g>", start);
  for (std::size_t at = svg.find('<', start + 1); at < stop; at = svg.find('<', at + 1)) {
    const std::string tag = svg.substr(at + 1, svg.find_first_of(" >", at) - at - 1);
    if (tag == "polyline") {
      const std::size_t q = svg.find("points=\"", at) + 8;
      std::istringstream points(svg.substr(q, svg.find('"', q) - q));
      double x, y;
      char comma;
      while (points >> x >> comma >> y) box.add(x, y);
    } else if (tag == "circle") {
      const double x = attribute(svg, at, "cx"), y = attribute(svg, at, "cy"), r = attribute(svg, at, "r");
      box.add(x - r, y - r), box.add(x + r, y + r);
    } else if (tag == "rect") {
      const double x = attribute(svg, at, "x"), y = attribute(svg, at, "y");
      box.add(x, y), box.add(x + attribute(svg, at, "width"), y + attribute(svg, at, "height"));
    } else if (tag == "line") {
      box.add(attribute(svg, at, "x1"), attribute(svg, at, "y1")), box.add(attribute(svg, at, "x2"), attribute(svg, at, "y2"));
    } else if (tag == "text") {
      const double x = attribute(svg, at, "x"), y = attribute(svg, at, "y"), size = attribute(svg, at, "font-size");
      const std::size_t open = svg.find('>', at) + 1;
      const double length = static_cast<double>(svg.find("</text>", open) - open);
      box.add(x, y - size), box.add(x + 0.62 * size * length, y + 0.3 * size);  // anchored at the start
    }
  }
  return box;
}

std::string folder(const std::string& name) {
  const fs::path dir = fs::path(ASPERITY_TEST_BINARY_DIR) / "topography_report" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

}  // namespace

// A symbolic link planted under a report file's name is never followed (before: its target was
// overwritten with the report): the run is refused before anything is written, the link and its
// target kept; with overwrite the link itself is replaced, its target still untouched.
TEST(TopographyReport, PlantedLinkIsNeverFollowed) {
  const std::string dir = folder("link");
  const std::string victim = fs::path(dir).parent_path() / "victim.txt";
  std::ofstream(victim) << "precious";
  fs::create_symlink(victim, dir + "/report.json");
  fs::create_symlink(victim, dir + "/fits.svg");
  try {
    t::write_report(analysis(), dir);
    ADD_FAILURE() << "a planted link was accepted";
  } catch (const asperity::Error& error) {
    EXPECT_NE(std::string(error.what()).find("report.json is a symbolic link, never followed"), std::string::npos)
        << error.what();
  }
  EXPECT_EQ(read_text(victim), "precious");
  EXPECT_TRUE(fs::is_symlink(dir + "/report.json"));
  EXPECT_FALSE(fs::exists(dir + "/report.md"));  // nothing written
  t::write_report(analysis(), dir, true);
  EXPECT_EQ(read_text(victim), "precious");
  EXPECT_FALSE(fs::is_symlink(dir + "/report.json"));
  EXPECT_NE(read_text(dir + "/report.json").find("asperity-surface/3"), std::string::npos);
  // a link planted as the folder's lock is refused, not followed
  const std::string other = folder("lock-link");
  fs::create_symlink(victim, other + "/.asperity.lock");
  EXPECT_THROW(t::write_report(analysis(), other), asperity::Error);
  EXPECT_EQ(read_text(victim), "precious");
  EXPECT_FALSE(fs::exists(other + "/report.md"));
}

// A FIFO planted under a report file's name is never opened (before: the command hung on it) and
// never replaced, not even with overwrite: refused at once; a FIFO as the lock too.
TEST(TopographyReport, PlantedFifoDoesNotHang) {
  const std::string dir = folder("fifo");
  ASSERT_EQ(mkfifo((dir + "/report.md").c_str(), 0600), 0);
  ASSERT_EQ(mkfifo((dir + "/summits.csv").c_str(), 0600), 0);
  for (bool overwrite : {false, true}) {
    EXPECT_THROW(t::write_report(analysis(), dir, overwrite), asperity::Error);
    EXPECT_TRUE(fs::is_fifo(dir + "/report.md"));
    EXPECT_TRUE(fs::is_fifo(dir + "/summits.csv"));
    EXPECT_FALSE(fs::exists(dir + "/report.json"));
  }
  const std::string other = folder("fifo-lock");
  ASSERT_EQ(mkfifo((other + "/.asperity.lock").c_str(), 0600), 0);
  EXPECT_THROW(t::write_report(analysis(), other), asperity::Error);
  // a directory in the way of a file is reported, and left
  const std::string third = folder("directory");
  fs::create_directories(third + "/curves.csv/inside");
  EXPECT_THROW(t::write_report(analysis(), third), asperity::Error);
  EXPECT_TRUE(fs::is_directory(third + "/curves.csv/inside"));
}

// Two runs into one folder, at the same time: the folder ends with one run's files, all of them
// (before: one input's JSON beside the other's Markdown); a later run without contact curves
// removes the earlier run's curves; nothing temporary is left.
TEST(TopographyReport, OneRunsFilesNeverBesideAnothers) {
  const std::string dir = folder("two-runs");
  const t::SurfaceAnalysis second = small_analysis(2);
  for (int round = 0; round < 5; ++round) {
    std::thread a([&] { t::write_report(analysis(), dir); });
    std::thread b([&] { t::write_report(second, dir); });
    a.join();
    b.join();
    const std::string md = read_text(dir + "/report.md"), json = read_text(dir + "/report.json"),
                      summits = read_text(dir + "/summits.csv");
    const bool first = md.find("synthetic-1") != std::string::npos;
    EXPECT_NE(md.find(first ? "synthetic-1" : "synthetic-2"), std::string::npos);
    EXPECT_NE(json.find(first ? "\"synthetic-1\"" : "\"synthetic-2\""), std::string::npos) << "round " << round;
    const t::SurfaceAnalysis& winner = first ? analysis() : second;
    EXPECT_EQ(static_cast<std::size_t>(std::count(summits.begin(), summits.end(), '\n')),
              winner.summits.list.size() + 1);
  }
  t::SurfaceAnalysis without = analysis();
  without.contact.reset();
  const t::ReportOutcome outcome = t::write_report(without, dir);
  EXPECT_FALSE(fs::exists(dir + "/curves.csv"));
  EXPECT_FALSE(fs::exists(dir + "/contact.svg"));
  EXPECT_EQ(outcome.files.size(), 4u);  // report.md, report.json, summits.csv, fits.svg
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
}

// A write error (here: the file-size limit, as a full disk) is reported naming the file, and
// leaves the earlier report's file whole and no temporary behind.
TEST(TopographyReport, WriteErrorReportedAndNothingLost) {
  const std::string dir = folder("full");
  t::write_report(analysis(), dir);
  const std::string before = read_text(dir + "/report.json");
  const pid_t pid = fork();
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const struct rlimit limit {1000, 1000};
    setrlimit(RLIMIT_FSIZE, &limit);
    try {
      t::write_report(small_analysis(3), dir);
    } catch (const asperity::Error& error) {
      _exit(std::string(error.what()).find("write error") != std::string::npos ? 42 : 1);
    }
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 42);
  EXPECT_EQ(read_text(dir + "/report.json"), before);
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
}

// The plots render with their axes and curves in both librsvg and ImageMagick's own SVG reader
// (before: ImageMagick drew matplotlib's SVGs with empty axes).
TEST(TopographyReport, PlotsRenderInEveryRenderer) {
  for (const Plot& p : plots) {
    const std::string plot = p.name, dir = folder("render-" + plot);
    ASSERT_TRUE(p.analysis().law == std::nullopt || p.analysis().law->served) << p.analysis().law->note;
    t::write_report(p.analysis(), dir);
    const std::string svg = dir + "/" + plot + ".svg";
    const std::string text = read_text(svg);
    for (const char* unknown : {"<defs", "<use", "clip-path", "<style", "class="})
      EXPECT_EQ(text.find(unknown), std::string::npos) << plot << ": " << unknown;
    for (const std::string renderer : {"rsvg", "imagemagick"}) {
      const std::string png = dir + "/" + plot + "-" + renderer + ".png", rgb = png + ".rgb";
      const std::string render = renderer == "rsvg" ? "rsvg-convert -b white -o '" + png + "' '" + svg + "'"
                                                    : "convert -background white 'msvg:" + svg + "' '" + png + "'";
      ASSERT_EQ(std::system(render.c_str()), 0) << render << " (scripts/setup.sh installs librsvg2-bin, imagemagick)";
      ASSERT_EQ(std::system(("convert '" + png + "' -depth 8 'rgb:" + rgb + "'").c_str()), 0);
      const std::string pixels = read_text(rgb);
      std::size_t blue = 0, red = 0, dark = 0;
      for (std::size_t k = 0; k + 2 < pixels.size(); k += 3) {
        const int r = static_cast<unsigned char>(pixels[k]), g = static_cast<unsigned char>(pixels[k + 1]),
                  b = static_cast<unsigned char>(pixels[k + 2]);
        blue += (b > 140 && r < 110 && g < 160 && b - r > 60) ? 1 : 0;   // #1f77b4
        red += (r > 160 && g < 110 && b < 110) ? 1 : 0;                  // #d62728
        dark += (r < 80 && g < 80 && b < 80) ? 1 : 0;                    // axes, text, the Gaussian
      }
      EXPECT_GT(blue, 200u) << plot << " in " << renderer;
      EXPECT_GT(red, 200u) << plot << " in " << renderer;
      EXPECT_GT(dark, 2000u) << plot << " in " << renderer;

      // The axes themselves, panel by panel (ImageMagick once drew plots with empty axes): the frame's
      // four sides dark along most of their length, and dark tick labels below the frame and left of
      // it. The picture is one pixel a unit (its size is the SVG's).
      const double width = attribute(text, text.find("<svg"), "width"), height = attribute(text, text.find("<svg"), "height");
      const std::size_t columns = static_cast<std::size_t>(width), rows = static_cast<std::size_t>(height);
      ASSERT_EQ(pixels.size(), 3 * columns * rows) << plot << " in " << renderer << ": not drawn at its size";
      const auto dark_at = [&](long x, long y) {
        if (x < 0 || y < 0 || x >= static_cast<long>(columns) || y >= static_cast<long>(rows)) return false;
        const std::size_t k = 3 * (static_cast<std::size_t>(y) * columns + static_cast<std::size_t>(x));
        // a black one-unit line on a pixel boundary is drawn as two pixels at half grey (128): dark;
        // the grid (#e0e0e0) and the bars' outline (#999999) are not
        return static_cast<unsigned char>(pixels[k]) < 140 && static_cast<unsigned char>(pixels[k + 1]) < 140 &&
               static_cast<unsigned char>(pixels[k + 2]) < 140;
      };
      // dark pixels in a rectangle; a side of the frame: dark within a pixel of the line, point by point
      const auto dark_in = [&](double x0, double y0, double x1, double y1) {
        std::size_t n = 0;
        for (long y = static_cast<long>(y0); y <= static_cast<long>(y1); ++y)
          for (long x = static_cast<long>(x0); x <= static_cast<long>(x1); ++x) n += dark_at(x, y) ? 1 : 0;
        return n;
      };
      const auto side = [&](double x0, double y0, double x1, double y1) {
        std::size_t covered = 0, steps = 0;
        for (double t = 0.02; t < 0.98; t += 0.01, ++steps) {
          const long x = std::lround(x0 + t * (x1 - x0)), y = std::lround(y0 + t * (y1 - y0));
          covered += (dark_at(x, y) || dark_at(x - 1, y) || dark_at(x + 1, y) || dark_at(x, y - 1) || dark_at(x, y + 1)) ? 1 : 0;
        }
        return static_cast<double>(covered) / static_cast<double>(steps);
      };
      int frames = 0;
      for (std::size_t at = text.find("<rect"); at != std::string::npos; at = text.find("<rect", at + 1)) {
        if (attribute_text(text, at, "stroke") != "#000000" || !(attribute(text, at, "width") > 200))
          continue;  // the frames: outlined in black, the full plot width
        ++frames;
        const double x = attribute(text, at, "x"), y = attribute(text, at, "y");
        const double w = attribute(text, at, "width"), h = attribute(text, at, "height");
        const std::string where = plot + " panel " + std::to_string(frames) + " in " + renderer;
        EXPECT_GT(side(x, y, x + w, y), 0.9) << where << ": top";
        EXPECT_GT(side(x, y + h, x + w, y + h), 0.9) << where << ": bottom axis";
        EXPECT_GT(side(x, y, x, y + h), 0.9) << where << ": left axis";
        EXPECT_GT(side(x + w, y, x + w, y + h), 0.9) << where << ": right";
        EXPECT_GT(dark_in(x, y + h + 6, x + w, y + h + 20), 60u) << where << ": x tick labels";
        EXPECT_GT(dark_in(x - 50, y, x - 6, y + h), 60u) << where << ": y tick labels";
        EXPECT_GT(dark_in(x - 74, y + h / 2 - 40, x - 54, y + h / 2 + 40), 60u) << where << ": y label";
        EXPECT_EQ(dark_in(width - 1, 0, width - 1, height - 1) + dark_in(0, height - 1, width - 1, height - 1), 0u)
            << where << ": the picture's edges";
      }
      EXPECT_GE(frames, 2) << plot << " in " << renderer;
    }
  }
}

// The legends are off the data: in every panel of every plot, the box around the legend meets no
// drawn curve, marker or bar (the box around all of them).
TEST(TopographyReport, LegendsNeverOnTheData) {
  for (const Plot& p : plots) {
    const std::string plot = p.name, dir = folder("legends-" + plot);
    t::write_report(p.analysis(), dir);
    const std::string svg = read_text(dir + "/" + plot + ".svg");
    int panels = 0;
    for (int k = 0; svg.find("<g id=\"data-" + std::to_string(k) + "\">") != std::string::npos; ++k, ++panels) {
      const Box data = group_box(svg, "data-" + std::to_string(k)), legend = group_box(svg, "legend-" + std::to_string(k));
      ASSERT_FALSE(data.empty()) << plot << " panel " << k;
      ASSERT_FALSE(legend.empty()) << plot << " panel " << k;
      EXPECT_FALSE(legend.meets(data)) << plot << " panel " << k << ": legend [" << legend.x0 << ", " << legend.x1
                                       << "] x [" << legend.y0 << ", " << legend.y1 << "], data [" << data.x0 << ", "
                                       << data.x1 << "] x [" << data.y0 << ", " << data.y1 << "]";
    }
    EXPECT_GE(panels, 2) << plot;
  }
}

// Every output that shows a bootstrap p-value writes it as a bound at its floor 1/(B' + 1): the
// report's text, its JSON (…_p_is_bound), its Markdown table and its plots' legends. A
// Gaussian sample tested as a Weibull-shaped one (and a Weibull sample as Gaussian) puts the
// p-values at the floor.
TEST(TopographyReport, PValuesAtTheFloorAreBounds) {
  EXPECT_EQ(t::p_value_text(0.005, true), "p <= 0.005");
  EXPECT_EQ(t::p_value_text(0.0123, false), "p = 0.0123");
  EXPECT_EQ(t::p_value_text(1.0 / 41, true), "p <= 0.0244");  // never rounded below the floor
  EXPECT_EQ(t::p_value_text(NAN, false), "not tested");
  // a sample no Gaussian would give: exponential values, 40 bootstrap samples
  std::vector<double> values;
  for (int k = 0; k < 400; ++k) values.push_back(-std::log(1 - (k + 0.5) / 400));
  t::AssessmentOptions options;
  options.bootstrap = 40;
  options.threads = 2;
  const t::SampleAssessment tested = t::assess_sample("exponential", values, options);
  const t::ModelAssessment& gaussian = tested.model(t::HeightModel::gaussian);
  ASSERT_TRUE(gaussian.p_at_floor);
  ASSERT_TRUE(gaussian.kolmogorov_smirnov_p_at_floor);
  EXPECT_DOUBLE_EQ(gaussian.anderson_darling_p, 1.0 / (41 - gaussian.failed_refits));
  EXPECT_NE(tested.verdict.text.find("not Gaussian (Anderson-Darling p <= 0.0244, Kolmogorov-Smirnov p <= 0.0244"),
            std::string::npos) << tested.verdict.text;
  EXPECT_EQ(tested.verdict.text.find("p = 0.0244"), std::string::npos) << tested.verdict.text;

  // the surface report's writers: the Gaussian's p-values at their floor (1/41, 40 surrogates) are
  // written as bounds in the Markdown table, the JSON and the plot's legend
  t::SurfaceAnalysis a = analysis();
  t::ModelAssessment& m = a.summit_heights.models[static_cast<int>(t::HeightModel::gaussian)];
  ASSERT_EQ(m.bootstrap, 40);
  m.failed_refits = 0;
  m.anderson_darling_p = m.kolmogorov_smirnov_p = 1.0 / 41;
  m.p_at_floor = m.kolmogorov_smirnov_p_at_floor = true;
  const std::string dir = folder("bounds");
  t::write_report(a, dir);
  const std::string json = read_text(dir + "/report.json"), md = read_text(dir + "/report.md");
  const std::string fits = read_text(dir + "/fits.svg");
  EXPECT_NE(md.find("| ≤ 0.0244 | " + std::string()), std::string::npos) << md;  // AD p
  EXPECT_NE(md.find(" | ≤ 0.0244 | "), md.rfind(" | ≤ 0.0244 | ")) << "the KS p too";
  EXPECT_EQ(md.find("| 0.024 |"), std::string::npos);
  EXPECT_EQ(md.find("| 0.0244 |"), std::string::npos);
  EXPECT_NE(json.find("\"anderson_darling_p_is_bound\": true"), std::string::npos);
  EXPECT_NE(json.find("\"kolmogorov_smirnov_p_is_bound\": true"), std::string::npos);
  EXPECT_NE(fits.find("(AD p &lt;= 0.0244)"), std::string::npos);
  EXPECT_EQ(fits.find("(AD p = 0.0244)"), std::string::npos);
}

#ifdef ASPERITY_TEST_LAW
// A contact law beside the elastic curves (issue 30 item 6): its section in report.md, its rows in
// curves.csv, its object in the JSON and law.svg; none of them without a law.
TEST(TopographyReport, TheLawInEveryOutput) {
  const t::SurfaceAnalysis& with = law_analysis();
  ASSERT_TRUE(with.law.has_value());
  ASSERT_TRUE(with.law->served) << with.law->note;
  const std::string dir = folder("law");
  const t::ReportOutcome outcome = t::write_report(with, dir);
  EXPECT_TRUE(fs::exists(dir + "/law.svg"));
  EXPECT_NE(read_text(dir + "/report.md").find("### Under the contact law: kogut-etsion"), std::string::npos);
  EXPECT_NE(read_text(dir + "/report.md").find("![law](law.svg)"), std::string::npos);
  const std::string curves = read_text(dir + "/curves.csv");
  std::size_t rows = 0;
  for (std::size_t at = curves.find("\nlaw:kogut-etsion,"); at != std::string::npos; at = curves.find("\nlaw:kogut-etsion,", at + 1))
    ++rows;
  EXPECT_EQ(rows, with.law->curve.size());
  const std::string json = t::analysis_json(with);
  EXPECT_NE(json.find("\"law\": {\n   \"law\": \"kogut-etsion\""), std::string::npos);
  EXPECT_NE(t::analysis_summary(with).find("law kogut-etsion on the "), std::string::npos);
  // every parameter the law takes (the registry's, issue 38 item 1): Kogut-Etsion's Y and nu
  const nlohmann::json parameters = nlohmann::json::parse(json)["contact"]["law"]["parameters"];
  const asperity::ContactLawDescriptor* ke = asperity::find_contact_law("kogut-etsion");
  ASSERT_TRUE(ke);
  ASSERT_EQ(parameters.size(), static_cast<std::size_t>(ke->parameter_count)) << parameters;
  const double given[] = {1e9, 0.3};  // yield_strength, poisson: the law's order
  for (int k = 0; k < ke->parameter_count; ++k) {
    const asperity::LawParameterInfo& info = asperity::law_parameter_info(ke->parameters[k].parameter);
    EXPECT_EQ(parameters[k]["key"], info.key);
    EXPECT_EQ(parameters[k]["symbol"], info.symbol);
    EXPECT_EQ(parameters[k]["unit"], info.unit);
    EXPECT_EQ(parameters[k]["value"].get<double>(), given[k]) << info.key;
  }
  const std::string law_line = "law kogut-etsion on the " + std::string(t::to_string(with.law->fit)) + " fit (" +
                               with.law->model_reason + "): Y = 1e+09 Pa, nu = 0.3, sigma_s ";
  EXPECT_NE(t::analysis_summary(with).find(law_line), std::string::npos) << t::analysis_summary(with);
  EXPECT_NE(read_text(dir + "/report.md").find("| the law's parameters | Y = 1e+09 Pa, nu = 0.3 |"), std::string::npos);

  const std::string plain = folder("no-law");
  t::write_report(analysis(), plain);
  EXPECT_FALSE(fs::exists(plain + "/law.svg"));
  EXPECT_EQ(read_text(plain + "/curves.csv").find("law:"), std::string::npos);
  EXPECT_EQ(t::analysis_json(analysis()).find("\"law\""), std::string::npos);
  EXPECT_EQ(read_text(plain + "/report.md").find("contact law"), std::string::npos);
}

// An adhesive law is elastic: its report has the adhesion rows and no hardness, ω_c or plasticity
// index (they used to print "nan"); no number of either report is "nan".
TEST(TopographyReport, AnAdhesiveLawReportsItsAdhesionNotPlasticity) {
  asperity::cli::LawOptions jkr;
  jkr.law = "jkr";
  jkr.material.set(asperity::LawParameter::work_of_adhesion, 0.5);
  const t::SurfaceAnalysis adhesive =
      small_analysis(1, 0, [jkr](const asperity::RoughSurface& surface, double s_min, double s_max, double approach) {
        return asperity::cli::law_scene(jkr, surface, s_min, s_max, "test", approach);
      });
  ASSERT_TRUE(adhesive.law.has_value());
  ASSERT_TRUE(adhesive.law->served) << adhesive.law->note;
  const std::string dir = folder("adhesive-law");
  t::write_report(adhesive, dir);
  const std::string md = read_text(dir + "/report.md");
  EXPECT_NE(md.find("### Under the contact law: jkr"), std::string::npos);
  EXPECT_NE(md.find("| adhesion parameter σs/δc (Fuller–Tabor 1975) |"), std::string::npos);
  EXPECT_NE(md.find("| pull-off: greatest tension of the approach branch |"), std::string::npos);
  EXPECT_EQ(md.find("ω_c"), std::string::npos);
  EXPECT_EQ(md.find("| H (GW's ψ) |"), std::string::npos);
  EXPECT_EQ(md.find("nan"), std::string::npos) << md;

  const std::string plastic = folder("law-md");
  t::write_report(law_analysis(), plastic);
  const std::string ke = read_text(plastic + "/report.md");
  EXPECT_NE(ke.find("| ω_c (the law's, at R) |"), std::string::npos);
  EXPECT_EQ(ke.find("adhesion parameter"), std::string::npos);
  EXPECT_EQ(ke.find("nan"), std::string::npos) << ke;
}

// An elastic law (Hertz) defines no hardness, no omega_c and so no plasticity index: each of its
// rows says "not used" and why, never a bare "–" (issue 38).
TEST(TopographyReport, AnElasticLawSaysWhatItDoesNotUse) {
  asperity::cli::LawOptions hertz;
  hertz.law = "hertz";
  const t::SurfaceAnalysis elastic =
      small_analysis(1, 0, [hertz](const asperity::RoughSurface& surface, double s_min, double s_max, double approach) {
        return asperity::cli::law_scene(hertz, surface, s_min, s_max, "test", approach);
      });
  ASSERT_TRUE(elastic.law.has_value());
  const std::string dir = folder("elastic-law");
  t::write_report(elastic, dir);
  const std::string md = read_text(dir + "/report.md");
  EXPECT_NE(md.find("| H (GW's ψ) | not used: the law has no hardness |"), std::string::npos) << md;
  EXPECT_NE(md.find("| ω_c (the law's, at R) | not used: the law does not yield |"), std::string::npos);
  EXPECT_NE(md.find("CEB/KE ω_c) | not used: no ω_c |"), std::string::npos);
  EXPECT_NE(md.find("(Greenwood–Williamson 1966's) | not used: no H |"), std::string::npos);
  EXPECT_EQ(md.find("nan"), std::string::npos) << md;
}
#endif

// ---- issue 40: labels from the code that runs; "closest" only where summits carry it ----

namespace {

nlohmann::json parsed_json(const t::SurfaceAnalysis& a) { return nlohmann::json::parse(t::analysis_json(a)); }

// the FFT's sizes: the least n' >= n of factors 2, 3 and 5 (as surrogates.cpp pads)
std::size_t smooth_size(std::size_t n) {
  for (;; ++n) {
    std::size_t m = n;
    for (std::size_t f : {2, 3, 5})
      while (m % f == 0) m /= f;
    if (m == 1) return n;
  }
}

}  // namespace

// Every method label of report.json and report.md is made from what the code reads (issue 40,
// item 6): the surrogates' words from the window and constants SurrogateFields uses, each
// sample's intervals from the ShapeInterval its intervals were made by. A label naming another
// method (the old "periodogram ... Hann window ... 3 x 3", "percentile intervals" for the
// bias-corrected heights) fails here.
TEST(TopographyReport, MethodLabelsComeFromTheCodeThatRuns) {
  using S = t::SurrogateSpectrum;
  // the window SurrogateFields applies is Tukey's split cosine bell, as its words say
  for (double u = 0; u <= 1.2; u += 0.01) {
    const double tukey = u >= 1 ? 0 : u <= S::window_flat ? 1 : 0.5 * (1 + std::cos(M_PI * (u - S::window_flat) / (1 - S::window_flat)));
    EXPECT_NEAR(t::surrogate_lag_window(u), tukey, 1e-15) << u;
  }
  EXPECT_EQ(t::surrogate_lag_window(0.5), 1.0);
  EXPECT_NEAR(t::surrogate_lag_window(0.75), 0.5, 1e-15);
  const std::string method = t::surrogate_method();
  for (const char* words : {"Blackman and Tukey", "Tukey's lag window", "unbiased autocovariance", "1 to 0.5 of the largest lag",
                            "6 correlation lengths", "at most 3/4 of the map", "F^-1(Phi(g))"})
    EXPECT_NE(method.find(words), std::string::npos) << words << " in " << method;
  for (const char* stale : {"periodogram", "Hann", "Parzen", "3 x 3", "two correlation lengths"})
    EXPECT_EQ(method.find(stale), std::string::npos) << stale << " in " << method;

  t::HeightMap map = t::gaussian_random_field(96, 80, 1e-7, 1e-7, {{1.5, 4e-16}}, 3);
  map.source = "labels";
  t::AnalysisOptions options;
  options.assessment.bootstrap = 40;
  options.assessment.threads = 2;
  options.fit_heights = true;
  const t::SurfaceAnalysis a = t::analyse_height_map(map, options);
  const nlohmann::json j = parsed_json(a);
  EXPECT_EQ(j["ensemble"]["method"], method);
  // the padded grid is the map plus the largest lag the words state, from the constants they name
  const auto largest_lag = [](std::size_t points, std::size_t length) {
    return std::max<std::size_t>(2, std::min(S::largest_lag_map_numerator * points / S::largest_lag_map_denominator,
                                             S::largest_lag_lengths * std::max<std::size_t>(1, length)));
  };
  EXPECT_EQ(j["ensemble"]["padded_grid"][0], smooth_size(96 + largest_lag(96, a.correlation.x)));
  EXPECT_EQ(j["ensemble"]["padded_grid"][1], smooth_size(80 + largest_lag(80, a.correlation.y)));

  // each sample's intervals: the words of the method its Weibull intervals were made by
  ASSERT_TRUE(a.heights);
  const struct {
    const char* key;
    const t::SampleAssessment* sample;
    t::ShapeInterval expected;
  } samples[] = {{"summit_heights", &a.summit_heights, t::ShapeInterval::centred_on_estimate},
                 {"heights", &*a.heights, t::ShapeInterval::bias_corrected}};
  for (const auto& s : samples) {
    for (const t::ModelAssessment& m : s.sample->models) EXPECT_EQ(m.shape_interval, s.expected) << s.key;
    EXPECT_EQ(j["fits"][s.key]["intervals"], t::interval_method(s.expected)) << s.key;
    for (const auto& m : j["fits"][s.key]["models"]) EXPECT_EQ(m["interval_shape_method"], t::to_string(s.expected)) << s.key;
  }
  // the bias-corrected interval is the one that measures a bias slope; the others do not
  for (t::HeightModel model : {t::HeightModel::weibull_tail, t::HeightModel::weibull_bounded}) {
    EXPECT_TRUE(std::isfinite(a.heights->model(model).bias_slope));
    EXPECT_TRUE(std::isnan(a.summit_heights.model(model).bias_slope));
  }
  const std::string bias = t::interval_method(t::ShapeInterval::bias_corrected);
  EXPECT_NE(bias.find("corrected for a bias"), std::string::npos) << bias;
  EXPECT_EQ(bias.find("shape: percentile"), std::string::npos) << bias;
  EXPECT_NE(t::interval_method(t::ShapeInterval::percentile).find("shape: percentile"), std::string::npos);
  EXPECT_NE(t::interval_method(t::ShapeInterval::centred_on_estimate), t::interval_method(t::ShapeInterval::percentile));
  // an i.i.d. bootstrap's intervals are percentile ones, and say so
  std::vector<double> values;
  for (int k = 0; k < 200; ++k) values.push_back(std::sqrt(-std::log(1 - (k + 0.5) / 200)));
  t::AssessmentOptions iid;
  iid.bootstrap = 20;
  iid.threads = 2;
  for (const t::ModelAssessment& m : t::assess_sample("iid", values, iid).models)
    EXPECT_EQ(m.shape_interval, t::ShapeInterval::percentile);
  // report.md gives the same words
  const std::string dir = folder("labels");
  t::write_report(a, dir);
  const std::string md = read_text(dir + "/report.md");
  EXPECT_NE(md.find(method), std::string::npos);
  EXPECT_NE(md.find(t::interval_method(t::ShapeInterval::centred_on_estimate)), std::string::npos);
  EXPECT_NE(md.find(bias), std::string::npos);
  EXPECT_EQ(j["leveling"]["method"], "least-squares plane subtracted");
  // the tables named are those that served the curves: here the given one (small_analysis)
  const nlohmann::json given = parsed_json(analysis());
  EXPECT_NE(given["contact"]["tables"].get<std::string>().find(std::string("the given table ") + ASPERITY_TEST_TABLE),
            std::string::npos)
      << given["contact"]["tables"];
  EXPECT_NE(analysis().contact->find(t::ContactModelKind::weibull_tail)->note.find("table " ASPERITY_TEST_TABLE),
            std::string::npos);
  // no ensemble: no intervals, and the label says so; not leveled: nor does the leveling's
  options.assessment.bootstrap = 0;
  options.fit_heights = false;
  options.level = false;
  const nlohmann::json none = parsed_json(t::analyse_height_map(map, options));
  EXPECT_EQ(none["fits"]["summit_heights"]["intervals"], t::interval_method(t::ShapeInterval::none));
  EXPECT_EQ(none["leveling"]["leveled"], false);
  EXPECT_EQ(none["leveling"]["method"], "none: the heights as read");
}

// How many measured summits carry the answer at each pressure (issue 40, item 4): counted, written
// in every output, and below min_summits_to_compare no model is named closest at that pressure.
TEST(TopographyReport, ClosestModelOnlyWhereEnoughSummitsAreInContact) {
  const t::SurfaceAnalysis& base = analysis();
  ASSERT_TRUE(base.contact);
  const t::ContactComparison& c = *base.contact;
  const t::ModelContact* measured = c.find(t::ContactModelKind::measured_summits);
  ASSERT_TRUE(measured && measured->served);
  ASSERT_EQ(c.measured_summits_in_contact.size(), c.pressures.size());
  const double scale = c.nominal_area / base.summits.area_searched;
  for (std::size_t k = 0; k < c.pressures.size(); ++k) {
    // the count is the measured summits', not scaled to the nominal area
    EXPECT_NEAR(static_cast<double>(c.measured_summits_in_contact[k]), measured->at_pressures[k].count / scale, 1e-6);
    EXPECT_EQ(c.compared_at(k), c.measured_summits_in_contact[k] >= t::min_summits_to_compare);
  }
  const nlohmann::json j = parsed_json(base);
  EXPECT_EQ(j["contact"]["measured_summits_in_contact"].get<std::vector<std::size_t>>(), c.measured_summits_in_contact);
  EXPECT_EQ(j["contact"]["min_measured_summits_to_compare"], t::min_summits_to_compare);
  ASSERT_EQ(j["contact"]["compared_at_pressures"].size(), c.pressures.size());

  // the same comparison with too few summits at the first pressure, then at every pressure
  t::SurfaceAnalysis a = base;
  t::ContactComparison& few = *a.contact;
  ASSERT_GE(few.pressures.size(), 2u);
  for (std::size_t& n : few.measured_summits_in_contact) n = std::max<std::size_t>(n, t::min_summits_to_compare);
  few.measured_summits_in_contact[0] = t::min_summits_to_compare - 1;
  t::conclude_contact(few);
  EXPECT_TRUE(few.closest.has_value());
  EXPECT_NE(few.headline.find("Closest to GW on the measured summits"), std::string::npos) << few.headline;
  EXPECT_NE(few.headline.find("only " + std::to_string(t::min_summits_to_compare - 1) +
                              " measured summits in contact: too few to compare models"),
            std::string::npos)
      << few.headline;
  // the closest is the nearest at the pressures compared only
  double best = INFINITY;
  std::optional<t::ContactModelKind> nearest;
  for (const t::ModelContact& m : few.models) {
    if (!m.served || !t::is_fitted(m.kind)) continue;
    double worst = 0;
    for (std::size_t k = 1; k < few.pressures.size(); ++k) worst = std::max(worst, std::fabs(std::log(m.stiffness_over_measured[k])));
    if (worst < best) {
      best = worst;
      nearest = m.kind;
    }
  }
  EXPECT_EQ(few.closest, nearest);

  for (std::size_t& n : few.measured_summits_in_contact) n = 1;
  t::conclude_contact(few);
  EXPECT_FALSE(few.closest.has_value());
  EXPECT_EQ(few.headline.rfind("No model is named closest to GW on the measured summits: at ", 0), 0u) << few.headline;
  EXPECT_NE(few.headline.find("only 1 measured summit in contact"), std::string::npos) << few.headline;
  EXPECT_EQ(few.headline.find("Closest to"), std::string::npos) << few.headline;
  a.verdict = t::surface_verdict(a);
  const nlohmann::json fj = parsed_json(a);
  EXPECT_EQ(fj["contact"]["closest_fitted_model"], "");
  for (const auto& compared : fj["contact"]["compared_at_pressures"]) EXPECT_EQ(compared, false);
  const std::string summary = t::analysis_summary(a);
  EXPECT_NE(summary.find("Pa (1 measured summit in contact: too few to compare models): stiffness per area"), std::string::npos)
      << summary;
  EXPECT_NE(summary.find("No model is named closest"), std::string::npos) << summary;  // the verdict carries the headline
  const std::string dir = folder("few-summits");
  t::write_report(a, dir);
  const std::string md = read_text(dir + "/report.md");
  EXPECT_NE(md.find("Pa (1 measured summit in contact: too few to compare models; the ratios below are that handful's):"),
            std::string::npos);
  EXPECT_NE(md.find("**No model is named closest"), std::string::npos);
}
