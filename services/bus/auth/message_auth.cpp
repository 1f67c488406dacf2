// SPDX-License-Identifier: Apache-2.0
#include "bus/auth/message_auth.hpp"

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/rand.h>

#include <algorithm>
#include <cstring>
#include <mutex>
#include <stdexcept>

#include "bus/transport/clock.hpp"

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

/// HMAC-SHA-256 (RFC 2104) on OpenSSL's SHA-256, with the key's inner and outer pad states
/// hashed once: a MAC then costs two digest-context copies, not a MAC context set-up (half the
/// time of EVP_MAC_init per message; the unit test checks equality with OpenSSL's HMAC()).
struct MessageAuth::Mac {
  std::mutex mutex;  // the work context, used by one thread at a time
  EVP_MD* sha256 = nullptr;
  EVP_MD_CTX* inner = nullptr;  // SHA-256 state after (key ^ ipad)
  EVP_MD_CTX* outer = nullptr;  // SHA-256 state after (key ^ opad)
  EVP_MD_CTX* work = nullptr;
  ~Mac() {
    EVP_MD_CTX_free(work);
    EVP_MD_CTX_free(outer);
    EVP_MD_CTX_free(inner);
    EVP_MD_free(sha256);
  }
};

MessageAuth::MessageAuth(const BusKey& key, std::uint64_t nonce) : mac_(std::make_unique<Mac>()), nonce_(nonce) {
  constexpr std::size_t kBlock = 64;  // [B] SHA-256 block; the 32-byte key is zero-padded to it
  static_assert(BusKey::kBytes <= kBlock);
  std::uint8_t ipad[kBlock];
  std::uint8_t opad[kBlock];
  for (std::size_t i = 0; i < kBlock; ++i) {
    const std::uint8_t k = i < BusKey::kBytes ? key.bytes[i] : 0;
    ipad[i] = k ^ 0x36;
    opad[i] = k ^ 0x5c;
  }
  Mac& m = *mac_;
  m.sha256 = EVP_MD_fetch(nullptr, "SHA256", nullptr);
  m.inner = EVP_MD_CTX_new();
  m.outer = EVP_MD_CTX_new();
  m.work = EVP_MD_CTX_new();
  const bool ok = m.sha256 != nullptr && m.inner != nullptr && m.outer != nullptr && m.work != nullptr &&
                  EVP_DigestInit_ex(m.inner, m.sha256, nullptr) == 1 && EVP_DigestUpdate(m.inner, ipad, kBlock) == 1 &&
                  EVP_DigestInit_ex(m.outer, m.sha256, nullptr) == 1 && EVP_DigestUpdate(m.outer, opad, kBlock) == 1;
  OPENSSL_cleanse(ipad, kBlock);
  OPENSSL_cleanse(opad, kBlock);
  if (!ok) throw std::runtime_error("OpenSSL has no usable SHA-256");
}

MessageAuth::~MessageAuth() = default;

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
  unsigned int inner_size = 0;
  unsigned int outer_size = 0;
  Mac& m = *mac_;
  std::lock_guard<std::mutex> lock(m.mutex);
  // stamp follows the payload in every caller (it is the trailer's start): one update for both.
  const bool contiguous = stamp == data + payload;
  std::uint8_t prefix[256];
  prefix[0] = channel_length;
  std::memcpy(prefix + 1, channel.data(), channel_length);
  const bool ok = EVP_MD_CTX_copy_ex(m.work, m.inner) == 1 && EVP_DigestUpdate(m.work, prefix, 1u + channel_length) == 1 &&
                  (contiguous ? EVP_DigestUpdate(m.work, data, payload + kStampBytes) == 1
                              : EVP_DigestUpdate(m.work, data, payload) == 1 &&
                                    EVP_DigestUpdate(m.work, stamp, kStampBytes) == 1) &&
                  EVP_DigestFinal_ex(m.work, out.data(), &inner_size) == 1 && EVP_MD_CTX_copy_ex(m.work, m.outer) == 1 &&
                  EVP_DigestUpdate(m.work, out.data(), inner_size) == 1 &&
                  EVP_DigestFinal_ex(m.work, out.data(), &outer_size) == 1 && outer_size == kMacBytes;
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
