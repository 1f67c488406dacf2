// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Replay protection for one subscription: a signed message (bus/auth/message_auth.hpp) is accepted
/// at most once, and only while it is fresh.
///  - Fresh: its signing time is within kMaxAge of this machine's wall clock (either way), so a
///    message recorded earlier cannot be played back to a process that started since; the
///    machines of one bus need clocks agreeing to well within that (NTP).
///  - Once: per sender nonce, the highest sequence seen and a window of the kWindow sequences
///    below it (UDP may reorder a little); a sequence seen before, or older than the window, is
///    a replay.
/// The table holds at most kMaxSenders nonces; a nonce silent for longer than kMaxAge is
/// forgotten first (its messages are stale by then anyway), else the one heard from longest ago.

#include <cstdint>
#include <unordered_map>

#include "bus/auth/message_auth.hpp"

namespace wrc::bus {

/// Why a message was refused.
enum class ReplayCheck { kFresh, kReplayed, kStale };

class ReplayGuard {
 public:
  static constexpr std::int64_t kMaxAge = 30'000'000;  ///< [us] largest |receiver clock - signing time|
  static constexpr std::uint64_t kWindow = 256;       ///< [-] sequences below the highest still accepted
  static constexpr std::size_t kMaxSenders = 1024;    ///< [-] nonces remembered

  /// Checks origin at receiver wall time now_utime [us] and, when fresh, records it.
  ReplayCheck admit(const MessageOrigin& origin, std::int64_t now_utime);
  /// Nonces remembered now.
  std::size_t senders() const { return senders_.size(); }

 private:
  struct Sender {
    std::uint64_t highest = 0;                  // highest sequence accepted
    std::uint64_t seen[kWindow / 64] = {};      // bit i: sequence highest - i was accepted
    std::int64_t last_utime = 0;                // [us] receiver time of the last accepted message
  };
  void make_room(std::int64_t now_utime);

  std::unordered_map<std::uint64_t, Sender> senders_;
};

}  // namespace wrc::bus
