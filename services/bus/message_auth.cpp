#include "bus/message_auth.hpp"

#include <openssl/core_names.h>
#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/rand.h>

#include <algorithm>
#include <cstring>
#include <mutex>
#include <stdexcept>

#include "bus/clock.hpp"

namespace wrc::bus {

namespace {

constexpr std::size_t kStampBytes = 24;  // nonce, sequence, utime
constexpr std::size_t kMacBytes = 32;

void put_u64(std::uint8_t* out, std::uint64_t v) {
  for (int i = 7; i >= 0; --i) {
    out[i] = static_cast<std::uint8_t>(v & 0xff);
    v >>= 8;
  }
}

std::uint64_t get_u64(const std::uint8_t* in) {
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v = (v << 8) | in[i];
  return v;
}

}  // namespace

/// A keyed HMAC-SHA-256 context; computing a MAC re-initialises it with the stored key.
struct MessageAuth::Mac {
  std::mutex mutex;  // one context, used by one thread at a time
  EVP_MAC* algorithm = nullptr;
  EVP_MAC_CTX* context = nullptr;
};

MessageAuth::MessageAuth(const BusKey& key, std::uint64_t nonce) : mac_(std::make_unique<Mac>()), nonce_(nonce) {
  mac_->algorithm = EVP_MAC_fetch(nullptr, "HMAC", nullptr);
  if (mac_->algorithm != nullptr) mac_->context = EVP_MAC_CTX_new(mac_->algorithm);
  char digest[] = "SHA256";
  const OSSL_PARAM params[] = {OSSL_PARAM_construct_utf8_string(OSSL_MAC_PARAM_DIGEST, digest, 0),
                               OSSL_PARAM_construct_end()};
  if (mac_->context == nullptr || EVP_MAC_init(mac_->context, key.bytes.data(), key.bytes.size(), params) != 1) {
    EVP_MAC_CTX_free(mac_->context);
    EVP_MAC_free(mac_->algorithm);
    throw std::runtime_error("OpenSSL has no usable HMAC-SHA-256");
  }
}

MessageAuth::~MessageAuth() {
  EVP_MAC_CTX_free(mac_->context);
  EVP_MAC_free(mac_->algorithm);
}

std::uint64_t MessageAuth::random_nonce() {
  std::uint8_t bytes[8];
  if (RAND_bytes(bytes, sizeof bytes) != 1) throw std::runtime_error("OpenSSL's random generator failed");
  return get_u64(bytes);
}

std::array<std::uint8_t, 32> MessageAuth::mac(const std::string& channel, const std::uint8_t* data,
                                              std::size_t payload, const std::uint8_t* stamp) const {
  // The channel goes in with its length, so that channel and payload cannot trade bytes.
  const auto channel_length = static_cast<std::uint8_t>(std::min<std::size_t>(channel.size(), 255));
  std::array<std::uint8_t, 32> out{};
  std::size_t out_size = 0;
  std::lock_guard<std::mutex> lock(mac_->mutex);
  const bool ok = EVP_MAC_init(mac_->context, nullptr, 0, nullptr) == 1 &&
                  EVP_MAC_update(mac_->context, &channel_length, 1) == 1 &&
                  EVP_MAC_update(mac_->context, reinterpret_cast<const unsigned char*>(channel.data()),
                                 channel_length) == 1 &&
                  EVP_MAC_update(mac_->context, data, payload) == 1 &&
                  EVP_MAC_update(mac_->context, stamp, kStampBytes) == 1 &&
                  EVP_MAC_final(mac_->context, out.data(), &out_size, out.size()) == 1 && out_size == kMacBytes;
  if (!ok) throw std::runtime_error("OpenSSL failed computing an HMAC-SHA-256");
  return out;
}

void MessageAuth::sign(const std::string& channel, std::vector<std::uint8_t>& message) {
  std::uint64_t sequence;
  {
    std::lock_guard<std::mutex> lock(mac_->mutex);
    sequence = next_sequence_++;
  }
  sign(channel, message, sequence, wall_utime());
}

void MessageAuth::sign(const std::string& channel, std::vector<std::uint8_t>& message, std::uint64_t sequence,
                       std::int64_t utime) const {
  const std::size_t payload = message.size();
  message.resize(payload + kTrailerBytes);
  std::uint8_t* stamp = message.data() + payload;
  put_u64(stamp, nonce_);
  put_u64(stamp + 8, sequence);
  put_u64(stamp + 16, static_cast<std::uint64_t>(utime));
  const auto tag = mac(channel, message.data(), payload, stamp);
  std::memcpy(stamp + kStampBytes, tag.data(), kMacBytes);
  std::memcpy(stamp + kStampBytes + kMacBytes, kMagic, sizeof kMagic);
}

TrailerCheck MessageAuth::verify(const std::string& channel, const std::uint8_t* data, std::size_t size,
                                 std::size_t* payload_size, MessageOrigin* origin) const {
  if (size < kTrailerBytes || std::memcmp(data + size - sizeof kMagic, kMagic, sizeof kMagic) != 0) {
    return TrailerCheck::kMissing;
  }
  const std::size_t payload = size - kTrailerBytes;
  const std::uint8_t* stamp = data + payload;
  const auto expected = mac(channel, data, payload, stamp);
  if (CRYPTO_memcmp(expected.data(), stamp + kStampBytes, kMacBytes) != 0) return TrailerCheck::kBadSignature;
  *payload_size = payload;
  origin->nonce = get_u64(stamp);
  origin->sequence = get_u64(stamp + 8);
  origin->utime = static_cast<std::int64_t>(get_u64(stamp + 16));
  return TrailerCheck::kValid;
}

}  // namespace wrc::bus
