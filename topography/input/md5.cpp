#include "md5.hpp"

#include <openssl/evp.h>

#include "asperity/error.hpp"

namespace asperity::topography::detail {
namespace {
std::string hex_of(const unsigned char* digest) {
  static const char* hex = "0123456789abcdef";
  std::string text(32, '0');
  for (unsigned int k = 0; k < 16; ++k) {
    text[2 * k] = hex[digest[k] >> 4];
    text[2 * k + 1] = hex[digest[k] & 15];
  }
  return text;
}
}  // namespace

std::string md5_hex(const unsigned char* data, std::size_t size) {
  Md5 md5;
  md5.update(data, size);
  return md5.hex();
}

struct Md5::Context {
  EVP_MD_CTX* context = EVP_MD_CTX_new();
  ~Context() { EVP_MD_CTX_free(context); }
};

Md5::Md5() : context_(std::make_unique<Context>()) {
  if (!context_->context || EVP_DigestInit_ex(context_->context, EVP_md5(), nullptr) != 1)
    throw Error("MD5 unavailable from libcrypto");
}

Md5::~Md5() = default;

void Md5::update(const unsigned char* data, std::size_t size) {
  if (EVP_DigestUpdate(context_->context, data, size) != 1) throw Error("MD5 unavailable from libcrypto");
}

std::string Md5::hex() {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(context_->context, digest, &length) != 1 || length != 16)
    throw Error("MD5 unavailable from libcrypto");
  return hex_of(digest);
}

}  // namespace asperity::topography::detail
