// The commands' outputs under the one output policy (docs/reliability.md, "Outputs"): each
// case a hostile user found (issue 37), run through the command itself.
#include <gtest/gtest.h>
#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "file_helpers.hpp"

namespace {

const std::string afm = std::string(ASPERITY_TEST_SURFACES) + "/afm-zsensor-10um.txt";

using test_files::entries;
using test_files::plant;
using test_files::read_bytes;

std::string test_directory(const std::string& name) { return test_files::fresh_directory("outputs", name); }

struct Outcome {
  int status = -1;  // exit status; -1: killed by the time limit
  std::string err;
};

// Runs the asperity command with `args`, standard error to a file; killed after `seconds`.
// `interrupt_after_ms` >= 0: SIGINT sent then, and the time it took to exit after it recorded.
Outcome run(const std::vector<std::string>& args, int seconds = 120, int interrupt_after_ms = -1,
            double* exit_after_signal_s = nullptr) {
  const std::string err_file = std::string(ASPERITY_TEST_BINARY_DIR) + "/outputs-stderr.txt";
  const pid_t child = fork();
  if (child == 0) {
    const int err = open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = open("/dev/null", O_WRONLY);
    dup2(err, 2);
    dup2(null, 1);
    std::vector<char*> argv{const_cast<char*>(ASPERITY_COMMAND)};
    for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    execv(ASPERITY_COMMAND, argv.data());
    _exit(127);
  }
  using clock = std::chrono::steady_clock;
  const clock::time_point start = clock::now();
  clock::time_point signalled{};
  Outcome outcome;
  for (;;) {
    int status = 0;
    if (waitpid(child, &status, WNOHANG) == child) {
      outcome.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      if (exit_after_signal_s && signalled != clock::time_point{})
        *exit_after_signal_s = std::chrono::duration<double>(clock::now() - signalled).count();
      break;
    }
    const auto elapsed = clock::now() - start;
    if (interrupt_after_ms >= 0 && signalled == clock::time_point{} &&
        elapsed > std::chrono::milliseconds(interrupt_after_ms)) {
      kill(child, SIGINT);
      signalled = clock::now();
    }
    if (elapsed > std::chrono::seconds(seconds)) {
      kill(child, SIGKILL);
      waitpid(child, nullptr, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  outcome.err = read_bytes(err_file);
  return outcome;
}

// exact-contact --fields DIR wrote through a planted link (its target overwritten) and hung on a
// planted FIFO; --card the same.
TEST(CommandOutputs, ExactContactNeverFollowsALinkNorOpensAFifo) {
  const std::string dir = test_directory("planted");
  plant(dir + "/victim", "the user's");
  ASSERT_EQ(symlink((dir + "/victim").c_str(), (dir + "/step-1-pressure.pgm").c_str()), 0);
  ASSERT_EQ(mkfifo((dir + "/step-1-gap.pgm").c_str(), 0600), 0);
  ASSERT_EQ(symlink((dir + "/victim").c_str(), (dir + "/card.inp").c_str()), 0);
  ASSERT_EQ(mkfifo((dir + "/fifo.inp").c_str(), 0600), 0);
  for (const std::vector<std::string>& output :
       {std::vector<std::string>{"--fields", dir}, {"--card", dir + "/card.inp"}, {"--card", dir + "/fifo.inp"}}) {
    std::vector<std::string> args = {"exact-contact", afm, "--modulus", "1e11", "--pressure", "1e6", "--quiet"};
    args.insert(args.end(), output.begin(), output.end());
    const Outcome outcome = run(args, 60);
    EXPECT_EQ(outcome.status, 2) << output[0] << ": " << outcome.err;
    EXPECT_NE(outcome.err.find(output[0] + " " + dir), std::string::npos) << outcome.err;
  }
  EXPECT_EQ(read_bytes(dir + "/victim"), "the user's");
}

// exact-contact replaced files silently: --table over a GW table, --card or --table naming the
// map, --card X --table X.
TEST(CommandOutputs, ExactContactReplacesNothingNotItsOwnAndNeverTheInput) {
  const std::string dir = test_directory("replace");
  const std::string map = dir + "/map.txt";
  plant(map, read_bytes(afm));
  plant(dir + "/gw.h5", read_bytes(ASPERITY_TEST_TABLE));
  const std::vector<std::string> base = {"exact-contact", map, "--modulus", "1e11", "--pressure", "1e6,2e6,4e6",
                                         "--quiet"};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    return run(args, 60);
  };
  Outcome outcome = with({"--table", dir + "/gw.h5"});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("not a contact-curves table written by asperity"), std::string::npos) << outcome.err;
  EXPECT_EQ(read_bytes(dir + "/gw.h5"), read_bytes(ASPERITY_TEST_TABLE));
  for (const char* option : {"--card", "--table"}) {
    outcome = with({option, map, "--overwrite"});
    EXPECT_EQ(outcome.status, 2);
    EXPECT_NE(outcome.err.find("is an input of this run"), std::string::npos) << outcome.err;
  }
  EXPECT_EQ(read_bytes(map), read_bytes(afm));
  outcome = with({"--card", dir + "/x", "--table", dir + "/x"});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("the same file as --card"), std::string::npos) << outcome.err;
  EXPECT_EQ(outcome.err.find("nodes"), std::string::npos) << outcome.err;  // nothing solved
  // its own outputs are replaced run after run
  for (int k = 0; k < 2; ++k) {
    outcome = with({"--card", dir + "/c.inp", "--table", dir + "/t.h5", "--fields", dir + "/fields"});
    EXPECT_EQ(outcome.status, 0) << outcome.err;
  }
  EXPECT_EQ(entries(dir + "/fields").size(), 7u);  // 3 steps x 2 images, and the folder's lock
}

// surface --report DIR into a folder that never held a report deleted the user's curves.csv and
// contact.svg.
TEST(CommandOutputs, ASurfaceReportKeepsTheUsersFiles) {
  const std::string dir = test_directory("report");
  plant(dir + "/curves.csv", "mine\n");
  plant(dir + "/contact.svg", "<svg>mine</svg>\n");
  const std::vector<std::string> args = {"surface", afm, "--modulus", "1e11", "--pressure", "1e6", "--report", dir};
  Outcome outcome = run(args, 300);
  EXPECT_EQ(outcome.status, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("curves.csv holds something that is not a surface report's file"), std::string::npos)
      << outcome.err;
  EXPECT_EQ(read_bytes(dir + "/curves.csv"), "mine\n");
  EXPECT_EQ(read_bytes(dir + "/contact.svg"), "<svg>mine</svg>\n");
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"contact.svg", "curves.csv"}));
}

// Ctrl-C: the command stops, removes what it had staged, and exits with 130.
TEST(CommandOutputs, ExactContactStopsOnCtrlCLeavingNothing) {
  const std::string dir = test_directory("interrupt");
  double exit_after = -1;
  const Outcome outcome =
      run({"exact-contact", afm, "--modulus", "1e11", "--sweep", "pressure:1e5:1e8:2000", "--table", dir + "/t.h5",
           "--fields", dir + "/fields", "--quiet"},
          120, 1500, &exit_after);
  EXPECT_EQ(outcome.status, 130) << outcome.err;
  EXPECT_NE(outcome.err.find("interrupted"), std::string::npos) << outcome.err;
  EXPECT_LT(exit_after, 1.0);
  EXPECT_TRUE(entries(dir).empty()) << entries(dir).front();
}

}  // namespace
