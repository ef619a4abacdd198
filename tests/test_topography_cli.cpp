// `asperity surface`: the command end to end, run as the `asperity` program (summary, JSON,
// report directory). Its usage errors and messages are checked with cli_check in CMakeLists.txt,
// like the other commands'.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {
const std::string surfaces = ASPERITY_TEST_SURFACES;
const std::string work = std::string(ASPERITY_TEST_BINARY_DIR) + "/topography_cli";

struct CommandRun {
  int status;
  std::string out, err;
};

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

std::string quoted(const std::string& argument) {
  std::string text = "'";
  for (char c : argument) text += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return text + "'";
}

// Runs `asperity surface ARGUMENTS...`, standard output and error into files.
CommandRun run(const std::vector<std::string>& arguments) {
  std::filesystem::create_directories(work);
  std::string command = quoted(ASPERITY_COMMAND) + " surface";
  for (const std::string& argument : arguments) command += " " + quoted(argument);
  const std::string out = work + "/stdout.txt", err = work + "/stderr.txt";
  const int status = std::system((command + " >" + quoted(out) + " 2>" + quoted(err)).c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err)};
}
}  // namespace

TEST(TopographyCli, SummaryOfTheRealX3P) {
  const CommandRun r = run({surfaces + "/digitalsurf-650x650.x3p", "--bootstrap", "20", "--no-height-fit",
                            "--modulus", "1e11", "--pressure", "1e6"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("650 x 650 points"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("summits 2482"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at 1e+06 Pa: stiffness per area"), std::string::npos) << r.out;
}

TEST(TopographyCli, JsonAndReport) {
  const std::string dir = work + "/report";
  std::filesystem::remove_all(dir);
  const CommandRun r = run({surfaces + "/afm-zsensor-10um.txt", "--bootstrap", "20", "--json", "--report", dir,
                            "--modulus=2e9", "--load", "1e-5", "--summit-window", "2"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{", 0), 0u);
  EXPECT_NE(r.out.find("\"schema\": \"asperity-surface/1\""), std::string::npos);
  EXPECT_NE(r.out.find("\"window_points\": 2"), std::string::npos);
  EXPECT_EQ(r.err, "");
  for (const char* name : {"report.md", "report.json", "curves.csv", "summits.csv", "fits.svg", "contact.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + name)) << name;
  const std::string text = read_text(dir + "/report.md");
  EXPECT_NE(text.find("![fits](fits.svg)"), std::string::npos);
  // --load 1e-5 N over the measured 1e-10 m^2: 1e5 Pa
  EXPECT_NE(text.find("At a nominal pressure of 1e+05 Pa"), std::string::npos);
}
