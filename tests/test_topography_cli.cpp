// `asperity surface`: the command end to end, run as the `asperity` program (summary, JSON,
// report directory). Its usage errors and messages are checked with cli_check in CMakeLists.txt,
// like the other commands'.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
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
  const CommandRun r = run({surfaces + "/digitalsurf-650x650.x3p", "--ensemble", "40", "--no-height-fit",
                            "--modulus", "1e11", "--pressure", "1e6"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("650 x 650 points"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("summits 2482"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at 1e+06 Pa: stiffness per area"), std::string::npos) << r.out;
}

TEST(TopographyCli, JsonAndReport) {
  const std::string dir = work + "/report";
  std::filesystem::remove_all(dir);
  const CommandRun r = run({surfaces + "/afm-zsensor-10um.txt", "--ensemble", "40", "--json", "--report", dir,
                            "--modulus=2e9", "--load", "1e-5", "--summit-window", "2"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{", 0), 0u);
  EXPECT_NE(r.out.find("\"schema\": \"asperity-surface/2\""), std::string::npos);
  EXPECT_NE(r.out.find("\"window_points\": 2"), std::string::npos);
  // standard error holds at most the ensemble's progress (a run over a second)
  std::istringstream lines(r.err);
  for (std::string line; std::getline(lines, line);)
    EXPECT_EQ(line.rfind("asperity surface: ensemble ", 0), 0u) << line;
  for (const char* name : {"report.md", "report.json", "curves.csv", "summits.csv", "fits.svg", "contact.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + name)) << name;
  const std::string text = read_text(dir + "/report.md");
  EXPECT_NE(text.find("![fits](fits.svg)"), std::string::npos);
  // --load 1e-5 N over the measured 1e-10 m^2: 1e5 Pa
  EXPECT_NE(text.find("At a nominal pressure of 1e+05 Pa"), std::string::npos);
}

// ---- hostile inputs (issue 26): a clear message, exit 2, nothing run or lost ----

namespace {
void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}
}  // namespace

// A map at its noise floor gets its statistics and the statement, and exit 2 (what was asked
// beyond the statistics does not exist); a too small bootstrap is refused.
TEST(TopographyCli, NoiseFloorAndTooSmallBootstrap) {
  std::string matrix = "# Width: 1 um\n# Height: 1 um\n# Value units: nm\n";
  for (int j = 0; j < 40; ++j) {
    for (int i = 0; i < 40; ++i) matrix += std::to_string(i + 2 * j) + (i + 1 < 40 ? " " : "\n");  // a plane in whole nm
  }
  const std::string plane = work + "/plane.txt";
  std::filesystem::create_directories(work);
  write_text(plane, matrix);
  const CommandRun r = run({plane, "--ensemble", "40", "--modulus", "1e11"});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.out.find("noise floor"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("at the level of the heights' quantization"), std::string::npos) << r.err;
  const CommandRun small = run({surfaces + "/afm-zsensor-10um.txt", "--bootstrap", "10"});
  EXPECT_EQ(small.status, 2);
  EXPECT_NE(small.err.find("an ensemble of 10 surrogate surfaces can never give p below 0.025"), std::string::npos)
      << small.err;
}

// Bytes of a bad file never reach the terminal as an escape sequence.
TEST(TopographyCli, FileBytesInMessagesArePrintable) {
  const std::string path = work + "/escape.txt";
  std::filesystem::create_directories(work);
  write_text(path, "# Width: 1 um\n# Height: 1 um\n# Value units: m\n1 2 3\n4 \x1b]0;owned\x07 6\n");
  const CommandRun r = run({path});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\x07'), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\\x1b]0;owned\\x07"), std::string::npos) << r.err;
}

// More threads than the system gives (an address-space limit: 1024 stacks do not fit) is not
// std::terminate (exit 134): the threads that start do the work.
TEST(TopographyCli, ThreadsTheSystemRefuses) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "an address-space limit is incompatible with the sanitizers' shadow memory";
#else
  const std::string out = work + "/threads.txt";
  const std::string command = "ulimit -v 1500000; " + quoted(ASPERITY_COMMAND) + " surface " +
                              quoted(surfaces + "/afm-zsensor-10um.txt") +
                              " --bootstrap 40 --no-height-fit --threads 1024 >" + quoted(out) + " 2>&1";
  const int status = std::system(("sh -c " + quoted(command)).c_str());
  ASSERT_TRUE(WIFEXITED(status)) << read_text(out);
  EXPECT_EQ(WEXITSTATUS(status), 0) << read_text(out);
  EXPECT_NE(read_text(out).find("summits"), std::string::npos);
#endif
}
