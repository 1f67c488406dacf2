// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Counting and logging of rejected messages (undecodable, out of range, not answerable).
/// A bad message never crashes a process: it is counted and logged, with the log rate-limited so
/// that a flood of bad messages cannot flood stderr.

#include <cstdint>
#include <string>

namespace wrc::bus {

/// Counts rejections of one component and logs them to stderr as
/// `<who>: rejected message on <channel>: <reason>` (at most `burst` lines per second).
class RejectionLog {
 public:
  /// who: the component named in log lines, e.g. "wrc-pingd PING server".
  explicit RejectionLog(std::string who, int burst = 5) : who_(std::move(who)), burst_(burst) {}

  /// Counts and (rate-limited) logs one rejection.
  void reject(const std::string& channel, const std::string& reason);
  /// Rejections so far.
  std::int64_t count() const { return count_; }

 private:
  std::string who_;
  int burst_;
  std::int64_t count_ = 0;
  double window_start_ = -1.0;  // [s] monotonic start of the current one-second log window
  int logged_in_window_ = 0;
  std::int64_t suppressed_ = 0;
};

}  // namespace wrc::bus
