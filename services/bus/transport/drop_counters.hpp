// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The process-wide tally of received messages that the guarded receive path
/// (bus/transport/guarded_subscription.hpp) dropped, by kind, and its log: per kind at most kDropLogBurst
/// lines per kDropLogInterval, the next line saying how many were not logged in between, so a
/// flood of bad datagrams costs a few lines, not a full disk.
/// The heartbeat reports the counts (bus/service/heartbeat_publisher.hpp), `wrc status` shows them.

#include <atomic>
#include <cstdint>
#include <string>

namespace wrc::bus {

/// Why a received message was dropped.
enum class DropKind : int {
  kOversize,      ///< larger than the subscription accepts
  kUnsigned,      ///< no authentication trailer
  kBadSignature,  ///< a trailer whose MAC does not verify under the bus key
  kReplayed,      ///< sequence of its sender seen before (or older than the replay window)
  kStale,         ///< signed too long ago, or in the future, by this machine's clock
  kWrongType,     ///< fingerprint of another type (or of another interface version)
  kUndecodable,   ///< truncated, inconsistent, counts beyond its size, bad strings
  kTrailingBytes, ///< bytes between the decoded message and the trailer
  kHandlerFailed, ///< decoded, but the receiving code threw (a bug, or a value it cannot take)
};
inline constexpr int kDropKinds = 9;

/// Short name of a kind for log lines, e.g. "unsigned", "bad-signature".
const char* drop_kind_name(DropKind kind);

/// Counts per kind since the process started.
struct DropCounts {
  std::int64_t by_kind[kDropKinds] = {};
  std::int64_t of(DropKind kind) const { return by_kind[static_cast<int>(kind)]; }
  /// kUnsigned.
  std::int64_t unsigned_messages() const { return of(DropKind::kUnsigned); }
  /// kBadSignature.
  std::int64_t bad_signature() const { return of(DropKind::kBadSignature); }
  /// kReplayed + kStale.
  std::int64_t replayed() const { return of(DropKind::kReplayed) + of(DropKind::kStale); }
  /// kOversize + kWrongType + kUndecodable + kTrailingBytes + kHandlerFailed.
  std::int64_t malformed() const;
  /// Every kind.
  std::int64_t total() const;
};

/// Records one drop: counts it and logs it (rate-limited per kind) as
/// `<who>: dropped <kind> message on <channel>: <reason> (<n> <kind> so far[, <k> not logged])`.
/// Thread-safe.
void record_drop(DropKind kind, const std::string& who, const std::string& channel, const std::string& reason);

/// The counts now.
DropCounts drop_counts();

/// [s] log window of one kind.
inline constexpr double kDropLogInterval = 5.0;
/// [-] lines per kind and window.
inline constexpr int kDropLogBurst = 3;

}  // namespace wrc::bus
