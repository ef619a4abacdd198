// MD5 of a byte buffer as 32 lowercase hex digits (OpenSSL's libcrypto: X3P files carry MD5
// checksums of their parts; this is a checksum against corruption, not a security measure).
#pragma once
#include <cstddef>
#include <string>

namespace asperity::topography::detail {

std::string md5_hex(const unsigned char* data, std::size_t size);

}  // namespace asperity::topography::detail
