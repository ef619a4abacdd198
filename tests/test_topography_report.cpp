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
#include <string>
#include <thread>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/topography/analysis.hpp"
#include "asperity/topography/surface_report.hpp"
#include "asperity/topography/synthetic.hpp"

namespace t = asperity::topography;
namespace fs = std::filesystem;

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A small synthetic surface analysed with its contact curves (the default table).
t::SurfaceAnalysis small_analysis(std::uint64_t seed) {
  t::HeightMap map = t::gaussian_random_field(96, 96, 1e-7, 1e-7, {{1.5, 4e-16}}, seed);
  map.source = "synthetic-" + std::to_string(seed);
  t::AnalysisOptions options;
  options.assessment.bootstrap = 40;
  options.assessment.threads = 2;
  options.fit_heights = false;
  t::ContactOptions contact;
  contact.contact_modulus = 1e11;
  contact.curve_points = 9;
  contact.table_path = ASPERITY_TEST_TABLE;
  options.contact = contact;
  return t::analyse_height_map(map, options);
}

const t::SurfaceAnalysis& analysis() {
  static const t::SurfaceAnalysis a = small_analysis(1);
  return a;
}

std::string folder(const std::string& name) {
  const fs::path dir = fs::path(ASPERITY_TEST_BINARY_DIR) / "topography_report" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

}  // namespace

// A symbolic link planted under a report file's name is replaced, never followed: the file it
// points at keeps its bytes (before: overwritten with the report).
TEST(TopographyReport, PlantedLinkIsReplacedNotFollowed) {
  const std::string dir = folder("link");
  const std::string victim = fs::path(dir).parent_path() / "victim.txt";
  std::ofstream(victim) << "precious";
  fs::create_symlink(victim, dir + "/report.json");
  fs::create_symlink(victim, dir + "/fits.svg");
  t::write_report(analysis(), dir);
  EXPECT_EQ(read_text(victim), "precious");
  EXPECT_FALSE(fs::is_symlink(dir + "/report.json"));
  EXPECT_NE(read_text(dir + "/report.json").find("asperity-surface/2"), std::string::npos);
  // a link planted as the lock is refused, not followed
  const std::string other = folder("lock-link");
  fs::create_symlink(victim, other + "/.asperity-report.lock");
  EXPECT_THROW(t::write_report(analysis(), other), asperity::Error);
  EXPECT_EQ(read_text(victim), "precious");
}

// A FIFO planted under a report file's name is replaced without being opened (before: the
// command hung on it); a FIFO as the lock is refused at once.
TEST(TopographyReport, PlantedFifoDoesNotHang) {
  const std::string dir = folder("fifo");
  ASSERT_EQ(mkfifo((dir + "/report.md").c_str(), 0600), 0);
  ASSERT_EQ(mkfifo((dir + "/summits.csv").c_str(), 0600), 0);
  t::write_report(analysis(), dir);
  EXPECT_TRUE(fs::is_regular_file(dir + "/report.md"));
  EXPECT_TRUE(fs::is_regular_file(dir + "/summits.csv"));
  const std::string other = folder("fifo-lock");
  ASSERT_EQ(mkfifo((other + "/.asperity-report.lock").c_str(), 0600), 0);
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
  const std::string dir = folder("render");
  t::write_report(analysis(), dir);
  for (const std::string plot : {"fits", "contact"}) {
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
    }
  }
}
