// SPDX-License-Identifier: Apache-2.0
// Message authentication: the trailer verifies only for the same key, channel and bytes; the MAC
// is OpenSSL's HMAC-SHA-256; an unsigned message is told from a forged one.
#include <gtest/gtest.h>
#include <openssl/hmac.h>

#include <vector>

#include "bus/auth/message_auth.hpp"
#include "test_bus_key.hpp"

namespace {
using namespace wrc::bus;

std::vector<std::uint8_t> payload() { return {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}; }

TEST(MessageAuth, SignedMessageVerifiesWithItsOrigin) {
  MessageAuth auth(test::test_bus_key(), 0x1122334455667788ULL);
  auto bytes = payload();
  auth.sign("PING", bytes, 42, 1700000000000000);
  ASSERT_EQ(bytes.size(), payload().size() + MessageAuth::kTrailerBytes);
  std::size_t size = 0;
  MessageOrigin origin;
  ASSERT_EQ(auth.verify("PING", bytes.data(), bytes.size(), &size, &origin), TrailerCheck::kValid);
  EXPECT_EQ(size, payload().size());
  EXPECT_EQ(origin.nonce, 0x1122334455667788ULL);
  EXPECT_EQ(origin.sequence, 42u);
  EXPECT_EQ(origin.utime, 1700000000000000);
  EXPECT_TRUE(std::equal(bytes.begin(), bytes.begin() + static_cast<long>(size), payload().begin()));
}

TEST(MessageAuth, MacIsOpenSslHmacSha256) {
  MessageAuth auth(test::test_bus_key(), 7);
  auto bytes = payload();
  auth.sign("CH", bytes, 3, 5);
  // HMAC over: channel length, channel, payload, nonce, sequence, utime (the trailer's first 24 bytes).
  std::vector<std::uint8_t> input{2, 'C', 'H'};
  input.insert(input.end(), bytes.begin(), bytes.begin() + static_cast<long>(payload().size() + 24));
  unsigned char expected[32];
  unsigned int length = 0;
  const auto key = test::test_bus_key();
  HMAC(EVP_sha256(), key.bytes.data(), static_cast<int>(key.bytes.size()), input.data(), input.size(), expected,
       &length);
  ASSERT_EQ(length, 32u);
  EXPECT_TRUE(std::equal(expected, expected + 32, bytes.begin() + static_cast<long>(payload().size() + 24)));
}

TEST(MessageAuth, AlteredMovedForgedOrUnsignedMessagesDoNotVerify) {
  MessageAuth auth(test::test_bus_key(), 1);
  auto bytes = payload();
  auth.sign("PING", bytes);
  std::size_t size = 0;
  MessageOrigin origin;
  EXPECT_EQ(auth.verify("PONG", bytes.data(), bytes.size(), &size, &origin), TrailerCheck::kBadSignature);
  for (std::size_t i = 0; i + 4 < bytes.size(); ++i) {  // every byte but the magic
    auto altered = bytes;
    altered[i] ^= 0x01;
    EXPECT_EQ(auth.verify("PING", altered.data(), altered.size(), &size, &origin), TrailerCheck::kBadSignature) << i;
  }
  BusKey other = test::test_bus_key();
  other.bytes[0] ^= 0x80;
  MessageAuth forger(other, 1);
  auto forged = payload();
  forger.sign("PING", forged);
  EXPECT_EQ(auth.verify("PING", forged.data(), forged.size(), &size, &origin), TrailerCheck::kBadSignature);
  const auto plain = payload();
  EXPECT_EQ(auth.verify("PING", plain.data(), plain.size(), &size, &origin), TrailerCheck::kMissing);
  EXPECT_EQ(auth.verify("PING", plain.data(), 0, &size, &origin), TrailerCheck::kMissing);
}

TEST(MessageAuth, SequenceCountsUpAndNoncesDiffer) {
  MessageAuth auth(test::test_bus_key(), 9);
  std::size_t size = 0;
  MessageOrigin first, second;
  auto a = payload();
  auto b = payload();
  auth.sign("X", a);
  auth.sign("X", b);
  ASSERT_EQ(auth.verify("X", a.data(), a.size(), &size, &first), TrailerCheck::kValid);
  ASSERT_EQ(auth.verify("X", b.data(), b.size(), &size, &second), TrailerCheck::kValid);
  EXPECT_EQ(second.sequence, first.sequence + 1);
  EXPECT_NE(MessageAuth::random_nonce(), MessageAuth::random_nonce());
}

}  // namespace
