#include "replace_file.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstring>
#include <ctime>
#include <string>

#include "asperity/error.hpp"
#include "asperity/number_text.hpp"

namespace asperity {
namespace {

[[noreturn]] void fail(const std::string& what) { throw Error("writing the table failed: " + what); }
std::string reason() { return std::strerror(errno); }

struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// This host's name as it appears in temporary names: letters, digits, '.' and '_' only.
std::string host_tag() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "host";
  std::string tag;
  for (const char* c = name; *c && tag.size() < 64; ++c)
    tag += (std::isalnum(static_cast<unsigned char>(*c)) || *c == '.' || *c == '_') ? *c : '_';
  return tag.empty() ? "host" : tag;
}

// ".tablegen-HOST-PID-N.tmp": short whatever the target's name, so a long name still fits.
std::string temporary_name(const std::string& host, long pid, unsigned long serial) {
  return std::string(temporary_prefix) + host + "-" + std::to_string(pid) + "-" + std::to_string(serial) + ".tmp";
}

// Removes the temporaries of writers that died. A temporary is removed only if its name is
// ours for this host, it is a regular file of this user, its process no longer exists, and it
// has not changed for 10 minutes (a writer in another PID namespace on the same host is still
// writing if it has changed more recently). Best effort: never fails the write.
void remove_stale_temporaries(int directory) {
  const int listing_fd = ::dup(directory);
  if (listing_fd < 0) return;
  DIR* listing = ::fdopendir(listing_fd);
  if (!listing) {
    ::close(listing_fd);
    return;
  }
  const std::string host = host_tag();
  const std::string prefix = std::string(temporary_prefix) + host + "-";
  const std::time_t now = std::time(nullptr);
  while (const dirent* entry = ::readdir(listing)) {
    const std::string name = entry->d_name;
    if (name.compare(0, prefix.size(), prefix) != 0 || name.size() < prefix.size() + 7 ||
        name.compare(name.size() - 4, 4, ".tmp") != 0)
      continue;
    const std::string rest = name.substr(prefix.size(), name.size() - prefix.size() - 4);  // PID-N
    const std::size_t dash = rest.find('-');
    if (dash == 0 || dash == std::string::npos || rest.find_first_not_of("0123456789-") != std::string::npos ||
        rest.find('-', dash + 1) != std::string::npos || dash + 1 == rest.size() || dash > 9)
      continue;
    long long pid = 0;
    if (!read_whole_number(rest.substr(0, dash), 1, INT_MAX, pid) || pid == static_cast<long long>(::getpid()))
      continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to know
    struct stat status {};
    if (::fstatat(directory, name.c_str(), &status, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(status.st_mode) ||
        status.st_uid != ::geteuid() || now - status.st_mtime < 600)
      continue;
    ::unlinkat(directory, name.c_str(), 0);
  }
  ::closedir(listing);
}

}  // namespace

void replace_file(const std::string& path, const void* data, std::size_t size) {
  if (path.empty()) fail("no output file named");
  const std::size_t slash = path.rfind('/');
  const std::string directory_name = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  if (base.empty() || base == "." || base == "..") fail("'" + path + "' names a directory, not a file");
  if (base.size() > NAME_MAX)
    fail("the file name '" + base.substr(0, 40) + "...' has " + std::to_string(base.size()) +
         " characters, more than a file name may have (" + std::to_string(NAME_MAX) + ")");

  Descriptor directory{::open(directory_name.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
  if (directory.fd < 0) fail("cannot open the directory '" + directory_name + "': " + reason());

  mode_t mode = 0;
  bool replacing = false;
  struct stat target {};
  if (::fstatat(directory.fd, base.c_str(), &target, AT_SYMLINK_NOFOLLOW) == 0) {
    if (S_ISLNK(target.st_mode))
      fail("'" + path + "' is a symbolic link; tablegen replaces only regular files (name the file itself)");
    if (S_ISDIR(target.st_mode)) fail("'" + path + "' is a directory");
    if (!S_ISREG(target.st_mode))
      fail("'" + path + "' is a device, FIFO or socket; tablegen replaces only regular files");
    if (::faccessat(directory.fd, base.c_str(), W_OK, AT_EACCESS) != 0)
      fail("'" + path + "' is read-only; make it writable or remove it first");
    mode = target.st_mode & 07777;
    replacing = true;
  } else if (errno != ENOENT) {
    fail("cannot examine '" + path + "': " + reason());
  }

  remove_stale_temporaries(directory.fd);

  static unsigned long serial = 0;
  const std::string host = host_tag();
  std::string temporary;
  Descriptor file;
  for (int attempt = 0; attempt < 100 && file.fd < 0; ++attempt) {
    temporary = temporary_name(host, static_cast<long>(::getpid()), ++serial);
    file.fd = ::openat(directory.fd, temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (file.fd < 0 && errno != EEXIST)
      fail("cannot create a temporary file in '" + directory_name + "': " + reason());
  }
  if (file.fd < 0) fail("cannot find a free temporary name in '" + directory_name + "'");
  // From here on, any failure removes the temporary file.
  struct Remove {
    int directory;
    const std::string& name;
    bool armed = true;
    ~Remove() {
      if (armed) ::unlinkat(directory, name.c_str(), 0);
    }
  } remove{directory.fd, temporary};

  const auto* bytes = static_cast<const char*>(data);
  for (std::size_t written = 0; written < size;) {
    const ssize_t count = ::write(file.fd, bytes + written, size - written);
    if (count < 0 && errno == EINTR) continue;
    if (count <= 0) fail("writing '" + path + "': " + (count < 0 ? reason() : "no progress"));
    written += static_cast<std::size_t>(count);
  }
  if (replacing && ::fchmod(file.fd, mode) != 0) fail("keeping the mode of '" + path + "': " + reason());
  if (::fsync(file.fd) != 0) fail("syncing '" + path + "' to disk: " + reason());
  const int descriptor = file.fd;
  file.fd = -1;
  if (::close(descriptor) != 0) fail("closing '" + path + "': " + reason());
  if (::renameat(directory.fd, temporary.c_str(), directory.fd, base.c_str()) != 0)
    fail("renaming the finished table to '" + path + "': " + reason());
  remove.armed = false;
  // The rename is durable once the directory is synced (some file systems cannot: EINVAL).
  if (::fsync(directory.fd) != 0 && errno != EINVAL && errno != EROFS)
    fail("'" + path + "' was written, but syncing its directory failed: " + reason());
}

}  // namespace asperity
