#include "md5.hpp"

#include <openssl/evp.h>

#include "asperity/error.hpp"

namespace asperity::topography::detail {

std::string md5_hex(const unsigned char* data, std::size_t size) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(data, size, digest, &length, EVP_md5(), nullptr) != 1 || length != 16)
    throw Error("MD5 unavailable from libcrypto");
  static const char* hex = "0123456789abcdef";
  std::string text(32, '0');
  for (unsigned int k = 0; k < 16; ++k) {
    text[2 * k] = hex[digest[k] >> 4];
    text[2 * k + 1] = hex[digest[k] & 15];
  }
  return text;
}

}  // namespace asperity::topography::detail
