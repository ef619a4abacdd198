#include "input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "reader_support.hpp"

namespace asperity::topography::detail {

InputFile::InputFile(const std::string& path, std::uint64_t max_bytes) : path_(path) {
  if (path.find('\0') != std::string::npos) fail(path, "a path with a NUL byte");
  // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused just below.
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd_ < 0) {
    const int error = errno;
    // only ENOENT is "no such file": a symbolic-link loop (ELOOP), a file where a folder should
    // be (ENOTDIR) and the rest are named as the system names them
    if (error == ENOENT) fail(path, "cannot open (no such file)");
    fail(path, std::string("cannot open: ") + std::strerror(error));
  }
  struct stat status {};
  if (::fstat(fd_, &status) != 0) {
    const int error = errno;
    ::close(fd_);
    fail(path, std::string("cannot be examined: ") + std::strerror(error));
  }
  if (!S_ISREG(status.st_mode)) {
    ::close(fd_);
    fail(path, S_ISDIR(status.st_mode) ? "a directory, not a file" : "not a regular file (a FIFO, device or socket)");
  }
  // back to blocking reads: a regular file never blocks, and EAGAIN must not look like the end
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags >= 0) ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK);
  size_ = static_cast<std::uint64_t>(status.st_size);
  if (size_ > max_bytes) {
    ::close(fd_);
    fail(path, "is " + std::to_string(size_) + " bytes, more than the " + std::to_string(max_bytes) +
                   " this format can need within the point limit (ReadOptions::max_points)");
  }
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t InputFile::read_some(unsigned char* buffer, std::size_t count) {
  for (;;) {
    const ssize_t got = ::read(fd_, buffer, count);
    if (got >= 0) return static_cast<std::size_t>(got);
    if (errno == EINTR) continue;
    fail(path_, std::string("read error: ") + std::strerror(errno));
  }
}

void InputFile::read_at(std::uint64_t offset, unsigned char* buffer, std::size_t count) {
  std::size_t filled = 0;
  while (filled < count) {
    const ssize_t got = ::pread(fd_, buffer + filled, count - filled, static_cast<off_t>(offset + filled));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) fail(path_, std::string("read error: ") + std::strerror(errno));
    if (got == 0) fail(path_, "truncated (it changed while it was read?)");
    filled += static_cast<std::size_t>(got);
  }
}

std::vector<unsigned char> InputFile::read_all() {
  std::vector<unsigned char> bytes(static_cast<std::size_t>(size_) + 1);  // one more: to see a file that grew
  std::size_t filled = 0;
  while (filled < bytes.size()) {
    const std::size_t got = read_some(bytes.data() + filled, bytes.size() - filled);
    if (got == 0) break;
    filled += got;
  }
  if (filled != size_) fail(path_, "its size changed while it was read");
  bytes.resize(filled);
  return bytes;
}

LineReader::LineReader(InputFile& file, std::size_t max_line_bytes)
    : file_(file), max_line_bytes_(max_line_bytes), block_(std::size_t{1} << 16) {}

bool LineReader::refill() {
  filled_ = file_.read_some(block_.data(), block_.size());
  position_ = 0;
  return filled_ > 0;
}

bool LineReader::next(std::string& line) {
  line.clear();
  bool any = false;
  for (;;) {
    if (position_ == filled_ && !refill()) {
      if (any) ++line_number_;
      return any;
    }
    // the longest run without a line end, appended at once
    const unsigned char* start = block_.data() + position_;
    std::size_t run = 0;
    while (position_ + run < filled_ && start[run] != '\n' && start[run] != '\r') ++run;
    if (run > 0) {
      if (skip_lf_) skip_lf_ = false;
      if (line.size() + run > max_line_bytes_)
        fail(file_.path(), "line " + std::to_string(line_number_ + 1) + " is longer than " +
                               std::to_string(max_line_bytes_) + " bytes");
      line.append(reinterpret_cast<const char*>(start), run);
      position_ += run;
      any = true;
      continue;
    }
    const unsigned char c = block_[position_++];
    if (skip_lf_) {  // the LF of a CRLF
      skip_lf_ = false;
      if (c == '\n') continue;
    }
    ++line_number_;
    if (c == '\r') skip_lf_ = true;
    return true;
  }
}

}  // namespace asperity::topography::detail
