// SPDX-License-Identifier: Apache-2.0
// Replay protection: each (nonce, sequence) once, a little reordering tolerated, old and future
// messages refused, the table bounded.
#include <gtest/gtest.h>

#include "bus/auth/replay_guard.hpp"

namespace {
using namespace wrc::bus;

constexpr std::int64_t kNow = 1700000000000000;  // [us]

MessageOrigin origin(std::uint64_t nonce, std::uint64_t sequence, std::int64_t utime = kNow) {
  return MessageOrigin{nonce, sequence, utime};
}

TEST(ReplayGuard, EachSequenceOnce) {
  ReplayGuard guard;
  EXPECT_EQ(guard.admit(origin(1, 10), kNow), ReplayCheck::kFresh);
  EXPECT_EQ(guard.admit(origin(1, 10), kNow), ReplayCheck::kReplayed);
  EXPECT_EQ(guard.admit(origin(1, 12), kNow), ReplayCheck::kFresh);
  EXPECT_EQ(guard.admit(origin(1, 11), kNow), ReplayCheck::kFresh);  // reordered: still new
  EXPECT_EQ(guard.admit(origin(1, 11), kNow), ReplayCheck::kReplayed);
  EXPECT_EQ(guard.admit(origin(2, 10), kNow), ReplayCheck::kFresh);  // another sender
  EXPECT_EQ(guard.admit(origin(1, 12 + ReplayGuard::kWindow + 5), kNow), ReplayCheck::kFresh);
  EXPECT_EQ(guard.admit(origin(1, 12), kNow), ReplayCheck::kReplayed);  // below the window
  EXPECT_EQ(guard.admit(origin(1, 12 + 10), kNow), ReplayCheck::kFresh);  // inside it, unseen
  EXPECT_EQ(guard.senders(), 2u);
}

TEST(ReplayGuard, StaleAndFutureMessagesRefused) {
  ReplayGuard guard;
  EXPECT_EQ(guard.admit(origin(1, 1, kNow - ReplayGuard::kMaxAge - 1), kNow), ReplayCheck::kStale);
  EXPECT_EQ(guard.admit(origin(1, 2, kNow + ReplayGuard::kMaxAge + 1), kNow), ReplayCheck::kStale);
  EXPECT_EQ(guard.admit(origin(1, 3, kNow - ReplayGuard::kMaxAge + 1000), kNow), ReplayCheck::kFresh);
}

TEST(ReplayGuard, TableIsBounded) {
  ReplayGuard guard;
  for (std::uint64_t nonce = 1; nonce <= 3 * ReplayGuard::kMaxSenders; ++nonce) {
    EXPECT_EQ(guard.admit(origin(nonce, 1), kNow + static_cast<std::int64_t>(nonce)), ReplayCheck::kFresh);
  }
  EXPECT_LE(guard.senders(), ReplayGuard::kMaxSenders);
  // the most recent senders are still remembered
  EXPECT_EQ(guard.admit(origin(3 * ReplayGuard::kMaxSenders, 1), kNow + 1), ReplayCheck::kReplayed);
}

}  // namespace
