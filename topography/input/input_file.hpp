// A file from outside, opened safely (internal to the readers): only a regular file, never
// waiting on a FIFO or device, its size known before a byte is read, read through the one
// descriptor that was checked (a file swapped for a FIFO after the check cannot hang a read).
// Lines are read in blocks with a bound on their length, so memory stays bounded whatever the
// bytes (a file without newlines is not a 2 GB line).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace asperity::topography::detail {

class InputFile {
 public:
  // Throws asperity::Error naming `path`: no such file, a directory, FIFO, device or socket, no
  // permission, or more than max_bytes.
  InputFile(const std::string& path, std::uint64_t max_bytes);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::string& path() const noexcept { return path_; }
  std::uint64_t size() const noexcept { return size_; }
  int descriptor() const noexcept { return fd_; }

  // Up to `count` bytes from the current position; 0 at the end. Throws on a read error.
  std::size_t read_some(unsigned char* buffer, std::size_t count);
  // Exactly `count` bytes from byte `offset`, or throws (truncated, read error).
  void read_at(std::uint64_t offset, unsigned char* buffer, std::size_t count);
  // The whole file (its size was bounded when it was opened); throws if it changed size.
  std::vector<unsigned char> read_all();

 private:
  std::string path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

// Lines of an InputFile: LF, CRLF or a lone CR end a line. A line longer than max_line_bytes
// is an error naming its number (no text format here needs more).
class LineReader {
 public:
  LineReader(InputFile& file, std::size_t max_line_bytes);
  // False at the end of the file.
  bool next(std::string& line);
  std::size_t line_number() const noexcept { return line_number_; }

 private:
  bool refill();
  InputFile& file_;
  std::size_t max_line_bytes_;
  std::vector<unsigned char> block_;
  std::size_t position_ = 0, filled_ = 0, line_number_ = 0;
  bool skip_lf_ = false;
};

}  // namespace asperity::topography::detail
