// SPDX-License-Identifier: Apache-2.0
#include "core/identity/sha256.hpp"

#include <openssl/evp.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace wrc {

std::string sha256_hex(const void* data, std::size_t size) {
  const EVP_MD* md = EVP_sha256();
  if (md == nullptr) throw std::runtime_error("SHA-256: OpenSSL's EVP_sha256() returned no digest");
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  static const unsigned char kEmpty = 0;  // EVP_Digest wants a valid pointer even for 0 bytes
  if (EVP_Digest(size == 0 ? &kEmpty : data, size, digest, &length, md, nullptr) != 1 || length != 32) {
    throw std::runtime_error("SHA-256: OpenSSL's EVP_Digest failed on " + std::to_string(size) + " bytes");
  }
  static const char kHex[] = "0123456789abcdef";
  std::string hex(2 * length, '0');
  for (unsigned int i = 0; i < length; ++i) {
    hex[2 * i] = kHex[digest[i] >> 4];
    hex[2 * i + 1] = kHex[digest[i] & 0x0f];
  }
  return hex;
}

std::string sha256_hex(const std::string& text) { return sha256_hex(text.data(), text.size()); }

std::string sha256_hex_of_doubles(const std::vector<double>& values) {
  std::vector<unsigned char> bytes;
  bytes.reserve(8 * values.size());
  for (double value : values) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    for (int i = 0; i < 8; ++i) bytes.push_back(static_cast<unsigned char>(bits >> (8 * i)));
  }
  return sha256_hex(bytes.data(), bytes.size());
}

}  // namespace wrc
