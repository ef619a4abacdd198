// Reading a whole file from outside (a table, a scene) safely: only a regular file, never
// waiting on a FIFO, its size bounded before a byte is read. Internal: not installed.
#pragma once
#include <cstdint>
#include <string>

#include "asperity/error.hpp"

namespace asperity::detail {

enum class FileFailure { missing, unreadable, too_large };

class RegularFileError : public Error {
 public:
  RegularFileError(FileFailure failure, const std::string& what) : Error(what), failure_(failure) {}
  FileFailure failure() const noexcept { return failure_; }

 private:
  FileFailure failure_;
};

// The file's bytes. Throws RegularFileError (its message does not name the file): no such file,
// not a regular file (a directory, FIFO, device), no permission, a read error, a size that
// changed while reading, or more than max_bytes.
std::string read_regular_file(const std::string& path, std::uint64_t max_bytes);

}  // namespace asperity::detail
