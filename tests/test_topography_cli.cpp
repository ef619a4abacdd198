// `asperity surface`: the command end to end (summary, JSON, report, errors and exit status).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "surface_command.hpp"

namespace {
const std::string surfaces = ASPERITY_TEST_SURFACES;

struct CommandRun {
  int status;
  std::string out, err;
};

CommandRun run(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), "surface");
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  std::ostringstream out, err;
  const int status = asperity::cli::surface_command(static_cast<int>(argv.size()), argv.data(), out, err);
  return {status, out.str(), err.str()};
}
}  // namespace

TEST(TopographyCli, SummaryOfTheRealX3P) {
  const CommandRun r = run({surfaces + "/digitalsurf-650x650.x3p", "--bootstrap", "19", "--no-height-fit", "--modulus", "1e11",
                     "--pressure", "1e6"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("650 x 650 points"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("summits 2482"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at 1e+06 Pa: stiffness per area"), std::string::npos) << r.out;
}

TEST(TopographyCli, JsonAndReportWithoutMatplotlib) {
  const std::string dir = std::string(ASPERITY_TEST_BINARY_DIR) + "/topography_cli_report";
  std::filesystem::remove_all(dir);
  setenv("ASPERITY_SURFACE_PLOTS", (surfaces + "/no_matplotlib.py").c_str(), 1);
  const CommandRun r = run({surfaces + "/afm-zsensor-10um.txt", "--bootstrap", "9", "--json", "--report", dir, "--modulus", "2e9",
                     "--load", "1e-5", "--summit-window", "2"});
  unsetenv("ASPERITY_SURFACE_PLOTS");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{", 0), 0u);
  EXPECT_NE(r.out.find("\"schema\": \"asperity-surface/1\""), std::string::npos);
  EXPECT_NE(r.out.find("\"window_points\": 2"), std::string::npos);
  EXPECT_NE(r.err.find("no plots: python3 has no matplotlib"), std::string::npos) << r.err;
  for (const char* name : {"report.md", "report.json", "curves.csv", "summits.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + name)) << name;
  std::ifstream md(dir + "/report.md");
  const std::string text((std::istreambuf_iterator<char>(md)), {});
  EXPECT_NE(text.find("no plots: python3 has no matplotlib"), std::string::npos);
  // --load 1e-5 N over the measured 1e-10 m^2: 1e5 Pa
  EXPECT_NE(text.find("At a nominal pressure of 1e+05 Pa"), std::string::npos);
}

TEST(TopographyCli, ErrorsNameTheProblem) {
  CommandRun r = run({surfaces + "/no-such-file.x3p"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no such file"), std::string::npos) << r.err;
  r = run({surfaces + "/afm-zsensor-10um.txt", "--pressure", "1e6"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--modulus"), std::string::npos) << r.err;
  r = run({surfaces + "/afm-zsensor-10um.txt", "--pixel-size", "3"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("needs its unit"), std::string::npos) << r.err;
  r = run({surfaces + "/afm-zsensor-10um.txt", "--format", "tiff"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown format 'tiff'"), std::string::npos) << r.err;
  r = run({surfaces + "/afm-zsensor-10um.txt", "--modulus", "1e11", "--pressure", "-5"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("not a positive number"), std::string::npos) << r.err;
  r = run({surfaces + "/afm-zsensor-10um.txt", "--e1", "2e11", "--nu1", "0.7", "--e2", "2e11", "--nu2", "0.3"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("Poisson"), std::string::npos) << r.err;
  r = run({"--no-such-option"});
  EXPECT_EQ(r.status, 2);
  r = run({"--help"});
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--pixel-size"), std::string::npos);
}
