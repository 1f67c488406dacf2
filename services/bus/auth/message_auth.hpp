// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Authentication of wrc messages: a trailer appended after the LCM encoding of a message.
///
///     [LCM-encoded message][nonce 8 B][sequence 8 B][utime 8 B][HMAC-SHA-256 32 B]["WRC1"]
///
/// LCM decoders read a message's fields and ignore what follows, so lcm-spy, lcm-logger and
/// every typed LCM subscriber still decode the message; wrc's guarded receive path
/// (bus/transport/guarded_subscription.hpp) checks and strips the trailer before it decodes anything.
/// The MAC (HMAC-SHA-256, RFC 2104, on OpenSSL's SHA-256, under the bus key) covers the channel name, the message bytes
/// and the trailer's nonce, sequence and time, so a message moved to another channel, altered in
/// any byte or re-stamped does not verify. The nonce is random per process start, the sequence
/// counts the messages the process signed (all channels), utime is the wall clock at signing;
/// bus/replay_guard.hpp turns them into replay protection. Integers are big-endian, as in LCM.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bus/auth/bus_key.hpp"

namespace wrc::bus {

/// What a verified trailer said about its message.
struct MessageOrigin {
  std::uint64_t nonce = 0;     ///< [-] random number of the sending process (per start)
  std::uint64_t sequence = 0;  ///< [-] the sender's message counter, from 1
  std::int64_t utime = 0;      ///< [us] sender's wall clock at signing, since the Unix epoch
};

/// Outcome of checking a trailer.
enum class TrailerCheck {
  kValid,         ///< the MAC verifies: origin and payload size are set
  kMissing,       ///< no trailer (too short or no "WRC1" at the end): an unsigned message
  kBadSignature,  ///< a trailer whose MAC does not verify under this key
};

/// Signs and verifies messages under one bus key. Thread-safe.
class MessageAuth {
 public:
  static constexpr std::size_t kTrailerBytes = 8 + 8 + 8 + 32 + 4;  ///< [B] 60
  static constexpr char kMagic[4] = {'W', 'R', 'C', '1'};

  /// key: the bus key; nonce: this process's random number (see random_nonce()).
  MessageAuth(const BusKey& key, std::uint64_t nonce);
  ~MessageAuth();
  MessageAuth(const MessageAuth&) = delete;
  MessageAuth& operator=(const MessageAuth&) = delete;

  /// Appends the trailer for `channel` to message (the LCM encoding), with the next sequence
  /// number and the current wall clock.
  void sign(const std::string& channel, std::vector<std::uint8_t>& message);
  /// Same with an explicit sequence and time (tests build replays and stale messages with it).
  void sign(const std::string& channel, std::vector<std::uint8_t>& message, std::uint64_t sequence,
            std::int64_t utime) const;
  /// Checks the trailer of data[0..size) received on channel. On kValid, *payload_size is the
  /// size of the LCM encoding before the trailer and *origin what the trailer says.
  TrailerCheck verify(const std::string& channel, const std::uint8_t* data, std::size_t size,
                      std::size_t* payload_size, MessageOrigin* origin) const;

  /// This process's nonce.
  std::uint64_t nonce() const { return nonce_; }
  /// A random 64-bit number from OpenSSL's generator (throws std::runtime_error if it fails).
  static std::uint64_t random_nonce();

 private:
  struct Mac;
  std::array<std::uint8_t, 32> mac(const std::string& channel, const std::uint8_t* data, std::size_t payload,
                                   const std::uint8_t* stamp) const;

  std::unique_ptr<Mac> mac_;
  std::uint64_t nonce_;
  std::uint64_t next_sequence_ = 1;
};

}  // namespace wrc::bus
