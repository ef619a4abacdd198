// MD5 as 32 lowercase hex digits (OpenSSL's libcrypto: X3P files carry MD5 checksums of their
// parts; this is a checksum against corruption, not a security measure).
#pragma once
#include <cstddef>
#include <memory>
#include <string>

namespace asperity::topography::detail {

std::string md5_hex(const unsigned char* data, std::size_t size);

// The same over data given in pieces (a point data entry read in blocks).
class Md5 {
 public:
  Md5();
  ~Md5();
  Md5(const Md5&) = delete;
  Md5& operator=(const Md5&) = delete;
  void update(const unsigned char* data, std::size_t size);
  std::string hex();  // once, at the end

 private:
  struct Context;
  std::unique_ptr<Context> context_;
};

}  // namespace asperity::topography::detail
