#include "report_directory.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "asperity/error.hpp"
#include "reader_support.hpp"

namespace asperity::topography::detail {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int error) {
  throw Error(printable(path, 4096) + ": " + what + ": " + std::strerror(error));
}

std::string temporary_name(const std::string& name) {
  static std::atomic<unsigned> counter{0};
  return "." + name + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

}  // namespace

ReportDirectory::ReportDirectory(const std::string& path) : path_(path) {
  if (path.empty() || path.find('\0') != std::string::npos) throw Error("the report folder's name is empty or has a NUL");
  std::error_code error;
  std::filesystem::create_directories(path, error);
  if (error) throw Error(printable(path, 4096) + ": cannot create the report folder: " + error.message());
  directory_ = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (directory_ < 0) fail(path, "cannot open the report folder", errno);
  // the lock: a regular file of ours (O_NOFOLLOW: a planted link is refused; O_NONBLOCK: a
  // planted FIFO does not hang the open)
  lock_ = ::openat(directory_, ".asperity-report.lock", O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
  struct stat status {};
  if (lock_ < 0 || ::fstat(lock_, &status) != 0 || !S_ISREG(status.st_mode)) {
    const int code = lock_ < 0 ? errno : EINVAL;
    if (lock_ >= 0) ::close(lock_);
    ::close(directory_);
    lock_ = directory_ = -1;
    fail(path + "/.asperity-report.lock", "cannot lock the report folder (not a regular file?)", code);
  }
  while (::flock(lock_, LOCK_EX) != 0) {
    if (errno == EINTR) continue;
    const int code = errno;
    ::close(lock_);
    ::close(directory_);
    lock_ = directory_ = -1;
    fail(path, "cannot lock the report folder", code);
  }
}

ReportDirectory::~ReportDirectory() {
  if (lock_ >= 0) ::close(lock_);  // releases the lock
  if (directory_ >= 0) ::close(directory_);
}

std::string ReportDirectory::write(const std::string& name, std::string_view bytes) {
  const std::string full = (std::filesystem::path(path_) / name).string();
  const std::string temporary = temporary_name(name);
  const int fd = ::openat(directory_, temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) fail(full, "cannot write", errno);
  const auto abandon = [&](const char* what, int code) {
    ::close(fd);
    ::unlinkat(directory_, temporary.c_str(), 0);
    fail(full, what, code);
  };
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t count = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (count < 0 && errno == EINTR) continue;
    if (count < 0) abandon("write error", errno);
    written += static_cast<std::size_t>(count);
  }
  if (::fsync(fd) != 0) abandon("write error", errno);
  if (::close(fd) != 0) {
    const int code = errno;
    ::unlinkat(directory_, temporary.c_str(), 0);
    fail(full, "write error", code);
  }
  // rename replaces a link, FIFO or file of that name without opening it
  if (::renameat(directory_, temporary.c_str(), directory_, name.c_str()) != 0) {
    const int code = errno;
    ::unlinkat(directory_, temporary.c_str(), 0);
    fail(full, code == EISDIR ? "a directory of that name is in the way" : "cannot replace it", code);
  }
  return full;
}

void ReportDirectory::remove(const std::string& name) {
  struct stat status {};
  if (::fstatat(directory_, name.c_str(), &status, AT_SYMLINK_NOFOLLOW) != 0) return;  // not there
  if (S_ISDIR(status.st_mode)) return;
  if (::unlinkat(directory_, name.c_str(), 0) != 0 && errno != ENOENT)
    fail((std::filesystem::path(path_) / name).string(), "cannot remove the earlier run's file", errno);
}

void ReportDirectory::remove_stale_temporaries(const std::vector<std::string>& names) {
  const int fd = ::dup(directory_);
  if (fd < 0) return;
  DIR* listing = ::fdopendir(fd);
  if (!listing) {
    ::close(fd);
    return;
  }
  ::rewinddir(listing);
  std::vector<std::string> stale;
  while (const dirent* entry = ::readdir(listing)) {
    const std::string entry_name = entry->d_name;
    for (const std::string& name : names)
      if (entry_name.rfind("." + name + ".tmp-", 0) == 0) stale.push_back(entry_name);
  }
  ::closedir(listing);
  for (const std::string& name : stale) remove(name);
}

void ReportDirectory::finish() {
  if (::fsync(directory_) != 0 && errno != EINVAL) fail(path_, "cannot complete the report folder", errno);
}

}  // namespace asperity::topography::detail
