// Replacing a file (tablegen --out): never half-written, never a symlink or device replaced,
// a long name fits, the mode is kept, a failed write leaves nothing behind, and the temporaries
// of writers killed with -9 are cleaned up (carefully).
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <dirent.h>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "asperity/error.hpp"
#include "replace_file.hpp"

namespace {
using asperity::Error;
using asperity::replace_file;

// A fresh directory of its own for each test.
std::string test_directory(const std::string& name) {
  const std::string path = std::string(ASPERITY_TEST_BINARY_DIR) + "/replace-" + name;
  std::system(("rm -rf '" + path + "'").c_str());
  mkdir(path.c_str(), 0755);
  return path;
}

std::string read_bytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), {});
}

void write(const std::string& path, const std::string& text) { replace_file(path, text.data(), text.size()); }

std::string error_of(const std::string& path, const std::string& text = "new") {
  try {
    write(path, text);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

std::vector<std::string> entries(const std::string& directory) {
  std::vector<std::string> names;
  DIR* listing = opendir(directory.c_str());
  while (const dirent* entry = listing ? readdir(listing) : nullptr)
    if (std::string(entry->d_name) != "." && std::string(entry->d_name) != "..") names.push_back(entry->d_name);
  if (listing) closedir(listing);
  return names;
}

std::string host_tag() {
  char name[256] = {};
  gethostname(name, sizeof name - 1);
  std::string tag;
  for (const char* c = name; *c && tag.size() < 64; ++c)
    tag += (std::isalnum(static_cast<unsigned char>(*c)) || *c == '.' || *c == '_') ? *c : '_';
  return tag.empty() ? "host" : tag;
}

// A process id that is free now: a child that has exited and been reaped.
pid_t dead_pid() {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);
  return child;
}

void age(const std::string& path, int seconds) {
  const timespec times[2] = {{std::time(nullptr) - seconds, 0}, {std::time(nullptr) - seconds, 0}};
  utimensat(AT_FDCWD, path.c_str(), times, AT_SYMLINK_NOFOLLOW);
}

TEST(ReplaceFile, WritesAndReplacesKeepingTheMode) {
  const std::string directory = test_directory("mode");
  const std::string path = directory + "/table.h5";
  write(path, "first");
  EXPECT_EQ(read_bytes(path), "first");
  const mode_t mask = umask(0);
  umask(mask);
  struct stat status {};
  stat(path.c_str(), &status);
  EXPECT_EQ(status.st_mode & 0777, 0666 & ~mask);
  chmod(path.c_str(), 0640);
  write(path, "second");
  EXPECT_EQ(read_bytes(path), "second");
  stat(path.c_str(), &status);
  EXPECT_EQ(status.st_mode & 0777, 0640u);
  EXPECT_EQ(entries(directory), std::vector<std::string>{"table.h5"});  // no temporary left
}

TEST(ReplaceFile, ReadOnlyTargets) {
  const std::string directory = test_directory("read-only");
  const std::string path = directory + "/table.h5";
  write(path, "old");
  chmod(path.c_str(), 0444);
  if (geteuid() != 0) {
    EXPECT_NE(error_of(path).find("is read-only"), std::string::npos);
    EXPECT_EQ(read_bytes(path), "old");
  } else {  // root may write anything: then the mode is kept
    write(path, "new");
    struct stat status {};
    stat(path.c_str(), &status);
    EXPECT_EQ(status.st_mode & 0777, 0444u);
  }
}

TEST(ReplaceFile, SymlinksDevicesFifosAndDirectoriesAreNeverReplaced) {
  const std::string directory = test_directory("special");
  const std::string target = directory + "/real.h5", link = directory + "/link.h5";
  write(target, "real");
  ASSERT_EQ(symlink(target.c_str(), link.c_str()), 0);
  EXPECT_NE(error_of(link).find("is a symbolic link"), std::string::npos);
  struct stat status {};
  ASSERT_EQ(lstat(link.c_str(), &status), 0);
  EXPECT_TRUE(S_ISLNK(status.st_mode));
  EXPECT_EQ(read_bytes(target), "real");

  const std::string fifo = directory + "/fifo.h5";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(error_of(fifo).find("a device, FIFO or socket"), std::string::npos);
  ASSERT_EQ(lstat(fifo.c_str(), &status), 0);
  EXPECT_TRUE(S_ISFIFO(status.st_mode));

  if (geteuid() == 0) {  // a device node of our own (as root, --out /dev/full replaced the device)
    const std::string device = directory + "/full";
    ASSERT_EQ(mknod(device.c_str(), S_IFCHR | 0600, makedev(1, 7)), 0);
    EXPECT_NE(error_of(device).find("a device, FIFO or socket"), std::string::npos);
    ASSERT_EQ(lstat(device.c_str(), &status), 0);
    EXPECT_TRUE(S_ISCHR(status.st_mode));
  }
  EXPECT_NE(error_of(directory).find("is a directory"), std::string::npos);
  EXPECT_NE(error_of(directory + "/").find("names a directory"), std::string::npos);
  EXPECT_NE(error_of(directory + "/missing/table.h5").find("cannot open the directory"), std::string::npos);
  EXPECT_NE(error_of("").find("no output file"), std::string::npos);
}

TEST(ReplaceFile, LongNamesFit) {
  const std::string directory = test_directory("long");
  const std::string name(253, 'n');  // failed before: the temporary's suffix made it too long
  write(directory + "/" + name, "long");
  EXPECT_EQ(read_bytes(directory + "/" + name), "long");
  EXPECT_NE(error_of(directory + "/" + std::string(256, 'n')).find("more than a file name may have"),
            std::string::npos);
  EXPECT_EQ(entries(directory).size(), 1u);
}

// A write that fails midway (here: the file-size limit, as a full disk would) leaves the old
// file as it was and no temporary behind.
TEST(ReplaceFile, AFailedWriteLeavesNothingBehind) {
  const std::string directory = test_directory("fail");
  const std::string path = directory + "/table.h5";
  write(path, "old");
  const pid_t child = fork();
  if (child == 0) {
    signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    setrlimit(RLIMIT_FSIZE, &limit);
    const std::string big(1 << 20, 'x');
    try {
      replace_file(path, big.data(), big.size());
    } catch (const Error& error) {
      _exit(std::string(error.what()).find("File too large") != std::string::npos ? 0 : 2);
    }
    _exit(1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(read_bytes(path), "old");
  EXPECT_EQ(entries(directory), std::vector<std::string>{"table.h5"});
}

// kill -9 at any moment: the target is the old file or the new one, whole; the temporary the
// dead writer left is removed by a later write once it is old enough.
TEST(ReplaceFile, KillNineLeavesTheOldFileOrTheNewOne) {
  const std::string directory = test_directory("kill");
  const std::string path = directory + "/table.h5";
  const std::string old_bytes(3 << 20, 'o'), new_bytes(3 << 20, 'n');
  replace_file(path, old_bytes.data(), old_bytes.size());
  for (int delay_ms : {0, 1, 3, 7, 15}) {
    const pid_t child = fork();
    if (child == 0) {
      for (;;) replace_file(path, new_bytes.data(), new_bytes.size());
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    const std::string now = read_bytes(path);
    EXPECT_TRUE(now == old_bytes || now == new_bytes) << "a mix of " << now.size() << " bytes after " << delay_ms
                                                      << " ms";
  }
  // whatever temporaries the killed writers left: made old, then cleaned up by the next write
  for (const std::string& name : entries(directory))
    if (name != "table.h5") age(directory + "/" + name, 3600);
  replace_file(path, old_bytes.data(), old_bytes.size());
  EXPECT_EQ(entries(directory), std::vector<std::string>{"table.h5"});
}

TEST(ReplaceFile, OnlyTheTemporariesOfDeadWritersAreRemoved) {
  const std::string directory = test_directory("stale");
  const std::string host = host_tag(), prefix = directory + "/" + asperity::temporary_prefix;
  const std::string dead = std::to_string(dead_pid());
  const std::string stale = prefix + host + "-" + dead + "-1.tmp";                  // removed
  const std::string recent = prefix + host + "-" + dead + "-2.tmp";                 // too recent: kept
  const std::string alive = prefix + host + "-" + std::to_string(getppid()) + "-3.tmp";  // its writer lives
  const std::string other_host = prefix + "elsewhere-" + dead + "-4.tmp";           // another host's
  const std::string other_name = directory + "/table.h5.tmp." + dead;               // not our pattern
  for (const std::string& file : {stale, recent, alive, other_host, other_name}) std::ofstream(file) << "x";
  for (const std::string& file : {stale, alive, other_host, other_name}) age(file, 3600);
  write(directory + "/table.h5", "table");
  const std::vector<std::string> left = entries(directory);
  auto kept = [&](const std::string& path) {
    return std::find(left.begin(), left.end(), path.substr(directory.size() + 1)) != left.end();
  };
  EXPECT_FALSE(kept(stale));
  EXPECT_TRUE(kept(recent));
  EXPECT_TRUE(kept(alive));
  EXPECT_TRUE(kept(other_host));
  EXPECT_TRUE(kept(other_name));
  EXPECT_EQ(left.size(), 5u);
}

}  // namespace
