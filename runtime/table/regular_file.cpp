#include "asperity/detail/regular_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace asperity::detail {
namespace {

struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

[[noreturn]] void fail(FileFailure failure, const std::string& what) { throw RegularFileError(failure, what); }

}  // namespace

std::string read_regular_file(const std::string& path, std::uint64_t max_bytes) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer (it is refused just below).
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (file.fd < 0) {
    const int error = errno;
    if (error == ENOENT || error == ENOTDIR) fail(FileFailure::missing, "no such file");
    fail(FileFailure::unreadable, std::string("cannot be opened: ") + std::strerror(error));
  }
  struct stat status {};
  if (::fstat(file.fd, &status) != 0)
    fail(FileFailure::unreadable, std::string("cannot be examined: ") + std::strerror(errno));
  if (S_ISDIR(status.st_mode)) fail(FileFailure::unreadable, "a directory, not a file");
  if (!S_ISREG(status.st_mode)) fail(FileFailure::unreadable, "not a regular file (a FIFO, device or socket)");
  const std::uint64_t size = static_cast<std::uint64_t>(status.st_size);
  if (size > max_bytes)
    fail(FileFailure::too_large,
         std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) + " allowed");
  std::string bytes(static_cast<std::size_t>(size) + 1, '\0');  // one more: to see a file that grew
  std::size_t filled = 0;
  while (filled < bytes.size()) {
    const ssize_t count = ::read(file.fd, &bytes[filled], bytes.size() - filled);
    if (count < 0 && errno == EINTR) continue;
    if (count < 0) fail(FileFailure::unreadable, std::string("read error: ") + std::strerror(errno));
    if (count == 0) break;
    filled += static_cast<std::size_t>(count);
  }
  if (filled != size) fail(FileFailure::unreadable, "its size changed while it was read");
  bytes.resize(filled);
  return bytes;
}

}  // namespace asperity::detail
